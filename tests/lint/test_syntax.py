"""Syntax rules (cantools_od/lint/syntax.py): lines, sections, keys, dates, EDSVersion and [Comments]."""

from __future__ import annotations

from pathlib import Path

import pytest
from lintkit import BASE, FAMILIES, diff, findings, fix, line_of, messages, replace, run, table_tests

from cantools_od import load
from cantools_od.lint import lint
from cantools_od.lint.rules import RULES
from cantools_od.model import Severity

from support import EXAMPLES, corpus_params

VAR = "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\n"
COMPACT = "[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=2\n"

# (code, text, source, expected (line, column) of each finding)
FOUND = [
    ("EDS001", "[2000]\nParameterName=" + "x" * 290 + "\n", "t.eds", [(2, 256)]),
    ("EDS003", "[DeviceInfo]\nVendorName=Example\nBaudrate_100=1\n", "t.eds", [(3, 1)]),
    ("EDS003", VAR + "ParamterName=Speed\n", "t.eds", [(5, 1)]),
    ("EDS004", "[FileInfo]\nFileName=t.eds\n\n[DeviceInfos]\nVendorName=Example\n", "t.eds", [(4, 1)]),
    ("EDS004", "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M1Foo]\nX=1\n", "t.eds", [(5, 1)]),
    ("EDS005", COMPACT + "[2000Name]\nNrOfEntries=1\n1=" + "n" * 242 + "\n", "t.eds", [(1, 1)]),
    ("EDS006", "[FileInfo]\nCreationDate=2024-02-27\nCreationTime=17:24\n", "t.eds", [(2, 14), (3, 14)]),
    ("EDS006", "[FileInfo]\nModificationTime=9:05AM\nModificationDate=1-5-2024\n", "t.eds", [(2, 18), (3, 18)]),
    ("EDS007", "[FileInfo]\nFileName=t.eds\n", "t.eds", [(1, 1)]),
    ("EDS008", "[FileInfo]\nEDSVersion=4.2\n", "t.eds", [(2, 12)]),
    ("EDS009", "[FileInfo]\nFileName=t.eds\n", "t.eds", [(1, 1), (1, 1)]),
    ("EDS090", "[Comments]\nLines=3\nLine1=a\nLine2=b\n", "t.eds", [(2, 7)]),
    ("EDS090", "[Comments]\nLines=2\nLine1=a\nLine3=b\n", "t.eds", [(1, 1)]),
]

# (code, text, source): valid input without a finding of that code
CLEAN = [
    ("EDS001", "[2000]\nParameterName=" + "x" * 241 + "\n", "t.eds"),
    ("EDS003", "[DeviceInfo]\nProductVersion=1\nLMT_ProductName=x\nBaudRate_500=1\n", "t.eds"),
    ("EDS003", VAR + "Unit=rpm\nFactor=0.1\n", "t.eds"),
    ("EDS003", "[Comments]\nLines=1\nLine1=x\n[DummyUsage]\nDummy0007=1\n", "t.eds"),
    ("EDS004", "[Tools]\nItems=0\n[Tool1]\nName=x\n[DynamicChannels]\nNrOfSeg=0\n", "t.eds"),
    ("EDS004", "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M1Fixed6000sub1]\nX=1\n", "t.eds"),
    ("EDS005", COMPACT + "[2000Name]\nNrOfEntries=1\n1=" + "n" * 241 + "\n", "t.eds"),
    ("EDS007", "[DeviceInfo]\nVendorName=x\n", "t.eds"),
    ("EDS009", "[FileInfo]\nFileName=t\n[DeviceInfo]\nVendorName=x\n[DummyUsage]\n", "t.eds"),
]
test_finding_location, test_no_finding, test_rule_on_a_valid_file, test_rule_documented = table_tests(
    "syntax", FOUND, CLEAN
)


def test_messages() -> None:
    assert messages("[DeviceInfo]\nBaudrate_100=1\n", "EDS003") == [
        "[DeviceInfo] Baudrate_100: not a CiA 306 key of this section; did you mean BaudRate_1000 or BaudRate_10?"
    ]
    # a file of this section alone is no device description (EDS000): another section makes it one
    assert messages("[FileInfo]\nFileName=t.eds\n[DeviceInfos]\nX=1\n", "EDS004") == [
        "[DeviceInfos]: not a CiA 306 section; did you mean DeviceInfo?"
    ]


def test_severities() -> None:
    assert run("[FileInfo]\nFileName=t.eds\n", "EDS007")[0].severity.value == "info"
    assert run("[FileInfo]\nEDSVersion=4.2\n", "EDS008")[0].severity.value == "warning"


def test_comment_count_fix() -> None:
    text = replace(BASE, "Lines=2", "Lines=5")
    assert findings(text, "EDS090") == [(line_of(text, "Lines=5"), 7)]
    after = fix(text, "EDS090")
    assert diff(text, after) == ["- Lines=5", "+ Lines=2"]
    assert findings(after, "EDS090") == []


def test_comment_gap_fix_is_unsafe() -> None:
    text = "[Comments]\nLines=3\nLine1=a\nLine3=b\n"
    found = run(text, "EDS090")
    assert [(f.location.line, f.fix is not None and f.fix.safe) for f in found] == [(1, False), (2, False)]


# ---- whole files: the seven families (syntax, objects, dcf, objlists, values, identity, portability) together --

OURS = {code for code, rule in RULES.items() if rule.family in FAMILIES}


@pytest.mark.parametrize("name", ["io_device.eds", "cia402_drive.eds"])
def test_example_files_have_no_errors_or_warnings(name: str) -> None:
    found = [f.format() for f in lint(load(EXAMPLES / name)) if f.code in OURS and f.severity is not Severity.INFO]
    assert found == []


@pytest.mark.parametrize("path", corpus_params())
def test_no_rule_fails_on_the_corpus(path: Path) -> None:
    failures = [f.message for f in lint(load(path)) if f.code == "LNT001"]
    assert [m for m in failures if any(f"rule {code} " in m for code in OURS)] == []
