"""The spellings vendor manuals use, read by cantools_od.tableimport.notation."""

from __future__ import annotations

import pytest

from cantools_od.model import AccessType, NodeIdExpr, ObjectKind
from cantools_od.tableimport.notation import (
    clean,
    parse_access,
    parse_index,
    parse_mapping,
    parse_number,
    parse_object_code,
    parse_range,
    parse_sub,
    parse_type,
    parse_value,
    split_per_index,
)


@pytest.mark.parametrize(
    ("text", "first", "last", "sub"),
    [
        ("0x1A00", 0x1A00, 0x1A00, None),
        ("1A00h", 0x1A00, 0x1A00, None),
        ("1A00h - 1A03h", 0x1A00, 0x1A03, None),
        ("1A00h - 1A03", 0x1A00, 0x1A03, None),
        ("0x1400~0x1403", 0x1400, 0x1403, None),
        ("0x1A00 ~ 0x1A03", 0x1A00, 0x1A03, None),
        ("5007h -500Eh", 0x5007, 0x500E, None),
        ("0x1400-0x15FF", 0x1400, 0x15FF, None),
        ("1600h...1603h", 0x1600, 0x1603, None),
        ("2200h \u2013 22FFh", 0x2200, 0x22FF, None),
        ("1016hh", 0x1016, 0x1016, None),
        ("Object2110h", 0x2110, 0x2110, None),
        ("0x1600sub1", 0x1600, 0x1600, 1),
        ("$607A_h$", 0x607A, 0x607A, None),
        ("580_{h}", 0x580, 0x580, None),
        ("$0x2014$", 0x2014, 0x2014, None),
        ("4000.01 _h *", 0x4000, 0x4000, 1),
        ("1A00 _h", 0x1A00, 0x1A00, None),
        ("<b>0x1000</b>", 0x1000, 0x1000, None),
    ],
)
def test_index_spellings(text: str, first: int, last: int, sub: int | None) -> None:
    spec = parse_index(text)
    assert spec is not None
    assert (spec.first, spec.last, spec.sub) == (first, last, sub)


@pytest.mark.parametrize("text", ["", "Object", "14003h", "see below", "Sub-index"])
def test_not_an_index(text: str) -> None:
    assert parse_index(text) is None


def test_bare_index_only_when_asked() -> None:
    assert parse_index("1000 - 1FFF") is None
    spec = parse_index("1000 - 1FFF", bare=True)
    assert spec is not None and (spec.first, spec.last) == (0x1000, 0x1FFF)


@pytest.mark.parametrize(
    ("text", "hex_singles", "subs"),
    [
        ("0", False, (0,)),
        ("00h", False, (0,)),
        ("0h", False, (0,)),
        ("00", False, (0,)),
        ("0x00", False, (0,)),
        ("0A", False, (10,)),
        ("10", True, (16,)),  # Elmo writes single sub-indices in hex (000:2704)
        ("10", False, (10,)),
        ("1 - 8", False, tuple(range(1, 9))),
        ("1-24", True, tuple(range(1, 25))),  # ranges are decimal (000:3100)
        ("01h...02h", False, (1, 2)),
        ("1- 4", False, (1, 2, 3, 4)),
        ("0Ah *", False, (10,)),
        ("01 _h", False, (1,)),
    ],
)
def test_sub_index_spellings(text: str, hex_singles: bool, subs: tuple[int, ...]) -> None:
    spec = parse_sub(text, hex_singles)
    assert spec is not None and spec.subs == subs


def test_sub_index_with_name() -> None:
    spec = parse_sub("00h, Device type")
    assert spec is not None and spec.subs == (0,) and spec.name == "Device type"


def test_elision_is_not_a_sub_index() -> None:
    assert parse_sub(":") is None
    assert parse_sub("...") is None


@pytest.mark.parametrize(
    ("text", "access"),
    [
        ("R", AccessType.RO),
        ("Read only", AccessType.RO),
        ("Read", AccessType.RO),
        ("ro", AccessType.RO),
        ("W", AccessType.WO),
        ("Write only", AccessType.WO),
        ("R/W", AccessType.RW),
        ("RW", AccessType.RW),
        ("Read/Write", AccessType.RW),
        ("Read/write", AccessType.RW),
        ("RW W", AccessType.RW),
        ("CONST", AccessType.CONST),
        ("Const", AccessType.CONST),
        ("RWR", AccessType.RWR),
        ("RWW", AccessType.RWW),
    ],
)
def test_access_spellings(text: str, access: AccessType) -> None:
    spec = parse_access(text)
    assert spec is not None and spec.access is access


