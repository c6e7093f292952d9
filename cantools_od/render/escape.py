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


def rust_doc(text: str) -> str:
    """For after /// or //!: one ASCII line that rustdoc's Markdown shows as written (no link, HTML
    tag, emphasis or code span of its own, and no bare URL for rustdoc to warn about)."""
    return markdown_text(line_comment(text))


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


# Every ASCII punctuation CommonMark/GFM gives a meaning somewhere: emphasis and code (`*_~``), links and
# images (`[]()!`), HTML and entities (`<>&`), block starts (`#+-=>.` and list numbers' `.`/`)`), table
# cells (`|`), math on GitHub (`$^`), autolinks (`:` of a scheme, `@` of an e-mail, `.` of `www.`),
# emoji (`:`). A backslash before any ASCII punctuation is a valid escape that renders the character itself.
_MARKDOWN_SPECIAL = re.compile(r"[\\`*_{}\[\]()#+\-.!|<>&~^$:@=]")


def _markdown_escape(match: re.Match[str]) -> str:
    char, text, at = match.group(), match.string, match.start()
    # Between two ASCII letters or digits, `-` and `_` mean nothing (an intraword `_` neither opens nor
    # closes emphasis): left as they are, names such as "Pre-defined" and "io_device" stay readable.
    if char in "-_" and 0 < at < len(text) - 1 and _word(text[at - 1]) and _word(text[at + 1]):
        return char
    return "\\" + char


def _word(char: str) -> bool:
    return char.isascii() and char.isalnum()


def markdown_text(text: str) -> str:
    """Inline Markdown that renders as `text`, literally: one line, punctuation escaped, no HTML or link.

    Every backslash is escaped too, so every `|` is preceded by exactly one escaping backslash: a GFM
    table never splits a cell at it.
    """
    return _MARKDOWN_SPECIAL.sub(_markdown_escape, _one_line(text))


def markdown_cell(text: str) -> str:
    """A GFM table cell: like markdown_text, and never empty-looking (an em dash stands for no text)."""
    return markdown_text(text) or "\u2014"


_NOT_XML = re.compile(r"[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff]")


def xml_text(text: str) -> str:
    """For SVG or HTML text and attribute values: markup characters as entities, and the control characters
    XML cannot hold spelled as `\\xNN`, so that the document always parses and shows what the file says."""
    escaped = text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;").replace('"', "&quot;")
    return _NOT_XML.sub(lambda m: f"\\x{ord(m.group()):02x}", escaped)


def xml_comment(text: str) -> str:
    """For inside <!-- ... -->: one line that cannot end the comment."""
    return xml_text(_one_line(text)).replace("--", "- -")
