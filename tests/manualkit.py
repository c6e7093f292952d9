"""Independent counts of what the four vendor manuals document, for the importer's tests.

Each counter reads the raw manual text with plain regular expressions written for that one
manual — none of cantools_od.tableimport is used — and returns, per (index, sub-index) pair the
manual documents, the access and data type it states, or None where the manual is silent or
contradicts itself (the pair then counts for coverage but not for correctness).

How each manual is counted is written above its counter."""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import Path

from support import ROOT

SEEDS = ROOT.parent / "shared" / "seeds"
MANUALS = {
    "000": "000_3cb15f7fa7effd3d.txt",
    "001": "001_6a6bb34a259a2c0a.txt",
    "002": "002_ceb85346843789e0.txt",
    "003": "003_07695d6ad21280c4.txt",
    "004": "004_154176570a080d38.txt",
}

TYPES = {
    "UNSIGNED8": 5, "UNSIGNED16": 6, "UNSIGNED32": 7, "INTEGER8": 2, "INTEGER16": 3, "INTEGER32": 4,
    "SIGNED8": 2, "SIGNED16": 3, "SIGNED32": 4, "VISIBLESTRING": 9, "OCTETSTRING": 10, "FLOATINGPOINT(FLOAT)": 8,
    "UINT32": 7, "USIGN16": 6, "STRING": 9, "REAL32": 8, "BYTE": 5,
}  # fmt: skip
ACCESS = {
    "readonly": "ro", "read": "ro", "r": "ro", "ro": "ro", "readwrite": "rw", "rw": "rw", "r/w": "rw",
    "writeonly": "wo", "wo": "wo", "w": "wo", "const": "const", "rw*": "rw",
}  # fmt: skip


def type_of(text: str) -> int | None:
    return TYPES.get(re.sub(r"[\s_]", "", text).upper())


def access_of(text: str) -> str | None:
    return ACCESS.get(re.sub(r"[\s/]", "", text).lower().replace("readwrite", "readwrite")) or ACCESS.get(
        text.strip().lower()
    )


@dataclass
class Stated:
    """What the manual states for one pair, each value with the lines saying it."""

    access: dict[str, set[int]] = field(default_factory=dict)
    types: dict[int, set[int]] = field(default_factory=dict)

    def say_access(self, value: str | None, line: int) -> None:
        if value is not None:
            self.access.setdefault(value, set()).add(line)

    def say_type(self, value: int | None, line: int) -> None:
        if value is not None:
            self.types.setdefault(value, set()).add(line)

    @property
    def unambiguous_access(self) -> str | None:
        return next(iter(self.access)) if len(self.access) == 1 else None

    @property
    def unambiguous_type(self) -> int | None:
        return next(iter(self.types)) if len(self.types) == 1 else None


Pairs = dict[tuple[int, int], Stated]


def read(prefix: str) -> list[str] | None:
    path = SEEDS / MANUALS[prefix]
    return path.read_text(encoding="utf-8").split("\n") if path.is_file() else None


def _pair(pairs: Pairs, index: int, sub: int) -> Stated:
    return pairs.setdefault((index, sub), Stated())


def _strip(cell: str) -> str:
    return re.sub(r"</?\w+>|\*\*", "", cell).strip()


# --------------------------------------------------------------------------- 000 Elmo
# Counted: every block `Index⇥XXXXh` (Ch. 12-13; `A - B` index ranges expanded) with its
# `Sub-index` entries (decimal ranges `1-24`, single values hex: `0A`, `10`), a block without
# `Sub-index` being the VAR's pair (X, 0); plus the Table 3-1 rows (000:465-540) that have
# no block (1006h, 2003h) as (X, 0); plus the §5.3.6 default-value tables (000:1014-1066).
# Stated access: the entry's `Access` (per-index lists split); Table 3-1's access for a VAR
# and for the sub-indices >= 1 of a container. Stated type: a VAR's `Data type`, an entry's
# `Value range` when it is a type name, an ARRAY's `Data type` for sub-indices >= 1, the
# record tables 0020h/0021h (000:354-369) for PDO parameter records.


