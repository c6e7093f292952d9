"""Lines and columns of XML elements and attributes, from their byte offsets.

Expat tells where an element starts; where each attribute and its value sit
is found by scanning the start tag, whose syntax is simple (names, `=`,
quoted values). Columns count characters from 1, like the EDS reader's.
"""

from __future__ import annotations

import re
from bisect import bisect_right
from collections.abc import Callable
from functools import partial

from .safe import Element

_TAG_NAME = re.compile(rb"<[^\s/>]+")
_ATTRIBUTE = re.compile(rb"""([^\s=/>"']+)\s*=\s*(?:"([^"]*)"|'([^']*)')""")


class Positions:
    """Turns byte offsets of one input into (line, column)."""

    def __init__(self, data: bytes) -> None:
        self.data = data
        self.starts = [0]
        found = data.find(b"\n")
        while found >= 0:
            self.starts.append(found + 1)
            found = data.find(b"\n", found + 1)
        self.at: Callable[[int], tuple[int, int]] = partial(position, self.starts, data)
        """(line, column) of a byte offset (below 0: of the first byte)."""


Spans = dict[str, tuple[int, int, int]]


def attribute_spans(data: bytes, element: Element) -> Spans:
    """Attribute name as written → (name offset, value start, value end) in bytes."""
    return spans_in(data, element.start, element.content_start)


def _position_python(starts: list[int], data: bytes, offset: int) -> tuple[int, int]:
    """(line, column) of `offset` in `data`, whose lines start at `starts`.

    The reference for the compiled `_tags.position`, as `_spans_python` is for `_tags.attribute_spans`: each
    compiled form does the same, and is used when it is installed."""
    if not starts:
        raise ValueError("position() takes a non-empty list of line starts")
    offset = max(offset, 0)  # expat's "no position"
    line = bisect_right(starts, offset)
    start = starts[line - 1]
    prefix = data[start:offset]
    column = len(prefix) if prefix.isascii() else len(prefix.decode("utf-8", "replace"))
    return line, column + 1


def _spans_python(data: bytes, start: int, end: int) -> Spans:
    """The attributes of the start tag data[start:end]."""
    first = _TAG_NAME.match(data, start, end)
    spans: Spans = {}
    for match in _ATTRIBUTE.finditer(data, first.end() if first else start, end):
        group = 2 if match.group(2) is not None else 3
        name = match.group(1).decode("utf-8", "replace")
        spans[name] = (match.start(1), match.start(group), match.end(group))
    return spans


position: Callable[[list[int], bytes, int], tuple[int, int]]
spans_in: Callable[[bytes, int, int], Spans]
try:
    from ._tags import attribute_spans as spans_in
    from ._tags import position
except ImportError:  # built without a C compiler: the same, in Python
    position, spans_in = _position_python, _spans_python
