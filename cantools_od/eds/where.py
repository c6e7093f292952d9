"""Which object's section a line of an EDS/DCF belongs to: what a diagnostic at that line touches."""

from __future__ import annotations

from bisect import bisect_right
from collections.abc import Callable

from ..model import Device, Diagnostic
from ..model.device import blocking_errors
from . import ini
from .decode import decode
from .keys import OBJECT_SECTION


def object_at(data: bytes) -> Callable[[int], int | None]:
    """A function from a line number of `data` to the index of the object whose section holds it
    ([2000], [2000sub1], [2000Value]...), or None outside object sections."""
    sections = ini.parse(decode(data)[0]).sections
    starts = [section.line for section in sections]
    indices = [_index(section.name) for section in sections]

    def find(line: int) -> int | None:
        position = bisect_right(starts, line) - 1
        return indices[position] if position >= 0 else None

    return find


def _index(name: str) -> int | None:
    match = OBJECT_SECTION.match(name)
    return int(match.group(1), 16) if match else None


def damaged_objects(device: Device) -> dict[int, list[Diagnostic]]:
    """The objects whose sections have an error, with those errors: an invalid value, a stray or
    over-long line, a broken header, a sub-object without its object... Not the errors about peers on a value
    read whole (`READ_WHOLE`: `0x80+$NODEID` is 80h + node-ID to the reader and to the code made of it)."""
    errors = [d for d in blocking_errors(device) if d.location.line > 0]
    if not errors or device._original is None:
        return {}
    find = object_at(device._original)
    damaged: dict[int, list[Diagnostic]] = {}
    for diagnostic in errors:
        index = find(diagnostic.location.line)
        if index is not None:
            damaged.setdefault(index, []).append(diagnostic)
    return damaged
