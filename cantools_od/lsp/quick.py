"""A quick first answer after an edit inside one object of a large EDS, before the exact one.

Reading and linting a 500 kB file again takes a good part of a second. When an edit changes only
entry lines of one object's section (the usual keystroke), the server first reads and lints a text
that holds that object, the objects it needs to be judged (the device type, its PDO's other record,
the objects its mapping entries name) and the file's non-object sections, every other line left
blank so that line numbers stay; it takes the findings on the object's lines from that, with the
dialect of the whole file, and keeps the previous findings of every other line (moved by the lines
the edit added or removed) and of the rules that count over the whole file. It publishes that
without a document version, at once; the full check of the whole text follows and publishes the
exact findings with the version, which replace these. What the quick answer can miss is what the
object means to the rest of the file (a PDO mapping that names it, a list that counts it).
"""

from __future__ import annotations

import re
from bisect import bisect_right
from dataclasses import dataclass
from functools import cache

from ..lint import RULES, Finding, LintOptions, lint
from ..lint.codes import load as load_families
from ..lint.runner import moved
from ..model.cia301.objects import COMM_BASE, DEVICE_TYPE, MAP_BASE, PDO_SPAN
from ..sniff import NotADeviceDescription
from .document import Analysis, Encoding, read, selection_for

_HEADER = re.compile(r"^[ \t]*\[([^\]\r\n]*)", re.MULTILINE)
_OBJECT = re.compile(r"([0-9a-f]{1,4})(?:sub[0-9a-f]{1,3}|name|value|denotation|objectlinks)?\Z", re.IGNORECASE)
_OTHER_BREAKS = ("\x0b", "\x0c", "\x1c", "\x1d", "\x1e", "\x85", "\u2028", "\u2029")


@dataclass(frozen=True)
class _Layout:
    """A text's sections: where each header starts, its line (from 1) and its object index (None for
    a section that is no object's)."""

    text: str
    starts: list[int]
    lines: list[int]
    objects: list[int | None]

    @staticmethod
    def of(text: str) -> _Layout:
        starts, lines, objects = [], [], []
        line, counted = 1, 0
        for header in _HEADER.finditer(text):
            line += text.count("\n", counted, header.start())
            counted = header.start()
            found = _OBJECT.match(header.group(1).strip())
            starts.append(header.start())
            lines.append(line)
            objects.append(int(found.group(1), 16) if found is not None else None)
        return _Layout(text, starts, lines, objects)

    def section_at(self, offset: int) -> int:
        """The section (its number in `starts`) the character at `offset` is in; -1 before the first."""
        return bisect_right(self.starts, offset) - 1

    def spans(self, index: int) -> set[int]:
        """The lines (from 1) of `index`'s sections, headers included."""
        total = self.text.count("\n") + 2
        return {
            number
            for at, owner in enumerate(self.objects)
            if owner == index
            for number in range(self.lines[at], self.lines[at + 1] if at + 1 < len(self.lines) else total)
        }


_CHUNK = 4096


def _changed(old: str, new: str) -> tuple[int, int]:
    """How many characters the texts share at the start, and at the end (not overlapping)."""
    limit = min(len(old), len(new))
    start = 0
    while start < limit and old[start : start + _CHUNK] == new[start : start + _CHUNK]:
        start = min(start + _CHUNK, limit)
    while start < limit and old[start] == new[start]:
        start += 1
    end, most = 0, limit - start
    while (
        end + _CHUNK <= most
        and old[len(old) - end - _CHUNK : len(old) - end] == new[len(new) - end - _CHUNK : len(new) - end]
    ):
        end += _CHUNK
    while end < most and old[len(old) - end - 1] == new[len(new) - end - 1]:
        end += 1
    return start, end


def _edited_object(old: _Layout, text: str) -> tuple[int, int, int, _Layout] | None:
    """(object index, the lines before the first changed one, the lines added (or removed, below 0),
    the new text's layout) when the edit changed only entry lines inside one object's section; None
    otherwise (a header or the line end before one, lines of another section)."""
    start, end = _changed(old.text, text)
    line_start = old.text.rfind("\n", 0, start) + 1
    section = old.section_at(line_start)
    index = old.objects[section] if section >= 0 else None
    if index is None:
        return None
    following = old.starts[section + 1] if section + 1 < len(old.starts) else len(old.text) + 1
    old_last, new_last = len(old.text) - end, len(text) - end
    header_end = old.text.find("\n", old.starts[section])
    if header_end < 0 or line_start <= header_end or old_last >= following:
        return None
    line_end = text.find("\n", new_last)
    if _HEADER.search(text, line_start, line_end if line_end >= 0 else len(text)) is not None:
        return None  # the edit made a header
    chars = len(text) - len(old.text)
    lines = text.count("\n", start, new_last) - old.text.count("\n", start, old_last)
    after = section + 1
    layout = _Layout(
        text,
        old.starts[:after] + [at + chars for at in old.starts[after:]],
        old.lines[:after] + [line + lines for line in old.lines[after:]],
        old.objects,
    )
    return index, old.text.count("\n", 0, line_start), lines, layout


def object_edit(old: Analysis, text: str) -> tuple[_Layout, tuple[int, int, int, _Layout]] | None:
    """The old text's layout and what `_edited_object` says of the edit, when `text` is an edit inside
    one object of `old`'s EDS/DCF text; None otherwise (and for a save: the configuration may have changed)."""
    if old.device is None or old.device.file_format != "eds" or text == old.text or not plain_lines(text):
        return None
    before = _layout(old.text)
    edited = _edited_object(before, text)
    if edited is None:
        return None
    _keep(edited[3])
    return before, edited


