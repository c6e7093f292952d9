"""Portability rules (cantools_od/lint/portability.py): what python-canopen, lely and CANopenNode read differently."""

from __future__ import annotations

import pytest
from lintkit import findings, messages, table_tests

from cantools_od.lint.rules import RULES, Clause


def var(data_type: str, *lines: str, name: str = "Value") -> str:
    """[2000] of a data type: lines 1-4 are the header and fixed keys, `lines` start at line 5."""
    return "\n".join(["[2000]", f"ParameterName={name}", f"DataType={data_type}", "AccessType=rw", *lines]) + "\n"


DEFTYPE = "[0040]\nParameterName=My type\nObjectType=0x5\nDataType=0x0007\nAccessType=ro\n"
RECORD = "[2000]\nParameterName=Record\nObjectType=0x9\nSubNumber=3\n"
SUB = "[2000sub{n}]\nParameterName={name}\nDataType=0x0005\nAccessType=ro\n"
LELY = "[DeviceInfo]\nVendorName=Lely Industries N.V.\n"

# (code, text, expected (line, column) of each finding)
FOUND = [
    ("DIA001", "[DummyUsage]\nDummy0005=1\nDummy0006=1\nDummy0007=1\n", [(1, 1)]),
    ("DIA002", var("0x0009", 'DefaultValue="Drive"'), [(5, 14)]),
    ("DIA003", LELY + var("0x0008", "DefaultValue=0x3FC00000", "HighLimit=0x40200000"), [(7, 14)]),
    ("DIA004", RECORD.replace("SubNumber=3", "DataType=0x0007\nAccessType=rw\nCompactSubObj=8"), [(6, 1)]),
    ("DIA005", DEFTYPE, [(1, 1)]),
    ("DIA006", "[2000]\nParameterName=C\n;StorageLocation=RAM\nDataType=0x0007\nAccessType=rw\n", [(1, 1)]),
    ("DIA007", var("0x0007", name="Current [µA]"), [(2, 15)]),
    ("DIA007", "[FileInfo]\nDescription=Régulateur\n", [(2, 13)]),
    ("DIA008", DEFTYPE + var("0x0040"), [(8, 10)]),
    (
        "DIA009",
        RECORD + "\n".join(SUB.format(n=n, name=name) for n, name in enumerate(["N", "Value", "Value"])),
        [(16, 1)],
    ),
    ("DIA010", var("0x0006", "Unit=rpm", "Factor=0.1"), [(5, 1), (6, 1)]),
    ("DIA011", "[DeviceInfo]\nVendorName=x\nProductVersion=1\n", [(3, 1)]),
    ("DIA012", "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n", [(1, 1)]),
    ("DIA013", var("0x000C", "DefaultValue=365 43200000"), [(5, 14)]),
    ("DIA014", var("0x0007", "DefaultValue=$NODEID+0x600", "LowLimit=$NODEID+0x600"), [(6, 10)]),
    ("DIA015", var("0x0006", "PDOMapping="), [(5, 1)]),
    ("DIA016", var("0x0006", "ObjFlags=0x1") + var("0x0006", "ObjFlags=0x2").replace("2000", "2001"), [(5, 10)]),
    (
        "DIA017",
        var("0x0006", name="Motor #1 speed") + var("0x0009", "DefaultValue=a;b").replace("2000", "2001"),
        [(2, 15)],
    ),
]

CLEAN = [
    ("DIA001", "[FileInfo]\nFileName=t.eds\n"),  # no [DummyUsage] at all: EDS009
    ("DIA002", LELY + var("0x0009", 'DefaultValue="Drive"')),
    ("DIA002", var("0x0007", "DefaultValue=1")),
    ("DIA003", LELY + var("0x0007", "DefaultValue=1")),
    ("DIA003", var("0x0008", "DefaultValue=1.5")),  # decimals: what python-canopen and CANopenNode read
    ("DIA004", RECORD.replace("0x9", "0x8").replace("SubNumber=3", "DataType=0x0007\nAccessType=rw\nCompactSubObj=8")),
    ("DIA005", var("0x0007")),
    ("DIA006", "[2000]\nParameterName=C\n; a comment\nDataType=0x0007\nAccessType=rw\n"),
    ("DIA007", var("0x0007", name="Current [uA]")),
    ("DIA008", var("0x0007")),
    ("DIA008", var("0x0040")),  # undefined: EDS080
    ("DIA009", RECORD.replace("0x9", "0x8") + "\n".join(SUB.format(n=n, name="Value") for n in range(3))),
    ("DIA010", var("0x0006", "PDOMapping=0")),
    ("DIA011", "[DeviceInfo]\nVendorName=x\n"),
    ("DIA013", var("0x0007", "DefaultValue=1")),
    ("DIA014", var("0x0007", "DefaultValue=$NODEID+0x600", "LowLimit=0x601")),
    ("DIA015", var("0x0006", "PDOMapping=0")),
    ("DIA015", var("0x0006", "PDOMapping=2")),  # the reader's EDS030
    ("DIA016", var("0x0006", "ObjFlags=0x4")),  # reserved bits: EDS023
    ("DIA017", var("0x0006", name="Motor 1 speed")),
]
CODES = sorted({code for code, _, _ in FOUND})


test_finding_location, test_no_finding, test_rule_on_a_valid_file, test_rule_documented = table_tests(
    "portability", FOUND, CLEAN, CODES
)


@pytest.mark.parametrize("code", CODES)
def test_portability_is_an_error_only_where_a_peer_cannot_load_the_file(code: str) -> None:
    rule = RULES[code]
    assert rule.severity.value in ("warning", "info") or rule.placed.clause is Clause.PEER_CANNOT_LOAD


def test_messages() -> None:
    assert messages("[DummyUsage]\nDummy0007=1\n", "DIA001") == [
        "[DummyUsage] lacks Dummy0001, Dummy0002, Dummy0003, Dummy0004, Dummy0005, Dummy0006; "
        "python-canopen fails to load the file"
    ]
    assert messages(LELY + var("0x0008", "DefaultValue=0x3FC00000", "HighLimit=0x40200000"), "DIA003") == [
        "2 REAL values in lely's bit-pattern form; python-canopen drops them, CANopenNode misreads them"
    ]
    text = var("0x0006", name="A #1") + var("0x0006", name="B;2").replace("2000", "2001")
    assert messages(text, "DIA017") == [
        "2 text values with '#' or ';' ([2000] ParameterName, [2001] ParameterName); lely cuts them there"
    ]


def test_compact_record_names() -> None:
    """Names given by [xxxxName] to CompactSubObj sub-objects are reported at the object."""
    record = RECORD.replace("SubNumber=3", "DataType=0x0007\nAccessType=rw\nCompactSubObj=2")
    text = record + "[2000Name]\nNrOfEntries=2\n1=Same\n2=Same\n"
    assert findings(text, "DIA009") == [(1, 1)]


def test_key_spelling_that_python_canopen_misses() -> None:
    text = "[DeviceInfo]\nVendorName=x\nNrOfRxPDO=4\nBaudrate_500=1\n[1017]\nParameterName=Heartbeat\nDatatype=0x0006\n"
    assert findings(text, "DIA018") == [(3, 1), (4, 1), (7, 1)]
    assert (
        messages(text, "DIA018")[0]
        == "NrOfRxPDO: CiA 306 spells it NrOfRXPDO; python-canopen reads keys case-sensitively"
    )
    assert (
        findings(
            text.replace("NrOfRxPDO", "NrOfRXPDO").replace("Baudrate_", "BaudRate_").replace("Datatype", "DataType"),
            "DIA018",
        )
        == []
    )
