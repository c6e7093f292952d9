"""What sits at a line of the document: the model part whose origin (header or key) is written there."""

from __future__ import annotations

from bisect import bisect_right
from dataclasses import dataclass

from ..model import Device, Object, Section, Variable


@dataclass(frozen=True)
class Spot:
    """A section header (key None) or a key of a section, where the file writes it (from 1)."""

    section: Section
    key: str | None
    line: int
    column: int
    value_column: int
    owner: Object | None = None
    """The object the section belongs to (itself for an object's own section)."""
    subindex: int | None = None
    """The sub-index a sub-object's section describes; 0 for a VAR; None for the object of an ARRAY/RECORD."""

    @property
    def var(self) -> Variable | None:
        if self.owner is None:
            return None
        if self.subindex is None:
            return self.owner
        return self.owner.entry(self.subindex)


def _owners(device: Device) -> dict[int, tuple[Object, int | None]]:
    owners: dict[int, tuple[Object, int | None]] = {}
    for obj in device.objects.values():
        owners[id(obj)] = (obj, None if obj.has_subs else 0)
        for subindex, sub in obj.subs.items():
            owners[id(sub)] = (obj, subindex)
    return owners


class Index:
    """Every header and key of the device by line, and the headers in line order."""

    def __init__(self, device: Device) -> None:
        self.device = device
        self.by_line: dict[int, list[Spot]] = {}
        self.headers: list[Spot] = []
        owners = _owners(device)
        for section in device.sections():
            origin = section.origin
            if origin is None or origin.line <= 0:
                continue
            owner, subindex = owners.get(id(section), (None, None))
            header = Spot(section, None, origin.line, origin.column, origin.column, owner, subindex)
            self.headers.append(header)
            self.by_line.setdefault(origin.line, []).append(header)
            for key, (line, column, value_column) in origin.positions():
                spot = Spot(section, key, line, column, value_column, owner, subindex)
                self.by_line.setdefault(line, []).append(spot)
        self.headers.sort(key=lambda spot: (spot.line, spot.column))
        self._header_lines = [spot.line for spot in self.headers]

    def at(self, line: int, column: int) -> Spot | None:
        """The key or header written at (line, column); on a line of several, the last starting at or before it."""
        spots = sorted(self.by_line.get(line, []), key=lambda spot: spot.column)
        chosen = [spot for spot in spots if spot.column <= column]
        if chosen:
            return chosen[-1]
        if spots:
            return spots[0]
        return self.section_at(line)

    def section_at(self, line: int) -> Spot | None:
        """The header of the section a line lies in (the last header at or above it)."""
        found = bisect_right(self._header_lines, line)
        return self.headers[found - 1] if found else None

    def header_of(self, section: Section) -> Spot | None:
        origin = section.origin
        if origin is None:
            return None
        for spot in self.by_line.get(origin.line, []):
            if spot.section is section and spot.key is None:
                return spot
        return None

    def end_line(self, header: Spot) -> int:
        """The last line of the section a header starts: its last key's line."""
        origin = header.section.origin
        if origin is None:
            return header.line
        return max([header.line, *(where[0] for _, where in origin.positions())])
