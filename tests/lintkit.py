"""The lint test kit: small EDS texts, builders and the table-driven tests of every rule family.

Most tests lint a fragment (an object or two) and look only at the code under test; `BASE` is a
complete, valid EDS for the tests that need a whole file. Locations are (line, column), both from 1.
The PDO, COB-ID and network tests build their files with `eds()`, `comm()`, `mapping()`, `dcf()`
(below): a test writes only the objects it is about, `where()` finds a key's line.
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


Places = list[tuple[int, int]]
# A row: (code, text[, source[, node-ID]], expected places); a clean row the same without the places.
Found = list[tuple[object, ...]]
Clean = list[tuple[object, ...]]


def _found_row(row: tuple[object, ...]) -> tuple[str, str, str, int | None, Places]:
    code, text, *middle, expected = row
    source, node_id = (*middle, "t.eds", None)[:2] if middle else ("t.eds", None)
    return str(code), str(text), str(source), node_id, expected  # type: ignore[return-value]


def _clean_row(row: tuple[object, ...]) -> tuple[str, str, str, int | None]:
    code, text, *rest = row
    source, node_id = (*rest, "t.eds", None)[:2] if rest else ("t.eds", None)
    return str(code), str(text), str(source), node_id  # type: ignore[return-value]


def table_tests(
    family: str, found: Found, clean: Clean, codes: tuple[str, ...] | list[str] | None = None
) -> tuple[Callable[..., None], ...]:
    """The four table-driven tests of a rule family, for its test module to bind at module level:
    each finding at its exact place, none on the clean variants, none on a valid file, and every
    rule documented in the family. Rows give the source name and the node-ID when they matter
    (default `t.eds`, none); `codes` defaults to the codes of the found rows."""
    found_rows = [_found_row(row) for row in found]
    clean_rows = [_clean_row(row) for row in clean]
    codes = sorted(codes or {code for code, *_ in found_rows})

    @pytest.mark.parametrize(("code", "text", "source", "node_id", "expected"), found_rows)
    def test_finding_location(code: str, text: str, source: str, node_id: int | None, expected: Places) -> None:
        assert findings(text, code, source, node_id) == expected

    @pytest.mark.parametrize(("code", "text", "source", "node_id"), clean_rows)
    def test_no_finding(code: str, text: str, source: str, node_id: int | None) -> None:
        assert findings(text, code, source, node_id) == []

    @pytest.mark.parametrize("code", codes)
    def test_rule_on_a_valid_file(code: str) -> None:
        assert findings(BASE, code) == []

    @pytest.mark.parametrize("code", codes)
    def test_rule_documented(code: str) -> None:
        rule = RULES[code]
        assert rule.family == family and rule.summary and rule.description and rule.example

    return test_finding_location, test_no_finding, test_rule_on_a_valid_file, test_rule_documented


# --- PDO, COB-ID and network files ---------------------------------------------------------------------

VALUE_COLUMN = len("DefaultValue=") + 1


def section(name: str, **keys: object) -> str:
    lines = [f"[{name}]"] + [f"{key}={value}" for key, value in keys.items()]
    return "\n".join(lines) + "\n"


def var(
    index: int, name: str = "Object", dtype: int = 0x0006, access: str = "rw", mapping: int | None = 1, **extra: object
) -> str:
    """A VAR; `mapping=None` leaves PDOMapping out, `extra` adds keys (HighLimit=...)."""
    keys: dict[str, object] = {"ParameterName": name, "ObjectType": "0x7", "DataType": f"0x{dtype:04X}"}
    keys.update(AccessType=access, DefaultValue=0, **({} if mapping is None else {"PDOMapping": mapping}), **extra)
    return section(f"{index:04X}", **keys)


def sub(index: int, subindex: int, name: str, dtype: int, value: object, access: str = "rw", mapping: int = 0) -> str:
    return section(
        f"{index:04X}sub{subindex:X}",
        ParameterName=name,
        ObjectType="0x7",
        DataType=f"0x{dtype:04X}",
        AccessType=access,
        DefaultValue=value,
        PDOMapping=mapping,
    )


def record(
    index: int, name: str, subs: dict[int, tuple[str, int, object]], access: str = "rw", object_type: str = "0x9"
) -> str:
    """A RECORD with sub-objects {sub-index: (name, data type, default)}; sub0 is added when absent."""
    if 0 not in subs:
        subs = {0: ("Highest sub-index supported", 0x0005, max(subs, default=0)), **subs}
    text = section(f"{index:04X}", ParameterName=name, ObjectType=object_type, SubNumber=len(subs))
    for subindex, (sub_name, dtype, value) in sorted(subs.items()):
        text += "\n" + sub(index, subindex, sub_name, dtype, value, "ro" if subindex == 0 else access)
    return text


def comm(index: int, cob_id: str, tt: object = 255, *, object_type: object = "0x9", **extra: object) -> str:
    """A PDO communication record: COB-ID, transmission type and optional inhibit/timer/sync/sub0 values."""
    subs: dict[int, tuple[str, int, object]] = {1: ("COB-ID", 0x0007, cob_id), 2: ("Transmission type", 0x0005, tt)}
    for key, (subindex, dtype) in {"inhibit": (3, 0x0006), "timer": (5, 0x0006), "sync": (6, 0x0005)}.items():
        if key in extra:
            subs[subindex] = (key, dtype, extra[key])
    if "sub0" in extra:
        subs[0] = ("Highest sub-index supported", 0x0005, extra["sub0"])
    return record(index, f"PDO communication parameter {index:04X}", subs, object_type=str(object_type))


def mapping(
    index: int,
    *entries: str,
    count: object = None,
    object_type: str = "0x9",
    entry_type: int = 0x0007,
    count_access: str = "rw",
) -> str:
    """A PDO mapping record with the given entries; sub0 counts them unless `count` is given."""
    subs: dict[int, tuple[str, int, object]] = {
        0: ("Number of mapped objects", 0x0005, len(entries) if count is None else count)
    }
    for position, entry in enumerate(entries, 1):
        subs[position] = (f"Mapped object {position}", entry_type, entry)
    text = section(
        f"{index:04X}", ParameterName=f"PDO mapping parameter {index:04X}", ObjectType=object_type, SubNumber=len(subs)
    )
    for subindex, (sub_name, dtype, value) in sorted(subs.items()):
        text += "\n" + sub(index, subindex, sub_name, dtype, value, count_access if subindex == 0 else "rw")
    return text


def eds(*parts: str, granularity: int = 8, dummies: str = "0002,0003,0004,0005,0006,0007", head: str = "") -> str:
    """An EDS with [DeviceInfo], [DummyUsage] and the given object sections."""
    usage = "".join(f"Dummy{code}=1\n" for code in dummies.split(",") if code)
    text = (
        "[FileInfo]\nFileName=t.eds\nEDSVersion=4.0\n\n"
        f"[DeviceInfo]\nVendorName=Test\nGranularity={granularity}\nNrOfRXPDO=0\nNrOfTXPDO=0\n{head}\n"
        f"[DummyUsage]\n{usage}"
    )
    return text + "".join("\n" + part for part in parts)


def dcf(node_id: int | None, *parts: str, sync: bool = False) -> str:
    """A DCF of one node: NodeID (None: no NodeID key), SYNC producer or not, the given objects."""
    commissioning = "[DeviceComissioning]\n" + (f"NodeID={node_id}\n" if node_id is not None else "NodeName=x\n")
    sync_id = "0x40000080" if sync else "0x00000080"
    objects = (section("1005", ParameterName="COB-ID SYNC", DataType="0x0007", AccessType="rw", DefaultValue=sync_id),)
    return eds(*objects, *parts) + "\n" + commissioning


def load(text: str, source: str = "t.eds", node_id: int | None = None) -> Device:
    return loads(text.encode(), source=source, node_id=node_id)


def code_findings(text: str, code: str, options: LintOptions | None = None, source: str = "t.eds") -> list[Finding]:
    """The findings of one rule code (or code prefix) for an EDS text."""
    return [f for f in lint(load(text, source), options) if f.code.startswith(code)]


def where(text: str, name: str, key: str | None = None) -> int:
    """The line number of `[name]`, or of `key=` inside that section."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.strip().lower() == f"[{name.lower()}]")
    if key is None:
        return start + 1
    for number in range(start + 1, len(lines)):
        if lines[number].startswith("["):
            break
        if lines[number].split("=", 1)[0].strip().lower() == key.lower():
            return number + 1
    raise LookupError(f"[{name}] has no {key}")


def at(finding: Finding) -> tuple[int, int]:
    return finding.location.line, finding.location.column
