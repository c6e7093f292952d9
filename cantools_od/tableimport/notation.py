"""Readers for the spellings vendor manuals use: indices, sub-indices, access, data types,
PDO-mapping flags, values and ranges.

Every function takes the raw text of one cell and returns a normalised value, or None when
the text says nothing (empty, `---`, `N/A`, ...). They never raise on bad input.
"""

from __future__ import annotations

import re
import unicodedata
from dataclasses import dataclass, field

from ..model import AccessType, DataType, NodeIdExpr, ObjectKind, standard_type
from ..model.cia301 import cia402
from ..model.datatypes import INDEX_BY_NAME

# --------------------------------------------------------------------------- text clean-up

# Look-alike letters of OCR'd manuals (Cyrillic, Greek) and the Arabic-Indic digits that
# stand for punctuation in one of them; the key is replaced by the value.
HOMOGLYPHS = {
    "\u0425": "X",
    "\u0445": "x",
    "\u041c": "M",
    "\u0391": "A",
    "\u03b1": "a",
    "\u0415": "E",
    "\u0435": "e",
    "\u041e": "O",
    "\u043e": "o",
    "\u0420": "P",
    "\u0421": "C",
    "\u0441": "c",
    "\u0422": "T",
    "\u0412": "B",
    "\u041d": "H",
    "\u041a": "K",
    "\u0430": "a",
    "\u0443": "y",
    "\u0661": "\\",
    "\u0668": "^",
    "\u00d7": "x",
    "\u00a0": " ",
    "\u2009": " ",
    "\u202f": " ",
    "\u2013": "-",
    "\u2014": "-",
    "\u2212": "-",
    "\u2026": "...",
    "\u00b5": "\u03bc",
    "\u2019": "'",
    "\u201c": '"',
    "\u201d": '"',
}
_HOMOGLYPH_TABLE = str.maketrans(HOMOGLYPHS)
_TAG = re.compile(r"</?[a-zA-Z][^<>]*>")
_MD_LINK = re.compile(r"\[([^\]]*)\]\([^)]*\)")
_LATEX_CMD = re.compile(r"\\(?:text|mathrm|mathbf|textbf)\{([^{}]*)\}")
_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹", "0123456789")


def clean(text: str) -> str:
    """One cell's text without markup: HTML tags, Markdown emphasis and links, LaTeX dollars and
    escapes, look-alike letters; whitespace collapsed."""
    text = text.translate(_HOMOGLYPH_TABLE)
    text = _TAG.sub(" ", text)
    text = _MD_LINK.sub(r"\1", text)
    text = text.replace("**", "").replace("\\$", "$").replace("\\_", "_").replace("\\*", "*")
    text = _LATEX_CMD.sub(r"\1", text)
    if text.count("$") >= 2 and "$NODEID" not in text.upper():
        text = text.replace("$", "")
    text = re.sub(r"(?<![\w*])\*(?=\S)([^*]+?)(?<=\S)\*(?![\w*])", r"\1", text)  # *italic*
    text = re.sub(r"^[-▪•]\s+", "", text.strip())
    return " ".join(text.split())


def is_blank(text: str) -> bool:
    """Text that says nothing: empty, dashes, N/A, None, No, See below."""
    t = clean(text).strip(" .*").lower()
    return t in ("", "-", "--", "---", "----", "n/a", "na", "none", "no", "see below", "no value", "not used")


# --------------------------------------------------------------------------- indices

_HEX = r"[0-9A-Fa-f]"
# One index token: 0x1A00, 1A00h, 1A00 _h, 1A00_h, 1A00_{h}, 1016hh, bare 4 hex digits.
_INDEX_TOKEN = re.compile(
    rf"(?:0[xX](?P<x>{_HEX}{{1,4}})(?![0-9A-Fa-f])|(?P<h>{_HEX}{{3,4}})\s?_?\{{?[hH]\}}?(?:h)?(?![0-9A-Za-z])"
    rf"|(?<![0-9A-Za-z.])(?P<bare>{_HEX}{{4}})(?![0-9A-Za-z]))"
)
_RANGE_SEP = r"\s*(?:-|~|\.\.\.?|to|…)\s*"


