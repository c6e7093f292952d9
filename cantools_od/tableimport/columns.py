"""Column tables: a header row naming the columns, then one row per object or entry.

Used for TAB tables in manual text and for CSV, TSV, XLSX and Markdown sources. Handles
continuation rows (empty index cell), tables split across pages (the header repeats),
elision rows (`:` or `...`) and letter-keyed PDO tables (`A (default = 1)`)."""

from __future__ import annotations

import re
from dataclasses import dataclass, field

from ..model import ObjectKind
from .entries import Cell, Kind, RawEntry, ReadResult
from .notation import clean, parse_index, parse_object_code, parse_sub
from .text import Line

# header text (lower case, spaces folded) → column role
HEADER_WORDS: dict[str, str] = {
    "index": "index",
    "index (hex)": "index",
    "idx": "index",
    "od address": "index",
    "od index": "index",
    "object index": "index",
    "tpdo index": "index",
    "rpdo index": "index",
    "sub-index": "sub",
    "sub-idx": "sub",
    "subindex": "sub",
    "sub index": "sub",
    "sub": "sub",
    "si": "sub",
    "name": "name",
    "parameter name": "name",
    "parametername": "name",
    "comment fields": "name",
    "register name": "name",
    "entry name": "name",
    "obj. code": "object_code",
    "obj code": "object_code",
    "object code": "object_code",
    "object type": "object_code",
    "objecttype": "object_code",
    "object": "object_code",
    "data type": "data_type",
    "datatype": "data_type",
    "type": "data_type",
    "access": "access",
    "access type": "access",
    "accesstype": "access",
    "pdo": "pdo_mapping",
    "pdo mapping": "pdo_mapping",
    "pdomapping": "pdo_mapping",
    "mapped": "pdo_mapping",
    "mappable": "pdo_mapping",
    "can be mapped": "pdo_mapping",
    "default value": "default",
    "defaultvalue": "default",
    "default": "default",
    "default data": "default",
    "default cob-id": "default",
    "value": "default",
    "min": "low",
    "minimum": "low",
    "low limit": "low",
    "lowlimit": "low",
    "max": "high",
    "maximum": "high",
    "high limit": "high",
    "highlimit": "high",
    "unit": "unit",
    "units": "unit",
    "1lsb": "scale",
    "value range": "range",
    "range": "range",
    "description": "description",
    "meaning": "description",
    "comment": "description",
    "mapping destination": "description",
    "rxpdo": "letter",
    "txpdo": "letter",
}

# Columns that, with an index column, make a table an object table.
DATA_ROLES = {"sub", "name", "object_code", "data_type", "access", "pdo_mapping", "default", "low", "high"}


def header_roles(cells: list[str] | tuple[str, ...]) -> list[str | None] | None:
    """Each cell's role when `cells` is an object-table header, else None."""
    roles: list[str | None] = []
    for cell in cells:
        key = " ".join(clean(cell).lower().replace("*", "").split())
        role = HEADER_WORDS.get(key)
        if role is None and key.startswith("field in "):
            role = "name"
        roles.append(role)
    named = [r for r in roles if r is not None]
    filled = [c for c in cells if clean(c)]
    if any(clean(c).lower() in ("step", "action") for c in filled):
        return None  # a procedure (write this, then that), not a description of objects
    if not filled:
        return None
    # `PDO | Index | ...`: the first column names the PDO by letter.
    if len(roles) > 1 and roles[1] == "index" and clean(cells[0]).lower() in ("pdo", "rxpdo", "txpdo"):
        roles[0] = "letter"
    if "index" not in roles:
        # Nidec's `Object | Name`: the object column holds the index.
        if roles and roles[0] == "object_code" and "name" in roles:
            roles[0] = "index"
        else:
            return None
    if roles.count("object_code") > 1 or roles.count("index") > 1:
        return None
    if "name" not in roles and "description" in roles:
        roles[roles.index("description")] = "name"  # `Index | Sub-index | Description | ...`: short ones name
    if not DATA_ROLES.intersection(named) or len(named) * 2 < len(filled):
        return None
    return roles


@dataclass
class Table:
    header_line: int
    roles: list[str | None]
    rows: list[Line] = field(default_factory=list)

    def signature(self) -> tuple[str | None, ...]:
        return tuple(self.roles)


def find_tables(lines: list[Line], used: set[int]) -> list[Table]:
    """Header-led tables: rows up to a blank line or a line without cells."""
    tables: list[Table] = []
    current: Table | None = None
    for line in lines:
        if line.number in used:
            current = None
            continue
        roles = header_roles(line.cells) if len(line.filled) >= 2 else None
        if roles is not None:
            current = Table(line.number, roles)
            tables.append(current)
            continue
        if current is None:
            continue
        if line.blank:
            current = None
            continue
        current.rows.append(line)
    return tables


_ELISION = re.compile(r"^(?::|\.\.\.|…|⋮)$")


def is_elision(line: Line) -> bool:
    filled = line.filled
    return bool(filled) and all(_ELISION.match(cell) for cell in filled)


