"""Text from a file, made safe inside generated comments and literals.

Whatever an EDS says, it can never end a comment, a string literal or a
Markdown table cell early, nor bring raw HTML into a document.
"""

from __future__ import annotations

import re

_CONTROL = re.compile(r"[\x00-\x1f\x7f]")


def _one_line(text: str) -> str:
    return " ".join(_CONTROL.sub(" ", text).split())


def _ascii(text: str) -> str:
    return text.encode("ascii", "backslashreplace").decode("ascii")


def c_comment(text: str) -> str:
    """For inside /* ... */: one ASCII line, no comment end, no trigraph."""
    return _ascii(_one_line(text)).replace("*/", "* /").replace("/*", "/ *").replace("??", "? ?")


def c_string(text: str | bytes) -> str:
    """A C string literal (with quotes). Bytes other than printable ASCII become octal escapes."""
    data = text.encode("utf-8") if isinstance(text, str) else text
    out = []
    for byte in data:
        char = chr(byte)
        if char in '"\\?':
            out.append("\\" + char)
        elif 0x20 <= byte < 0x7F:
            out.append(char)
        else:
            out.append(f"\\{byte:03o}")
    return '"' + "".join(out) + '"'


def line_comment(text: str) -> str:
    """For after // or #: one line, ASCII."""
    return _ascii(_one_line(text)).replace("??", "? ?")


def rust_string(text: str) -> str:
    out = []
    for char in text:
        if char in '"\\':
            out.append("\\" + char)
        elif 0x20 <= ord(char) < 0x7F:
            out.append(char)
        else:
            out.append(f"\\u{{{ord(char):x}}}")
    return '"' + "".join(out) + '"'


def python_string(text: str) -> str:
    return repr(text)


_MARKDOWN_SPECIAL = re.compile(r"([\\`*_{}\[\]()#+\-.!|<>&~^$])")


def markdown_text(text: str) -> str:
    """Inline Markdown: every punctuation that could mean something is escaped; no HTML passes."""
    return _MARKDOWN_SPECIAL.sub(r"\\\1", _one_line(text))


def markdown_cell(text: str) -> str:
    """A GFM table cell: like markdown_text, and never empty-looking."""
    return markdown_text(text)
