"""Object-list rules (cantools_od/lint/objlists.py): presence, placement, counting, numbering, fixes."""

from __future__ import annotations

from lintkit import BASE, device, diff, findings, fix, line_of, messages, replace, run, table_tests

from cantools_od.lint import lint
from cantools_od.lint.rules import RULES

MANUFACTURER = "[ManufacturerObjects]\nSupportedObjects=2\n1=0x2000\n2=0x2001\n"
OBJECT_2002 = "\n[2002]\nParameterName=Extra\nDataType=0x0005\nAccessType=ro\n"
VAR_1017 = "[1017]\nParameterName=Heartbeat\nDataType=0x0006\nAccessType=rw\n"
CODES = ("EDS010", "EDS012", "EDS013", "EDS014", "EDS015", "EDS016", "EDS017", "EDS018", "EDS019")


def base_with(old: str, new: str) -> str:
    return replace(BASE, old, new)


# (code, text, expected (line, column) of each finding)
FOUND = [
    ("EDS010", "[OptionalObjects]\nSupportedObjects=1\n1=0x6505\n", [(3, 3)]),
    ("EDS012", "[OptionalObjects]\nSupportedObjects=0\n\n" + VAR_1017, [(4, 1)]),
    ("EDS013", "[MandatoryObjects]\nSupportedObjects=1\n1=0x1017\n" + VAR_1017, [(3, 3)]),
    ("EDS013", "[OptionalObjects]\nSupportedObjects=1\n1=0x1018\n", [(3, 3)]),
    ("EDS017", "[OptionalObjects]\nSupportedObjects=1\n1=0x2000\n", [(3, 3)]),
    ("EDS017", "[ManufacturerObjects]\nSupportedObjects=1\n1=0x7001\n", [(3, 3)]),
    ("EDS017", "[OptionalObjects]\nSupportedObjects=1\n1=0xC000\n", [(3, 3)]),
    ("EDS018", "[OptionalObjects]\nSupportedObjects=1\n1=0x0040\n", [(3, 3)]),
    ("EDS016", "[OptionalObjects]\nSupportedObjects=2\n1=0x1017\n2=0x1017\n", [(4, 3)]),
    ("EDS016", "[OptionalObjects]\nSupportedObjects=1\n1=0x2000\n" + MANUFACTURER, [(3, 3)]),
    ("EDS014", "[OptionalObjects]\nSupportedObjects=3\n1=0x1017\n", [(2, 18)]),
    ("EDS014", "[OptionalObjects]\n1=0x1017\n", [(1, 1)]),
    ("EDS015", "[OptionalObjects]\nSupportedObjects=2\n1=0x1017\n3=0x1005\n", [(1, 1)]),
    ("EDS015", "[OptionalObjects]\nSupportedObjects=1\n01=0x1017\n", [(3, 1)]),
    ("EDS019", "[FileInfo]\nFileName=t.eds\n", [(1, 1), (1, 1), (1, 1)]),
]

CLEAN = [
    ("EDS010", "[OptionalObjects]\nSupportedObjects=1\n1=0x1400\n[DeviceInfo]\nNrOfRXPDO=1\nCompactPDO=0x01\n"),
    ("EDS012", "[DeviceInfo]\nNrOfRXPDO=1\nCompactPDO=0x01\n[OptionalObjects]\nSupportedObjects=0\n"),
    ("EDS012", "[0040]\nParameterName=T\nObjectType=0x5\nDataType=0x0007\nAccessType=ro\n"),
    ("EDS013", "[OptionalObjects]\nSupportedObjects=1\n1=0x0040\n"),  # EDS018's case
    ("EDS010", "[MandatoryObjects]\nSupportedObjects=1\n1=0x1018\n"),  # a missing 1018h: EDS011
    ("EDS017", "[OptionalObjects]\nSupportedObjects=1\n1=0x2000\n" + MANUFACTURER),  # EDS016's case
    (
        "EDS017",
        "[OptionalObjects]\nSupportedObjects=1\n1=0x6000\n[ManufacturerObjects]\nSupportedObjects=1\n1=0x5FFF\n",
    ),
    ("EDS016", "[OptionalObjects]\nSupportedObjects=2\n1=0x1017\n2=0x1016\n"),
    ("EDS014", "[OptionalObjects]\nSupportedObjects=0\n"),
    ("EDS014", "[OptionalObjects]\nSupportedObjects=x\n"),  # the reader's EDS030
    ("EDS015", "[OptionalObjects]\nSupportedObjects=1\n1=0x1017\n"),
    ("EDS015", "[OptionalObjects]\nSupportedObjects=1\n1=next\n"),  # the reader's EDS030
    ("EDS015", "[OptionalObjects]\nSupported Objects=1\n1=0x1017\n"),
]


test_finding_location, test_no_finding, test_rule_on_a_valid_file, test_rule_documented = table_tests(
    "objlists", FOUND, CLEAN, CODES
)


