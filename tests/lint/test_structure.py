"""Structure rules (cantools_od/lint/structure.py): lines, sections, keys, objects, DCF and module sections."""

from __future__ import annotations

from pathlib import Path

import pytest
from lintkit import BASE, FAMILIES, diff, findings, fix, line_of, messages, replace, run

from cantools_od import load
from cantools_od.lint import lint
from cantools_od.lint.rules import RULES
from cantools_od.model import Severity

from support import EXAMPLES, corpus_params

VAR = "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\n"
RECORD = "[2000]\nParameterName=Record\nObjectType=0x9\nSubNumber=2\n"
SUB0 = "[2000sub0]\nParameterName=Highest sub-index\nDataType=0x0005\nAccessType=ro\nDefaultValue=1\n"
SUB1 = "[2000sub1]\nParameterName=Value\nDataType=0x0006\nAccessType=rw\n"
COMPACT = "[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=2\n"
DCF_NODE = "[DeviceComissioning]\nNodeID=5\n"

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
    ("EDS020", "[2000]\nParameterName=Speed\nDataType=0x0006\n", "t.eds", [(1, 1)]),
    ("EDS020", "[2000]\nParameterName=\nDataType=0x0006\nAccessType=rw\n", "t.eds", [(2, 1)]),
    ("EDS020", "[2000]\nParameterName=Record\nObjectType=0x9\n\n" + SUB0, "t.eds", [(1, 1)]),
    ("EDS020", RECORD + "\n" + SUB0 + "\n[2000sub1]\nParameterName=Value\nAccessType=rw\n", "t.eds", [(12, 1)]),
    ("EDS020", "[2000]\nParameterName=Inputs\nObjectType=0x8\nCompactSubObj=2\n", "t.eds", [(1, 1), (1, 1)]),
    ("EDS024", RECORD + "AccessType=ro\n\n" + SUB0 + "\n" + SUB1, "t.eds", [(5, 1)]),
    ("EDS024", VAR + "SubNumber=1\n", "t.eds", [(5, 1)]),
    ("EDS024", RECORD + "\n" + SUB0 + "SubNumber=1\n\n" + SUB1, "t.eds", [(11, 1)]),
    ("EDS024", "[2000]\nParameterName=Blob\nObjectType=0x2\nPDOMapping=1\nLowLimit=0\n", "t.eds", [(4, 1), (5, 1)]),
    ("EDS021", RECORD.replace("SubNumber=2", "SubNumber=3") + "\n" + SUB0 + "\n" + SUB1, "t.eds", [(4, 11)]),
    ("EDS022", VAR + "CompactSubObj=2\n", "t.eds", [(5, 1)]),
    ("EDS022", COMPACT + "SubNumber=3\n", "t.eds", [(7, 1)]),
    ("EDS022", COMPACT.replace("=2", "=255"), "t.eds", [(6, 15)]),
    ("EDS022", COMPACT + "\n" + SUB1, "t.eds", [(8, 1)]),
    ("EDS023", VAR + "ObjFlags=0x4\n", "t.eds", [(5, 10)]),
    ("EDS023", RECORD + "\n" + SUB0 + "ObjFlags=0x80000001\n\n" + SUB1, "t.eds", [(11, 10)]),
    ("EDS025", RECORD.replace("=2", "=1") + "\n" + SUB1, "t.eds", [(1, 1)]),
    ("EDS025", RECORD + "\n" + SUB0.replace("0x0005", "0x0007") + "\n" + SUB1, "t.eds", [(8, 10)]),
    ("EDS026", RECORD + "\n" + SUB0.replace("=1\n", "=0\n") + "\n" + SUB1, "t.eds", [(10, 14)]),
    (
        "EDS027",
        RECORD.replace("=2", "=3") + "\n" + SUB0 + "\n" + SUB1 + "\n" + SUB1.replace("sub1", "subFF"),
        "t.eds",
        [(17, 1)],
    ),
    (
        "EDS028",
        RECORD.replace("0x9", "0x8").replace("=2", "=3")
        + "\n"
        + SUB0.replace("=1\n", "=2\n")
        + "\n"
        + SUB1
        + "\n"
        + SUB1.replace("sub1", "sub2").replace("0x0006", "0x0007"),
        "t.eds",
        [(19, 10)],
    ),
    ("EDS080", "[2000]\nParameterName=Gain\nDataType=0x0040\nAccessType=rw\n", "t.eds", [(3, 10)]),
    ("EDS080", "[2000]\nParameterName=Gain\nDataType=0x000E\nAccessType=rw\n", "t.eds", [(3, 10)]),
    ("EDS081", "[2000]\nParameterName=Type\nObjectType=0x5\nDataType=0x0007\nAccessType=ro\n", "t.eds", [(3, 1)]),
    ("EDS081", "[0040]\nParameterName=Not a type\nDataType=0x0007\nAccessType=ro\n", "t.eds", [(1, 1)]),
    (
        "EDS050",
        DCF_NODE + "[1F50]\nParameterName=P\nObjectType=0x2\nAccessType=rw\nDownloadFile=f.bin\n",
        "t.dcf",
        [(7, 1)],
    ),
    ("EDS050", DCF_NODE + "[1F50]\nParameterName=P\nObjectType=0x2\nUploadFile=f.bin\n", "t.dcf", [(6, 1)]),
    ("EDS051", DCF_NODE + VAR.replace("rw", "ro") + "UploadFile=speed.bin\n", "t.dcf", [(7, 1)]),
    ("EDS052", VAR + "ParameterValue=5\nDenotation=Left\n", "t.eds", [(5, 1), (6, 1)]),
    ("EDS052", "[FileInfo]\nLastEDS=device.eds\n", "t.eds", [(2, 1)]),
    ("EDS060", VAR, "t.dcf", [(1, 1)]),
    ("EDS060", "[DeviceComissioning]\nNodeName=Drive\n", "t.dcf", [(1, 1)]),
    ("EDS062", "[DeviceComissioning]\nNodeID=128\n", "t.dcf", [(2, 8)]),
    ("EDS062", "[DeviceComissioning]\nNodeID=0\n", "t.dcf", [(2, 8)]),
    ("EDS063", "[DeviceComissioning]\nNodeID=0xFF\n", "t.dcf", [(2, 8)]),
    ("EDS070", "[SupportedModules]\nNrOfEntries=2\n\n[M1ModuleInfo]\nProductName=A\n", "t.eds", [(1, 1)]),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M2ModuleInfo]\nProductName=B\n",
        "t.eds",
        [(5, 1)],
    ),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M1FixedObjects]\nNrOfEntries=2\n"
        "1=0x6000\n[M1Fixed6000]\nParameterName=X\n",
        "t.eds",
        [(6, 1)],
    ),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M1SubExtends]\nNrOfEntries=1\n1=0x6000\n",
        "t.eds",
        [(7, 1)],
    ),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[ConnectedModules]\nNrOfEntries=2\n"
        "1=1\n2=2\n",
        "t.dcf",
        [(8, 1)],
    ),
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
    ("EDS020", "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=RWX\n", "t.eds"),  # the reader's EDS030
    ("EDS020", "[2000]\nParameterName=Blob\nObjectType=0x2\n", "t.eds"),
    ("EDS024", COMPACT + "LowLimit=0\nHighLimit=9\nDefaultValue=1\n", "t.eds"),
    ("EDS021", COMPACT + "SubNumber=0\n", "t.eds"),
    ("EDS022", COMPACT + "SubNumber=0\n", "t.eds"),
    ("EDS022", VAR + "CompactSubObj=0\n", "t.eds"),
    ("EDS023", VAR + "ObjFlags=0x3\n", "t.eds"),
    ("EDS025", COMPACT, "t.eds"),
    (
        "EDS026",
        "[1003]\nParameterName=Errors\nObjectType=0x8\nSubNumber=2\n\n"
        + SUB0.replace("2000", "1003").replace("=1\n", "=0\n")
        + "\n"
        + SUB1.replace("2000", "1003"),
        "t.eds",
    ),
    ("EDS026", RECORD + "\n" + SUB0.replace("=1\n", "=0\n").replace("=ro", "=rw") + "\n" + SUB1, "t.eds"),
    (
        "EDS026",
        "[1A00]\nParameterName=Map\nObjectType=0x9\nSubNumber=2\n\n"
        + SUB0.replace("2000", "1A00").replace("=1\n", "=0\n")
        + "\n"
        + SUB1.replace("2000", "1A00"),
        "t.eds",
    ),
    (
        "EDS026",
        "[1010]\nParameterName=Store\nObjectType=0x8\nSubNumber=2\n\n"
        + SUB0.replace("2000", "1010").replace("=1\n", "=4\n")
        + "\n"
        + SUB1.replace("2000", "1010sub4").replace("sub4sub1", "sub4"),
        "t.eds",
    ),
    (
        "EDS028",
        RECORD + "\n" + SUB0 + "\n" + SUB1 + "\n" + SUB1.replace("sub1", "sub2").replace("0x0006", "0x07"),
        "t.eds",
    ),
    (
        "EDS080",
        "[0040]\nParameterName=T\nObjectType=0x5\nDataType=0x0007\nAccessType=ro\n"
        "[2000]\nParameterName=Gain\nDataType=0x0040\nAccessType=rw\n",
        "t.eds",
    ),
    ("EDS081", "[0040]\nParameterName=T\nObjectType=0x5\nDataType=0x0007\nAccessType=ro\n", "t.eds"),
    ("EDS050", DCF_NODE + "[1F50]\nParameterName=P\nObjectType=0x2\nAccessType=wo\nDownloadFile=f.bin\n", "t.dcf"),
    ("EDS051", DCF_NODE + "[2000]\nParameterName=P\nDataType=0x000F\nAccessType=ro\nUploadFile=f.bin\n", "t.dcf"),
    ("EDS050", DCF_NODE + VAR + "UploadFile=speed.bin\n", "t.dcf"),  # not a DOMAIN: EDS051
    ("EDS052", DCF_NODE + VAR + "ParameterValue=5\n", "t.dcf"),
    ("EDS060", DCF_NODE + VAR, "t.dcf"),
    ("EDS060", VAR, "t.eds"),
    ("EDS062", "[DeviceComissioning]\nNodeID=127\n", "t.dcf"),
    ("EDS062", "[DeviceComissioning]\nNodeID=255\n", "t.dcf"),
    ("EDS063", "[DeviceComissioning]\nNodeID=0x7F\n", "t.dcf"),
    (
        "EDS070",
        "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=A\n[M1FixedObjects]\nNrOfEntries=1\n"
        "1=0x6000\n[M1Fixed6000]\nParameterName=X\n[ConnectedModules]\nNrOfEntries=1\n1=1\n",
        "t.dcf",
    ),
]
CODES = sorted({code for code, *_ in FOUND})


