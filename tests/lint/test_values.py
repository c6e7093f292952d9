"""Value rules (cantools_od/lint/values.py): type ranges, limits, $NODEID, strings, REALs."""

from __future__ import annotations

from lintkit import BASE, findings, messages, table_tests

CODES = ("EDS031", "EDS034", "EDS035", "EDS036", "EDS037", "EDS038", "EDS039", "EDS061")
NODE = "[DeviceComissioning]\nNodeID=5\n"


def var(data_type: str, *lines: str, access: str = "rw") -> str:
    """[2000] of a data type: lines 1-4 are the header and fixed keys, `lines` start at line 5."""
    return "\n".join(["[2000]", "ParameterName=Value", f"DataType={data_type}", f"AccessType={access}", *lines]) + "\n"


def compact(*lines: str, values: str = "") -> str:
    """A DCF with a CompactSubObj ARRAY [2000] at line 3 (its keys from line 9) and an optional [2000Value]."""
    head = [NODE + "[2000]", "ParameterName=Inputs", "ObjectType=0x8", "DataType=0x0005", "AccessType=rw"]
    text = "\n".join([*head, "CompactSubObj=2", *lines]) + "\n"
    return text + (f"[2000Value]\nNrOfEntries=1\n{values}\n" if values else "")


# (code, text, source, node-ID option, expected (line, column) of each finding)
FOUND = [
    ("EDS034", var("0x0005", "DefaultValue=300"), "t.eds", None, [(5, 14)]),
    ("EDS034", var("0x0002", "DefaultValue=-200"), "t.eds", None, [(5, 14)]),
    ("EDS034", var("0x0006", "LowLimit=-1", "HighLimit=0x10000"), "t.eds", None, [(5, 10), (6, 11)]),
    ("EDS034", var("0x0005", "DefaultValue=$NODEID+0x100"), "t.eds", None, [(5, 14)]),
    ("EDS034", var("0x0005", "DefaultValue=$NODEID+0x81"), "t.eds", 127, [(5, 14)]),
    ("EDS034", var("0x000C", "DefaultValue=1 86400000"), "t.eds", None, [(5, 14)]),
    ("EDS034", NODE + var("0x0005", "ParameterValue=256"), "t.dcf", None, [(7, 16)]),
    ("EDS034", compact("DefaultValue=300"), "t.dcf", None, [(9, 14)]),
    ("EDS034", compact(values="2=256"), "t.dcf", None, [(11, 3)]),  # the [2000Value] entry
    ("EDS031", var("0x0003", "LowLimit=100", "HighLimit=-100"), "t.eds", None, [(5, 10)]),
    ("EDS031", var("0x0007", "LowLimit=$NODEID+0x200", "HighLimit=0x180"), "t.eds", None, [(5, 10)]),
    ("EDS035", var("0x0006", "DefaultValue=5000", "HighLimit=3000"), "t.eds", None, [(5, 14)]),
    ("EDS035", var("0x0003", "DefaultValue=-5", "LowLimit=0"), "t.eds", None, [(5, 14)]),
    ("EDS035", var("0x0007", "DefaultValue=$NODEID+0x180", "HighLimit=0x100"), "t.eds", None, [(5, 14)]),
    ("EDS035", var("0x0007", "DefaultValue=$NODEID+0x180", "HighLimit=0x18F"), "t.eds", 16, [(5, 14)]),
    ("EDS035", compact("DefaultValue=20", "HighLimit=10"), "t.dcf", None, [(9, 14)]),
    ("EDS036", var("0x0009", "LowLimit=0", "HighLimit=9"), "t.eds", None, [(5, 1), (6, 1)]),
    ("EDS037", var("0x0009", "DefaultValue=$NODEID+0x180"), "t.eds", None, [(5, 14)]),
    ("EDS038", var("0x0009", "DefaultValue=Motor 5°"), "t.eds", None, [(5, 14)]),
    ("EDS038", var("0x0009", "DefaultValue=a\tb"), "t.eds", None, [(5, 14)]),
    ("EDS039", var("0x0008", "DefaultValue=nan"), "t.eds", None, [(5, 14)]),
    ("EDS039", var("0x0011", "HighLimit=inf"), "t.eds", None, [(5, 11)]),
    ("EDS061", NODE + var("0x0006", "HighLimit=3000", "ParameterValue=5000"), "t.dcf", None, [(8, 16)]),
    ("EDS061", compact("HighLimit=10", values="2=20"), "t.dcf", None, [(12, 3)]),  # the [2000Value] entry
]

