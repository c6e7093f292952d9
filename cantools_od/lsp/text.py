"""The editor's text of a document, with edits applied without walking every line.

pygls applies an edit by copying the document line by line in Python: about a second on the main loop for each
keystroke in a 20 MB file, during which no other document is answered. Here the edit's two ends are found by
counting line ends in large blocks (in C) and the text is cut there; a text with line ends other than LF and
CRLF (a lone CR, or those str.splitlines also breaks at) keeps pygls's way, whose lines those are.
"""

from __future__ import annotations

import re
from typing import Any

from lsprotocol import types
from pygls.workspace import TextDocument, Workspace

_BLOCK = 1 << 16
_OTHER_BREAKS = re.compile("[\v\f\x1c\x1d\x1e\x85\u2028\u2029]|\r(?!\n)")


def _line_start(text: str, line: int) -> int:
    """The offset where line `line` (from 0) starts; len(text) past the last line."""
    offset, left = 0, line
    while left > 0:
        block = text.count("\n", offset, offset + _BLOCK)
        if block >= left or offset + _BLOCK >= len(text):
            break
        left -= block
        offset += _BLOCK
    for _ in range(left):
        found = text.find("\n", offset)
        if found < 0:
            return len(text)
        offset = found + 1
    return offset


def _offset(text: str, position: types.Position) -> int:
    start = _line_start(text, position.line)
    end = text.find("\n", start)
    line = text[start : end if end >= 0 else len(text)].removesuffix("\r")
    if line.isascii():
        return start + min(position.character, len(line))
    units = 0
    for column, char in enumerate(line):
        if units >= position.character:
            return start + column
        units += 2 if ord(char) > 0xFFFF else 1
    return start + len(line)


class Text(TextDocument):
    plain: bool | None = None
    """The text breaks lines with LF and CRLF only (None: not yet looked at)."""

    def _apply_incremental_change(self, change: types.TextDocumentContentChangePartial) -> None:
        source = self.source
        if self.plain is None:
            self.plain = _OTHER_BREAKS.search(source) is None
        if not self.plain or _OTHER_BREAKS.search(change.text) or change.text.endswith("\r"):
            super()._apply_incremental_change(change)
            self.plain = None
            return
        start, end = _offset(source, change.range.start), _offset(source, change.range.end)
        self._source = source[:start] + change.text + source[max(start, end) :]
        seam = self._source[max(start - 1, 0) : start + len(change.text) + 1]
        self.plain = _OTHER_BREAKS.search(seam) is None  # a CR left alone where the edit cut a CRLF

    def _apply_full_change(self, change: types.TextDocumentContentChangeEvent) -> None:
        super()._apply_full_change(change)
        self.plain = None


def faster(workspace: Workspace) -> None:
    """Make the workspace hold its documents as `Text`."""
    create = workspace._create_text_document

    def created(*args: Any, **kwargs: Any) -> TextDocument:
        document = create(*args, **kwargs)
        document.__class__ = Text
        return document

    workspace._create_text_document = created  # type: ignore[method-assign]