def count_000() -> Pairs | None:
    lines = read("000")
    if lines is None:
        return None
    pairs: Pairs = {}
    summary: dict[int, tuple[str | None, int]] = {}
    for n, line in enumerate(lines[464:540], start=465):
        cells = line.split("\t")
        if len(cells) >= 4 and re.fullmatch(r"0x[0-9A-F]{4}", cells[1]):
            summary[int(cells[1], 16)] = (access_of(cells[3]) if cells[3] else None, n)
    records = {0x20: {0: 5, 1: 7, 2: 5, 3: 6, 4: 5, 5: 6}, 0x21: {0: 5, **{s: 7 for s in range(1, 0x41)}}}
    blocks: list[tuple[list[int], dict[str, str], list[dict[str, tuple[str, int]]]]] = []
    current: tuple[list[int], dict[str, str], list[dict[str, tuple[str, int]]]] | None = None
    for n, line in enumerate(lines, start=1):
        cells = line.split("\t")
        key = cells[0].strip()
        value = cells[1].strip() if len(cells) > 1 else ""
        if key == "Index" and re.match(r"[0-9A-F]{4}h", value):
            m = re.match(r"([0-9A-F]{4})h(?:\s*-\s*([0-9A-F]{4})h?)?", value)
            assert m is not None
            low = int(m.group(1), 16)
            high = int(m.group(2), 16) if m.group(2) else low
            current = (list(range(low, high + 1)), {}, [])
            blocks.append(current)
        elif current is not None and key in ("Data type", "Object code") and not current[2]:
            current[1][key] = value
        elif current is not None and key == "Sub-index":
            current[2].append({"Sub-index": (value, n)})
        elif current is not None and key in ("Access", "Value range", "Default value"):
            if not current[2]:
                current[2].append({})
            current[2][-1].setdefault(key, (value, n))
        elif line.startswith(("Object 0x", "Objects 0x", "Chapter")):
            current = None
    for indices, head, entries in blocks:
        code = head.get("Object code", "VAR")
        element = type_of(head.get("Data type", ""))
        record = (
            records.get(0x20 if "CommPar" in head.get("Data type", "") else 0x21)
            if "PDO" in head.get("Data type", "")
            else None
        )
        for entry in entries:
            subs = [0]
            if "Sub-index" in entry:
                text = entry["Sub-index"][0]
                rng = re.fullmatch(r"(\d+)\s*-\s*(\d+)", text)
                subs = list(range(int(rng.group(1)), int(rng.group(2)) + 1)) if rng else [int(text, 16)]
            for index in indices:
                for sub in subs:
                    if sub > 254:
                        continue
                    stated = _pair(pairs, index, sub)
                    if "Access" in entry:
                        text, n = entry["Access"]
                        per = dict(re.findall(r"Object ([0-9A-F]{4})h: (Read/Write|Read only|Write only)", text))
                        stated.say_access(access_of(per.get(f"{index:04X}", text)) if text else None, n)
                    rng_text, rng_line = entry.get("Value range", ("", 0))
                    if code == "VAR" and "Sub-index" not in entry:
                        stated.say_type(element, rng_line)
                    if type_of(rng_text) is not None:
                        stated.say_type(type_of(rng_text), rng_line)
                    if code == "ARRAY" and sub >= 1:
                        stated.say_type(element, rng_line)
                    if record is not None and sub in record:
                        stated.say_type(record[sub], 354)
                    if index in summary and (code == "VAR" or sub >= 1) and summary[index][0] is not None:
                        stated.say_access(summary[index][0], summary[index][1])
    for index, (access, n) in summary.items():
        if not any(i == index for i, _ in pairs):
            _pair(pairs, index, 0).say_access(access, n)
    for line in lines[1013:1066]:
        cells = line.split("\t")
        if len(cells) == 4 and re.fullmatch(r"[0-9A-F]{4}h?", cells[0]):
            table_index = int(cells[0].rstrip("h"), 16)
        if len(cells) == 4 and re.fullmatch(r"[0-9A-F]h?", cells[1]):
            _pair(pairs, table_index, int(cells[1].rstrip("h"), 16))
    return pairs


