"""The file comments of an EDS (`[Comments]`: `Lines=`, `Line1=`...) in an XDD/XDC, where CiA 311 has no
element for them: one XML comment right after the XML declaration, before the root element.

The comment's first line is MARKER (with a note on the escapes); the lines after it are the section
as an EDS writes it, `[Comments]` header included. An XML comment cannot hold `--`, nor the control
characters XML 1.0 excludes, and a parser reads CR as LF; so the text is escaped, reversibly:

- `\\\\` stands for `\\`,
- `\\-` for a `-` that follows a `-` (`---` is written `-\\-\\-`),
- `\\uXXXX` for a character XML cannot hold, and for CR.

Reading takes the first comment before the root element whose first line starts with MARKER; any other
XML comment of a file (a tool's banner, notes of a hand-written XDD) is no `[Comments]`.
"""

from __future__ import annotations

import re

from ..eds.reader import comments_in
from ..eds.report import Report
from ..eds.writer import comments_section, render
from ..model import Comments

MARKER = "cantools-od: EDS [Comments]"
_FIRST_LINE = MARKER + r" as CiA 306 text; \- is a - after a -, \\ is \, \uXXXX a control character"
_ESCAPED = re.compile(r"\\|(?<=-)-|[\x00-\x08\x0b-\x1f\ud800-\udfff\ufffe\uffff]")
_UNESCAPED = re.compile(r"\\(\\|-|u[0-9A-Fa-f]{4})")


def comment_block(comments: Comments) -> str:
    """The XML comment holding `comments`; its text ends with a line end, so it never ends with `-`."""
    return f"<!--{_FIRST_LINE}\n{_escape(render([comments_section(comments)], []))}-->"


def marked(text: str, marker: str = MARKER) -> bool:
    """Whether an XML comment's text is one of ours: its first line starts with `marker` (by default
    the one of the comment holding `[Comments]`) and more lines follow."""
    first, newline, _ = text.partition("\n")
    return bool(newline) and first.startswith(marker)


def read_comment_block(text: str, line: int, report: Report) -> Comments | None:
    """The `[Comments]` in a marked comment's text; `line` is the line its `<!--` is on, so that the
    positions read are the file's."""
    return comments_in("\n" * line + _unescape(text.partition("\n")[2]), report)


def _escape(text: str) -> str:
    return _ESCAPED.sub(_escaped, text)


def _escaped(match: re.Match[str]) -> str:
    char = match.group()
    if char in "\\-":
        return "\\" + char
    return f"\\u{ord(char):04X}"


def _unescape(text: str) -> str:
    return _UNESCAPED.sub(lambda m: chr(int(m.group(1)[1:], 16)) if m.group(1)[0] == "u" else m.group(1), text)
