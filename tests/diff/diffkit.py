"""Edits of a shipped example EDS, as a firmware engineer would make them, for diff tests."""

from __future__ import annotations

import re

from cantools_od import loads
from cantools_od.changes import Change, DeviceDiff, Kind, compare
from cantools_od.model import Device

from support import EXAMPLES

BASE = (EXAMPLES / "io_device.eds").read_text(encoding="utf-8")


def _section(text: str, name: str) -> re.Match[str]:
    match = re.search(rf"^\[{re.escape(name)}\]\n(?:(?!\[).*\n?)*", text, re.MULTILINE | re.IGNORECASE)
    assert match is not None, f"no [{name}] in the example"
    return match


def set_key(text: str, section: str, key: str, value: str | None) -> str:
    """`key=value` in `[section]` replaced, added (when missing) or removed (value None)."""
    match = _section(text, section)
    block = match.group(0)
    pattern = re.compile(rf"^{re.escape(key)}=.*$\n?", re.MULTILINE | re.IGNORECASE)
    if value is None:
        new_block = pattern.sub("", block)
    elif pattern.search(block):
        new_block = pattern.sub(lambda _: f"{key}={value}\n", block, count=1)
    else:
        header, _, rest = block.partition("\n")
        new_block = f"{header}\n{key}={value}\n{rest}"
    return text[: match.start()] + new_block + text[match.end() :]


def drop_section(text: str, section: str) -> str:
    match = _section(text, section)
    return text[: match.start()] + text[match.end() :]


def device(text: str = BASE) -> Device:
    return loads(text, source="io_device.eds")


def diff_of(new_text: str, old_text: str = BASE, **options: object) -> DeviceDiff:
    return compare(device(old_text), device(new_text), **options)  # type: ignore[arg-type]


def summary(result: DeviceDiff) -> set[tuple[str, str, int | None, int | None]]:
    """(kind, impact, index, sub-index) of every change."""
    return {(c.kind.value, c.impact.value, c.index, c.subindex) for c in result.changes()}


def only(result: DeviceDiff) -> Change:
    changes = list(result.changes())
    assert len(changes) == 1, [(c.kind.value, c.index, c.subindex, c.field) for c in changes]
    return changes[0]


def beyond_respelling(result: DeviceDiff) -> list[tuple[str, int | None, int | None, str]]:
    """The changes between a file and its `fmt` output other than fmt's respelling of names python-canopen
    looks up (#39: fmt writes them as CiA 306 spells them, which python-canopen then reads; fmt's own peer test
    judges that). Each such respelling must make python-canopen read more, never less."""
    kept = []
    for change in result.changes():
        if change.kind is Kind.PEER_READING and change.note.startswith("python-canopen now reads"):
            continue
        kept.append((change.kind.value, change.index, change.subindex, change.field))
    return kept
