"""Edits applied to the editor's text as pygls applies them, without its walk over every line (text.py)."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st
from lsprotocol import types
from pygls.workspace import TextDocument

from cantools_od.lsp.text import Text

from support import EXAMPLES

LF = (EXAMPLES / "cia402_drive.eds").read_text(encoding="utf-8") + "Name=é𝄞x\n\nlast"
TEXTS = ["", "x", "a\nb", "\n", "\r\n", "DefaultValue=1\r\n", "é", "𝄞", "\r"]
BASES = [LF, LF.replace("\n", "\r\n"), LF.replace("\n", "\r\n", 40)]


def _units(line: str) -> int:
    return len(line.removesuffix("\r").encode("utf-16-le")) // 2


def _column(lines: list[str], line: int, wanted: int) -> int:
    """A position inside the line: past its end, clients never send."""
    return min(wanted, _units(lines[line])) if line < len(lines) else 0


@st.composite
def _edits(draw: st.DrawFn) -> list[tuple[int, int, int, int, str]]:
    count = LF.count("\n") + 1
    found = []
    for _ in range(draw(st.integers(1, 6))):
        first = draw(st.integers(0, count + 1))
        last = draw(st.integers(first, count + 1))
        found.append((first, draw(st.integers(0, 12)), last, draw(st.integers(0, 12)),
                      draw(st.sampled_from(TEXTS))))  # fmt: skip
    return found


@settings(max_examples=300, deadline=None)
@given(base=st.sampled_from(BASES), edits=_edits())
def test_an_edit_gives_the_text_pygls_gives(base: str, edits: list[tuple[int, int, int, int, str]]) -> None:
    ours, theirs = TextDocument("file:///a.eds", base), TextDocument("file:///a.eds", base)
    ours.__class__ = Text
    for first, first_column, last, last_column, text in edits:
        lines = theirs.source.split("\n")
        start, end = _column(lines, first, first_column), _column(lines, last, last_column)
        if first == last and end < start:
            start, end = end, start
        change = types.TextDocumentContentChangePartial(
            types.Range(types.Position(first, start), types.Position(last, end)), text
        )
        ours.apply_change(change)
        theirs.apply_change(change)
        assert ours.source == theirs.source
