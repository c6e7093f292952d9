"""The EDS/DCF reader, feature by feature, on small inline files."""

from __future__ import annotations

import struct
from pathlib import Path

import pytest

from cantools_od import load, loads
from cantools_od.model import AccessType, Dialect, NodeIdExpr, ObjectKind, RawValue, Severity, TimeValue
from cantools_od.sniff import NotADeviceDescription


def codes(device: object) -> list[str]:
    return [d.code for d in device.diagnostics]  # type: ignore[attr-defined]


VAR = "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\nDefaultValue={value}\n"


def test_section_and_key_names_are_case_insensitive() -> None:
    device = loads(
        b"[deviceinfo]\nvendornumber=0x12\nNrOfRxPdo=3\n[1a00]\nparametername=Map\nOBJECTTYPE=0x9\nsubnumber=1\n"
        b"[1A00SUB0]\nParameterName=n\nDataType=0x0005\nAccessType=RO\nDefaultValue=0\n"
    )
    assert device.device_info.vendor_number == 0x12
    assert device.device_info.nr_of_rx_pdo == 3
    obj = device.objects[0x1A00]
    assert obj.kind is ObjectKind.RECORD and obj.subs[0].access is AccessType.RO
    assert not [d for d in device.diagnostics if d.severity is Severity.ERROR]


@pytest.mark.parametrize("eol", [b"\n", b"\r\n", b"\r"])
def test_line_ends(eol: bytes) -> None:
    device = loads(VAR.format(value="7").encode().replace(b"\n", eol))
    assert device.objects[0x2000].default == 7
    assert device.objects[0x2000].origin is not None
    assert device.objects[0x2000].origin.value("DefaultValue").line == 5


def test_mixed_line_ends_and_bom() -> None:
    data = b"\xef\xbb\xbf[2000]\r\nParameterName=Speed\nDataType=0x0006\r\nAccessType=rw\nDefaultValue=9\r\n"
    device = loads(data)
    assert device.objects[0x2000].default == 9
    assert device.objects[0x2000].name == "Speed"


def test_code_page_fallback_is_reported() -> None:
    device = loads(b"[2000]\nParameterName=Temp \xb0C \x94\nDataType=0x0005\nAccessType=ro\n")
    assert device.objects[0x2000].name == "Temp °C \u201d"
    assert "EDS100" in codes(device)


@pytest.mark.parametrize(
    ("text", "value", "code"),
    [
        ("0x10", 16, None),
        ("16", 16, None),
        ("020", 16, "EDS032"),  # octal per CiA 306
        ("0x1234LL", 0x1234, "EDS032"),  # C suffix
        ("0x3E8 ; one thousand", 1000, "EDS032"),  # inline comment
        ("1000 # note", 1000, "EDS032"),
        ("09", RawValue(text="09"), "EDS030"),
        ("twelve", RawValue(text="twelve"), "EDS030"),
    ],
)
def test_integer_forms(text: str, value: object, code: str | None) -> None:
    device = loads(VAR.format(value=text).encode())
    assert device.objects[0x2000].default == value
    assert (code in codes(device)) if code else not codes(device)


def test_diagnostic_points_at_the_value() -> None:
    device = loads(VAR.format(value="twelve").encode(), source="x.eds")
    (diag,) = device.diagnostics
    assert (diag.location.file, diag.location.line, diag.location.column) == ("x.eds", 5, 14)
    assert diag.format().startswith("x.eds:5:14: error: ")


def test_inline_comment_is_kept_as_a_comment() -> None:
    device = loads(VAR.format(value="0x3ED ; prevent homing").encode())
    assert device.objects[0x2000].comments["DefaultValue"] == ["; prevent homing"]


def test_signed_limits_minus_and_twos_complement() -> None:
    text = (
        "[2001]\nParameterName=T\nDataType=0x0003\nAccessType=rw\nLowLimit=0xFFF6\nHighLimit=-0x10\nDefaultValue=-5\n"
    )
    device = loads(text.encode())
    obj = device.objects[0x2001]
    assert (obj.low_limit, obj.high_limit, obj.default) == (-10, -16, -5)
    assert codes(device) == ["EDS032"]


def test_real_decimal_and_bit_pattern() -> None:
    text = "[2002]\nParameterName=R\nDataType=0x0008\nAccessType=rw\nDefaultValue=0x40490FDB\nLowLimit=-1.5\n"
    device = loads(text.encode())
    obj = device.objects[0x2002]
    assert obj.default == struct.unpack("<f", bytes.fromhex("db0f4940"))[0]
    assert obj.low_limit == -1.5


