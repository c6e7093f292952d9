"""Attribute tables under an object heading (MOONS' Appendix A):

    0x1000 - Device type
    Object Type⇥Data Type⇥Access Type⇥PDO Mapping⇥COS ¹⇥Default value
    Var⇥UNSIGNED32⇥ro⇥no⇥no⇥0x00000000

ARRAY/RECORD objects follow with a `Subindex` table. OCR split cells (`Da⇥ita Type`,
`UNS⇥IGNED8`) are rejoined by reading each row's cells run together against the known
vocabulary instead of by column position."""

from __future__ import annotations

import re

from .entries import Cell, Kind, RawEntry, ReadResult
from .notation import clean, parse_index
from .text import Line

LAYOUT = "attribute table"
_HEADING = re.compile(
    r"^(?P<index>0x[0-9A-Fa-f]{4}(?:\s*(?:~|-|\u2013)\s*0x[0-9A-Fa-f]{4})?)\s*(?:-|\u2013|:)?\s*(?P<name>.*)$"
)
_KIND = re.compile(r"^(?P<kind>Var|Array|Record|Reco\s*ord|Domain)\b", re.IGNORECASE)
_TYPE = r"(?:UNSIGNED|INTEGER)(?:64|32|24|16|8)|VISIBLE[_ ]?STRING|OCTET[_ ]?STRING|REAL32|BOOLEAN|DOMAIN"
_ACCESS = r"const|rw|ro|wo"
_PDO = r"no|yes|optional"
_ROW = re.compile(
    rf"(?P<type>{_TYPE})\s*(?P<access>{_ACCESS})\s*(?P<pdo>{_PDO})?\s*(?P<cos>no|yes)?\s*(?P<default>.*)$",
    re.IGNORECASE,
)


def _joined(cells: list[str]) -> str:
    """Cells run together: `UNS`+`IGNED8` → `UNSIGNED8`; spaces inside a cell are kept."""
    return "".join(cells)


def read_attribute_tables(lines: list[Line], result: ReadResult, used: set[int]) -> list[RawEntry]:
    entries: list[RawEntry] = []
    heading: tuple[Cell, str] | None = None
    in_subs = False
    sub_columns: list[str] = []
    kind_entry: RawEntry | None = None
    for line in lines:
        text = clean(line.raw.replace("\t", " "))
        if not line.blank and len(line.filled) == 1:
            match = _HEADING.match(text)
            if match and parse_index(match.group("index")) is not None and not _decoy(match.group("name")):
                if heading is None or heading[0].text != match.group("index") or kind_entry is not None:
                    heading = (Cell(match.group("index"), line.number), match.group("name").strip(" .-"))
                    in_subs, kind_entry = False, None
                continue
        if heading is None or line.blank:
            continue
        first = clean(line.filled[0]) if line.filled else ""
        squashed = re.sub(r"\s+", "", _joined(list(line.filled))).lower()
        if squashed.startswith("subindex") and "name" in squashed:
            in_subs = True
            sub_columns = _sub_header(line)
            used.add(line.number)
            continue
        if squashed.startswith("objecttyp"):
            used.add(line.number)
            continue
        kind = _KIND.match(first) if first else None
        if kind is not None and not in_subs:
            kind_entry = _attribute_row(line, heading, result, kind.group("kind"))
            if kind_entry is not None:
                entries.extend(_with_name(kind_entry, heading, result))
                used.add(line.number)
            continue
        if in_subs and re.fullmatch(r"(?:0x)?[0-9A-Fa-f]{2}", first):
            entry = _sub_row(line, heading[0], sub_columns, result)
            if entry is not None:
                entries.append(entry)
                used.add(line.number)
            continue
        if in_subs and not re.fullmatch(r"(?:0x)?[0-9A-Fa-f]{2}", first):
            in_subs = False
    return entries


def _decoy(name: str) -> bool:
    """Flattened tables leave heading-like lines (`0x1400 - 0x1403 RPDO communication parameter max sub-index`)."""
    return bool(re.search(r"max sub-index$|\(To change mapping|^\W*$", name))


def _with_name(entry: RawEntry, heading: tuple[Cell, str], result: ReadResult) -> list[RawEntry]:
    name = re.sub(r"\s*\((?:not implement(?:ed)?)\)\s*", "", heading[1], flags=re.IGNORECASE).strip(" .")
    name = re.sub(r"\(not implement(?:ed)?\)$", "", name, flags=re.IGNORECASE).strip(" .")
    if not name:
        return [entry]
    titled = RawEntry(
        file=result.file, layout=LAYOUT + " heading", kind=Kind.HEADING, index=heading[0], object_level=True
    )
    titled.add("name", name, heading[0].line)
    if re.search(r"not implement", heading[1], re.IGNORECASE):
        titled.add("note", "not implemented", heading[0].line)
    return [titled, entry]


def _attribute_row(line: Line, heading: tuple[Cell, str], result: ReadResult, kind: str) -> RawEntry | None:
    cells = list(line.filled)
    code = re.sub(r"\s+", "", kind).upper()
    rest = _joined(cells)[len(cells[0]) :] if cells else ""
    entry = RawEntry(file=result.file, layout=LAYOUT, kind=Kind.DETAIL, index=heading[0], object_level=True)
    entry.add("object_code", code, line.number)
    number = re.match(r"\s*(\d{1,3})(?!\d)", rest)
    if code != "VAR" and number:
        entry.add("sub_number", number.group(1), line.number)
        rest = rest[number.end() :]
    match = _ROW.search(rest)
    if match is None:
        return entry
    if code == "VAR":
        # A VAR's attributes are those of its one entry.
        value = RawEntry(file=result.file, layout=LAYOUT, kind=Kind.DETAIL, index=heading[0])
        _fill(value, match, line.number)
        result.entries.append(value)
        return entry
    # ARRAY: one type, access and mapping for every sub-index, sub 0 included.
    entry.add("data_type", match.group("type"), line.number)
    entry.add("access", match.group("access"), line.number)
    if match.group("pdo"):
        entry.add("pdo_mapping", match.group("pdo"), line.number)
    return entry


def _fill(entry: RawEntry, match: re.Match[str], line: int) -> None:
    entry.add("data_type", match.group("type"), line)
    entry.add("access", match.group("access"), line)
    if match.group("pdo"):
        entry.add("pdo_mapping", match.group("pdo"), line)
    default = match.group("default").strip()
    if default:
        entry.add("default", default, line)


def _sub_header(line: Line) -> list[str]:
    names = []
    for cell in line.filled:
        key = re.sub(r"\s+", "", cell).lower()
        names.append(key)
    return names


def _sub_row(line: Line, index: Cell, columns: list[str], result: ReadResult) -> RawEntry | None:
    cells = list(line.filled)
    sub, rest = cells[0], cells[1:]
    sub_text = sub if sub.lower().startswith("0x") else sub + "h"
    entry = RawEntry(
        file=result.file, layout=LAYOUT + " sub-table", kind=Kind.TABLE, index=index, sub=Cell(sub_text, line.number)
    )
    if not rest:
        return None
    joined = _joined(rest)
    match = _ROW.search(joined)
    if match is not None:
        name = joined[: match.start()].strip()
        if name:
            entry.add("name", name, line.number)
        _fill(entry, match, line.number)
        return entry
    # `Subindex | Name | Default value`: the type and access come from the attribute row.
    entry.add("name", rest[0], line.number)
    if len(rest) > 1 and any("default" in c for c in columns):
        entry.add("default", rest[1], line.number)
    return entry
