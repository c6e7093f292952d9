"""The Markdown report: a release note or pull-request comment, grouped by impact, PDOs as bit tables."""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import PurePath

from ..model.cia301.pdo import is_dummy_index
from . import describe
from .pdos import TIMING_SUBS, timing_text, transmission_text
from .records import IMPACT_ORDER, Breaks, Change, DeviceDiff, Impact, Kind, PdoDiff, PdoEntryView, PdoView

_HEADINGS = {
    Impact.BREAKING: "Breaking changes",
    Impact.COMPATIBLE: "Compatible changes",
    Impact.VALUE: "Changed values",
    Impact.COSMETIC: "Cosmetic changes",
}
_INTRO = {
    Impact.BREAKING: "wire: a master or node configured for the old file may fail on the bus; "
    "code: firmware generated from the old file may no longer build or keep its stored data.",
    Impact.COMPATIBLE: "Additions and widened ranges: what worked before still works.",
    Impact.VALUE: "Defaults and other values: interfaces stay, behaviour may differ.",
    Impact.COSMETIC: "Names whose identifiers stay, comments, file metadata.",
}
_WHO = {Breaks.WIRE: "on the bus", Breaks.CODE: "in generated code"}
_FOLD_AFTER = 40  # lines of a section (other than breaking changes) shown before it folds into <details>
_LAYOUT_KINDS = (Kind.PDO_LAYOUT,)
_PDO_KINDS = frozenset(
    {Kind.PDO_LAYOUT, Kind.PDO_COB_ID, Kind.PDO_TRANSMISSION_TYPE, Kind.PDO_TIMING, Kind.PDO_ADDED, Kind.PDO_REMOVED}
)


def _escape(text: str) -> str:
    """Text safe in a list item or table cell (CommonMark and GitHub): no emphasis, no cell breaks, no HTML."""
    for char in "\\`*|<>[]":
        text = text.replace(char, "\\" + char)
    return text.replace("\n", " ")


def _code(text: str) -> str:
    text = text.replace("\n", " ").replace("|", "\\|")
    return f"`` {text} ``" if "`" in text else f"`{text}`"


@dataclass
class _Group:
    """The changes of one object, PDO or the device within one impact class."""

    title: str
    lines: list[str] = field(default_factory=list)

    def render(self) -> list[str]:
        if len(self.lines) == 1:
            return [f"- {self.title}: {self.lines[0]}"]
        return [f"- {self.title}", *(f"  - {line}" for line in self.lines)]


def side_name(source: str) -> str:
    """A side as the title names it: `/dev/null` (a new or deleted file), `v1.2:device.eds` (a revision), or the
    file's name."""
    if source == "/dev/null":
        return source
    revision, colon, path = source.rpartition(":")
    if colon and revision and "/" not in revision and "\\" not in revision:
        return f"{revision}:{PurePath(path).name}"
    return PurePath(source).name or source


def render(diff: DeviceDiff, names: tuple[str, str] | None = None) -> str:
    """The report; `names`: the sides as the title shows them (default: `side_name` of each source)."""
    old, new = names or (side_name(diff.old), side_name(diff.new))
    lines = [f"## Object dictionary changes: {_code(old)} → {_code(new)}", ""]
    if diff.empty:
        return "\n".join([*lines, "No changes.", ""])
    counts = diff.counts()
    parts = [f"{counts[impact]} {impact.value}" for impact in IMPACT_ORDER]
    if counts[Impact.BREAKING]:
        who = ", ".join(f"{sum(hurt in c.breaks for c in diff.changes())} {_WHO[hurt]}" for hurt in Breaks)
        parts[0] = f"**{parts[0]}** ({who})"
    lines += [", ".join(parts) + " changes.", ""]
    for impact in IMPACT_ORDER:
        groups = list(_groups(diff, impact))
        if not groups:
            continue
        items = [line for group in groups for line in group.render()]
        lines += [f"### {_HEADINGS[impact]} ({counts[impact]})", "", f"*{_INTRO[impact]}*", ""]
        if impact is not Impact.BREAKING and len(items) > _FOLD_AFTER:
            lines += ["<details><summary>Show them</summary>", "", *items, "", "</details>", ""]
        else:
            lines += [*items, ""]
    tables = [line for pdo in diff.pdos for line in _pdo_table(pdo)]
    if tables:
        lines += ["### PDO layouts", "", *tables]
    return "\n".join(lines).rstrip("\n") + "\n"