@pytest.mark.parametrize(
    ("text", "offset", "warned"),
    [
        ("$NODEID+0x180", 0x180, False),
        ("$nodeid+0x180", 0x180, True),
        ("0x180+$NODEID", 0x180, True),
        ("$NODEID + 0x100 + 0x80", 0x180, True),
        ("$NODEID", 0, False),
    ],
)
def test_nodeid_formulas(text: str, offset: int, warned: bool) -> None:
    device = loads(VAR.format(value=text).encode(), node_id=5)
    value = device.objects[0x2000].default
    assert isinstance(value, NodeIdExpr) and value.offset == offset
    assert device.resolve(value) == 5 + offset
    assert ("EDS033" in codes(device)) is warned


def test_nodeid_with_multiplication_is_an_error() -> None:
    device = loads(VAR.format(value="2*$NODEID").encode())
    assert isinstance(device.objects[0x2000].default, RawValue)
    assert codes(device) == ["EDS030"]


def test_strings_octets_domain_time() -> None:
    text = (
        "[2003]\nParameterName=S\nDataType=0x0009\nAccessType=ro\nDefaultValue=Motor #1; left\n"
        "[2004]\nParameterName=O\nDataType=0x000A\nAccessType=ro\nDefaultValue=01a1053c\n"
        "[2005]\nParameterName=D\nObjectType=0x2\nDefaultValue=0A0B\n"
        "[2006]\nParameterName=T\nDataType=0x000C\nAccessType=ro\nDefaultValue=365 43200000\n"
    )
    device = loads(text.encode())
    assert device.objects[0x2003].default == "Motor #1; left"  # no inline comments in strings
    assert device.objects[0x2004].default == bytes.fromhex("01a1053c")
    assert device.objects[0x2005].default == b"\x0a\x0b"
    assert device.objects[0x2006].default == TimeValue(days=365, ms=43200000)
    assert not codes(device)


def test_lely_strings_are_unquoted() -> None:
    text = (
        "[DeviceInfo]\nVendorName=Lely Industries N.V.\n"
        '[2003]\nParameterName=S\nDataType=0x0009\nAccessType=ro\nDefaultValue="say \\"hi\\""\n'
    )
    device = loads(text.encode())
    assert device.dialect is Dialect.LELY
    assert device.objects[0x2003].default == 'say "hi"'


def test_spaces_around_equals_and_supported_objects_spelling() -> None:
    device = loads(b"[OptionalObjects]\nSupported Objects = 2\n1 = 0x1005\n2=0x1017\n")
    assert device.optional_objects is not None
    assert device.optional_objects.supported_objects == 2
    assert device.optional_objects.entries == {1: 0x1005, 2: 0x1017}


COMPACT = """[1600]
ParameterName=RPDO1 mapping
ObjectType=0x9
DataType=0x0007
AccessType=rw
CompactSubObj=3
DefaultValue=0
[1600Name]
NrOfEntries=1
2=Second
[1600Value]
NrOfEntries=2
1=0x60400010
3=0x60600008
[1600Denotation]
NrOfEntries=1
1=control
"""


def test_compact_sub_obj_expansion() -> None:
    obj = loads(COMPACT.encode(), fmt="dcf").objects[0x1600]
    assert sorted(obj.subs) == [0, 1, 2, 3]
    assert obj.subs[0].default == 3 and obj.subs[0].name == "NrOfObjects"
    assert [obj.subs[i].name for i in (1, 2, 3)] == ["RPDO1 mapping1", "Second", "RPDO1 mapping3"]
    assert obj.subs[1].parameter_value == 0x60400010 and obj.subs[2].parameter_value is None
    assert obj.subs[1].denotation == "control"
    assert all(s.implicit for s in obj.subs.values())


def test_compact_name_section_errors() -> None:
    device = loads(b"[2000]\nParameterName=X\nDataType=0x0005\nAccessType=ro\n[2000Name]\nNrOfEntries=1\n1=a\n")
    assert "EDS104" in codes(device)
    assert [s.name for s in device.other_sections] == ["2000Name"]  # kept, not dropped


