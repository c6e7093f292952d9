"""Small EDS texts and helpers for the tests of the CiA 306 structure, value, identity and portability rules.

Most tests lint a fragment (an object or two) and look only at the code under test; `BASE` is a
complete, valid EDS for the tests that need a whole file. Locations are (line, column), both from 1.
"""

from __future__ import annotations

import difflib
from collections.abc import Callable

import pytest

from cantools_od import dumps, loads
from cantools_od.lint import Finding, LintOptions, lint
from cantools_od.lint.rules import RULES
from cantools_od.model import Device

FAMILIES = ("syntax", "objects", "dcf", "objlists", "values", "identity", "portability")

BASE = """\
[FileInfo]
FileName=t.eds
FileVersion=1
FileRevision=0
EDSVersion=4.0
Description=Test device
CreationTime=09:00AM
CreationDate=01-31-2025
CreatedBy=tests
ModificationTime=09:30PM
ModificationDate=02-01-2025
ModifiedBy=tests

[DeviceInfo]
VendorName=Example
VendorNumber=0x0000ABCD
ProductName=Demo
ProductNumber=0x00000001
RevisionNumber=0x00010000
OrderCode=DEMO-1
BaudRate_10=0
BaudRate_20=0
BaudRate_50=0
BaudRate_125=1
BaudRate_250=1
BaudRate_500=1
BaudRate_800=0
BaudRate_1000=1
SimpleBootUpMaster=0
SimpleBootUpSlave=1
Granularity=8
DynamicChannelsSupported=0
GroupMessaging=0
NrOfRXPDO=0
NrOfTXPDO=0
LSS_Supported=0

[DummyUsage]
Dummy0001=0
Dummy0002=1
Dummy0003=1
Dummy0004=1
Dummy0005=1
Dummy0006=1
Dummy0007=1

[Comments]
Lines=2
Line1=First line
Line2=Second line

[MandatoryObjects]
SupportedObjects=3
1=0x1000
2=0x1001
3=0x1018

[OptionalObjects]
SupportedObjects=1
1=0x1017

[ManufacturerObjects]
SupportedObjects=2
1=0x2000
2=0x2001

[1000]
ParameterName=Device type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00000000
PDOMapping=0

[1001]
ParameterName=Error register
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=0
PDOMapping=1

[1017]
ParameterName=Producer heartbeat time
ObjectType=0x7
DataType=0x0006
AccessType=rw
DefaultValue=0
PDOMapping=0

[1018]
ParameterName=Identity object
ObjectType=0x9
SubNumber=4

[1018sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=3
PDOMapping=0

[1018sub1]
ParameterName=Vendor-ID
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x0000ABCD
PDOMapping=0

[1018sub2]
ParameterName=Product code
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00000001
PDOMapping=0

[1018sub3]
ParameterName=Revision number
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00010000
PDOMapping=0

[2000]
ParameterName=Speed
ObjectType=0x7
DataType=0x0006
AccessType=rw
DefaultValue=100
LowLimit=0
HighLimit=3000
PDOMapping=1

[2001]
ParameterName=Inputs
ObjectType=0x8
DataType=0x0005
AccessType=ro
DefaultValue=0
PDOMapping=1
CompactSubObj=4
"""


def device(text: str, source: str = "t.eds") -> Device:
    return loads(text.encode("utf-8"), source=source)


def run(text: str, code: str, source: str = "t.eds", node_id: int | None = None) -> list[Finding]:
    """The findings of one rule for a text."""
    return [f for f in lint(device(text, source), LintOptions(node_id=node_id)) if f.code == code]


def findings(text: str, code: str, source: str = "t.eds", node_id: int | None = None) -> list[tuple[int, int]]:
    """(line, column) of each finding of `code`."""
    return [(f.location.line, f.location.column) for f in run(text, code, source, node_id)]


def messages(text: str, code: str, source: str = "t.eds") -> list[str]:
    return [f.message for f in run(text, code, source)]


def family_findings(text: str, source: str = "t.eds") -> list[Finding]:
    """Every finding of the five families (not the reader's, PDO or COB-ID codes)."""
    return [f for f in lint(device(text, source)) if f.code in RULES and RULES[f.code].family in FAMILIES]


def line_of(text: str, needle: str, nth: int = 1) -> int:
    """The number of the nth line that contains `needle`."""
    hits = [number for number, line in enumerate(text.splitlines(), 1) if needle in line]
    return hits[nth - 1]


def replace(text: str, old: str, new: str) -> str:
    assert old in text, old
    return text.replace(old, new, 1)


def fix(text: str, code: str, source: str = "t.eds", safe_only: bool = True) -> str:
    """The text after applying the fixes of every `code` finding, written back in preserve style."""
    model = device(text, source)
    selected = [f for f in lint(model) if f.code == code and f.fix is not None and (f.fix.safe or not safe_only)]
    assert selected, f"no fixable {code} finding"
    for finding in selected:
        assert finding.fix is not None
        finding.fix.apply(model)
        finding.fix.apply(model)  # fixes are idempotent
    return dumps(model, "dcf" if model.is_dcf else "eds").decode("utf-8")


def diff(before: str, after: str) -> list[str]:
    """The changed lines: `-old` and `+new`, in order."""
    return [
        line
        for line in difflib.ndiff(before.splitlines(), after.splitlines())
        if line[:1] in "-+" and not line.startswith(("---", "+++"))
    ]


Found = list[tuple[str, str, str, list[tuple[int, int]]]]
Clean = list[tuple[str, str, str]]


def table_tests(family: str, found: Found, clean: Clean) -> tuple[Callable[..., None], ...]:
    """The four table-driven tests of a rule family, for its test module to bind at module level:
    each finding at its exact place, none on the clean variants, none on a valid file, and every
    rule documented in the family."""
    codes = sorted({code for code, *_ in found})

    @pytest.mark.parametrize(("code", "text", "source", "expected"), found)
    def test_finding_location(code: str, text: str, source: str, expected: list[tuple[int, int]]) -> None:
        assert findings(text, code, source) == expected

    @pytest.mark.parametrize(("code", "text", "source"), clean)
    def test_no_finding(code: str, text: str, source: str) -> None:
        assert findings(text, code, source) == []

    @pytest.mark.parametrize("code", codes)
    def test_rule_on_a_valid_file(code: str) -> None:
        assert findings(BASE, code) == []

    @pytest.mark.parametrize("code", codes)
    def test_rule_documented(code: str) -> None:
        rule = RULES[code]
        assert rule.family == family and rule.summary and rule.description and rule.example

    return test_finding_location, test_no_finding, test_rule_on_a_valid_file, test_rule_documented