@dataclass(frozen=True)
class IndexSpec:
    """An index or an index range as written; `sub` when the cell also gives a sub-index."""

    first: int
    last: int
    sub: int | None = None

    @property
    def is_range(self) -> bool:
        return self.last != self.first

    def indices(self) -> range:
        return range(self.first, self.last + 1)


def _token_value(match: re.Match[str]) -> int:
    text = match.group("x") or match.group("h") or match.group("bare")
    return int(text, 16)


def parse_index(raw: str, bare: bool = False) -> IndexSpec | None:
    """`0x1A00`, `1A00h`, `1A00h - 1A03h`, `0x1400~0x1403`, `4000.01 _h`, `0x1600sub1`, `Object2110h`.

    Bare 4-digit hex (`1A00`) is accepted only with `bare=True` (data-type tables, CSV)."""
    text = clean(raw).replace("$", "")
    text = re.sub(r"^(?:Objects?|Index)\s*", "", text, flags=re.IGNORECASE)
    if not text:
        return None
    dotted = re.match(rf"^({_HEX}{{4}})\.({_HEX}{{1,2}})\s*_?\s*[hH]?\b", text)
    if dotted:
        return IndexSpec(int(dotted.group(1), 16), int(dotted.group(1), 16), int(dotted.group(2), 16))
    subbed = re.match(rf"^0[xX]({_HEX}{{4}})\s*sub\s*(\d+)", text, flags=re.IGNORECASE)
    if subbed:
        index = int(subbed.group(1), 16)
        return IndexSpec(index, index, int(subbed.group(2)))
    first = _INDEX_TOKEN.match(text)
    if first is None or (first.group("bare") and not bare and not re.fullmatch(rf"{_HEX}{{4}}", text)):
        if first is None:
            plain = re.match(rf"^({_HEX}{{4}})(?:\s*{_RANGE_SEP}\s*({_HEX}{{3,4}}))?$", text)
            if plain and bare:
                low = int(plain.group(1), 16)
                return IndexSpec(low, int(plain.group(2), 16) if plain.group(2) else low)
            return None
        if not bare:
            return None
    low = _token_value(first)
    rest = text[first.end() :]
    second = re.match(_RANGE_SEP + rf"(0[xX])?({_HEX}{{3,4}})\s*_?[hH]?(?![0-9A-Za-z])", rest)
    if second:
        high = int(second.group(2), 16)
        if high > low:
            return IndexSpec(low, high)
    return IndexSpec(low, low)


def find_indices(text: str) -> list[int]:
    """Every explicit index (`0x1A00` or `1A00h`) in running text."""
    found = []
    for match in re.finditer(rf"0[xX]({_HEX}{{4}})(?![0-9A-Fa-f])|(?<![0-9A-Za-z])({_HEX}{{4}})h\b", clean(text)):
        found.append(int(match.group(1) or match.group(2), 16))
    return found


# --------------------------------------------------------------------------- sub-indices


@dataclass(frozen=True)
class SubSpec:
    subs: tuple[int, ...]
    name: str = ""  # `00h, Device type` carries the entry's name
    note: str = ""


def parse_sub(raw: str, hex_singles: bool = False) -> SubSpec | None:
    """`0`, `00h`, `0h`, `0x00`, `0A`, `1 - 8`, `1-24`, `01h...02h`, `1- 4`, `0Ah *`, `00h, Name`.

    Explicit `h`/`0x` is hex; a bare single token is hex when it has a letter or a leading zero,
    or when `hex_singles` says the layout writes single sub-indices in hex; bare range ends are
    decimal unless they carry a suffix."""
    text = clean(raw)
    if not text or text in (":", "...", "…"):
        return None
    name = ""
    note = ""
    if "," in text:
        head, _, tail = text.partition(",")
        if re.fullmatch(r"\s*[0-9A-Fa-f]{1,3}\s*[hH]?(?:\s*\.\.\.?\s*[0-9A-Fa-f]{1,3}\s*[hH]?)?\s*", head):
            text, name = head.strip(), tail.strip()
    if text.endswith("*"):
        text, note = text.rstrip("* ").strip(), "footnote"
    text = re.sub(r"^(?:sub-?index|sub)\s*", "", text, flags=re.IGNORECASE)
    text = re.sub(r"\s+_\s*[hH]\b", "h", text)  # `01 _h`
    token = r"(0[xX][0-9A-Fa-f]+|[0-9A-Fa-f]{1,3}\s*[hH]|\d+|[0-9A-Fa-f]{1,2})"
    ranged = re.fullmatch(token + r"\s*(?:-|~|\.\.\.?|to)\s*" + token, text)
    if ranged:
        low = _sub_token(ranged.group(1), hex_singles, in_range=True)
        high = _sub_token(ranged.group(2), hex_singles, in_range=True)
        if low is None or high is None or high < low or high > 255:
            return None
        return SubSpec(tuple(range(low, high + 1)), name, note)
    single = re.fullmatch(token, text)
    if single:
        value = _sub_token(single.group(1), hex_singles, in_range=False)
        if value is None or value > 255:
            return None
        return SubSpec((value,), name, note)
    return None