def test_access_with_condition_keeps_the_note() -> None:
    spec = parse_access("RW *Write: only 0 (means information clear) is accepted")
    assert spec is not None and spec.access is AccessType.RW and "only 0" in spec.note
    starred = parse_access("RW*")
    assert starred is not None and starred.access is AccessType.RW and starred.note


def test_per_index_access_list() -> None:
    spec = parse_access("Object 1800h: Read/Write Object 1801h: Read only")
    assert spec is not None
    assert spec.per_index == {0x1800: AccessType.RW, 0x1801: AccessType.RO}


@pytest.mark.parametrize("text", ["", "---", "-"])
def test_no_access(text: str) -> None:
    assert parse_access(text) is None


@pytest.mark.parametrize(
    ("text", "index"),
    [
        ("UNSIGNED16", 0x06),
        ("U16", 0x06),
        ("USIGN16", 0x06),
        ("UINT32", 0x07),
        ("Unsigned8", 0x05),
        ("Integer 32", 0x04),
        ("SIGNED16", 0x03),
        ("SignedT32", 0x04),
        ("SIGNED24", 0x10),
        ("Insigned16", 0x03),
        ("Floating Point (Float)", 0x08),
        ("VISIBLE STRING", 0x09),
        ("Visible string", 0x09),
        ("STRING", 0x09),
        ("String octet", 0x0A),
        ("OCTET_STRING", 0x0A),
        ("BYTE", 0x05),
        ("PDO CommPar (object 0x20)", 0x20),
        ("PDOCommPar", 0x20),
        ("PDO mapping", 0x21),
        ("SDO Parameter (object 0x22)", 0x22),
        ("Identity", 0x23),
        ("Interpolation time period record (0080h)", 0x80),
        ("PVT DataPar (object 0x40)", 0x40),
    ],
)
def test_type_spellings(text: str, index: int) -> None:
    spec = parse_type(text)
    assert spec is not None and spec.index == index


def test_container_markers_are_not_types() -> None:
    array, record = parse_type("ARRAY"), parse_type("RECORD")
    assert array is not None and array.container is ObjectKind.ARRAY and array.index is None
    assert record is not None and record.container is ObjectKind.RECORD
    assert parse_type("Command Par") is None
    assert parse_type("RAMP") is None


@pytest.mark.parametrize(
    ("text", "kind"),
    [("VAR", ObjectKind.VAR), ("ARR", ObjectKind.ARRAY), ("Array", ObjectKind.ARRAY), ("REC", ObjectKind.RECORD),
     ("Reco ord", ObjectKind.RECORD), ("DOMAIN", ObjectKind.DOMAIN)],
)  # fmt: skip
def test_object_codes(text: str, kind: ObjectKind) -> None:
    assert parse_object_code(text) is kind


@pytest.mark.parametrize(
    ("text", "mappable", "direction"),
    [
        ("Yes", True, "both"),
        ("Y", True, "both"),
        ("Possible", True, "both"),
        ("optional", True, "both"),
        ("No", False, None),
        ("N", False, None),
        ("----", False, None),
        ("RPDO", True, "rx"),
        ("TPDO", True, "tx"),
    ],
)
def test_mapping_flags(text: str, mappable: bool, direction: str | None) -> None:
    spec = parse_mapping(text)
    assert spec is not None and spec.mappable is mappable and spec.direction == direction


def test_empty_mapping_says_nothing_unless_the_table_says_so() -> None:
    assert parse_mapping("") is None
    spec = parse_mapping("", empty_means_no=True)
    assert spec is not None and spec.mappable is False


@pytest.mark.parametrize(
    ("text", "type_index", "value"),
    [
        ("0x191", 0x07, 0x191),
        ("100h", 0x07, 0x100),
        ("0000 0080h", 0x07, 0x80),
        ("6040 00 10h", 0x07, 0x60400010),
        ("80000280 _h", 0x07, 0x80000280),
        ("0x0000080", 0x07, 0x80),
        ("FFFFh", 0x03, -1),
        ("8000 0001h", 0x04, -2147483647),
        ("$-2^{31}-1$", 0x04, -2147483649),
        ("0 (no inhibit time between messages)", 0x06, 0),
        ("0xFF (all emergencies on)", 0x06, 0xFF),
        ("6 [6: 500Kbit per second]", 0x05, 6),
        ("-3 (ms)", 0x03, -3),
        ("255h", 0x05, 255),  # 'h' on a decimal number (002:4643)
        ("Value = 4", 0x05, 4),
        ("On (1)", 0x05, 1),
        ("SI-CANopen", 0x09, "SI-CANopen"),
    ],
)
def test_values(text: str, type_index: int, value: object) -> None:
    spec = parse_value(text, type_index)
    assert spec is not None and spec.value == value