# --------------------------------------------------------------------------- 002 Sanyo
# Counted: the object lists (7-column, 002:1472-1585, 2794-2873, 4181-4224; 12-column
# 2200h group 002:4991-5278 with the `:` elision rows expanded), each row with a sub-index its
# pair and each VAR row without one (X, 0); the description blocks' `Sub-index⇥NNh[...MMh]`
# entries (002:1586-4978); Table 7-1 (002:1884-2010). Stated access and type: the list's
# columns, the block's `Access` and, for VARs, the block's `Data type`.


def count_002() -> Pairs | None:
    lines = read("002")
    if lines is None:
        return None
    pairs: Pairs = {}
    index = None
    previous_sub: tuple[int, str, str, str] | None = None
    elided = False
    for n, raw in enumerate(lines, start=1):
        cells = [_strip(c) for c in raw.split("\t")]
        if len(cells) >= 6 and (re.fullmatch(r"[0-9A-F]{4}h", cells[0]) or (cells[0] == "" and index is not None)):
            if cells[0]:
                index = int(cells[0][:4], 16)
            if cells[1] == ":":
                elided = True
                continue
            if cells[3] not in ("VAR", "ARR", "REC") or index is None:
                continue
            sub_text = cells[1].replace("*", "").strip()
            if cells[3] == "VAR":
                sub = int(sub_text.rstrip("h"), 16) if sub_text else 0
                if elided and previous_sub is not None:
                    for between in range(previous_sub[0] + 1, sub):
                        stated = _pair(pairs, index, between)
                        stated.say_access(access_of(previous_sub[2]), n - 1)
                        stated.say_type(type_of(previous_sub[1]), n - 1)
                elided = False
                stated = _pair(pairs, index, sub)
                stated.say_access(access_of(cells[5]), n)
                stated.say_type(type_of(cells[4]), n)
                previous_sub = (sub, cells[4], cells[5], "")
        elif not raw.strip():
            index = None if not elided else index
    block_index: list[int] = []
    var = False
    var_type: int | None = None
    for n, raw in enumerate(lines[1585:4978], start=1586):
        cells = [_strip(c) for c in raw.split("\t") if _strip(c)]
        if (len(cells) >= 2 and cells[-2] == "Index") or (len(cells) >= 3 and cells[1] == "Index"):
            value = cells[cells.index("Index") + 1]
            block_index = [int(v, 16) for v in re.findall(r"([0-9A-F]{4})h", value)]
        elif "Object code" in cells:
            var = cells[cells.index("Object code") + 1] == "VAR"
        elif "Data type" in cells:
            var_type = type_of(cells[cells.index("Data type") + 1])
        elif "Sub-index" in cells:
            text = cells[cells.index("Sub-index") + 1]
            m = re.match(r"([0-9A-F]{2})h(?:\.\.\.([0-9A-F]{2})h)?", text)
            if m and block_index:
                low = int(m.group(1), 16)
                high = int(m.group(2), 16) if m.group(2) else low
                current = [(i, s) for i in block_index for s in range(low, high + 1)]
                for pair in current:
                    stated = _pair(pairs, *pair)
                    if var:
                        stated.say_type(var_type, n)
        elif "Access" in cells and block_index:
            access = access_of(cells[cells.index("Access") + 1].split("*")[0].strip())
            for pair in current:
                _pair(pairs, *pair).say_access(access, n)
    index = None
    for raw in lines[1885:2010]:
        cells = raw.split("\t")
        if len(cells) == 6 and re.fullmatch(r"([0-9A-F]{4}h)?", cells[0]) and re.fullmatch(r"[0-9A-F]{2}h", cells[1]):
            index = int(cells[0][:4], 16) if cells[0] else index
            if index is not None:
                _pair(pairs, index, int(cells[1][:2], 16))
    return pairs