def _sub_token(token: str, hex_singles: bool, in_range: bool) -> int | None:
    token = token.replace(" ", "")
    if token.lower().startswith("0x"):
        return int(token[2:], 16)
    if token[-1] in "hH":
        return int(token[:-1], 16)
    if re.search(r"[A-Fa-f]", token):
        return int(token, 16)
    if not in_range and (hex_singles or (len(token) == 2 and token[0] == "0")):
        return int(token, 16)
    return int(token)


def looks_hex_sub(raw: str) -> bool:
    """A bare single sub-index that can only be hex (`0A`, `0F`) or is zero-padded (`00`, `01`)."""
    text = clean(raw)
    return bool(re.fullmatch(r"0[0-9A-Fa-f]|[0-9]?[A-Fa-f]", text))


# --------------------------------------------------------------------------- access


@dataclass(frozen=True)
class AccessSpec:
    access: AccessType | None
    per_index: dict[int, AccessType] = field(default_factory=dict)
    note: str = ""  # conditions: `RW*`, `Write: only 0 ...`


_ACCESS_WORDS = [
    (r"rwr", AccessType.RWR),
    (r"rww", AccessType.RWW),
    (r"read\s*/\s*write|r\s*/\s*w|rw\s+w|rw|read-write", AccessType.RW),
    (r"read\s*only|read|ro|r", AccessType.RO),
    (r"write\s*only|write|wo|w", AccessType.WO),
    (r"const(?:ant)?", AccessType.CONST),
]


def parse_access(raw: str) -> AccessSpec | None:
    """`R`, `RO`, `Read only`, `R/W`, `RW`, `Read/Write`, `RW*`, `RW W`, `const`, `WO`,
    `RW *Write: only 0 ... accepted`, `Object 1800h: Read/Write Object 1801h: ...`."""
    text = clean(raw)
    if not text or text.strip("-") == "":
        return None
    per_index: dict[int, AccessType] = {}
    for match in re.finditer(
        r"(?:Object|Index)\s+([0-9A-Fa-f]{4})h\s*(?:\(\d+\))?\s*:\s*([A-Za-z/ ]+?)(?=\s+(?:Object|Index)\s|$)", text
    ):
        spec = parse_access(match.group(2))
        if spec is not None and spec.access is not None:
            per_index[int(match.group(1), 16)] = spec.access
    if per_index:
        values = set(per_index.values())
        return AccessSpec(values.pop() if len(values) == 1 else None, per_index, "per-index list")
    note = ""
    head = text
    if "*" in text:
        head, _, rest = text.partition("*")
        note = ("* " + rest.strip()).strip()
    head = head.strip().lower()
    for pattern, access in _ACCESS_WORDS:
        if re.fullmatch(pattern, head):
            return AccessSpec(access, {}, note)
    return None


# --------------------------------------------------------------------------- data types

