"""The text a value had in the file a device was read from, found by the value's recorded position.

Only a hint: a writer keeps a spelling choice from it (radix, a REAL written as an integer) when the
model's value is still what that text reads as. Positions are (line, key column, value column); in an
EDS/DCF the value runs to the end of its line, in an XDD/XDC to the quote that opened the attribute.
"""

from __future__ import annotations

from html import unescape

from ..model import Device, Section
from . import ini
from .decode import decode_as


class Hints:
    def __init__(self, original: bytes | None, xml: bool = False) -> None:
        self._original = original
        self._xml = xml
        self._split: list[str] | None = None  # the lines, split when a hint is first asked for

    @property
    def _lines(self) -> list[str]:
        if self._split is None:
            self._split = ini.split_lines(decode_as(self._original)[0]) if self._original else []
        return self._split

    @classmethod
    def of(cls, device: Device) -> Hints:
        """The hints of the file `device` was read from (none for JSON or a device made in memory)."""
        if device.file_format not in ("eds", "xdd"):
            return NO_HINTS
        return cls(device._original, xml=device.file_format == "xdd")

    def text(self, section: Section, key: str) -> str | None:
        where = section.origin.where(key) if section.origin is not None and self._original else None
        if where is None or not 0 < where[0] <= len(self._lines) or where[2] < 1:
            return None
        line = self._lines[where[0] - 1]
        rest = line[where[2] - 1 :]
        if not self._xml:
            return rest.strip()
        quote = line[where[2] - 2 : where[2] - 1]
        end = rest.find(quote) if quote in ('"', "'") else -1
        return unescape(rest[:end]).strip() if end >= 0 else None  # element text or a broken line: no hint


NO_HINTS = Hints(None)
