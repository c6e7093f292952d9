"""Identity rules (cantools_od/lint/identity.py): mandatory objects, [DeviceInfo] against the dictionary."""

from __future__ import annotations

import pytest
from lintkit import BASE, diff, findings, fix, line_of, messages, replace, run

from cantools_od.lint.rules import RULES

CODES = ("EDS011", "EDS040", "EDS041", "EDS042", "EDS043", "EDS044", "EDS045", "EDS046")
SUB4 = "[1018sub4]\nParameterName=Serial number\nDataType=0x0007\nAccessType=ro\n"
MAPPING = (
    "\n[1A00]\nParameterName=TPDO1 mapping\nObjectType=0x9\nSubNumber=1\n\n"
    "[1A00sub0]\nParameterName=Number of mapped objects\nDataType=0x0005\nAccessType={access}\nDefaultValue=0\n"
)


def base(old: str, new: str) -> str:
    return replace(BASE, old, new)


def at(text: str, needle: str, column: int) -> list[tuple[int, int]]:
    return [(line_of(text, needle), column)]


def test_mandatory_objects_missing() -> None:
    text = "[MandatoryObjects]\nSupportedObjects=2\n1=0x1000\n2=0x1001\n"
    assert findings(text, "EDS011") == [(1, 1), (1, 1), (1, 1)]
    assert messages(text, "EDS011") == [
        "mandatory object 1000h (device type) is missing",
        "mandatory object 1001h (error register) is missing",
        "mandatory object 1018h (identity object) is missing",
    ]
    assert findings("[FileInfo]\nFileName=t.eds\n\n[DeviceInfo]\nVendorName=x\n", "EDS011") == [(1, 1)] * 3
    text = base("[1001]\nParameterName=Error register", "[1002]\nParameterName=Error register")
    assert findings(text, "EDS011") == [(line_of(text, "[MandatoryObjects]"), 1)]


def test_identity_mismatch_and_fix() -> None:
    text = base("RevisionNumber=0x00010000", "RevisionNumber=0")
    assert findings(text, "EDS040") == at(text, "RevisionNumber=0", 16)
    assert messages(text, "EDS040") == ["RevisionNumber=0x00000000 but 1018h sub3 DefaultValue=0x00010000"]
    # from an EDS's DefaultValue, maybe a template's placeholder: unsafe
    assert [f.fix.safe for f in run(text, "EDS040") if f.fix is not None] == [False]
    after = fix(text, "EDS040", safe_only=False)
    assert diff(text, after) == ["- RevisionNumber=0", "+ RevisionNumber=0x00010000"]
    assert findings(after, "EDS040") == []


def _dcf(product: str, default: str, value: str) -> str:
    """A DCF (python-canopen__e35-like shape): [DeviceInfo] ProductNumber, and 1018h sub2's template DefaultValue
    and the configured device's ParameterValue."""
    text = base("ProductNumber=0x00000001", f"ProductNumber={product}")
    section = text.index("[1018sub2]")
    start = text.index("DefaultValue=", section)
    end = text.index("\n", start)
    return text[:start] + f"DefaultValue={default}\nParameterValue={value}" + text[end:]


def test_identity_takes_a_dcfs_parameter_value_as_the_truth() -> None:
    # [DeviceInfo] agrees with the device's ParameterValue but not with the template's DefaultValue: no finding,
    # and above all no fix that writes the template over the device's number
    text = _dcf("0x30030209", "0x0101503C", "0x30030209")
    assert findings(text, "EDS040") == []
    # [DeviceInfo] differs from the ParameterValue: the fix writes the ParameterValue, safely
    text = _dcf("0x0101503C", "0x0101503C", "0x30030209")
    assert messages(text, "EDS040") == ["ProductNumber=0x0101503C but 1018h sub2 ParameterValue=0x30030209"]
    after = fix(text, "EDS040")
    assert diff(text, after) == ["- ProductNumber=0x0101503C", "+ ProductNumber=0x30030209"]


def test_identity_all_three() -> None:
    text = base(
        "VendorNumber=0x0000ABCD\nProductName=Demo\nProductNumber=0x00000001", "VendorNumber=1\nProductNumber=2"
    )
    assert findings(text, "EDS040") == at(text, "VendorNumber=1", 14) + at(text, "ProductNumber=2", 15)


