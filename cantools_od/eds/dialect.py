"""Which tool's value conventions a file follows (the dialects peer tools write), and lely string quoting."""

from __future__ import annotations

import re
from functools import lru_cache

from ..canopennode.info import EDS_COMMENT_KEYS
from ..model import Dialect
from .ini import IniSection, Stream

DIRECTIVE = re.compile(r"[;#]\s*cantools-od\s*:\s*dialect\s*[=:]?\s*([\w-]+)", re.IGNORECASE)
_MAPPING_SECTION = re.compile(r"1[67ab][0-9a-f]{2}\Z", re.IGNORECASE)
_NODEID_LAST = re.compile(r"\+\s*\$nodeid\s*\Z", re.IGNORECASE)


def directive(text: str) -> Dialect | None:
    """The dialect a `; cantools-od: dialect=<name>` comment names, if it is one."""
    match = DIRECTIVE.match(text)
    if match is None:
        return None
    try:
        return Dialect(match.group(1).lower())
    except ValueError:
        return None


def text_dialect(text: str) -> Dialect:
    """The dialect the reader finds in `text`, a whole EDS/DCF: what a writer checks its output against."""
    stream = Stream([text])
    evidence = DialectEvidence(may_hold_markers(text))
    for section in stream:
        evidence.see(section)
    return evidence.dialect(stream.trailing)


class DialectEvidence:
    """Dialect evidence gathered from sections seen one at a time, for a reader that does not keep them."""

    def __init__(self, markers: bool = True) -> None:
        self.lely = False
        self.other: Dialect | None = None  # the first evidence of another family, in file order
        self.markers = markers  # False: the text has none of MARKERS, so only keys can tell
        self.top: list[str] | None = None  # the comments above the first section, where a directive stands

    def see(self, section: IniSection) -> None:
        """Takes the next section, as read (a directive among the first one's comments still there)."""
        if self.top is None:
            self.top = section.comments
        if not self.lely:
            self.lely = _lely(section)
        if self.other is None and (self.markers or section.plain is None or _telling_keys(section.plain[0])):
            self.other = _other(section)

    def dialect(self, trailing: list[str]) -> Dialect:
        """`trailing`: the comments after the last section, where a text without sections has its directive."""
        for comment in self.top if self.top is not None else trailing:
            named = directive(comment)
            if named is not None:
                return named
        if self.lely:
            return Dialect.LELY
        return self.other or Dialect.CIA306


def _lely(section: IniSection) -> bool:
    name = section.name  # tested by length first: this runs once per section of a file
    if len(name) == 4:
        return _MAPPING_SECTION.match(name) is not None and any(
            e.key.lower() == "compactsubobj" for e in section.entries
        )
    return (
        len(name) == 10
        and name.lower() == "deviceinfo"
        and any(e.key.lower() == "vendorname" and "lely" in e.value.lower() for e in section.entries)
    )


def _other(section: IniSection) -> Dialect | None:
    if section.comments and any(map(_canopennode_comment, section.comments)):
        return Dialect.CANOPENNODE
    for key, value, _, _, _, above, _ in section.entries:  # once per entry of a file: cheap tests first
        if above and _canopennode_comment(above[0]):
            return Dialect.CANOPENNODE
        if len(key) == 9 and key.lower() == "createdby" and _CANOPENNODE_TOOL.search(value):
            return Dialect.CANOPENNODE
        if "$" in value and _NODEID_LAST.search(value):
            return Dialect.PYTHON_CANOPEN
        if len(key) == 10 and key.lower() == "edsversion" and value.strip() == "4.2":
            return Dialect.PYTHON_CANOPEN
    return None


@lru_cache(maxsize=256)  # the few lists of keys of a file's sections
def _telling_keys(keys: tuple[str, ...]) -> bool:
    """Whether any of the keys is one whose value `_other` looks at."""
    return any(key.lower() in ("createdby", "edsversion") for key in keys)


# Comments only CANopenNode's tools write (a match at the start, as `str.startswith`).
_canopennode_comment = re.compile("|".join(map(re.escape, EDS_COMMENT_KEYS))).match
MARKERS = EDS_COMMENT_KEYS
"""Comments of which a text must hold one, or else a `+ $NODEID` ending (`_PLUS_DOLLAR`), for `_other` to find
evidence in anything but a key (`CreatedBy`, `EDSVersion`)."""
# What `_NODEID_LAST` needs of a value, and more: "+", blanks, "$". In UTF-8 bytes, a blank `str` patterns know and
# `bytes` patterns do not is \x1c-\x1f or non-ASCII: any such byte is taken as one.
_PLUS_DOLLAR = re.compile(r"\+\s*\$")
_PLUS_DOLLAR_UTF8 = re.compile(rb"\+(?:\s|[\x1c-\x1f\x80-\xff])*\$")


def may_hold_markers(data: bytes | str) -> bool:
    """Whether the text (UTF-8 bytes, or decoded) may hold dialect evidence besides keys: False lets the reader
    look only at sections with telling keys. Most files have a `$NODEID+...` but no `+ $NODEID` ending."""
    if isinstance(data, bytes):
        return any(marker.encode("ascii") in data for marker in MARKERS) or bool(_PLUS_DOLLAR_UTF8.search(data))
    return any(marker in data for marker in MARKERS) or bool(_PLUS_DOLLAR.search(data))


_CANOPENNODE_TOOL = re.compile("canopen(node|editor)|libedssharp", re.IGNORECASE)


def unquote(text: str) -> str | None:
    """A lely-style quoted string's content, or None when `text` is not quoted."""
    if len(text) < 2 or text[0] != '"' or text[-1] != '"':
        return None
    return re.sub(r'\\(["\\])', r"\1", text[1:-1])


def quote(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'
