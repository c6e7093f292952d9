"""Model positions (lines and columns of characters, from 1) to LSP positions (from 0, in UTF-16 units) and back."""

from __future__ import annotations

import re

from lsprotocol import types

_LINE = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+")
_OTHER_BREAKS = re.compile("[\v\f\x1c\x1d\x1e\x85\u2028\u2029]")
"""Where str.splitlines breaks a line and LSP does not."""


class Lines:
    """The lines of one text, split as LSP splits them (LF, CRLF, CR)."""

    def __init__(self, text: str) -> None:
        self.text = text
        plain = _OTHER_BREAKS.search(text) is None  # the usual text: str.splitlines splits it as LSP does, far faster
        self.lines: list[str] = (text.splitlines(keepends=True) if plain else _LINE.findall(text)) or [""]
        if text.endswith(("\n", "\r")):
            self.lines.append("")

    def __len__(self) -> int:
        return len(self.lines)

    def line(self, number: int) -> str:
        """Line `number` (from 0) without its line end; "" past the end."""
        if not 0 <= number < len(self.lines):
            return ""
        return self.lines[number].rstrip("\r\n")

    def units(self, number: int, column: int) -> int:
        """UTF-16 units before character `column` (from 0) of line `number`."""
        text = self.line(number)[:column]
        return len(text) if text.isascii() else len(text.encode("utf-16-le")) // 2

    def column(self, number: int, units: int) -> int:
        """Character column (from 0) of UTF-16 offset `units` on line `number`."""
        text = self.line(number)
        if text.isascii():
            return min(units, len(text))
        count = 0
        for index, char in enumerate(text):
            if count >= units:
                return index
            count += 2 if ord(char) > 0xFFFF else 1
        return len(text)

    def position(self, line: int, column: int) -> types.Position:
        """The LSP position of a model (line, column) counted from 1; 0 (unknown) is the start."""
        number = max(line - 1, 0)
        return types.Position(number, self.units(number, max(column - 1, 0)))

    def rest_of_line(self, line: int, column: int) -> types.Range:
        """From the model position to the end of its line's text (at least one character when there is one)."""
        start = self.position(line, column)
        text = self.line(start.line).rstrip()
        end = max(self.units(start.line, len(text)), start.character)
        return types.Range(start, types.Position(start.line, end))

    def whole_line(self, line: int) -> types.Range:
        number = max(line - 1, 0)
        return types.Range(
            types.Position(number, 0), types.Position(number, self.units(number, len(self.line(number))))
        )

    def end(self) -> types.Position:
        last = len(self.lines) - 1
        return types.Position(last, self.units(last, len(self.line(last))))

    def model(self, position: types.Position) -> tuple[int, int]:
        """The model (line, column) from 1 of an LSP position."""
        return position.line + 1, self.column(position.line, position.character) + 1