@pytest.mark.parametrize(
    ("text", "offset"),
    [
        ("512 (200h) + Node-ID", 0x200),
        ("0000 0080h + Node-ID", 0x80),
        ("0000 0200h + Node ID", 0x200),
        ("0x600+\\$NODEID", 0x600),
        ("\\$NODEID+0x200 \u00b2", 0x200),
        ("0x180+\\$NODEID3", 0x180),
        ("0x80000200 + node address.", 0x80000200),
    ],
)
def test_node_relative_values(text: str, offset: int) -> None:
    spec = parse_value(text, 0x07)
    assert spec is not None and spec.value == NodeIdExpr(offset=offset)


@pytest.mark.parametrize("text", ["No", "None", "-", "---", "N/A", "", "See below", "Pr 1.06"])
def test_no_value(text: str) -> None:
    assert parse_value(text, 0x07) is None


@pytest.mark.parametrize(
    ("text", "low", "high"),
    [
        ("1...127", 1, 127),
        ("0..2", 0, 2),
        ("0...65,535", 0, 65535),
        ("1 to 0xFE", 1, 0xFE),
        ("0 to 511", 0, 511),
        ("Range 0 to 511", 0, 511),
        ("-10 \u2079 ...10 \u2079", -(10**9), 10**9),
        ("0x81...0xFFFFFFFF", 0x81, 0xFFFFFFFF),
        ("$[(-2^{30} + 1) \\dots (2^{30} - 1)]$", -(2**30) + 1, 2**30 - 1),
        ("0000 0001...0000 07FFh", 1, 0x7FF),
        ("0, 2000...100000 (only the multiple of 1000 can be set)", 0, 100000),
        ("0...20000 [0.1ms]", 0, 20000),
        ("0, 1, 2, 4, 5, 6, 7, 8", 0, 8),
        ("0 to 3000 ms", 0, 3000),
    ],
)
def test_ranges(text: str, low: int, high: int) -> None:
    spec = parse_range(text)
    assert spec is not None and (spec.low, spec.high) == (low, high)


def test_type_names_as_ranges() -> None:
    spec = parse_range("UNSIGNED32")
    assert spec is not None and spec.type_index == 0x07 and spec.low is None
    enum = parse_range("UNSIGNED8: 0: Execute next command immediately 1 - 2: Not supported 3: Abort execution")
    assert enum is not None and enum.type_index == 0x05
    assert parse_range("Refer to Table 13-1") is None


def test_per_index_value_lists() -> None:
    assert split_per_index("Index 1800h: 0x400001FF Index 1801h: 0x400002FF") == {
        0x1800: "0x400001FF",
        0x1801: "0x400002FF",
    }
    mixed = split_per_index("Object 1600h(1): 0x20010040 (controlword) Object 1602h: 0")
    assert mixed == {0x1600: "0x20010040 (controlword)", 0x1602: "0"}
    assert split_per_index("0x27F") == {}


def test_clean_markup_and_homoglyphs() -> None:
    assert clean("<b>Index</b>") == "Index"
    assert clean("**COB-ID** *italic*") == "COB-ID italic"
    assert clean("vl\\_target\\_velocity") == "vl_target_velocity"
    assert clean("\u0425") == "X"  # Cyrillic Ha
    assert parse_number("2 \u00b3\u00b9 -1") == 2**31 - 1


def test_no_spelling_raises() -> None:
    """Whatever a cell holds, the readers answer or say None; they never raise."""
    import random
    import string

    from cantools_od.tableimport import notation

    rng = random.Random(7)
    alphabet = string.printable + "h_~\u2013\u2026\u2079\u00b2\u00b5\u03bc\u0425\u0661$\\{}()[]^*"
    readers = [notation.parse_index, notation.parse_sub, notation.parse_access, notation.parse_type,
               notation.parse_object_code, notation.parse_mapping, notation.parse_number, notation.parse_range,
               notation.split_per_index, notation.clean]  # fmt: skip
    for _ in range(3000):
        text = "".join(rng.choice(alphabet) for _ in range(rng.randint(0, 24)))
        for read in readers:
            read(text)
        for type_index in (None, 0x03, 0x07, 0x08, 0x09, 0x0A):
            parse_value(text, type_index)