# Vendor spellings of CiA 301 type names (and of the record types), by the name datatypes gives the type.
_TYPE_ALIASES = {
    alias: INDEX_BY_NAME[name]
    for alias, name in {
        "BOOLEAN": "BOOLEAN",
        "BOOL": "BOOLEAN",
        "REAL32": "REAL32",
        "FLOAT": "REAL32",
        "FLOATINGPOINT": "REAL32",
        "FLOATINGPOINT(FLOAT)": "REAL32",
        "REAL64": "REAL64",
        "VISIBLESTRING": "VISIBLE_STRING",
        "STRING": "VISIBLE_STRING",
        "OCTETSTRING": "OCTET_STRING",
        "STRINGOCTET": "OCTET_STRING",
        "UNICODESTRING": "UNICODE_STRING",
        "TIMEOFDAY": "TIME_OF_DAY",
        "TIMEDIFFERENCE": "TIME_DIFFERENCE",
        "DOMAIN": "DOMAIN",
        "BYTE": "UNSIGNED8",
        "PDOCOMMPAR": "PDO_COMMUNICATION_PARAMETER",
        "PDOCOMMUNICATIONPARAMETER": "PDO_COMMUNICATION_PARAMETER",
        "PDOMAPPING": "PDO_MAPPING",
        "PDOMAPPINGPARAMETER": "PDO_MAPPING",
        "SDOPARAMETER": "SDO_PARAMETER",
        "IDENTITY": "IDENTITY",
    }.items()
}


@dataclass(frozen=True)
class TypeSpec:
    """A data-type cell: a type index, a container marker (ARRAY/RECORD) or a note."""

    index: int | None = None
    container: ObjectKind | None = None
    note: str = ""


def parse_type(raw: str) -> TypeSpec | None:
    """`UNSIGNED16`, `U16`, `USIGN16`, `UINT32`, `Integer 32`, `SIGNED24`, `SignedT32`, `Visible String`,
    `Floating Point (Float)`, `PDO CommPar (object 0x20)`, `0080h` records, `ARRAY`/`RECORD` markers."""
    text = clean(raw)
    if not text or is_blank(text):
        return None
    explicit = re.search(r"\((?:object\s+)?(?:0x)?([0-9A-Fa-f]{2,4})h?\)\s*$", text, flags=re.IGNORECASE)
    if explicit and not re.match(r"(?i)floating", text):
        return TypeSpec(int(explicit.group(1), 16))
    key = re.sub(r"[\s_\-]", "", text).upper()
    if key in ("ARRAY", "ARR"):
        return TypeSpec(container=ObjectKind.ARRAY)
    if key in ("RECORD", "REC"):
        return TypeSpec(container=ObjectKind.RECORD)
    if key in _TYPE_ALIASES:
        return TypeSpec(_TYPE_ALIASES[key])
    if key.startswith("INTERPOLATIONTIMEPERIOD"):
        return TypeSpec(cia402.INTERPOLATION_TIME_PERIOD_TYPE)
    if key.startswith("INTERPOLATIONDATACONFIGURATION"):
        return TypeSpec(cia402.INTERPOLATION_DATA_CONFIGURATION_TYPE)
    match = re.fullmatch(r"(UNSIGNED|INSIGNED|USIGN|UINT|U|INTEGER|SIGNEDT?|SINT|INT|I|S)(\d{1,2})", key)
    if match:
        family = "UNSIGNED" if match.group(1) in ("UNSIGNED", "USIGN", "UINT", "U") else "INTEGER"
        bits = int(match.group(2))
        note = "typo 'Insigned'" if match.group(1) == "INSIGNED" else ""
        index = INDEX_BY_NAME.get(f"{family}{bits}")  # UNSIGNED8 ... UNSIGNED64, INTEGER8 ... INTEGER64
        return TypeSpec(index, note=note) if index is not None else None
    return None


def type_prefix(raw: str) -> TypeSpec | None:
    """A type name that starts a value-range cell: `UNSIGNED8: 0: Execute ...`, `0 - not used UNSIGNED16`."""
    text = clean(raw)
    match = re.search(
        r"\b(UNSIGNED\d+|INTEGER\s?\d+|SIGNED\d+|Unsigned\d+|Integer\s?\d+|Signed\d+)\b", text, flags=re.IGNORECASE
    )
    if match is None:
        return None
    return parse_type(match.group(1))


def type_name(index: int | None) -> str:
    dtype = standard_type(index)
    if dtype is not None:
        return dtype.name
    return "" if index is None else f"0x{index:04X}"