# --------------------------------------------------------------------------- 003 MOONS'
# Counted: the summary Tables 3-6 (003:317-432), a row with Sub `0` on a non-container its
# (X, 0), sub rows of ARRAY/RECORD their pair, `5007h -500Eh` expanded; the Appendix A sections
# (headings `0x....`): a `Var` attribute row is (X, 0), a `Subindex` table row (two hex digits or
# `0x..`) is (X, sub) for each index of the heading's range (a `Var` row followed by a sub-table
# contradicts it and states nothing); Table 7 (`4000.xx`). Stated
# access and type: the summary row, the Var row, the sub-table row's own type/access, or the
# Array row's access for every sub-index and its type (the element type) for sub-indices >= 1.

_MOONS_ROW = re.compile(
    r"(UNSIGNED(?:8|16|32)|INTEGER(?:8|16|32)|VISIBLE_?STRING|OCTET_?STRING)\s*(ro|rw|wo|const)", re.IGNORECASE
)


def count_003() -> Pairs | None:
    lines = read("003")
    if lines is None:
        return None
    pairs: Pairs = {}
    index: list[int] = []
    for n, raw in enumerate(lines[316:432], start=317):
        cells = raw.split("\t")
        if len(cells) < 4:
            continue
        m = re.fullmatch(r"([0-9A-F]{4})h(?:\s*-\s*([0-9A-F]{4})h)?", cells[0].strip())
        if m:
            low = int(m.group(1), 16)
            index = list(range(low, int(m.group(2), 16) + 1 if m.group(2) else low + 1))
        if not index or cells[3].strip() in ("ARRAY", "RECORD"):
            continue
        if re.fullmatch(r"\d+", cells[1].strip()):
            for i in index:
                stated = _pair(pairs, i, int(cells[1]))
                stated.say_type(type_of(cells[3]), n)
                stated.say_access(access_of(cells[4]) if len(cells) > 4 and cells[4].strip() else None, n)
    heading: list[int] = []
    var_rows: list[tuple[list[int], int | None, str, int]] = []
    array: tuple[int | None, str | None, int] | None = None
    in_subs = False
    for n, raw in enumerate(lines[517:], start=518):
        text = raw.replace("\t", " ").strip()
        m = re.match(r"^0x([0-9A-F]{4})(?:\s*[~-]\s*0x([0-9A-F]{4}))?\s*[-\u2013]?\s*(.*)$", text)
        if m and "\t" not in raw and not text.endswith("max sub-index") and "(To change" not in text:
            low = int(m.group(1), 16)
            heading = list(range(low, int(m.group(2), 16) + 1 if m.group(2) else low + 1))
            array, in_subs = None, False
            continue
        cells = [c.strip() for c in raw.split("\t") if c.strip()]
        if not heading or not cells:
            continue
        squashed = "".join(cells)
        if re.match(r"^Var", cells[0]):
            row = _MOONS_ROW.search(squashed)
            for i in heading:
                _pair(pairs, i, 0)
            if row:
                var_rows.append((list(heading), type_of(row.group(1)), row.group(2).lower(), n))
        elif re.match(r"^(Array|Record|Reco)", cells[0]):
            row = _MOONS_ROW.search(squashed)
            array = (type_of(row.group(1)), row.group(2).lower(), n) if row and cells[0] == "Array" else None
        elif re.sub(r"\s", "", squashed).lower().startswith("subindex") and "ame" in squashed:
            in_subs = True
            if var_rows and var_rows[-1][0] == heading:
                var_rows.pop()  # a `Var` with a sub-table (1011h, 003:732): the row contradicts the table
        elif in_subs and re.fullmatch(r"(0x)?[0-9A-F]{2}", cells[0]):
            sub = int(cells[0][-2:], 16)
            row = _MOONS_ROW.search(squashed)
            for i in heading:
                stated = _pair(pairs, i, sub)
                if row:
                    stated.say_type(type_of(row.group(1)), n)
                    stated.say_access(row.group(2).lower(), n)
                if array is not None:  # one access for every sub-index; the type is the elements'
                    stated.say_access(array[1], array[2])
                    if sub > 0:
                        stated.say_type(array[0], array[2])
        elif in_subs:
            in_subs = False
    for indices, dtype, access, n in var_rows:
        for i in indices:
            _pair(pairs, i, 0).say_type(dtype, n)
            _pair(pairs, i, 0).say_access(access, n)
    for raw in lines[466:490]:
        m = re.search(r"4000\.([0-9A-F]{2})", raw)
        if m:
            _pair(pairs, 0x4000, int(m.group(1), 16))
    return pairs


