"""Key/value blocks: `Index⇥1000h`, `Name⇥Device type`, ... one or more pairs a line.

One reader for the per-object description blocks of all four manuals: Elmo's
"Object description / Entry description" (one pair a line, sub-entries led by
`Sub-index`), Sanyo's grid with a group label in column 0 and drifting indentation,
and Nidec's two- and three-pair lines with the entry name sometimes in the key position.
A block starts at an `Index` key and ends at the next one or at a line of other text."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from .entries import Cell, Kind, RawEntry, ReadResult
from .notation import clean, parse_index
from .text import Line, heading_title

# key text (lower case) → field
KEYS: dict[str, str] = {
    "index": "index",
    "sub-index": "sub",
    "subindex": "sub",
    "sub index": "sub",
    "name": "name",
    "description": "name",
    "object code": "object_code",
    "object type": "object_code",
    "data type": "data_type",
    "category": "category",
    "entry category": "category",
    "access": "access",
    "pdo mapping": "pdo_mapping",
    "value range": "range",
    "default value": "default",
    "default": "default",
    "units": "unit",
    "unit": "unit",
    "meaning": "description",
    "note": "note",
    "elements": "sub_number",
}
OBJECT_FIELDS = {"name", "object_code", "data_type", "category", "sub_number"}
GROUP_LABELS = {"object description", "entry description"}
_MARKER = re.compile(r"(?:object|entry)\s+description\s*:?\s*:?\s*$", re.IGNORECASE)
_STOP_LABELS = ("data description", "bit coding", "description of", "byte stream")


def key_of(cell: str) -> str | None:
    text = " ".join(clean(cell).lower().rstrip(":").split())
    return KEYS.get(text)


@dataclass
class _Block:
    index: Cell
    start: int
    object_fields: dict[str, list[Cell]] = field(default_factory=dict)
    entries: list[RawEntry] = field(default_factory=list)
    current: RawEntry | None = None
    title: Cell | None = None
    lines: int = 0


def _pairs(line: Line) -> tuple[str | None, list[tuple[str, Cell]], list[str]] | None:
    """(leading name, [(field, value cell)], loose cells) of a key/value line, else None.

    A key's value is the next cell; an empty next cell is skipped when the one after it is
    not a key (Sanyo's shifted values). A line whose value cell is itself a key is a table header."""
    cells = [c for c in line.cells]
    while cells and not cells[0]:
        cells.pop(0)
    if cells and " ".join(cells[0].lower().rstrip(":").split()) in GROUP_LABELS:
        cells.pop(0)
        while cells and not cells[0]:
            cells.pop(0)
    if not cells:
        return None
    lead: str | None = None
    if key_of(cells[0]) is None:
        lead = cells[0]
        cells = cells[1:]
    pairs: list[tuple[str, Cell]] = []
    loose: list[str] = []
    i = 0
    while i < len(cells):
        key = key_of(cells[i])
        if key is None:
            if cells[i]:
                loose.append(cells[i])
            i += 1
            continue
        value = cells[i + 1] if i + 1 < len(cells) else ""
        step = 2
        if (
            value
            and key_of(value) is not None
            and (key == "index" or (i + 2 < len(cells) and key_of(cells[i + 2]) is not None))
        ):
            return None  # `Index | Sub-index | Description`: a header row
        if not value and i + 2 < len(cells) and cells[i + 2] and key_of(cells[i + 2]) is None:
            value, step = cells[i + 2], 3
        pairs.append((key, Cell(value, line.number)))
        i += step
    if not pairs and lead is None:
        return None
    return lead, pairs, loose


def read_blocks(lines: list[Line], result: ReadResult, layout: str, used: set[int]) -> list[RawEntry]:
    """Every key/value block of a manual."""
    entries: list[RawEntry] = []
    block: _Block | None = None
    title: Cell | None = None
    hex_singles = False
    for line in lines:
        if line.number in used:
            title = None  # a table between a heading and a block: the heading is the table's
            continue
        if line.blank:
            continue
        parsed = _pairs(line)
        if parsed is not None and not parsed[1] and not _name_line_allowed(block, parsed):
            parsed = None
        if parsed is not None and parsed[0] is not None and parsed[1] and not _name_line_allowed(block, parsed):
            parsed = None
        if parsed is None:
            if block is not None and _MARKER.search(line.raw.strip().strip("*").strip()):
                continue
            if block is not None:
                entries.extend(_finish(block, result, layout))
                block = None
            found = heading_title(line.raw) or _object_heading(line)
            if found is not None:
                title = Cell(found, line.number)
            elif title is not None and line.number - title.line > 80:
                title = None
            continue
        lead, pairs, loose = parsed
        keys = [k for k, _ in pairs]
        if "index" in keys:
            if block is not None:
                entries.extend(_finish(block, result, layout))
            block = _Block(dict(pairs)["index"], line.number)
            block.title, title = title, None
        if block is None:
            continue
        block.lines += 1
        used.add(line.number)
        if lead is not None:
            if block.current is None or "name" in block.current.fields:
                _start_entry(block, result, layout, hex_singles)
            assert block.current is not None
            block.current.add("name", lead, line.number)
        for key, value in pairs:
            if key == "index":
                continue
            if key == "sub":
                if re.fullmatch(r"0[A-Fa-f]|[0-9][A-Fa-f]", clean(value.text)):
                    hex_singles = True
                current = block.current
                if current is not None and current.sub is None and not current.fields.keys() - {"access", "name"}:
                    current.sub = value
                    continue
                _start_entry(block, result, layout, hex_singles)
                assert block.current is not None
                block.current.sub = value
                continue
            if block.current is None and key in OBJECT_FIELDS:
                block.object_fields.setdefault(key, []).append(value)
                continue
            if block.current is None:
                _start_entry(block, result, layout, hex_singles)
            assert block.current is not None
            block.current.add(key, value.text, value.line)
        for cell in loose:
            if block.current is None:
                continue
            text = clean(cell)
            if re.match(r"(?i)value\s*=", text):
                block.current.add("default", text, line.number)
            elif re.match(r"(?i)range\b", text):
                block.current.add("range", text, line.number)
    if block is not None:
        entries.extend(_finish(block, result, layout))
    for entry in entries:
        entry.hex_singles = entry.hex_singles or hex_singles
    return entries


def _name_line_allowed(block: _Block | None, parsed: tuple[str | None, list[tuple[str, Cell]], list[str]]) -> bool:
    """A line led by a non-key cell is an entry name only right after the block's Index line."""
    lead, pairs, loose = parsed
    if block is None or lead is None or not (pairs or loose):
        return False
    lower = lead.lower()
    if lower.startswith(_STOP_LABELS) or len(lead) > 80:
        return False
    return block.lines <= 2


def _start_entry(block: _Block, result: ReadResult, layout: str, hex_singles: bool) -> None:
    entry = RawEntry(
        file=result.file,
        layout=layout,
        kind=Kind.DETAIL,
        index=Cell(block.index.text, block.index.line),
        hex_singles=hex_singles,
    )
    block.entries.append(entry)
    block.current = entry


def _finish(block: _Block, result: ReadResult, layout: str) -> list[RawEntry]:
    out: list[RawEntry] = []
    head = RawEntry(
        file=result.file,
        layout=layout,
        kind=Kind.DETAIL,
        index=block.index,
        object_level=True,
    )
    single = block.entries[0] if len(block.entries) == 1 and block.entries[0].sub is not None else None
    if single is not None and set(block.object_fields) <= {"object_code"}:
        # `Index | 0x6046 | Object code | VAR` above `Sub-index | 1`: the code is the entry's
        for cell in block.object_fields.pop("object_code", []):
            single.add("object_code", cell.text, cell.line)
    for key, cells in block.object_fields.items():
        for cell in cells:
            head.add(key, cell.text, cell.line)
    if head.fields:
        out.append(head)
    if block.title is not None:
        # The heading names the one entry of a block such as `#### Vendor ID`, else the object.
        title = re.sub(r"^(?:0x[0-9A-Fa-f]{4}|[0-9A-Fa-f]{4}h)\s*[-:\u2013]?\s*", "", block.title.text).strip()
        target: RawEntry | None = head
        only = block.entries[0] if len(block.entries) == 1 else None
        if not head.fields and only is not None and only.sub is not None and "name" not in only.fields:
            target = only
        if target is not None and title:
            titled = RawEntry(
                file=result.file,
                layout=layout + " heading",
                kind=Kind.HEADING,
                index=block.index,
                sub=target.sub,
                object_level=target.object_level,
            )
            titled.add("name", title, block.title.line)
            out.append(titled)
    out.extend(block.entries)
    return out


_OBJECT_HEADING = re.compile(
    r"^(?:Objects?\s+)?(?:0x[0-9A-Fa-f]{4}|[0-9A-Fa-f]{4}h)(?:\s*(?:-|~|,)\s*(?:0x)?[0-9A-Fa-f]{4}h?)*\s*(?::|-|\u2013)?\s*(.+)$"
)


def _object_heading(line: Line) -> str | None:
    """`Object 0x1000: *Device type*` → `Device type` (Elmo, Sanyo); `0x2F60 - Zero torque threshold`."""
    if len(line.filled) != 1:
        return None
    text = clean(line.raw)
    if not re.match(r"^(?:Objects?\s+)", text):
        return None
    match = _OBJECT_HEADING.match(text)
    if match is None or parse_index(text) is None:
        return None
    name = match.group(1).strip(" *:")
    return name if 0 < len(name) <= 80 else None