# --------------------------------------------------------------------------- object code


def parse_object_code(raw: str) -> ObjectKind | None:
    """`VAR`, `ARRAY`, `ARR`, `Array`, `RECORD`, `REC`, `Reco ord` (OCR), `DOMAIN`, `DEFTYPE`, `DEFSTRUCT`."""
    key = re.sub(r"[\s_\-]", "", clean(raw)).upper()
    key = {"RECOORD": "RECORD", "RECORDS": "RECORD"}.get(key, key)
    table = {
        "VAR": ObjectKind.VAR,
        "VARIABLE": ObjectKind.VAR,
        "ARRAY": ObjectKind.ARRAY,
        "ARR": ObjectKind.ARRAY,
        "RECORD": ObjectKind.RECORD,
        "REC": ObjectKind.RECORD,
        "DOMAIN": ObjectKind.DOMAIN,
        "DEFTYPE": ObjectKind.DEFTYPE,
        "DEFSTRUCT": ObjectKind.DEFSTRUCT,
        "NULL": ObjectKind.NULL,
    }
    return table.get(key)


# --------------------------------------------------------------------------- PDO mapping


@dataclass(frozen=True)
class MappingSpec:
    mappable: bool | None
    direction: str | None = None  # "rx", "tx", "both" or None


def parse_mapping(raw: str, empty_means_no: bool = False) -> MappingSpec | None:
    """`Yes`/`No`, `Y`/`N`, `Possible`, `optional`, `RPDO`/`TPDO`, `---`; empty says nothing unless
    the table documents that an empty cell means no."""
    text = clean(raw).strip(" .*").lower()
    if text in ("", "---", "----", "-"):
        return MappingSpec(False) if empty_means_no or text else None
    if text in ("yes", "y", "possible", "true", "1", "x"):
        return MappingSpec(True, "both")
    if text in ("no", "n", "false", "0"):
        return MappingSpec(False)
    if text == "optional":
        return MappingSpec(True, "both")
    if text in ("rpdo", "rxpdo", "rx"):
        return MappingSpec(True, "rx")
    if text in ("tpdo", "txpdo", "tx"):
        return MappingSpec(True, "tx")
    return None


# --------------------------------------------------------------------------- values


@dataclass(frozen=True)
class ValueSpec:
    """A default or limit: an int, float, string or `$NODEID` sum; `note` keeps the comment."""

    value: int | float | str | bytes | NodeIdExpr
    note: str = ""


_NODE_WORDS = r"(?:node[\s-]*id|node\s*address|\$NODEID)"


def parse_number(text: str) -> int | float | None:
    """`0x191`, `100h`, `0000 0080h`, `6040 00 10h`, `80000280 _h`, `-3`, `65,535`, `1e20`, `2 ³¹ -1`, `2^{31}-1`."""
    t = clean(text).translate(_SUPERSCRIPTS).strip().rstrip(".")
    t = t.replace("{", "").replace("}", "")
    if not t:
        return None
    m = re.fullmatch(r"([-+]?)\s*0[xX]\s*([0-9A-Fa-f](?:[0-9A-Fa-f ]*[0-9A-Fa-f])?)", t)
    if m:
        return _signed(m.group(1), int(m.group(2).replace(" ", ""), 16))
    m = re.fullmatch(r"([-+]?)\s*([0-9A-Fa-f](?:[0-9A-Fa-f ]*[0-9A-Fa-f])?)\s*_?\s*[hH]", t)
    if m:
        return _signed(m.group(1), int(m.group(2).replace(" ", ""), 16))
    m = re.fullmatch(r"([-+]?)\s*(\d{1,3}(?:,\d{3})+|\d+)", t)
    if m:
        return _signed(m.group(1), int(m.group(2).replace(",", "")))
    m = re.fullmatch(r"([-+]?)\s*(\d+(?:\.\d*)?(?:[eE][-+]?\d+)?|\.\d+)", t)
    if m:
        real = float(m.group(2))
        return -real if m.group(1) == "-" else real
    m = re.fullmatch(r"\(?([-+]?)\s*(2|10)\s*\^?\s*(\d+)\s*(?:([-+])\s*(\d+))?\)?", t)  # 2^31-1, -2^31-1
    if m:
        power = int(int(m.group(2)) ** int(m.group(3)))
        power = -power if m.group(1) == "-" else power
        if m.group(4):
            power = power - int(m.group(5)) if m.group(4) == "-" else power + int(m.group(5))
        return power
    return None