def test_severities() -> None:
    severities = {code: RULES[code].severity.value for code in CODES}
    assert severities == {
        **{code: "error" for code in ("EDS010", "EDS012", "EDS013", "EDS014", "EDS015", "EDS019")},
        **{code: "warning" for code in ("EDS016", "EDS017", "EDS018")},
    }


def test_messages() -> None:
    assert messages("[OptionalObjects]\nSupportedObjects=1\n1=0x6505\n", "EDS010") == [
        "[OptionalObjects] 1=0x6505: no [6505] section"
    ]
    assert messages("[ManufacturerObjects]\nSupportedObjects=0\n\n[2000]\nParameterName=x\n", "EDS012") == [
        "[2000] is in no object list; it belongs in [ManufacturerObjects]"
    ]
    assert messages("[OptionalObjects]\nSupportedObjects=0\n1=0x1017\n", "EDS014") == [
        "[OptionalObjects]: SupportedObjects=0 but 1 entry"
    ]


def test_unlisted_fix_appends() -> None:
    text = BASE + OBJECT_2002
    assert findings(text, "EDS012") == [(line_of(text, "[2002]"), 1)]
    after = fix(text, "EDS012")
    assert diff(text, after) == ["- SupportedObjects=2", "+ SupportedObjects=3", "+ 3=0x2002"]
    assert line_of(after, "3=0x2002") == line_of(text, "2=0x2001") + 1
    assert findings(after, "EDS012") == [] and findings(after, "EDS014") == []


def test_unlisted_fix_creates_the_list() -> None:
    text = base_with(MANUFACTURER, "")
    after = fix(text, "EDS012")
    assert diff(text, after) == ["+ ", "+ [ManufacturerObjects]", "+ SupportedObjects=2", "+ 1=0x2000", "+ 2=0x2001"]
    assert [f.code for f in lint(device(after)) if f.code.startswith("EDS01")] == []


def test_missing_list_fix() -> None:
    text = base_with(MANUFACTURER, "")
    assert findings(text, "EDS019") == [(1, 1)]
    after = fix(text, "EDS019")
    assert diff(text, after) == ["+ ", "+ [ManufacturerObjects]", "+ SupportedObjects=0"]
    assert findings(after, "EDS019") == []
    assert len(findings(after, "EDS012")) == 2  # the objects are still to be listed


def test_count_fix() -> None:
    text = base_with("SupportedObjects=2\n1=0x2000", "SupportedObjects=5\n1=0x2000")
    assert findings(text, "EDS014") == [(line_of(text, "SupportedObjects=5"), 18)]
    after = fix(text, "EDS014")
    assert diff(text, after) == ["- SupportedObjects=5", "+ SupportedObjects=2"]
    assert findings(after, "EDS014") == []


def test_renumber_fix() -> None:
    text = base_with("2=0x2001", "4=0x2001")
    assert findings(text, "EDS015") == [(line_of(text, "[ManufacturerObjects]"), 1)]
    after = fix(text, "EDS015")
    assert diff(text, after) == ["- 4=0x2001", "+ 2=0x2001"]
    assert findings(after, "EDS015") == []


def test_duplicate_fix_keeps_the_right_list() -> None:
    text = base_with("SupportedObjects=1\n1=0x1017", "SupportedObjects=2\n1=0x2001\n2=0x1017")
    assert findings(text, "EDS016") == [(line_of(text, "1=0x2001"), 3)]
    assert messages(text, "EDS016") == ["[OptionalObjects] 1=0x2001: already listed in [ManufacturerObjects] as 2"]
    after = fix(text, "EDS016")
    assert diff(text, after) == [
        "- SupportedObjects=2",
        "+ SupportedObjects=1",
        "- 1=0x2001",
        "- 2=0x1017",
        "+ 1=0x1017",
    ]
    assert [f.code for f in lint(device(after)) if f.code.startswith("EDS01")] == []


def test_listed_absent_fix_is_unsafe() -> None:
    text = base_with("3=0x1018", "3=0x1018\n4=0x1002").replace("SupportedObjects=3", "SupportedObjects=4")
    found = run(text, "EDS010")
    assert [(f.location.line, f.location.column) for f in found] == [(line_of(text, "4=0x1002"), 3)]
    assert found[0].fix is not None and not found[0].fix.safe
    after = fix(text, "EDS010", safe_only=False)
    assert diff(text, after) == ["- SupportedObjects=4", "+ SupportedObjects=3", "- 4=0x1002"]


def test_wrong_list_fix_is_unsafe() -> None:
    text = base_with("1=0x1017\n", "1=0x1017\n2=0x2002\n").replace("SupportedObjects=1\n", "SupportedObjects=2\n")
    text += OBJECT_2002
    found = run(text, "EDS017")
    assert [f.fix is not None and not f.fix.safe for f in found] == [True]
    after = fix(text, "EDS017", safe_only=False)
    assert [f.code for f in lint(device(after)) if f.code.startswith("EDS01")] == []