@pytest.mark.parametrize(("code", "text", "source", "expected"), FOUND)
def test_finding_location(code: str, text: str, source: str, expected: list[tuple[int, int]]) -> None:
    assert findings(text, code, source) == expected


@pytest.mark.parametrize(("code", "text", "source"), CLEAN)
def test_no_finding(code: str, text: str, source: str) -> None:
    assert findings(text, code, source) == []


@pytest.mark.parametrize("code", CODES)
def test_rule_on_a_valid_file(code: str) -> None:
    assert findings(BASE, code) == []


@pytest.mark.parametrize("code", CODES)
def test_rule_documented(code: str) -> None:
    rule = RULES[code]
    assert rule.family == "structure" and rule.summary and rule.description and rule.example


def test_messages() -> None:
    assert messages("[DeviceInfo]\nBaudrate_100=1\n", "EDS003") == [
        "[DeviceInfo] Baudrate_100: not a CiA 306 key of this section; did you mean BaudRate_1000 or BaudRate_10?"
    ]
    assert messages("[DeviceInfos]\nX=1\n", "EDS004") == [
        "[DeviceInfos]: not a CiA 306 section; did you mean DeviceInfo?"
    ]
    assert messages("[2000]\nParameterName=\nDataType=0x0006\n", "EDS020") == [
        "[2000]: no AccessType; VAR needs it",  # at the header: line 1
        "[2000]: ParameterName is empty; VAR needs it",
    ]
    assert messages("[DeviceComissioning]\nNodeID=0xFF\n", "EDS063") == ["NodeID=255: node-ID not configured"]


