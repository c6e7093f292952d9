"""No false family: each shape here made the linter report what is not so, or report one cause many times. Each is
built from the real file that showed it (named), and the finding that explains the cause is still there."""

from __future__ import annotations

from lintkit import BASE, replace
from xddkit import document

from cantools_od import loads
from cantools_od.lint import LintOptions, lint
from cantools_od.model import Severity

DRIVE = replace(
    BASE, "DefaultValue=0x00000000\nPDOMapping=0\n\n[1001]", "DefaultValue=0x00020192\nPDOMapping=0\n\n[1001]"
)


def _codes(text: str, source: str = "t.eds", profile: str | None = None) -> list[tuple[str, str]]:
    device = loads(text, source=source)
    return [(f.code, f.message) for f in lint(device, LintOptions(profile=profile))]


def _section(index: str, **keys: str) -> str:
    return f"\n[{index}]\n" + "".join(f"{key}={value}\n" for key, value in keys.items())


# 6099h as nanotec/trinamic-style drives extend it: the two homing speeds of CiA 402-2 and a vendor's third.
HOMING = (
    _section("6099", ParameterName="Homing speeds", ObjectType="0x8", SubNumber="4")
    + _section("6099sub0", ParameterName="Highest sub-index supported", ObjectType="0x7", DataType="0x0005",
               AccessType="ro", DefaultValue="3", PDOMapping="0")
    + "".join(_section(f"6099sub{n}", ParameterName=f"Speed {n}", ObjectType="0x7", DataType="0x0007",
                       AccessType="rw", DefaultValue="0", PDOMapping="0") for n in (1, 2, 3))
)  # fmt: skip


def test_std003_says_a_vendor_sub_index_is_not_the_profiles_and_gives_it_no_type() -> None:
    found = [(code, m) for code, m in _codes(DRIVE + HOMING) if code == "STD003"]
    assert found == [
        (
            "STD003",
            "[6099sub3]: sub-index 3 of 6099h Homing speeds is not defined by CiA 402-2 (a vendor's extension; "
            "its data type is the vendor's)",
        )
    ]
    speed = "DataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n[6099sub2]"
    text = DRIVE + HOMING.replace(speed, speed.replace("0x0007", "0x0004"))
    assert any("sub-index 1 (Homing speeds) as UNSIGNED32" in m for code, m in _codes(text) if code == "STD003")
    severities = {f.severity for f in lint(loads(DRIVE + HOMING, source="t.eds")) if f.code == "STD003"}
    assert severities == {Severity.WARNING}


# kacanopen's example EDS (eds-history KITmedical__kacanopen__1/new.eds): a comment after the ObjectType value.
UNREADABLE_KIND = (
    _section("6000", ParameterName="Read input 8 bit", ObjectType="0x08 # Array")
    + "# SubNumber=6\n"
    + _section("6000sub00", ParameterName="Number of inputs 8-bit", ObjectType="0x007 # VAR",
               DataType="0x0005 # Unsigned8", AccessType="ro", PDOMapping="0 # No")
    + _section("1003", ParameterName="Pre-defined error field", ObjectType="0x08 # ARRAY", SubNumber="2")
    + _section("1003sub0", ParameterName="Number of errors", ObjectType="0x7", DataType="0x0005", AccessType="rw",
               DefaultValue="0")
    + _section("1003sub1", ParameterName="Standard error field", ObjectType="0x7", DataType="0x0007",
               AccessType="ro", DefaultValue="0")
)  # fmt: skip


def test_an_unreadable_object_type_is_one_error_not_a_var_with_knock_ons() -> None:
    found = _codes(BASE + UNREADABLE_KIND)
    # the object type decides the keys it needs (EDS020), may have (EDS024) and the standard's (STD001)
    knock_ons = [(code, m) for code, m in found if code in ("EDS020", "EDS024", "STD001", "STD002")]
    assert knock_ons == []
    assert [m for code, m in found if code == "EDS030" and "ObjectType" in m] == [
        "ObjectType: '0x08 # Array' is not a number",
        "ObjectType: '0x007 # VAR' is not a number",
        "ObjectType: '0x08 # ARRAY' is not a number",
    ]