def _signed(sign: str, value: int) -> int:
    return -value if sign == "-" else value


def parse_value(raw: str, type_index: int | None = None) -> ValueSpec | None:
    """A default value. Node-relative forms become `$NODEID+n`; annotations `0 (no inhibit time)`,
    `6 [6: 500Kbit]`, `0xFF (all emergencies on)` keep the number and the note; strings stay strings
    for string types; "no value" spellings give None."""
    text = clean(raw)
    if is_blank(text) or text.lower().startswith(("refer to", "see ", "index ", "object ")):
        return None
    dtype = standard_type(type_index)
    if dtype is not None and dtype.kind.value in ("string", "unicode"):
        return ValueSpec(text)
    node = _node_relative(text)
    if node is not None:
        return node
    if dtype is not None and dtype.kind.value == "octets":
        pairs = text.replace(" ", "")
        if re.fullmatch(r"(?:[0-9A-Fa-f]{2})+", pairs):
            return ValueSpec(bytes.fromhex(pairs), "octets")
        return None
    note = ""
    text = re.sub(r"^value\s*=\s*", "", text, flags=re.IGNORECASE)
    annotated = re.fullmatch(r"(.+?)\s*[(\[](.*)[)\]]\s*\.?", text)
    head = text
    if annotated and parse_number(annotated.group(1)) is not None:
        head, note = annotated.group(1), annotated.group(2)
    elif annotated and parse_number(annotated.group(2)) is not None and re.fullmatch(r"[A-Za-z ]+", annotated.group(1)):
        head, note = annotated.group(2), annotated.group(1)  # On (1)
    number = parse_number(head)
    if number is None:
        if re.fullmatch(r"[-+]?\s*[0-9][0-9A-Fa-f ]*", head):
            return None
        if dtype is not None and dtype.is_numeric:
            return None
        return ValueSpec(text) if dtype is None and re.search(r"[A-Za-z]", text) and len(text) < 60 else None
    if dtype is None:
        return ValueSpec(number, note)
    return _typed_number(number, head, note, dtype)


def _node_relative(text: str) -> ValueSpec | None:
    """`$NODEID + 0x180`, `0x180 + Node-ID`, `512 (200h) + node ID`: a value relative to the node-ID."""
    node = re.fullmatch(
        rf"(?:{_NODE_WORDS}\s*\+\s*(?P<a>.+?)|(?P<b>.+?)\s*\+\s*{_NODE_WORDS})\s*[\d²³¹]?\.?",
        text,
        flags=re.IGNORECASE,
    )
    if not node:
        return None
    base_text = node.group("a") or node.group("b") or ""
    base_text = re.sub(r"^\d+\s*\((.+)\)$", r"\1", base_text.strip())  # 512 (200h)
    base = parse_number(base_text)
    return ValueSpec(NodeIdExpr(offset=base, text=text), "node-relative") if isinstance(base, int) else None


def _typed_number(number: int | float, head: str, note: str, dtype: DataType) -> ValueSpec | None:
    """The number as the data type holds it: two's complement, a stray 'h', a whole float."""
    bits = dtype.bits if dtype.kind.value == "signed" and dtype.bits else 0
    if bits and isinstance(number, int) and (1 << (bits - 1)) <= number < (1 << bits) and _looks_hex(head):
        number -= 1 << bits  # a negative number printed in two's complement (`FFFFh` for INTEGER16)
        note = (note + "; " if note else "") + "two's complement"
    if isinstance(number, int) and dtype.int_range() is not None and _looks_hex(head):
        low, high = dtype.int_range() or (0, 0)
        decimal = parse_number(head.rstrip("hH _"))
        if not low <= number <= high and isinstance(decimal, int) and low <= decimal <= high:
            number, note = decimal, (note + "; " if note else "") + "'h' on a decimal number"
    if isinstance(number, float) and dtype.is_integer:
        if not number.is_integer():
            return None
        number = int(number)
    return ValueSpec(number, note)