def test_severities() -> None:
    assert run("[FileInfo]\nFileName=t.eds\n", "EDS007")[0].severity.value == "info"
    assert run("[FileInfo]\nEDSVersion=4.2\n", "EDS008")[0].severity.value == "warning"
    assert run(VAR + "ObjFlags=0x4\n", "EDS023")[0].severity.value == "error"


def test_sub_number_fix() -> None:
    text = replace(BASE, "SubNumber=4", "SubNumber=5")
    after = fix(text, "EDS021")
    assert diff(text, after) == ["- SubNumber=5", "+ SubNumber=4"]
    assert findings(after, "EDS021") == []


def test_sub0_fix() -> None:
    text = replace(BASE, "AccessType=ro\nDefaultValue=3", "AccessType=ro\nDefaultValue=1")
    line = line_of(text, "DefaultValue=1")
    assert findings(text, "EDS026") == [(line, 14)]
    after = fix(text, "EDS026")
    assert diff(text, after) == ["- DefaultValue=1", "+ DefaultValue=0x03"]  # the writer's UNSIGNED8 form
    assert after.splitlines()[line - 1] == "DefaultValue=0x03"
    assert findings(after, "EDS026") == []


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


def test_obligation_follows_compact_sub_obj() -> None:
    """CompactSubObj turns an ARRAY's keys from forbidden to mandatory (cia306.md §7.3)."""
    assert findings(COMPACT, "EDS024") == [] and findings(COMPACT, "EDS020") == []
    plain = COMPACT.replace("CompactSubObj=2\n", "SubNumber=1\n") + "\n" + SUB0.replace("=1\n", "=0\n")
    assert findings(plain, "EDS024") == [(4, 1), (5, 1)]