# --------------------------------------------------------------------------- 004 Nidec
# Counted: every OD entry block line `Index⇥0x....⇥Sub-index⇥S` or `Index⇥0x....` followed by
# a `Sub-index⇥S` line (004:2220-4500), `0x1400-0x15FF`-style ranges standing for the PDOs the
# manual names: RxPDO A-D = PDO 1, 3, 5, 6 (Table 11-9, 004:2651-2655) → 1400h, 1402h, 1404h,
# 1405h; TxPDO A-D likewise (Table 11-17, 004:2813-2816) → 1800h, 1802h, 1804h, 1805h; the
# mapping tables (Index⇥Sub-index columns with a concrete index: 1600h, 1605h, 1A00h, 1A02h,
# 1A04h, 1A05h, 1010h, 1011h); `1- 4` rows expanded. Module parameters (S.mm.ppp) are not OD
# entries of a fixed index and are not counted. Stated access and type: the block's Access and
# Data type; the Index⇥Sub-index⇥...⇥Data type⇥Access tables; the DS402 summary tables.

NIDEC_PDOS = {0x1400: (0x1400, 0x1402, 0x1404, 0x1405), 0x1800: (0x1800, 0x1802, 0x1804, 0x1805),
              0x1600: (0x1600, 0x1602, 0x1604, 0x1605), 0x1A00: (0x1A00, 0x1A02, 0x1A04, 0x1A05)}  # fmt: skip