@pytest.mark.parametrize(
    "text",
    [
        BASE,
        base("RevisionNumber=0x00010000\n", ""),  # one side missing
        base("DefaultValue=0x00010000", "DefaultValue=$NODEID"),  # not a plain number
    ],
)
def test_identity_clean(text: str) -> None:
    assert findings(text, "EDS040") == []


def test_serial_number() -> None:
    dcf = "[DeviceComissioning]\nNodeID=5\nLSS_SerialNumber=0x17\n\n[1018]\nParameterName=Identity\nObjectType=0x9\n"
    assert findings(dcf + SUB4 + "ParameterValue=0x18\n", "EDS045", "t.dcf") == [(3, 18)]
    assert findings(dcf + SUB4 + "DefaultValue=0x18\n", "EDS045", "t.dcf") == []  # the EDS default, not this device
    assert findings(dcf + SUB4 + "ParameterValue=0x17\n", "EDS045", "t.dcf") == []
    assert findings(dcf + SUB4 + "DefaultValue=0\n", "EDS045", "t.dcf") == []  # not configured
    assert findings(dcf.replace("0x17", "0") + SUB4 + "DefaultValue=5\n", "EDS045", "t.dcf") == []


def test_pdo_counts() -> None:
    text = base("NrOfRXPDO=0", "NrOfRXPDO=1")
    assert findings(text, "EDS041") == at(text, "NrOfRXPDO=1", 11)
    assert messages(text, "EDS041") == ["NrOfRXPDO=1 but 0 RPDO communication objects"]
    found = run(text, "EDS041")
    assert found[0].fix is not None and not found[0].fix.safe
    after = fix(text, "EDS041", safe_only=False)
    assert diff(text, after) == ["- NrOfRXPDO=1", "+ NrOfRXPDO=0"]


def test_pdo_counts_include_compact_pdo() -> None:
    text = base("NrOfTXPDO=0", "NrOfTXPDO=2\nCompactPDO=0x01")
    assert findings(text, "EDS041") == []
    assert findings(BASE, "EDS041") == []


def test_static_mapping() -> None:
    text = base("Granularity=8", "Granularity=0") + MAPPING.format(access="rw")
    assert findings(text, "EDS042") == at(text, "Granularity=0", 13)
    assert messages(text, "EDS042") == ["Granularity=0 (static mapping) but mapping objects are writable: 1A00h"]
    assert findings(base("Granularity=8", "Granularity=0") + MAPPING.format(access="ro"), "EDS042") == []
    assert findings(BASE + MAPPING.format(access="rw"), "EDS042") == []


def test_granularity_range() -> None:
    text = base("Granularity=8", "Granularity=65")
    assert findings(text, "EDS046") == at(text, "Granularity=65", 13)
    assert findings(base("Granularity=8", "Granularity=64"), "EDS046") == []


def test_commissioned_rate() -> None:
    text = BASE + "\n[DeviceComissioning]\nNodeID=5\nBaudrate=800\n"
    assert findings(text, "EDS043", "t.dcf") == at(text, "Baudrate=800", 10)
    assert messages(text, "EDS043", "t.dcf") == ["Baudrate=800 kbit/s is not a supported rate (125, 250, 500, 1000)"]
    assert findings(text.replace("Baudrate=800", "Baudrate=500"), "EDS043", "t.dcf") == []


def test_no_rates() -> None:
    assert findings("[DeviceInfo]\nVendorName=x\nBaudRate_500=0\n", "EDS044") == [(1, 1)]
    assert findings("[FileInfo]\nFileName=t.eds\n", "EDS044") == []  # no [DeviceInfo]: EDS009


@pytest.mark.parametrize("code", CODES)
def test_rule_on_a_valid_file(code: str) -> None:
    assert findings(BASE, code) == []


@pytest.mark.parametrize("code", CODES)
def test_rule_documented(code: str) -> None:
    rule = RULES[code]
    assert rule.family == "identity" and rule.summary and rule.description and rule.example