def test_a_domain_default_0_is_canopennodes_empty_not_an_unstorable_default() -> None:
    # CANopenNode's own editors write DefaultValue=0 on a DOMAIN (39 in the corpus); EDS030 already says it
    text = BASE + _section("2000", ParameterName="Program data", ObjectType="0x7", DataType="0x000F",
                           AccessType="rw", DefaultValue="0", PDOMapping="0")  # fmt: skip
    found = _codes(text, profile="canopennode")
    assert [code for code, _ in found if code == "CNO007"] == []
    assert any(code == "EDS030" and "CANopenNode's way to say empty" in m for code, m in found)
    # Any other DOMAIN default is ignored too, as CANopenEditor and the stack do (gen --explain says so; #21)
    odd = text.replace(
        "DataType=0x000F\nAccessType=rw\nDefaultValue=0", "DataType=0x000F\nAccessType=rw\nDefaultValue=0x1"
    )
    assert [code for code, _ in _codes(odd, profile="canopennode") if code == "CNO007"] == []


# odrive-canopen-cia402.xdd and oresat gps.xdd: 1023h's Command and Reply as <BITSTRING/>, no dataType, no default.
OS_COMMAND = """
          <CANopenObject index="1023" name="OS command" objectType="9" subNumber="4" uniqueIDRef="UID_OBJ_1023">
            <CANopenSubObject subIndex="00" name="Highest sub-index supported" objectType="7"
              uniqueIDRef="UID_SUB_102300" />
            <CANopenSubObject subIndex="01" name="Command" objectType="7" uniqueIDRef="UID_SUB_102301" />
            <CANopenSubObject subIndex="02" name="Status" objectType="7" uniqueIDRef="UID_SUB_102302" />
            <CANopenSubObject subIndex="03" name="Reply" objectType="7" uniqueIDRef="UID_SUB_102303" />
          </CANopenObject>
          <CANopenObject index="2122" name="Demo domain" objectType="7" uniqueIDRef="UID_OBJ_2122" />"""
OS_PARAMETERS = """
          <parameter uniqueID="UID_OBJ_1023"><label lang="en">OS command</label></parameter>
          <parameter uniqueID="UID_SUB_102300"><label lang="en">Highest</label><USINT />
            <defaultValue value="0x03" /></parameter>
          <parameter uniqueID="UID_SUB_102301" access="readWrite"><label lang="en">Command</label><BITSTRING />
          </parameter>
          <parameter uniqueID="UID_SUB_102302"><label lang="en">Status</label><USINT /></parameter>
          <parameter uniqueID="UID_SUB_102303"><label lang="en">Reply</label><BITSTRING /></parameter>
          <parameter uniqueID="UID_OBJ_2122" access="readWrite"><label lang="en">Demo domain</label><BITSTRING />
          </parameter>"""


def test_xdd_bitstring_of_a_standard_octet_string_is_not_read_as_domain() -> None:
    device = loads(document(OS_COMMAND, OS_PARAMETERS), source="t.xdd")
    assert device.objects[0x1023].subs[1].data_type == 0x000A
    assert device.objects[0x1023].subs[3].data_type == 0x000A
    assert device.objects[0x2122].data_type == 0x000F  # CANopenEditor's DOMAIN stays one
    assert [m for code, m in _codes(document(OS_COMMAND, OS_PARAMETERS), "t.xdd") if code == "STD003"] == []


def test_xdd_missing_name_is_reported_once() -> None:
    objects = '<CANopenObject index="2000" objectType="7" dataType="0006" accessType="rw" />'
    found = _codes(document(objects), "t.xdd")
    assert [code for code, _ in found if code in ("XDD006", "EDS020")] == ["XDD006"]