def _looks_hex(text: str) -> bool:
    t = text.strip().lower()
    return t.startswith(("0x", "-0x")) or t.endswith("h")


def _unwrap(text: str) -> str:
    text = text.strip()
    while text.startswith("(") and text.endswith(")"):
        text = text[1:-1].strip()
    return text


@dataclass(frozen=True)
class RangeSpec:
    low: int | float | None = None
    high: int | float | None = None
    type_index: int | None = None  # a type name used as the range ("UNSIGNED32")
    note: str = ""


def parse_range(raw: str) -> RangeSpec | None:
    """`1...127`, `0..2`, `0...65,535`, `1 to 0xFE`, `-10⁹...10⁹`, `0x81...0xFFFFFFFF`,
    `[(-2^{30} + 1) ... (2^{30} - 1)]`, `0000 0001...0000 07FFh`, `UNSIGNED32`, `0 - not used UNSIGNED16`."""
    text = clean(raw).translate(_SUPERSCRIPTS)
    if is_blank(text) or text.lower().startswith(("refer", "see")):
        return None
    whole = parse_type(text)
    if whole is not None and whole.index is not None:
        return RangeSpec(type_index=whole.index)
    body = text.replace("\\dots", "...").replace("\\ldots", "...").strip()
    if body.startswith("[") and body.endswith("]"):
        body = body[1:-1].strip()
    body = re.sub(r"^(?:range|value range)\s*", "", body, flags=re.IGNORECASE)
    body = re.sub(r"\s*[(\[][^()\[\]]*[a-zA-Z][^()\[\]]*[)\]]\s*$", "", body)  # trailing comment or unit
    m = re.fullmatch(
        r"(?:(?P<set>[-+\d., ]+),\s*)?(?P<low>.+?)\s*(?:\.\.\.?|…|\bto\b)\s*(?P<high>.+?)"
        r"(?:\s+[A-Za-zμ%/][A-Za-zμ%/.]*)?",
        body,
    )
    if m:
        low_text, high_text = _unwrap(m.group("low")), _unwrap(m.group("high"))
        if high_text.lower().endswith("h") and not low_text.lower().endswith("h") and " " in high_text:
            low_text += "h"  # 0000 0001...0000 07FFh
        low, high = parse_number(low_text), parse_number(high_text)
        if m.group("set"):
            extra = [parse_number(part) for part in m.group("set").split(",") if part.strip()]
            if low is not None and all(v is not None for v in extra):
                low = min([low, *[v for v in extra if v is not None]])
        if low is not None and high is not None and low <= high:
            return RangeSpec(low, high)
    listed = [parse_number(part) for part in body.split(",")]
    if len(listed) > 2 and all(v is not None for v in listed):
        values = [v for v in listed if v is not None]
        return RangeSpec(min(values), max(values), note="enumeration")
    prefix = type_prefix(text)
    if prefix is not None and prefix.index is not None:
        return RangeSpec(type_index=prefix.index, note="type name inside a range description")
    return None


# --------------------------------------------------------------------------- per-index lists


def split_per_index(raw: str) -> dict[int, str]:
    """`Index 1800h: 0x400001FF Index 1801h: 0x400002FF` or `Object 1600h(1): 0x20010040 (controlword)
    Object 1602h: 0` → {index: raw value}; {} when the cell is not such a list."""
    text = clean(raw)
    parts = re.split(r"(?:Index|Object)\s+([0-9A-Fa-f]{4})h\s*(?:\(\d+\))?\s*:\s*", text)
    if len(parts) < 3 or parts[0].strip():
        return {}
    out: dict[int, str] = {}
    for i in range(1, len(parts) - 1, 2):
        out[int(parts[i], 16)] = parts[i + 1].strip()
    return out


def norm_name(name: str) -> str:
    """A name for comparison: case, punctuation and spacing folded."""
    text = unicodedata.normalize("NFKC", clean(name)).lower()
    text = re.sub(r"\b(\d+)\s+(st|nd|rd|th)\b", r"\1\2", text)
    return re.sub(r"[^a-z0-9]+", "", text)
