"""CiA 306 files as sections of lines, with positions, before any meaning is given.

A section is its header line and every line after it up to the next header line (a line whose
first non-blank character is "["); the lines before the first header are the preamble. Each body
is then split into comment, blank, entry and stray lines.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from itertools import islice
from operator import itemgetter
from typing import AnyStr, NamedTuple


class Entry(NamedTuple):
    """One `key=value` line. A tuple, so that the reader makes one with a single C call (see `_split_body`)."""

    key: str  # as written, blanks around it removed
    value: str  # as written, blanks around it removed
    line: int
    key_col: int
    value_col: int
    comments: tuple[str, ...] = ()  # comment lines directly above
    spaced: bool = False  # blanks around "="


@dataclass
class IniSection:
    name: str  # between the brackets, blanks removed
    line: int
    column: int
    entries: list[Entry] = field(default_factory=list)
    comments: list[str] = field(default_factory=list)  # comment lines directly above the header
    trailing: list[str] = field(default_factory=list)  # comment lines after the last entry
    stray: list[tuple[int, str]] = field(default_factory=list)  # lines that are no entry
    header_text: str = ""  # the header line as written, for diagnostics
    closed: bool = True  # the header has its "]"
    plain: tuple[tuple[str, ...], tuple[str, ...]] | None = None
    """(keys, values) of the entries when they are written plainly: each `key=value` without blanks around "="
    or before the key, on the lines right after the header, with no comment among them (the layout of most
    sections). `None` otherwise. Lets the reader sort the keys of sections alike once for all of them."""


@dataclass
class IniFile:
    sections: list[IniSection]
    preamble_comments: list[str]
    preamble_stray: list[tuple[int, str]]
    long_lines: list[tuple[int, int]] = field(default_factory=list)  # (line, length) over MAX_LINE


_KEY, _VALUE = itemgetter(0), itemgetter(1)
MAX_LINE = 255  # CiA 306: characters in a line, without its end


_EOL = re.compile(r"\r\n|\r|\n")
# Characters besides CR and LF that `str.splitlines` breaks lines at, and the reader does not.
_OTHER_BREAKS = re.compile("[\v\f\x1c\x1d\x1e\x85\u2028\u2029]")
_LINE_WITH_END = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+\Z")


def split_lines(text: str) -> list[str]:
    """Lines with their ends, broken exactly where the reader breaks them (CR, LF, CRLF)."""
    return _LINE_WITH_END.findall(text)


_HEADER = re.compile(r"([ \t]*)\[([^\]\r\n]*)(\]?)")
_NAME = re.compile(r"[^\]\r\n]*")
_NAME_BYTES = re.compile(rb"[^\]\r\n]*")


def _header_starts(text: AnyStr) -> Iterator[int]:
    """Where each header line starts: a "[" with only blanks before it on its line.

    Found by `find`, which skips to the next "[" at C speed, rather than by a regular expression that
    has to try every line end (twenty times as long)."""
    bracket, blanks, ends = ("[", " \t", "\r\n") if isinstance(text, str) else (b"[", b" \t", b"\r\n")
    find = text.find
    position = find(bracket)
    while position >= 0:
        start = position
        while start and text[start - 1 : start] in blanks:
            start -= 1
        if not start or text[start - 1 : start] in ends:
            yield start
        position = find(bracket, position + 1)


def header_names(text: AnyStr) -> Iterator[AnyStr]:
    """The text between "[" and "]" (or the line end) of each header line."""
    name = _NAME if isinstance(text, str) else _NAME_BYTES
    bracket = "[" if isinstance(text, str) else b"["
    for start in _header_starts(text):
        found = name.match(text, text.index(bracket, start) + 1)
        assert found is not None  # the pattern matches the empty text too
        yield found.group()


def parse(text: str) -> IniFile:
    """Split text into sections. Never fails: odd lines are kept as stray."""
    stream = Stream([text])
    sections = list(stream)
    if sections:
        sections[-1].trailing = stream.trailing
        return IniFile(sections, [], stream.preamble_stray, stream.long_lines)
    return IniFile(sections, stream.trailing, stream.preamble_stray, stream.long_lines)


class Stream:
    """The sections of a text one at a time, so that a reader of a large file need not hold them all.

    The text comes in pieces, each but the first starting at a section header.

    Besides the sections, iterating fills in the lines before the first section that are no
    comment (`preamble_stray`), lines over MAX_LINE (`long_lines`), and, once done, the comment lines
    after the last entry of the file (`trailing`; the preamble's comments when there is no section).
    """

    def __init__(self, pieces: Iterable[str]) -> None:
        self.pieces = pieces
        self.preamble_stray: list[tuple[int, str]] = []
        self.long_lines: list[tuple[int, int]] = []
        self.trailing: list[str] = []

    def __iter__(self) -> Iterator[IniSection]:
        pending: list[str] = []
        line = 1  # lines end with CR, LF or CRLF
        for is_section, token, plain_breaks in self._tokens():
            if not is_section:
                trailing: list[str] = []
                line, _, _ = scan(token, line, 0, [], trailing, self.preamble_stray, self.long_lines, plain_breaks)
                pending = trailing
                continue
            entries: list[Entry] = []
            after: list[str] = []  # comments after a section's last entry stand above the next header
            stray: list[tuple[int, str]] = []
            first = line
            line, plain, header = scan(token, first, 1, entries, after, stray, self.long_lines, plain_breaks)
            assert header is not None
            name, column, closed, text = header
            # In field order (name, line, column, entries, comments, trailing, stray, header_text, closed, plain):
            # keywords cost 8 M instructions more over the Sevcon Nano EDS's 1,741 sections.
            yield IniSection(name, first, column, entries, pending, [], stray, text, closed, plain)
            pending = after
        self.trailing = pending

    def _tokens(self) -> Iterator[tuple[bool, str, bool]]:
        """(is a section, its text with its line ends, whether only CR and LF break its lines) in file order;
        the preamble is no section. Only the Python scanner asks the last: the compiled one is told True."""
        for piece in self.pieces:
            plain_breaks = scan is not _scan_python or _OTHER_BREAKS.search(piece) is None
            start, is_section = 0, False  # what begins at `start`
            for header in _header_starts(piece):
                if header > start:
                    yield is_section, piece[start:header], plain_breaks
                start, is_section = header, True
            if start < len(piece):
                yield is_section, piece[start:], plain_breaks


_NAMES_AFTER_LF = re.compile(rb"\n[ \t]*\[([^\]\r\n]*)")
_FIRST_NAME_BYTES = re.compile(rb"[ \t]*\[([^\]\r\n]*)")
_ASCII_SPACE = b" \t\n\r\x0b\x0c\x1c\x1d\x1e\x1f"  # what `str.strip` removes of ASCII


def repeated_section_names(text: str | bytes) -> set[str]:
    """The names (lower case) of sections given more than once, found without splitting the text.

    Names are remembered by hash, which keeps this small for a large file; a rare collision only
    adds a name that is given once."""
    if isinstance(text, bytes) and text.isascii() and text.count(b"\r") == text.count(b"\r\n"):
        # The common case at C speed: ASCII, every line ending in LF or CRLF (so that a header line follows an LF,
        # or starts the text), names folded as `str.strip().lower()` would. No name repeated ends it here.
        first = _FIRST_NAME_BYTES.match(text)
        listed = _NAMES_AFTER_LF.findall(text) + ([first.group(1)] if first is not None else [])
        folded = [name.strip(_ASCII_SPACE).lower() for name in listed]
        if len(set(folded)) == len(folded):
            return set()
    names: Iterator[str] = (
        header_names(text) if isinstance(text, str) else (n.decode("utf-8", "replace") for n in header_names(text))
    )
    seen: set[int] = set()
    repeated: set[str] = set()
    for found in names:
        name = found.strip().lower()
        key = hash(name)
        if key in seen:
            repeated.add(name)
        else:
            seen.add(key)
    return repeated


Plain = tuple[tuple[str, ...], tuple[str, ...]]
Header = tuple[str, int, bool, str]
"""A header line read: the name between the brackets (blanks removed), the column of "[", whether "]" closes it,
and the line as written."""


def _scan_python(
    token: str,
    first: int,
    skip: int,
    entries: list[Entry],
    comments: list[str],
    stray: list[tuple[int, str]],
    long_lines: list[tuple[int, int]],
    plain_breaks: bool,
) -> tuple[int, Plain | None, Header | None]:
    """Splits a token (a section's text, or the preamble) that starts on line `first` into lines, and the lines
    after the first `skip` into entries, comments and stray lines; notes lines over MAX_LINE.

    Returns the line the next token starts on; when `skip` is 1 (a section), what `IniSection.plain` holds and
    the header. `plain_breaks`: only CR and LF break the token's lines, so the faster `str.splitlines` breaks them
    where the reader does.

    The reference for the compiled `_scan.scan`, which does the same and is used when it is installed."""
    if plain_breaks:
        lines = token.splitlines()
        if token[-1] in "\r\n":
            lines.append("")
    else:
        lines = _EOL.split(token)
    if len(token) > MAX_LINE and max(map(len, lines)) > MAX_LINE:
        long_lines.extend((first + n, len(text)) for n, text in enumerate(lines) if len(text) > MAX_LINE)
    plain = _split_body(lines, first, skip, entries, comments, stray)
    if not skip:
        return first + len(lines) - 1, None, None
    match = _HEADER.match(lines[0])
    if match is None:
        raise ValueError("a section's text starts with its header line")
    header = (match.group(2).strip(), len(match.group(1)) + 1, bool(match.group(3)), lines[0])
    keys = None
    if plain and entries and entries[-1][2] - first == len(entries):  # on the lines after the header
        keys = (tuple(map(_KEY, entries)), tuple(map(_VALUE, entries)))
    return first + len(lines) - 1, keys, header


def _split_body(
    lines: list[str], first: int, skip: int, entries: list[Entry], comments: list[str], stray: list[tuple[int, str]]
) -> bool:
    """Sorts the lines into entries, comments and stray lines; whether every entry is written plainly (see
    `IniSection.plain`, but for where the entries stand)."""
    line = first - 1 + skip
    new = tuple.__new__  # an Entry without the Python-level call of Entry(...): this loop runs once per line
    add = entries.append
    plain = True
    for raw in islice(lines, skip, None):
        line += 1
        text = raw.strip(" \t")
        if not text:
            continue
        if text[0] in ";#":
            comments.append(text)
            continue
        key, equals, value = text.partition("=")
        if not equals:
            stray.append((line, text))
            continue
        if comments:
            above, plain = tuple(comments), False
            comments.clear()
        else:
            above = ()
        if raw[0] in " \t":
            indent, plain = len(raw) - len(raw.lstrip(" \t")), False
        else:
            indent = 0
        bare_key = key.rstrip(" \t")
        bare_value = value.lstrip(" \t")
        if bare_key is key and bare_value is value:  # no blanks around "=": strip gave back the same strings
            add(new(Entry, (key, value, line, indent + 1, indent + len(key) + 2, above, False)))
        else:
            value_col = indent + len(key) + 2 + len(value) - len(bare_value)
            add(new(Entry, (bare_key, bare_value, line, indent + 1, value_col, above, True)))
            plain = False
    return plain


Scan = Callable[
    [str, int, int, list[Entry], list[str], list[tuple[int, str]], list[tuple[int, int]], bool],
    tuple[int, Plain | None, Header | None],
]
scan: Scan
try:
    from . import _scan
except ImportError:  # built without a C compiler: the same, in Python
    scan = _scan_python
else:
    _scan.setup(Entry)
    scan = _scan.scan