def table_entries(
    table: Table,
    result: ReadResult,
    layout: str,
    previous: dict[tuple[str | None, ...], int | None],
    bare_index: bool = False,
    hex_singles: bool = False,
) -> list[RawEntry]:
    """The entries of one table. `previous` carries the last index of each header signature,
    so a table continued after a page break keeps its index."""
    roles = table.roles
    col = {role: i for i, role in reversed(list(enumerate(roles))) if role is not None}
    has_sub = "sub" in col
    indices_seen: set[str] = set()
    entries: list[RawEntry] = []
    current_index: Cell | None = None
    if previous.get(table.signature()) is not None:
        last = previous[table.signature()]
        current_index = Cell(f"0x{last:04X}", table.header_line) if last is not None else None
    pending_elision: Line | None = None
    empty_is_no = _empty_means_no(table, col.get("pdo_mapping"))
    for line in table.rows:
        cells = list(line.cells) + [""] * (len(roles) - len(line.cells))
        if is_elision(line):
            pending_elision = line
            continue

        def get(role: str, cells: list[str] = cells) -> str:
            i = col.get(role)
            return cells[i] if i is not None and i < len(cells) else ""

        index_text = get("index")
        letter = get("letter")
        if index_text:
            spec = parse_index(index_text, bare=bare_index)
            if spec is None:
                continue  # a note row, a garbled row
            current_index = Cell(index_text, line.number)
            indices_seen.add(index_text)
        elif current_index is None:
            continue
        assert current_index is not None
        entry = RawEntry(
            file=result.file,
            layout=layout,
            kind=Kind.TABLE,
            index=Cell(current_index.text, line.number),
            hex_singles=hex_singles,
            bare_index=bare_index,
        )
        if letter:
            entry.add("letter", letter, line.number)
        sub_text = get("sub")
        if has_sub and sub_text:
            entry.sub = Cell(sub_text, line.number)
        for role, i in col.items():
            if role in ("index", "sub", "letter") or i >= len(cells):
                continue
            if cells[i]:
                entry.add(role, cells[i], line.number)
        if empty_is_no and not get("pdo_mapping") and "pdo_mapping" in col:
            container = parse_object_code(get("object_code")) in _CONTAINERS or get("data_type").upper() in _MARKERS
            if not container:
                entry.add("pdo_mapping", "No", line.number)
        if not has_sub or not sub_text:
            entry.object_level = True
        if pending_elision is not None and entries:
            entries.extend(_expand_elision(entries[-1], entry, pending_elision, hex_singles))
        pending_elision = None
        entries.append(entry)
    if current_index is not None:
        spec = parse_index(current_index.text, bare=bare_index)
        previous[table.signature()] = spec.first if spec is not None and not spec.is_range else None
    kind = Kind.SUMMARY if len(indices_seen) > 5 else Kind.TABLE
    for entry in entries:
        entry.kind = kind
    return entries


_CONTAINERS = (ObjectKind.ARRAY, ObjectKind.RECORD)
_MARKERS = ("ARRAY", "RECORD", "ARR", "REC")


def _empty_means_no(table: Table, column: int | None) -> bool:
    """A mapping column that marks the mappable entries only (`Yes` or empty, `RPDO`/`TPDO` or empty)."""
    if column is None:
        return False
    values = {clean(row.cells[column]).lower() for row in table.rows if column < len(row.cells)}
    values.discard("")
    return bool(values) and values <= {"yes", "y", "rpdo", "tpdo", "possible"}


def _expand_elision(before: RawEntry, after: RawEntry, row: Line, hex_singles: bool) -> list[RawEntry]:
    """Entries for the sub-indices an elision row stands for, between two rows of one object."""
    if before.sub is None or after.sub is None or before.index.text != after.index.text:
        return []
    first = parse_sub(before.sub.text, hex_singles)
    last = parse_sub(after.sub.text, hex_singles)
    if first is None or last is None or len(first.subs) != 1 or len(last.subs) != 1:
        return []
    low, high = first.subs[0], last.subs[0]
    name_before = before.fields.get("name", [Cell("", 0)])[0].text
    name_after = after.fields.get("name", [Cell("", 0)])[0].text
    numbered = _numbered(name_before, name_after, high - low)
    out = []
    for offset, sub in enumerate(range(low + 1, high), start=1):
        entry = RawEntry(
            file=before.file,
            layout=before.layout + " (elision row)",
            kind=before.kind,
            index=Cell(before.index.text, row.number),
            sub=Cell(f"0x{sub:02X}", row.number),
            hex_singles=hex_singles,
            expanded_from=row.number,
        )
        for name, cells in before.fields.items():
            if name == "name":
                if numbered is not None:
                    entry.add("name", f"{numbered[0]}{numbered[1] + offset}{numbered[2]}", row.number)
                continue
            for cell in cells:
                entry.add(name, cell.text, row.number)
        out.append(entry)
    return out


def _numbered(first: str, last: str, steps: int) -> tuple[str, int, str] | None:
    """(`Motor Parameter `, 2, ``) when the names differ only in a number that grows by one a row."""
    a = re.fullmatch(r"(.*?)(\d+)(\D*)", first)
    b = re.fullmatch(r"(.*?)(\d+)(\D*)", last)
    if a is None or b is None or a.group(1) != b.group(1) or a.group(3) != b.group(3):
        return None
    if int(b.group(2)) - int(a.group(2)) != steps:
        return None
    return a.group(1), int(a.group(2)), a.group(3)


def read_tables(
    lines: list[Line], result: ReadResult, layout: str, used: set[int], bare_index: bool = False
) -> list[RawEntry]:
    """All object tables of a source; their lines are added to `used`."""
    previous: dict[tuple[str | None, ...], int | None] = {}
    hex_singles = any(_hex_sub_column(t) for t in find_tables(lines, used))
    entries: list[RawEntry] = []
    for table in find_tables(lines, used):
        found = table_entries(table, result, layout, previous, bare_index=bare_index, hex_singles=hex_singles)
        if found:
            used.add(table.header_line)
            used.update(row.number for row in table.rows)
        entries.extend(found)
    return entries


def _hex_sub_column(table: Table) -> bool:
    if "sub" not in table.roles:
        return False
    i = table.roles.index("sub")
    return any(i < len(row.cells) and re.fullmatch(r"[0-9]?[A-Fa-f]|0[0-9]", clean(row.cells[i])) for row in table.rows)
