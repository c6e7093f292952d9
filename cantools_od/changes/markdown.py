"""The Markdown report: a release note or pull-request comment, grouped by impact, PDOs as bit tables."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import PurePath

from . import describe
from .records import Change, DeviceDiff, Impact, ObjectDiff, PdoDiff, PdoView
from .text import summary

_HEADINGS = {
    Impact.BREAKING: "Breaking changes",
    Impact.COMPATIBLE: "Compatible changes",
    Impact.VALUE: "Changed values",
    Impact.COSMETIC: "Cosmetic changes",
}
_INTRO = {
    Impact.BREAKING: "Code generated from the old file, or a master configured for it, may fail with the new one.",
    Impact.COMPATIBLE: "Additions and widened ranges: what worked before still works.",
    Impact.VALUE: "Defaults and other values: interfaces stay, behaviour may differ.",
    Impact.COSMETIC: "Names whose identifiers stay, comments, file metadata.",
}


def _escape(text: str) -> str:
    return text.replace("\\", "\\\\").replace("|", "\\|").replace("*", "\\*").replace("_", "\\_").replace("\n", " ")


def _code(text: str) -> str:
    return f"`{text}`" if "`" not in text else text


def render(diff: DeviceDiff) -> str:
    old, new = PurePath(diff.old).name or diff.old, PurePath(diff.new).name or diff.new
    lines = [f"## Object dictionary changes: {_code(old)} → {_code(new)}", ""]
    if diff.empty:
        return "\n".join([*lines, "No changes.", ""])
    lines += [f"{summary(diff)}.", ""]
    for impact in _HEADINGS:
        items = list(_items(diff, impact))
        if not items:
            continue
        lines += [f"### {_HEADINGS[impact]} ({len(items)})", "", _INTRO[impact], ""]
        if impact is Impact.COSMETIC:
            lines += ["<details><summary>Show them</summary>", "", *items, "", "</details>", ""]
        else:
            lines += [*items, ""]
    pdos = [pdo for pdo in diff.pdos if pdo.before is not None or pdo.after is not None]
    if pdos:
        lines += ["### PDO layouts", ""]
        for pdo in pdos:
            lines += list(_pdo_table(pdo))
    return "\n".join(lines)


def _items(diff: DeviceDiff, impact: Impact) -> Iterator[str]:
    for change in diff.device:
        if change.impact is impact:
            yield f"- Device: {_sentence(change)}"
    for obj in diff.objects:
        for change in obj.changes:
            if change.impact is impact:
                yield f"- {_entry(obj, change)}: {_sentence(change)}"
    for pdo in diff.pdos:
        where = f"**{pdo.name}** ({_code(f'0x{pdo.comm_index:04X}')}/{_code(f'0x{pdo.map_index:04X}')})"
        for change in pdo.changes:
            if change.impact is impact:
                yield f"- {where}: {_sentence(change)}"


def _entry(obj: ObjectDiff, change: Change) -> str:
    if change.subindex is None:
        return f"{_code(f'0x{obj.index:04X}')} **{_escape(obj.name)}**"
    return f"{_code(f'0x{obj.index:04X} sub {change.subindex}')} **{_escape(obj.name)}** / {_escape(change.name)}"


def _sentence(change: Change) -> str:
    return _escape(describe.sentence(change))


def _pdo_table(pdo: PdoDiff) -> Iterator[str]:
    if not any(change.kind.value in ("pdo-layout", "pdo-added", "pdo-removed") for change in pdo.changes):
        return
    yield f"#### {pdo.name}"
    yield ""
    cob = f"COB-ID {_side(pdo.before, 'cob')} → {_side(pdo.after, 'cob')}"
    yield f"{cob}, transmission type {_side(pdo.before, 'tt')} → {_side(pdo.after, 'tt')}"
    yield ""
    yield "| Bits | Before | After |"
    yield "|---|---|---|"
    before, after = _fields(pdo.before), _fields(pdo.after)
    for bits in sorted(set(before) | set(after)):
        yield f"| {bits[0]}-{bits[1]} | {before.get(bits, '')} | {after.get(bits, '')} |"
    yield ""


def _side(view: PdoView | None, what: str) -> str:
    if view is None:
        return "(absent)"
    if what == "cob":
        return _code(describe.cob_id_text(view.cob_id))
    return _escape(str(view.transmission_type) if view.transmission_type is not None else "-")


def _fields(view: PdoView | None) -> dict[tuple[int, int], str]:
    if view is None:
        return {}
    return {
        (e.bit_offset, e.bit_offset + e.bit_length - 1): (
            f"{_code(e.identifier)} {e.data_type} ({_code(f'0x{e.index:04X} sub {e.subindex}')})"
            if e.identifier
            else f"dummy {e.data_type}"
        )
        for e in view.entries
    }
