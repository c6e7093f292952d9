"""Text edits that turn one text into another, the changed lines only."""

from __future__ import annotations

import difflib

from lsprotocol import types

from .positions import Lines


def _lines(text: str) -> list[str]:
    """The lines with their ends, split where LSP splits them (LF, CRLF, CR): nothing past the last end."""
    return [line for line in Lines(text).lines if line]


def edits(old: str, new: str) -> list[types.TextEdit]:
    """One edit per changed run of lines (difflib's, which skips lines too common to anchor a match), in
    document order."""
    if old == new:
        return []
    before, after = _lines(old), _lines(new)
    lines = Lines(old)
    found = []
    matcher = difflib.SequenceMatcher(None, before, after)
    for tag, i1, i2, j1, j2 in matcher.get_opcodes():
        if tag == "equal":
            continue
        start = types.Position(i1, 0) if i1 < len(before) else lines.end()
        end = types.Position(i2, 0) if i2 < len(before) else lines.end()
        found.append(types.TextEdit(types.Range(start, end), "".join(after[j1:j2])))
    return found


def one_edit(old: str, new: str) -> list[types.TextEdit]:
    """The smallest single edit: the lines between the common head and the common tail."""
    if old == new:
        return []
    before, after = _lines(old), _lines(new)
    head = 0
    while head < min(len(before), len(after)) and before[head] == after[head]:
        head += 1
    tail = 0
    while tail < min(len(before), len(after)) - head and before[-1 - tail] == after[-1 - tail]:
        tail += 1
    lines = Lines(old)
    stop = len(before) - tail
    start = types.Position(head, 0) if head < len(before) else lines.end()
    end = types.Position(stop, 0) if stop < len(before) else lines.end()
    return [types.TextEdit(types.Range(start, end), "".join(after[head : len(after) - tail]))]


def apply(text: str, changes: list[types.TextEdit]) -> str:
    """The text with edits applied (as a client applies them), for tests and checks."""
    lines = Lines(text)
    offsets = [0]
    for line in lines.lines:
        offsets.append(offsets[-1] + len(line))

    def offset(position: types.Position) -> int:
        if position.line >= len(lines.lines):
            return len(text)
        return offsets[position.line] + lines.column(position.line, position.character)

    out = text
    for change in sorted(changes, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        out = out[: offset(change.range.start)] + change.new_text + out[offset(change.range.end) :]
    return out