def quick_findings(
    old: Analysis, text: str, uri: str, encoding: Encoding, options: LintOptions
) -> list[Finding] | None:
    """The quick findings for `text`, an edit of `old`'s text; None when the edit is not one the quick
    answer covers (the full check alone answers)."""
    edit = object_edit(old, text)
    if edit is None or old.device is None:
        return None
    before, (index, start, delta, after) = edit
    try:
        device = read(uri, encoding.bytes(_only(after, _context(after, index))))
        device.dialect = old.device.dialect  # the whole file's, which the object alone may not show
        found = lint(device, options, selection_for(uri))
    except (NotADeviceDescription, RecursionError, ValueError):
        return None
    old_spans, kept = before.spans(index), after.spans(index)
    whole = _whole_file_codes()
    others = [moved(f, start, delta) for f in old.findings if f.location.line not in old_spans or f.code in whole]
    ours = [f for f in found if f.location.line in kept and f.code not in whole]
    return sorted(set(others + ours), key=_order)


def plain_lines(text: str) -> bool:
    """Lines end in LF or CRLF only: where the layout finds headers, the reader does too."""
    if any(b in text for b in _OTHER_BREAKS):
        return False
    return text.count("\r") == text.count("\r\n")  # lines that end in CR alone: headers are found after LF only


_MAPPED = re.compile(r"=[ \t]*(?:0x([0-9a-f]{5,8})|([1-9][0-9]{4,9}))[ \t]*\r?$", re.IGNORECASE | re.MULTILINE)


def _context(layout: _Layout, index: int) -> set[int]:
    """The object, the device type (which profile's objects the file has), its PDO's other record, and
    the objects its values name as mapping entries do."""
    wanted = {index, DEVICE_TYPE}
    for direction, communication in COMM_BASE.items():
        mapping = MAP_BASE[direction]
        if communication <= index < mapping + PDO_SPAN:
            wanted.add(index - communication + mapping if index < mapping else index - mapping + communication)
    text = layout.text
    for at, owner in enumerate(layout.objects):
        if owner == index:
            finish = layout.starts[at + 1] if at + 1 < len(layout.starts) else len(text)
            for value in _MAPPED.finditer(text, layout.starts[at], finish):
                wanted.add(int(value.group(1), 16) >> 16 if value.group(1) else int(value.group(2)) >> 16)
    return wanted


@cache
def _whole_file_codes() -> frozenset[str]:
    """The rules documented as reported once per file (a count over all objects, at the first one):
    the quick check keeps the previous check's finding of these."""
    load_families()
    return frozenset(code for code, rule in RULES.items() if re.search(r"once per\s+file", rule.description))


_LAYOUTS: dict[int, _Layout] = {}


def _layout(text: str) -> _Layout:
    """The layout of a text, kept for the texts of the last two calls: an edit's text is the next one's old text."""
    found = _LAYOUTS.get(id(text))
    if found is None or found.text is not text:
        found = _Layout.of(text)
        _keep(found)
    return found


def _keep(layout: _Layout) -> None:
    if len(_LAYOUTS) >= 2:
        _LAYOUTS.pop(next(iter(_LAYOUTS)))
    _LAYOUTS[id(layout.text)] = layout


_LIST = re.compile(r"[ \t]*\[[ \t]*(?:mandatory|optional|manufacturer)objects[ \t]*\]", re.IGNORECASE)


def _only(layout: _Layout, kept: set[int], lists: bool = True) -> str:
    """The text with the sections of objects not `kept` blanked (and the object lists, unless `lists`),
    line ends kept. The comment lines after a section's last entry stand above the next header: they
    are kept when that section is."""
    text, starts, objects = layout.text, layout.starts, layout.objects
    wanted = [
        owner in kept if owner is not None else lists or _LIST.match(text, starts[at]) is None
        for at, owner in enumerate(objects)
    ]
    pieces = [_blanked(text[: starts[0]] if starts else text, 0, True, not wanted or wanted[0])]
    for at, whole in enumerate(wanted):
        body = text[starts[at] : starts[at + 1] if at + 1 < len(starts) else len(text)]
        pieces.append(_blanked(body, 1, whole, at + 1 >= len(wanted) or wanted[at + 1]))
    return "".join(pieces)


def _blanked(body: str, skip: int, entries: bool, comments: bool) -> str:
    """A section's text (its header, `skip` lines, and its entries) kept or blanked, and the comment
    lines after its last entry kept or blanked, each line's end kept."""
    if entries and comments:
        return body
    if not entries and not comments:
        count, returns = body.count("\n"), body.count("\r")
        if returns == 0 or returns == count == body.count("\r\n"):
            return ("\r\n" if returns else "\n") * count
    lines = body.splitlines(keepends=True)
    last = skip - 1  # the last line that is an entry (key=value), as the reader tells them
    for number in range(len(lines) - 1, skip - 1, -1):
        line = lines[number].strip(" \t\r\n")
        if line and line[0] not in ";#" and "=" in line:
            last = number
            break
    out = []
    for number, line in enumerate(lines):
        bare = line.strip(" \t\r\n")
        keep = entries if number <= last or not bare or bare[0] not in ";#" else comments
        out.append(line if keep else line[len(line.rstrip("\r\n")) :])
    return "".join(out)


def _order(finding: Finding) -> tuple[str, int, int, str, str]:
    where = finding.location
    return (where.file, where.line, where.column, finding.code, finding.message)