def test_sub_index_ff_not_counted() -> None:
    text = RECORD + "\n" + SUB0 + "\n" + SUB1 + "\n" + SUB1.replace("sub1", "subFF")
    assert findings(text, "EDS021") == []
    assert findings(text, "EDS026") == []


def test_implicit_pdo_objects_are_not_checked() -> None:
    """CompactPDO creates objects that have no section: no structure rule looks at them."""
    text = replace(BASE, "NrOfRXPDO=0", "NrOfRXPDO=1\nCompactPDO=0x3")
    assert [f.code for f in run(text, "EDS020") + run(text, "EDS025") + run(text, "EDS021")] == []


# ---- whole files: the five families (structure, objlists, values, identity, portability) together ---------------

OURS = {code for code, rule in RULES.items() if rule.family in FAMILIES}


@pytest.mark.parametrize("name", ["io_device.eds", "cia402_drive.eds"])
def test_example_files_have_no_errors_or_warnings(name: str) -> None:
    found = [f.format() for f in lint(load(EXAMPLES / name)) if f.code in OURS and f.severity is not Severity.INFO]
    assert found == []


@pytest.mark.parametrize("path", corpus_params())
def test_no_rule_fails_on_the_corpus(path: Path) -> None:
    failures = [f.message for f in lint(load(path)) if f.code == "LNT001"]
    assert [m for m in failures if any(f"rule {code} " in m for code in OURS)] == []
