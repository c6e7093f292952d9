"""Across formats: an EDS or DCF against an XDD or XDC of the same device.

Each family can state things the other cannot (an XDD's CANopenNode properties and descriptions, an EDS's
[FileInfo] keys and comment lines). What one side states and the other leaves out is no change of the device:
it is reported once per field as "not comparable", with how many entries it concerns, instead of once per entry.
"""

from __future__ import annotations

from collections import defaultdict
from pathlib import PurePath

from . import describe
from .records import Change, Impact, Kind, new_change

_FAMILIES = {".eds": "EDS", ".dcf": "EDS", ".xdd": "XDD", ".xdc": "XDD", ".xpd": "XDD"}
_NAMES = {"EDS": "EDS/DCF", "XDD": "XDD/XDC"}
# Kinds of facts that one family may hold and the other not.
_ONE_SIDED = frozenset(
    {Kind.CANOPENNODE, Kind.EXTRA_KEY, Kind.FILE_INFO, Kind.SECTION, Kind.COMMENT, Kind.DEVICE_INFO, Kind.IDENTITY}
)
_SHOWN = 4  # entries named in a not-comparable line


def family(source: str) -> str | None:
    """`EDS` or `XDD` by the file's extension (a `REV:path` or `a/path` alike); None when unknown (JSON)."""
    return _FAMILIES.get(PurePath(source.rpartition(":")[2]).suffix.lower())


def _absent(value: object, text: str) -> bool:
    return value is None or text in ("", '""')


def _one_sided(change: Change) -> str | None:
    """`old` or `new`: the only side stating this fact; None when both do (a real change)."""
    if change.kind not in _ONE_SIDED:
        return None
    old_absent, new_absent = _absent(change.old, change.old_text), _absent(change.new, change.new_text)
    if old_absent == new_absent:
        return None
    return "new" if old_absent else "old"


def _field(change: Change) -> str:
    """The field a not-comparable line groups by: XDD sections as one, object fields as they are."""
    if change.kind is Kind.SECTION:
        return "sections"
    return change.field


def _places(group: list[Change]) -> str:
    """` (278 entries: 0x1001, 0x1003, 0x1003:00, 0x1003:01, ...)`, or empty for device-level fields."""
    places = [describe.address(c.index, c.subindex) for c in group if c.index is not None]
    if not places:
        return ""
    more = ", ..." if len(places) > _SHOWN else ""
    return f" ({len(places)} entries: {', '.join(places[:_SHOWN])}{more})"


def split(old_source: str, new_source: str, changes: list[Change]) -> tuple[list[Change], list[Change]]:
    """(changes kept, one not-comparable line per field) when the two sides are of different families."""
    old_family, new_family = family(old_source), family(new_source)
    if old_family is None or new_family is None or old_family == new_family:
        return changes, []
    kept: list[Change] = []
    grouped: dict[tuple[str, str], list[Change]] = defaultdict(list)
    for change in changes:
        side = _one_sided(change)
        if side is None:
            kept.append(change)
        else:
            grouped[(_field(change), side)].append(change)
    lines = []
    for (field, side), group in sorted(grouped.items()):
        stating = _NAMES[old_family if side == "old" else new_family]
        places = [
            f"0x{c.index:04X}" + (f":{c.subindex:02X}" if c.subindex is not None else "")
            for c in group
            if c.index is not None
        ]
        where = (
            f" ({len(group)} entries: {', '.join(places[:_SHOWN])}{', ...' if len(places) > _SHOWN else ''})"
            if places
            else ""
        )
        lines.append(
            new_change(
                kind=Kind.NOT_COMPARABLE,
                impact=Impact.COSMETIC,
                field=field,
                old_text=stating if side == "old" else "-",
                new_text=stating if side == "new" else "-",
                note=f"only the {stating} states it{where}",
            )
        )
    return kept, lines
