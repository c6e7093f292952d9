"""Object rules (cantools_od/lint/objects.py): the obligation matrix, sub-objects, sub-index 0 and FFh, data types."""

from __future__ import annotations

from lintkit import BASE, diff, findings, fix, line_of, messages, replace, run, table_tests

VAR = "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\n"
RECORD = "[2000]\nParameterName=Record\nObjectType=0x9\nSubNumber=2\n"
SUB0 = "[2000sub0]\nParameterName=Highest sub-index\nDataType=0x0005\nAccessType=ro\nDefaultValue=1\n"
SUB1 = "[2000sub1]\nParameterName=Value\nDataType=0x0006\nAccessType=rw\n"
COMPACT = "[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=2\n"

# (code, text, source, expected (line, column) of each finding)
FOUND = [
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
]

# (code, text, source): valid input without a finding of that code
CLEAN = [
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
]
test_finding_location, test_no_finding, test_rule_on_a_valid_file, test_rule_documented = table_tests(
    "objects", FOUND, CLEAN
)


def test_messages() -> None:
    assert messages("[2000]\nParameterName=\nDataType=0x0006\n", "EDS020") == [
        "[2000]: no AccessType; VAR needs it",  # at the header: line 1
        "[2000]: ParameterName is empty; VAR needs it",
    ]


def test_severities() -> None:
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
    # unsafe: the default every reader reads changes (and a vendor's sub0 may count entries, not sub-indices)
    assert [f.fix.safe for f in run(text, "EDS026") if f.fix is not None] == [False]
    after = fix(text, "EDS026", safe_only=False)
    assert diff(text, after) == ["- DefaultValue=1", "+ DefaultValue=3"]  # decimal, as the line was written
    assert after.splitlines()[line - 1] == "DefaultValue=3"
    assert findings(after, "EDS026") == []


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