def _groups(diff: DeviceDiff, impact: Impact) -> Iterator[_Group]:
    device = _Group("**Device**", [_who(c) + _sentence(c) for c in diff.device if c.impact is impact])
    if device.lines:
        yield device
    for obj in diff.objects:
        group = _Group(f"{_code(f'0x{obj.index:04X}')} **{_escape(obj.name)}**")
        group.lines = [_who(c) + _entry(c) + _sentence(c) for c in obj.changes if c.impact is impact]
        if group.lines:
            yield group
    for pdo in diff.pdos:
        title = f"**{pdo.name}** ({_code(f'0x{pdo.comm_index:04X}')}/{_code(f'0x{pdo.map_index:04X}')})"
        group = _Group(title, [_who(c) + _entry(c) + _sentence(c) for c in pdo.changes if c.impact is impact])
        if group.lines:
            yield group


def _who(change: Change) -> str:
    """`**wire** ` before a breaking change: who it hurts."""
    return f"**{'+'.join(hurt.value for hurt in change.breaks)}** " if change.breaks else ""


def _entry(change: Change) -> str:
    """`` `0x2000:02` Input filter time: `` for a sub-object, `` `0x1A00`: `` for an object line of a PDO."""
    if change.index is None or (change.subindex is None and change.kind not in _PDO_KINDS):
        return ""
    where = _code(describe.address(change.index, change.subindex))
    if change.kind is Kind.NAME or change.kind in _PDO_KINDS:  # the sentence (or the PDO's title) names it
        return f"{where}: "
    return f"{where} {_escape(change.name)}: "


_VERBS = {Kind.NAME: "renamed", Kind.OBJECT_MOVED: "moved", Kind.SUB_MOVED: "moved"}


def _sentence(change: Change) -> str:
    """`data type `UNSIGNED16` → `UNSIGNED32` (width 16 bits → 32 bits)`, values in code spans."""
    if change.kind in (Kind.OBJECT_ADDED, Kind.SUB_ADDED, Kind.PDO_ADDED):
        text = f"added ({_code(change.new_text)})"
    elif change.kind in (Kind.OBJECT_REMOVED, Kind.SUB_REMOVED, Kind.PDO_REMOVED):
        text = f"removed (was {_code(change.old_text)})"
    elif change.kind is Kind.PDO_LAYOUT:
        text = f"mapping: {_escape(change.note)} (table below)"
    else:
        what = _VERBS.get(change.kind) or _escape(describe.label(change.field))
        if change.kind is Kind.NODEID_FORM:
            what += " ($NODEID form)"
        before, after = change.old_text, change.new_text
        if change.kind is Kind.NAME and isinstance(change.old, str) and isinstance(change.new, str):
            before, after = change.old, change.new  # names as written, without the quotes of the text report
        text = f"{what} {_code(before)} → {_code(after)}"
    return f"{text} ({_escape(change.note)})" if change.note and change.kind is not Kind.PDO_LAYOUT else text


def _pdo_table(pdo: PdoDiff) -> Iterator[str]:
    if not any(change.kind in _LAYOUT_KINDS for change in pdo.changes):
        return
    yield f"#### {pdo.name}"
    yield ""
    yield f"COB-ID {_both(pdo, _cob)}, transmission type {_both(pdo, _transmission)}{_timing(pdo)}"
    yield ""
    yield "| Bits | Before | After |"
    yield "|---|---|---|"
    before, after = _fields(pdo.before), _fields(pdo.after)
    for bits in sorted(set(before) | set(after)):
        yield f"| {bits[0]}-{bits[1]} | {before.get(bits, '')} | {after.get(bits, '')} |"
    yield ""


def _timing(pdo: PdoDiff) -> str:
    """`, event timer `100 ms``: the timing entries either side configures."""
    parts = []
    for sub, (label, _, _) in TIMING_SUBS.items():
        if any(view is not None and sub in view.timing for view in (pdo.before, pdo.after)):
            parts.append(f", {label} {_both(pdo, lambda view, sub=sub: timing_text(sub, view.timing.get(sub)))}")
    return "".join(parts)


def _cob(view: PdoView) -> str:
    return describe.cob_id_text(view.cob_id)


def _transmission(view: PdoView) -> str:
    return transmission_text(view.transmission_type)


def _both(pdo: PdoDiff, show: object) -> str:
    assert callable(show)
    before = "(absent)" if pdo.before is None else _code(show(pdo.before))
    after = "(absent)" if pdo.after is None else _code(show(pdo.after))
    return before if before == after else f"{before} → {after}"


def _fields(view: PdoView | None) -> dict[tuple[int, int], str]:
    if view is None:
        return {}
    return {(e.bit_offset, e.bit_offset + e.bit_length - 1): _field(e) for e in view.entries}


def _field(entry: PdoEntryView) -> str:
    """`` `0x6064:00` `position_actual_value` INTEGER32 ``, `dummy UNSIGNED8`, `` `0x6064:00` (no such object) ``."""
    if is_dummy_index(entry.index):
        return f"dummy {entry.data_type}"
    where = _code(describe.address(entry.index, entry.subindex))
    if entry.identifier:
        return f"{where} {_code(entry.identifier)} {entry.data_type}"
    return f"{where} (no such object)"
