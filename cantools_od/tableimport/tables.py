"""Tabular sources — CSV, TSV, XLSX, Markdown pipe tables — as numbered lines of cells.

Each row keeps its place: the CSV/TSV/Markdown line, or the worksheet row (reported as
`file:row` with the sheet named in the layout). The column-table reader does the rest, so
a spreadsheet follows the same header vocabulary as a table in a manual."""

from __future__ import annotations

import csv
import importlib
import io
import re
from typing import Any

from .columns import read_tables
from .entries import ReadResult
from .notation import clean
from .text import Line

TABLE_LAYOUTS = ("csv", "tsv", "xlsx", "markdown")


def read_delimited(path: str, text: str, delimiter: str, layout: str) -> ReadResult:
    result = ReadResult(file=path, layout=layout)
    lines: list[Line] = []
    reader = csv.reader(io.StringIO(text), delimiter=delimiter)
    try:
        for row in reader:
            number = reader.line_num
            cells = tuple(clean(c) for c in row)
            lines.append(Line(number, delimiter.join(row), _trim(cells)))
    except csv.Error as error:
        result.warn("IMP004", f"not readable as {layout.upper()}: {error}", reader.line_num)
    return _finish(lines, result, layout)


def read_markdown(path: str, text: str) -> ReadResult:
    result = ReadResult(file=path, layout="markdown")
    lines: list[Line] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        stripped = raw.strip()
        if not stripped.startswith("|"):
            lines.append(Line(number, raw, ()))
            continue
        if re.fullmatch(r"\|?\s*:?-{2,}:?\s*(\|\s*:?-{2,}:?\s*)*\|?", stripped):
            continue  # the separator row
        body = stripped.strip("|")
        parts = re.split(r"(?<!\\)\|", body)
        cells = tuple(clean(p.replace("\\|", "|")) for p in parts)
        lines.append(Line(number, raw, _trim(cells)))
    return _finish(lines, result, "markdown")


def read_xlsx(path: str, data: bytes) -> ReadResult:
    """Every worksheet; lines are numbered by row, sheets one after another (row + 100000 * sheet)."""
    result = ReadResult(file=path, layout="xlsx")
    try:
        openpyxl: Any = importlib.import_module("openpyxl")
    except ImportError:
        result.warn("IMP001", "reading XLSX needs the openpyxl package (pip install openpyxl)", 0)
        return result
    try:
        book = openpyxl.load_workbook(io.BytesIO(data), read_only=True, data_only=True)
    except Exception as error:  # openpyxl raises many kinds on a damaged file
        result.warn("IMP001", f"not a readable XLSX workbook: {error}", 0)
        return result
    lines: list[Line] = []
    for sheet_number, sheet in enumerate(book.worksheets):
        for row_number, row in enumerate(sheet.iter_rows(values_only=True), start=1):
            cells = tuple(clean(_cell_text(v)) for v in row)
            lines.append(Line(sheet_number * 100000 + row_number, "\t".join(cells), _trim(cells)))
        lines.append(Line(sheet_number * 100000 + 99999, "", ()))
    book.close()
    return _finish(lines, result, "xlsx")


def _cell_text(value: object) -> str:
    if value is None:
        return ""
    if isinstance(value, float) and value.is_integer():
        return str(int(value))
    return str(value)


def _trim(cells: tuple[str, ...]) -> tuple[str, ...]:
    out = list(cells)
    while out and not out[-1]:
        out.pop()
    return tuple(out)


def _finish(lines: list[Line], result: ReadResult, layout: str) -> ReadResult:
    used: set[int] = set()
    result.entries.extend(read_tables(lines, result, layout, used, bare_index=True))
    if not result.entries and not result.diagnostics:
        result.warn(
            "IMP002",
            "no object table found: a header row needs an Index column and one of Sub-index, Name, Data type, "
            "Access, PDO mapping, Default value",
            1,
        )
    return result
