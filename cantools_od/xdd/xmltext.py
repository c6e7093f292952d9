"""Text and attribute values as XML writes them (XML 1.0 §2.4, §3.3.3).

The same escaping as the standard library's `xml.sax.saxutils`, which the reader cannot import cheaply: that
module imports urllib.request, and with it http, email and ssl, for reading any XDD.
"""

from __future__ import annotations

from functools import cache

_MARKUP = {"&": "&amp;", "<": "&lt;", ">": "&gt;"}
_ATTRIBUTE_BREAKS = {"\n": "&#10;", "\r": "&#13;", "\t": "&#9;"}  # an attribute value's line ends survive reading


def escape(text: str, more: dict[str, str] | None = None) -> str:
    """`text` as element content: `&`, `<` and `>` as references, and each single character of `more` as given."""
    return text.translate(_table(tuple(more.items())) if more else _MARKUP_TABLE)


def quoteattr(text: str, more: dict[str, str] | None = None) -> str:
    """`text` as a quoted attribute value: escaped as `escape` does and with line ends and tabs as references,
    in double quotes, or in single quotes when it holds a double quote and no single one (else `"` as &quot;)."""
    value = text.translate(_table((*(more or {}).items(), *_ATTRIBUTE_BREAKS.items())))
    if '"' not in value:
        return f'"{value}"'
    if "'" not in value:
        return f"'{value}'"
    return '"' + value.replace('"', "&quot;") + '"'


_MARKUP_TABLE = str.maketrans(_MARKUP)


@cache
def _table(more: tuple[tuple[str, str], ...]) -> dict[int, str]:
    """The translation table of the markup and `more` (later pairs win): a writer asks for the same few tables
    tens of thousands of times."""
    return str.maketrans({**_MARKUP, **dict(more)})