def count_004() -> Pairs | None:
    lines = read("004")
    if lines is None:
        return None
    pairs: Pairs = {}
    pending: list[int] = []
    current: list[tuple[int, int]] = []
    head_access: str | None = None
    for n, raw in enumerate(lines[2200:4500], start=2201):
        cells = [_strip(c) for c in raw.split("\t")]
        filled = [c for c in cells if c]
        if len(filled) >= 2 and filled[0] == "Index" and filled[1].startswith("0x"):
            m = re.match(r"0x([0-9A-F]{4})(?:-0x([0-9A-F]{4}))?", filled[1])
            assert m is not None
            low = int(m.group(1), 16)
            pending = list(NIDEC_PDOS.get(low, ())) if m.group(2) else [low]
            current = []
            head_access = access_of(filled[filled.index("Access") + 1]) if "Access" in filled else None
            if "Sub-index" in filled:
                sub = filled[filled.index("Sub-index") + 1]
                current = [(i, int(sub)) for i in pending]
        elif len(filled) >= 2 and filled[0] == "Sub-index" and pending:
            current = [(i, int(filled[1])) for i in pending]
            for pair in current:
                _pair(pairs, *pair).say_access(head_access, n - 1)
        elif not filled:
            continue
        for pair in current:
            stated = _pair(pairs, *pair)
            if "Access" in filled:
                stated.say_access(access_of(filled[filled.index("Access") + 1]), n)
            if "Data type" in filled:
                stated.say_type(type_of(filled[filled.index("Data type") + 1]), n)
        if not filled or (filled[0] not in ("Index", "Sub-index", "Default") and len(filled) < 2):
            current = []
    header: list[str] = []
    for n, raw in enumerate(lines[2200:4500], start=2201):
        cells = [_strip(c) for c in raw.split("\t")]
        if cells[:2] == ["Index", "Sub-index"] or cells[:3] == ["Index", "Object", "Name"]:
            header = cells
            continue
        if not raw.strip():
            header = []
            continue
        if not header or not cells[0].startswith("0x"):
            continue
        m = re.match(r"0x([0-9A-F]{4})(-0x([0-9A-F]{4}))?$", cells[0])
        if m is None:
            continue
        indices = list(NIDEC_PDOS.get(int(m.group(1), 16), ())) if m.group(2) else [int(m.group(1), 16)]
        if header[1] == "Object":
            if cells[1] == "VAR":
                for i in indices:
                    stated = _pair(pairs, i, 0)
                    stated.say_type(type_of(cells[3]), n)
                    stated.say_access(access_of(cells[4]), n)
            continue
        sub = re.fullmatch(r"(\d+)(?:-\s*(\d+))?", cells[1])
        if sub is None:
            continue
        for s in range(int(sub.group(1)), int(sub.group(2) or sub.group(1)) + 1):
            for i in indices:
                stated = _pair(pairs, i, s)
                if "Data type" in header and len(cells) > header.index("Access"):
                    stated.say_type(type_of(cells[header.index("Data type")]), n)
                    stated.say_access(access_of(cells[header.index("Access")]), n)
    return pairs


COUNTERS = {"000": count_000, "002": count_002, "003": count_003, "004": count_004}


@dataclass
class Score:
    documented: int
    imported: int
    unambiguous: int
    correct: int
    missing: list[tuple[int, int]]
    wrong: list[tuple[int, int, str]]

    @property
    def coverage(self) -> float:
        return self.imported / self.documented if self.documented else 0.0

    @property
    def correctness(self) -> float:
        return self.correct / self.unambiguous if self.unambiguous else 0.0


def score(pairs: Pairs, eds: Path) -> Score:
    """Coverage and access+type correctness of an EDS against a manual's count."""
    import configparser

    parser = configparser.ConfigParser(interpolation=None, strict=False)
    parser.optionxform = str  # type: ignore[assignment,method-assign]
    parser.read_string(eds.read_text(encoding="utf-8"))
    imported: dict[tuple[int, int], tuple[str, int | None]] = {}
    for name in parser.sections():
        m = re.fullmatch(r"([0-9A-F]{4})(?:sub([0-9A-F]+))?", name)
        if m is None:
            continue
        section = parser[name]
        index = int(m.group(1), 16)
        if m.group(2) is None and section.get("ObjectType", "0x7") not in ("0x7", "0x2"):
            continue
        sub = int(m.group(2), 16) if m.group(2) else 0
        dtype = section.get("DataType")
        imported[(index, sub)] = (section.get("AccessType", "").lower(), int(dtype, 16) if dtype else None)
    documented = set(pairs)
    found = documented & set(imported)
    unambiguous = correct = 0
    wrong: list[tuple[int, int, str]] = []
    for pair in sorted(found):
        stated = pairs[pair]
        access, dtype = stated.unambiguous_access, stated.unambiguous_type
        if access is None or dtype is None:
            continue
        unambiguous += 1
        got = imported[pair]
        if got == (access, dtype):
            correct += 1
        else:
            wrong.append((*pair, f"manual {access}/{dtype:#x}, EDS {got[0]}/{got[1]}"))
    missing = sorted(documented - set(imported))
    return Score(len(documented), len(found), unambiguous, correct, missing, wrong)
