"""One-cell-per-line extractions (a PDF web viewer's copy): rebuild the object summary table.

Every content line is one table cell, blank lines separate them, an empty cell is a line of
NBSP, wrapped cell text continues after the rest of the row, and page headers (four lines:
document title, running title, page number, document number) sit inside tables. The
summary table `Name | Index | Description | Access | Mapped` is rebuilt row by row,
anchored on the index token; the rows are handed on as TAB-like lines, each numbered
with the line of its index, so that the column-table reader reads them."""

from __future__ import annotations

import re
from collections import Counter

from .entries import ReadResult
from .notation import clean
from .text import Line

_INDEX = re.compile(r"^(?P<name>.*?)\s*(?P<index>0x[0-9A-Fa-f]{4})\b\s*(?P<rest>.*)$")
_ACCESS = re.compile(r"^(R/W|R|W|RW|RO|WO)$")
_MAPPED = re.compile(r"^(Y|N)$")
_HEADER = ("Name", "Index", "Description", "Access", "Mapped")


def _content(text: str) -> list[tuple[int, str]]:
    """(line number, cell) for every non-blank line; NBSP-only lines become ''."""
    out = []
    for number, raw in enumerate(text.splitlines(), start=1):
        if not raw.strip() and "\u00a0" not in raw:
            continue
        out.append((number, clean(raw)))
    return out


def _drop_page_headers(cells: list[tuple[int, str]]) -> list[tuple[int, str]]:
    counts = Counter(c for _, c in cells if c)
    markers = {c for c, n in counts.items() if n >= 5 and len(c) > 12 and not _ACCESS.match(c)}
    if not markers:
        return cells
    out: list[tuple[int, str]] = []
    i = 0
    while i < len(cells):
        number, cell = cells[i]
        if cell in markers:
            # title, running title, page number, document number, then empty cells
            j = i + 1
            while j < len(cells) and j <= i + 3:
                if cells[j][1] in markers:
                    j += 1
                    break
                j += 1
            while j < len(cells) and cells[j][1] == "":
                j += 1
            i = j
            continue
        out.append((number, cell))
        i += 1
    return out


def cells_to_lines(text: str, result: ReadResult) -> list[Line]:
    cells = _drop_page_headers(_content(text))
    lines: list[Line] = []
    i = 0
    while i < len(cells):
        if tuple(c for _, c in cells[i : i + 5]) == _HEADER:
            header_line = cells[i][0]
            if not lines or lines[-1].cells != _HEADER:
                if lines:
                    lines.append(Line(header_line - 1, "", ()))
                lines.append(Line(header_line, "\t".join(_HEADER), _HEADER))
            i = _rows(cells, i + 5, lines)
            continue
        i += 1
    return lines


def _rows(cells: list[tuple[int, str]], i: int, lines: list[Line]) -> int:
    """Rows of the summary table from position i; returns where the table ends."""
    rows: list[tuple[int, list[str]]] = []
    while i < len(cells):
        number, cell = cells[i]
        if tuple(c for _, c in cells[i : i + 5]) == _HEADER:
            break
        if re.match(r"^Table \d", cell):
            i += 1
            break
        match = _INDEX.match(cell)
        if match is not None and match.group("name") and not re.search(r"\s(?:R/W|R|W)\s+[YN]$", cell):
            match = None  # an index inside wrapped text (`Setting object 0x1003 ...`), not a row
        if match is None:
            i += 1
            continue
        name = match.group("name")
        if not name and i > 0 and cells[i - 1][1] and not _MAPPED.match(cells[i - 1][1]):
            name = cells[i - 1][1]
        rest = match.group("rest")
        collapsed = re.match(r"^(?P<desc>.*?)\s+(?P<access>R/W|R|W)\s+(?P<mapped>Y|N)$", rest)
        access = mapped = ""
        description = rest
        j = i + 1
        if collapsed:
            description, access, mapped = collapsed.group("desc"), collapsed.group("access"), collapsed.group("mapped")
        else:
            if not description and j < len(cells) and not _ACCESS.match(cells[j][1]):
                description = cells[j][1]
                j += 1
            if j < len(cells) and (_ACCESS.match(cells[j][1]) or cells[j][1] == ""):
                access = cells[j][1]
                j += 1
            if j < len(cells) and (_MAPPED.match(cells[j][1]) or (cells[j][1] == "" and not access)):
                mapped = cells[j][1]
                j += 1
        # continuation cells up to the next row's name: name, index, description, access, mapped
        end = j
        while end < len(cells) and not _INDEX.match(cells[end][1]):
            if tuple(c for _, c in cells[end : end + 5]) == _HEADER or re.match(r"^Table \d", cells[end][1]):
                break
            end += 1
        following = _INDEX.match(cells[end][1]) if end < len(cells) else None
        stop = end - 1 if following is not None and not following.group("name") else end
        continuation = [c for _, c in cells[j:stop]]
        # wrapped cells come in row order (name, index, description, access, mapped), the leading
        # empty cell sometimes missing: a name part sits in the first two places of a group of five
        name_more = [c for k, c in enumerate(continuation) if k % 5 in (0, 1) and c]
        desc_more = [c for k, c in enumerate(continuation) if k % 5 not in (0, 1) and c]
        if name_more:
            name = f"{name} {' '.join(name_more)}"
        if desc_more:
            description = f"{description} {' '.join(desc_more)}"
        rows.append((number, [name, match.group("index"), description, access, mapped]))
        i = stop
    for number, row in rows:
        lines.append(Line(number, "\t".join(row), tuple(row)))
    return i