def test_compact_pdo_creates_implicit_pdos() -> None:
    text = (
        "[DeviceInfo]\nCompactPDO=0x3\nNrOfRXPDO=2\nNrOfTXPDO=0\n"
        "[1401]\nParameterName=RPDO2\nObjectType=0x9\nSubNumber=0\n"
    )
    device = loads(text.encode())
    implicit = device.objects[0x1400]
    assert implicit.implicit and sorted(implicit.subs) == [0, 1, 2]
    assert implicit.subs[1].default == NodeIdExpr(offset=0x200)
    assert device.objects[0x1600].implicit
    assert 0x1402 not in device.objects


def test_object_links_deftype_unknown_sections_and_keys() -> None:
    text = (
        "[0040]\nParameterName=My type\nObjectType=0x5\nDataType=0x0006\nAccessType=ro\n"
        "[2000]\nParameterName=X\nDataType=0x0040\nAccessType=rw\nDefaultValue=0x10\nFactor=0.5\n"
        "[2000ObjectLinks]\nObjectLinks=1\n1=0x2001\n"
        "[VendorStuff]\nKey=Value\n"
    )
    device = loads(text.encode())
    obj = device.objects[0x2000]
    assert obj.default == 16  # typed through the DEFTYPE alias
    assert obj.extra == {"Factor": "0.5"}
    assert obj.links == [0x2001]
    assert device.other_sections[0].entries == {"Key": "Value"}


def test_duplicates_warn_and_last_wins() -> None:
    device = loads(b"[2000]\nParameterName=A\nParameterName=B\n[2000]\nDataType=0x0005\n")
    assert device.objects[0x2000].name == "B"
    assert device.objects[0x2000].data_type == 5
    assert codes(device) == ["EDS002", "EDS002"]


def test_repeated_sections_written_plainly_are_merged() -> None:
    # Each section alone is written plainly (sorted by a plan per list of keys): the merged one is not.
    device = loads(b"[2000]\nParameterName=A\nDataType=0x0005\n[2000]\nAccessType=ro\nDefaultValue=3\n")
    obj = device.objects[0x2000]
    assert (obj.name, obj.data_type, obj.access, obj.default) == ("A", 5, AccessType.RO, 3)
    assert obj.origin is not None
    assert [obj.origin.where(key) for key in ("DataType", "AccessType", "DefaultValue")] == [
        (3, 1, 10),
        (5, 1, 12),
        (6, 1, 14),
    ]
    assert codes(device) == ["EDS002"]


def test_a_repeat_found_late_is_merged_and_each_finding_reported_once() -> None:
    # Read on the guess that no section name repeats, the last header proves it wrong: the reader starts again.
    device = loads(b"[1000]\nParameterName=caf\xe9\nDataType=zz\n[2000]\nParameterName=A\n[ 1000 ]\nDefaultValue=1\n")
    assert [(d.code, d.location.line) for d in device.diagnostics] == [("EDS100", 1), ("EDS002", 6), ("EDS030", 3)]
    assert device.objects[0x1000].name == "caf\u00e9" and device.objects[0x2000].name == "A"
    origin = device.objects[0x1000].origin
    assert origin is not None and origin.where("DefaultValue") == (7, 1, 14)


def test_sections_written_alike_keep_their_own_positions_and_spellings() -> None:
    section = "[{}]\nparametername=A\nDataType=0x0005\nAccessType={}\n"
    device = loads((section.format(2000, "xx") + "\n" + section.format(2001, "yy")).encode())
    for index, line in ((0x2000, 1), (0x2001, 6)):
        origin = device.objects[index].origin
        assert origin is not None and origin.line == line
        assert origin.where("AccessType") == (line + 3, 1, 12)
        assert origin.spelled == {"ParameterName": "parametername"}
        assert device.objects[index].extra == {"AccessType": "xx" if index == 0x2000 else "yy"}
    assert [(d.code, d.location.line, d.location.column) for d in device.diagnostics] == [
        ("EDS030", 4, 12),
        ("EDS030", 9, 12),
    ]


def test_stray_lines_and_broken_headers_are_diagnosed() -> None:
    device = loads(b"junk before\n[2000\nParameterName=A\nnot an entry\n")
    assert sorted(codes(device)) == ["EDS101", "EDS101", "EDS102"]


def test_dcf_commissioning_both_spellings() -> None:
    for spelling in ("DeviceComissioning", "DeviceCommissioning"):
        device = loads(f"[{spelling}]\nNodeID=0x05\nBaudrate=500\n".encode())
        assert device.is_dcf and device.node_id == 5 and device.commissioning is not None