CLEAN = [
    ("EDS034", var("0x0005", "DefaultValue=255", "LowLimit=0", "HighLimit=0xFF"), "t.eds", None),
    ("EDS034", var("0x0002", "DefaultValue=-128", "HighLimit=0x7F"), "t.eds", None),
    ("EDS034", var("0x0005", "DefaultValue=$NODEID+0x80"), "t.eds", None),
    ("EDS034", var("0x0005", "DefaultValue=$NODEID+0x81"), "t.eds", None),  # fits node-IDs 1..126
    ("EDS034", var("0x0005", "DefaultValue=twelve"), "t.eds", None),  # the reader's EDS030
    ("EDS034", var("0x000C", "DefaultValue=1 86399999"), "t.eds", None),
    ("EDS034", var("0x0001", "DefaultValue=1"), "t.eds", None),
    ("EDS031", var("0x0003", "LowLimit=-100", "HighLimit=-100"), "t.eds", None),
    ("EDS031", var("0x0007", "LowLimit=$NODEID+0x180", "HighLimit=0x181"), "t.eds", None),  # node-ID 1 only
    ("EDS035", var("0x0007", "DefaultValue=$NODEID+0x180", "LowLimit=0x181", "HighLimit=0x18F"), "t.eds", None),
    ("EDS035", var("0x0007", "DefaultValue=$NODEID+0x180", "HighLimit=0x18F"), "t.eds", 15),
    ("EDS035", var("0x0006", "DefaultValue=5000", "LowLimit=6000", "HighLimit=3000"), "t.eds", None),  # EDS031
    ("EDS035", compact("DefaultValue=10", "HighLimit=10"), "t.dcf", None),
    ("EDS036", "[2000]\nParameterName=Blob\nObjectType=0x2\nLowLimit=0\n", "t.eds", None),  # EDS024's case
    ("EDS036", var("0x0001", "LowLimit=0", "HighLimit=1"), "t.eds", None),
    ("EDS037", var("0x0007", "DefaultValue=$NODEID+0x180"), "t.eds", None),
    ("EDS038", var("0x0009", "DefaultValue=Motor ~ 5 (ok)"), "t.eds", None),
    ("EDS039", var("0x0008", "DefaultValue=1.5", "LowLimit=-1e30"), "t.eds", None),
    ("EDS061", NODE + var("0x0006", "HighLimit=3000", "ParameterValue=3000"), "t.dcf", None),
    ("EDS061", compact("HighLimit=10", values="2=10"), "t.dcf", None),
]


test_finding_location, test_no_finding, test_rule_on_a_valid_file, test_rule_documented = table_tests(
    "values", FOUND, CLEAN, CODES
)


def test_messages() -> None:
    assert messages(var("0x0005", "DefaultValue=300"), "EDS034") == [
        "[2000] DefaultValue: 300 (0x12C) is outside UNSIGNED8 (0..255)"
    ]
    assert messages(var("0x0005", "DefaultValue=$NODEID+0x100"), "EDS034") == [
        "[2000] DefaultValue: 257 (0x101) for every node-ID 1..127 is outside UNSIGNED8 (0..255)"
    ]
    assert messages(compact("HighLimit=10", values="2=20"), "EDS061", "t.dcf") == [
        "[2000Value] 2 ParameterValue 20 is above HighLimit 10"
    ]
    assert messages(var("0x0002", "LowLimit=0", "HighLimit=0xFF"), "EDS031") == [
        "[2000] LowLimit 0 > HighLimit -1 (a hex HighLimit such as 0xFF is two's complement for a signed type)"
    ]


def test_compact_default_reported_once() -> None:
    """The CompactSubObj sub-objects copy the object's DefaultValue: one finding, at the object's key."""
    assert findings(compact("DefaultValue=300").replace("=2\n", "=50\n"), "EDS034", "t.dcf") == [(9, 14)]


def test_implicit_pdo_values_are_not_checked() -> None:
    text = BASE.replace("NrOfRXPDO=0", "NrOfRXPDO=2\nCompactPDO=0x3F")
    assert [findings(text, code) for code in CODES] == [[] for _ in CODES]
