"""CiA 306 files as sections of lines, with positions, before any meaning is given.

A section is its header line and every line after it up to the next header line (a line whose
first non-blank character is "["); the lines before the first header are the preamble. Each body
is then split into comment, blank, entry and stray lines.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from itertools import chain


@dataclass(slots=True)
class Entry:
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


@dataclass
class IniFile:
    sections: list[IniSection]
    preamble_comments: list[str]
    preamble_stray: list[tuple[int, str]]
    long_lines: list[tuple[int, int]] = field(default_factory=list)  # (line, length) over MAX_LINE


MAX_LINE = 255  # CiA 306: characters in a line, without its end


_EOL = re.compile(r"\r\n|\r|\n")
_LINE_WITH_END = re.compile(r"[^\r\n]*(?:\r\n|\r|\n)|[^\r\n]+\Z")


def split_lines(text: str) -> list[str]:
    """Lines with their ends, broken exactly where the reader breaks them (CR, LF, CRLF)."""
    return _LINE_WITH_END.findall(text)


_HEADER = re.compile(r"([ \t]*)\[([^\]\r\n]*)(\]?)")
# A header line after a line end (CR, LF, CRLF), from its line end on; the text's first line is matched
# on its own. (A look-behind for the line end would take the regular expression engine four times as long.)
_HEADER_AFTER_EOL = re.compile(r"[\r\n]([ \t]*\[([^\]\r\n]*))")
_HEADER_FIRST = re.compile(r"([ \t]*\[([^\]\r\n]*))")


def _headers(text: str) -> Iterator[re.Match[str]]:
    """Each header line's match, group 1 from its start and group 2 its name up to "]"."""
    first = _HEADER_FIRST.match(text)
    if first is not None:
        yield first
    yield from _HEADER_AFTER_EOL.finditer(text)


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
        for is_section, token in self._tokens():
            lines = _EOL.split(token)
            first, line = line, line + len(lines) - 1
            if len(token) > MAX_LINE and max(map(len, lines)) > MAX_LINE:
                self.long_lines.extend((first + n, len(text)) for n, text in enumerate(lines) if len(text) > MAX_LINE)
            if not is_section:
                trailing: list[str] = []
                _split_body(lines, first, 0, [], trailing, self.preamble_stray)
                pending = trailing
                continue
            match = _HEADER.match(lines[0])
            assert match is not None
            section = IniSection(
                name=match.group(2).strip(),
                line=first,
                column=len(match.group(1)) + 1,
                comments=pending,
                header_text=lines[0],
                closed=bool(match.group(3)),
            )
            # Comments after a section's last entry stand above the next header.
            pending = []
            _split_body(lines, first, 1, section.entries, pending, section.stray)
            yield section
        self.trailing = pending

    def _tokens(self) -> Iterator[tuple[bool, str]]:
        """(is a section, its text with its line ends) in file order; the preamble is no section."""
        for piece in self.pieces:
            start, is_section = 0, False  # what begins at `start`
            for match in _headers(piece):
                if match.start(1) > start:
                    yield is_section, piece[start : match.start(1)]
                start, is_section = match.start(1), True
            if start < len(piece):
                yield is_section, piece[start:]


_HEADER_LINE_BYTES = re.compile(_HEADER_AFTER_EOL.pattern.encode("ascii"))
_HEADER_FIRST_BYTES = re.compile(_HEADER_FIRST.pattern.encode("ascii"))


def repeated_section_names(text: str | bytes) -> set[str]:
    """The names (lower case) of sections given more than once, found without splitting the text.

    Names are remembered by hash, which keeps this small for a large file; a rare collision only
    adds a name that is given once."""
    if isinstance(text, str):
        names: Iterator[str] = (match.group(2) for match in _headers(text))
    else:
        first = _HEADER_FIRST_BYTES.match(text)
        found_bytes = chain([first] if first is not None else [], _HEADER_LINE_BYTES.finditer(text))
        names = (match.group(2).decode("utf-8", "replace") for match in found_bytes)
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


def _split_body(
    lines: list[str], first: int, skip: int, entries: list[Entry], comments: list[str], stray: list[tuple[int, str]]
) -> None:
    line = first - 1 + skip
    for raw in lines[skip:]:
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
        bare_key = key.rstrip(" \t")
        bare_value = value.lstrip(" \t")
        indent = len(raw) - len(raw.lstrip(" \t")) if raw[0] in " \t" else 0
        spaced = len(bare_key) != len(key) or len(bare_value) != len(value)
        entries.append(
            Entry(
                bare_key,
                bare_value,
                line,
                indent + 1,
                indent + len(key) + 2 + len(value) - len(bare_value) if spaced else indent + len(key) + 2,
                tuple(comments) if comments else (),
                spaced,
            )
        )
        if comments:
            comments.clear()