def test_origin_of_every_key() -> None:
    device = loads(b"[2000]\n; a comment\nParameterName = Speed\nDataType=0x0006\n", source="f.eds")
    origin = device.objects[0x2000].origin
    assert origin is not None and (origin.file, origin.line) == ("f.eds", 1)
    assert origin.where("ParameterName") == (3, 1, 17)
    assert device.objects[0x2000].comments == {"ParameterName": ["; a comment"]}


def test_unreadable_path_raises_oserror(tmp_path: Path) -> None:
    with pytest.raises(OSError):
        load(tmp_path / "missing.eds")


@pytest.mark.parametrize("data", [b"[FFFFsubFFF]\n", b"x\n[2000", b"[a]\nParameterName=x\n"])
def test_garbage_never_raises(data: bytes) -> None:
    loads(data)


# Sections, but none CiA 306 knows (no file section, no object's section with an object's key): an INI file or
# JSON of another tool, never read as an empty device that `fmt` would write back over it.
@pytest.mark.parametrize(
    "data",
    [b"", b" \r\n", b"\x00\xff\xfe", b"=", b"ParameterName=x\n", b"[", b"[]\n=\n", b"[1000sub]\n", b"[a]\nname=x\n"],
)
def test_what_is_no_device_description_is_refused(data: bytes) -> None:
    with pytest.raises(NotADeviceDescription, match=r"^not an EDS/DCF file: "):
        loads(data)


@pytest.mark.parametrize("name", ["device.xdd", "DEVICE.XDC", "device.xml"])
@pytest.mark.parametrize("data", [b"", b" \n", b"\x00\xff\xfe", b"no markup\n"])
def test_a_refused_xml_file_is_named_as_one(name: str, data: bytes) -> None:
    with pytest.raises(NotADeviceDescription, match=r"^not an XDD/XDC \(CiA 311\) file: ") as refused:
        loads(data, source=name)
    assert refused.value.code == "EDS000"


def test_xml_given_as_an_eds_is_refused() -> None:
    with pytest.raises(NotADeviceDescription, match=r"^not an EDS/DCF file: XML"):
        loads(b"<?xml version='1.0'?><a/>", fmt="eds")


def test_orphan_sub_object_section_is_kept_and_reported() -> None:
    device = loads(b"[2000sub1]\nParameterName=Orphan\nDataType=0x0005\n")
    (diag,) = device.diagnostics
    assert (diag.code, diag.location.line) == ("EDS103", 1)
    assert device.other_sections[0].name == "2000sub1"
    assert device.other_sections[0].entries["ParameterName"] == "Orphan"


_COB_ID = "[1800sub1]\nParameterName=COB-ID\nDataType=0x0007\nAccessType=rw\nDefaultValue={value}\n"


@pytest.mark.parametrize(
    ("value", "encoding", "dialect"),
    [
        ("0x180 + $NODEID", "utf-8", Dialect.PYTHON_CANOPEN),
        ("0x180+$nodeid ", "utf-8", Dialect.PYTHON_CANOPEN),
        ("0x180 +\x1c$NODEID", "utf-8", Dialect.PYTHON_CANOPEN),  # a blank to `str.split`, not to a bytes pattern
        ("0x180 +\u00a0$NODEID", "utf-8", Dialect.PYTHON_CANOPEN),  # two bytes in UTF-8
        ("0x180 +\u2003$NODEID", "utf-8", Dialect.PYTHON_CANOPEN),  # three bytes in UTF-8
        ("0x180 +\u00a0$NODEID", "latin-1", Dialect.PYTHON_CANOPEN),  # not UTF-8: read as a whole, decoded
        ("$NODEID+0x180", "utf-8", Dialect.CIA306),  # the usual form says nothing of the tool
        ("0x180 + $NODEID", "latin-1", Dialect.PYTHON_CANOPEN),
    ],
)
def test_dialect_evidence_in_values_is_found_whatever_the_blanks(value: str, encoding: str, dialect: Dialect) -> None:
    """The reader looks at every entry for dialect evidence only when the text may hold some (`+ $NODEID` at
    the end of a value, CANopenNode's comments): the test for that must let every blank through."""
    text = "[DeviceInfo]\nProductName=Drive \u00e9\n" + _COB_ID.format(value=value)
    assert loads(text.encode(encoding)).dialect is dialect
