"""Text extracted from a PDF manual: layout detection and the readers that apply to it.

Layouts:
  text   TAB-separated tables and key/value blocks, one row per line (most extractions)
  cells  one cell per line, blank line after each, page headers inside tables (web viewers)
"""

from __future__ import annotations

import itertools
import re

from .blocks import read_blocks
from .cells import cells_to_lines
from .columns import read_tables
from .entries import Cell, Kind, RawEntry, ReadResult
from .moons import read_attribute_tables
from .notation import clean, find_indices, parse_index
from .text import Line, split_lines

TEXT_LAYOUTS = ("text", "cells")

# Vendor names as manuals spell them (first match wins).
VENDORS = (
    (r"Elmo Motion Control", "Elmo Motion Control"),
    (r"SANYO DENKI|Sanyo Denki", "SANYO DENKI"),
    (r"MOONS'|Shanghai AMP", "MOONS'"),
    (r"Control Techniques", "Control Techniques"),
    (r"Nidec", "Nidec"),
)


def detect_text_layout(text: str) -> str:
    """`cells` when there is no TAB at all and most content lines are followed by a blank line."""
    lines = text.splitlines()
    if "\t" in text or len(lines) < 20:
        return "text"
    pairs = sum(1 for a, b in itertools.pairwise(lines) if a.strip() and not b.strip())
    content = sum(1 for a in lines if a.strip())
    return "cells" if content and pairs / content > 0.8 else "text"


def read_manual(path: str, text: str, layout: str) -> ReadResult:
    result = ReadResult(file=path, layout=layout)
    lines: list[Line] = cells_to_lines(text, result) if layout == "cells" else split_lines(text)
    used: set[int] = set()
    result.entries.extend(read_attribute_tables(lines, result, used))
    result.entries.extend(read_tables(lines, result, "table", used))
    result.entries.extend(read_blocks(lines, result, "object block", used))
    result.entries.extend(_default_notes(lines, result))
    _sub_from_context(result.entries)
    _vendor(text, result)
    _exclusions(lines, result)
    if not result.entries:
        result.warn("IMP002", f"no object table or object block found (layout {layout!r})", 1)
    return result


_NOTE = re.compile(
    r"Index\s+([0-9A-Fa-f]{4})\.([0-9A-Fa-f]{2})\s*h?\s+Default\s+value\s+is\s+(.+?)(?=\s+Index\s+[0-9A-Fa-f]{4}\.|$)",
    re.IGNORECASE,
)


def _default_notes(lines: list[Line], result: ReadResult) -> list[RawEntry]:
    """Footnotes giving per-object defaults: `Index 1401.01h Default value is 0x300+$NODEID`."""
    out = []
    for line in lines:
        for match in _NOTE.finditer(clean(line.raw)):
            index = Cell(match.group(1) + "h", line.number)
            sub = Cell(match.group(2) + "h", line.number)
            entry = RawEntry(file=result.file, layout="footnote", kind=Kind.DETAIL, index=index, sub=sub)
            entry.add("default", match.group(3).strip(), line.number)
            out.append(entry)
    return out


def _sub_from_context(entries: list[RawEntry]) -> None:
    """A table without a sub-index column that gives per-PDO values (`PDO | Index | Default COB-ID`)
    speaks for the sub-index of the entry block just above it in the same section."""
    blocks = sorted((e for e in entries if e.kind is Kind.DETAIL and e.sub is not None), key=lambda e: e.line)
    for entry in entries:
        if not entry.object_level or entry.kind is Kind.DETAIL or "default" not in entry.fields:
            continue
        spec = parse_index(entry.index.text)
        if spec is None:
            continue
        before = [b for b in blocks if entry.line - 60 < b.line < entry.line]
        for block in reversed(before):
            other = parse_index(block.index.text)
            if other is not None and other.first <= spec.first and spec.last <= other.last:
                entry.sub = block.sub
                entry.object_level = False
                break


def _vendor(text: str, result: ReadResult) -> None:
    head = text[:20000]
    for pattern, name in VENDORS:
        if re.search(pattern, head):
            result.vendor_name = name
            return


def _exclusions(lines: list[Line], result: ReadResult) -> None:
    """Objects the manual says were removed from its EDS (`This object was removed from the EDS file`)."""
    last_heading: tuple[int, int] | None = None
    for line in lines:
        text = clean(line.raw)
        if re.match(r"^(?:Objects?\s+)?(?:0x[0-9A-Fa-f]{4}|[0-9A-Fa-f]{4}h)\b", text) and len(line.filled) == 1:
            found = find_indices(text)
            if found:
                last_heading = (found[0], line.number)
        if last_heading and re.search(r"removed from the EDS", text, re.IGNORECASE):
            result.excluded[last_heading[0]] = Cell(text, line.number)
