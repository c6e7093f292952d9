"""Lines and columns of XML elements and attributes, from their byte offsets.

Expat tells where an element starts; where each attribute and its value sit
is found by scanning the start tag, whose syntax is simple (names, `=`,
quoted values). Columns count characters from 1, like the EDS reader's.
"""

from __future__ import annotations

import re
from bisect import bisect_right

from .safe import Element

_TAG_NAME = re.compile(rb"<[^\s/>]+")
_ATTRIBUTE = re.compile(rb"""([^\s=/>"']+)\s*=\s*(?:"([^"]*)"|'([^']*)')""")


class Positions:
    """Turns byte offsets of one input into (line, column)."""

    def __init__(self, data: bytes) -> None:
        self.data = data
        self.starts = [0]
        position = data.find(b"\n")
        while position >= 0:
            self.starts.append(position + 1)
            position = data.find(b"\n", position + 1)

    def at(self, offset: int) -> tuple[int, int]:
        line = bisect_right(self.starts, offset)
        start = self.starts[line - 1]
        prefix = self.data[start:offset]
        column = len(prefix) if prefix.isascii() else len(prefix.decode("utf-8", "replace"))
        return line, column + 1


def attribute_spans(data: bytes, element: Element) -> dict[str, tuple[int, int, int]]:
    """Attribute name as written → (name offset, value start, value end) in bytes."""
    end = element.content_start
    first = _TAG_NAME.match(data, element.start, end)
    spans: dict[str, tuple[int, int, int]] = {}
    for match in _ATTRIBUTE.finditer(data, first.end() if first else element.start, end):
        group = 2 if match.group(2) is not None else 3
        name = match.group(1).decode("utf-8", "replace")
        spans[name] = (match.start(1), match.start(group), match.end(group))
    return spans
