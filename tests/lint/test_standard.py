"""STD001-STD006: the CiA 301 / CiA 302 / CiA 402 objects checked against the standard's definitions."""

from __future__ import annotations

import re

import pytest
from lintkit import findings, messages

from cantools_od import load, loads
from cantools_od.lint import lint
from cantools_od.model import ObjectKind
from cantools_od.model.cia301 import cia402, definitions

from support import CORPUS, corpus_file


def var(index: int, data_type: int, access: str, **keys: str) -> str:
    extra = "".join(f"{key}={value}\n" for key, value in keys.items())
    head = f"[{index:04X}]\nParameterName=Object\nObjectType=0x7\n"
    return head + f"DataType=0x{data_type:04X}\nAccessType={access}\n{extra}\n"


def test_the_issues_test_file() -> None:
    """1000h UNSIGNED16, 1001h UNSIGNED32 rw and PDO-mappable, 1017h UNSIGNED32: each deviation at its key."""
    text = var(0x1000, 0x0006, "ro") + var(0x1001, 0x0007, "rw", PDOMapping="1") + var(0x1017, 0x0007, "rw")
    assert findings(text, "STD003") == [(4, 10), (10, 10), (17, 10)]
    assert messages(text, "STD003")[0] == (
        "[1000] DataType=UNSIGNED16 (0x0006): CiA 301 §7.5.2 defines 1000h Device type as UNSIGNED32 (0x0007)"
    )
    assert messages(text, "STD004") == [
        "[1001] AccessType=rw: CiA 301 §7.5.2 gives 1001h Error register access const/ro"
    ]
    assert findings(text, "STD005") == []  # 1001h may be mapped


def test_choices_the_standard_leaves_are_accepted() -> None:
    for access in ("ro", "rw", "const"):
        text = var(0x1017, 0x0006, access)
        assert [f.code for f in lint(loads(text)) if f.code.startswith("STD")] == []


def test_identity_record_entries_and_sub0_range() -> None:
    text = (
        "[1018]\nParameterName=Identity\nObjectType=0x9\nSubNumber=2\n\n"
        "[1018sub0]\nParameterName=Count\nDataType=0x0005\nAccessType=ro\nDefaultValue=7\n\n"
        "[1018sub1]\nParameterName=Vendor\nDataType=0x0004\nAccessType=rw\n"
    )
    assert findings(text, "STD003") == [(14, 10)]
    assert findings(text, "STD004") == [(15, 12)]
    assert messages(text, "STD006") == [
        "[1018sub0] DefaultValue=7: CiA 301 §7.5.2 allows 1-4 for 1018h Identity object sub-index 0 "
        "(Highest sub-index supported)"
    ]
    assert findings(text.replace("ObjectType=0x9", "ObjectType=0x8"), "STD002") == [(3, 12)]
    as_var = "[1018]\nParameterName=Identity\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\n"
    assert findings(as_var, "STD001") == [(3, 12)]


def test_compact_array_reported_once_at_the_object() -> None:
    text = (
        "[1016]\nParameterName=Consumer heartbeat time\nObjectType=0x8\nDataType=0x0006\nAccessType=rw\n"
        "CompactSubObj=4\n"
    )
    assert findings(text, "STD003") == [(4, 10)]


def test_mapping_where_the_standard_forbids_it() -> None:
    assert findings(var(0x1017, 0x0006, "rw", PDOMapping="1"), "STD005") == [(6, 12)]


def test_cia402_only_for_a_drive() -> None:
    drive = var(0x1000, 0x0007, "ro", DefaultValue="0x00020192")
    statusword = var(0x6041, 0x0005, "ro")
    assert findings(drive + statusword, "STD003") == [(11, 10)]
    assert messages(drive + statusword, "STD003") == [
        "[6041] DataType=UNSIGNED8 (0x0005): CiA 402-2 defines 6041h Statusword as UNSIGNED16 (0x0006)"
    ]
    io_module = drive.replace("0x00020192", "0x00000191")
    assert findings(io_module + statusword, "STD003") == []


@pytest.mark.parametrize(
    ("name", "line"),
    [
        ("curtis__inverter.eds", 2918),  # 1000h INTEGER32
        ("curtis__inverter.eds", 2924),  # 1001h INTEGER16
        ("adampower__UC42_.eds", 229),  # 1009h UNSIGNED16
        ("victron-sim__sevcon_gen4.eds", 83),  # 1018h sub3 UNSIGNED16
    ],
)
def test_real_files(name: str, line: int) -> None:
    device = load(corpus_file(name))
    assert line in {f.location.line for f in lint(device) if f.code == "STD003"}


def test_deviation_suppressed_by_code() -> None:
    text = var(0x1000, 0x0006, "ro")
    assert findings(text, "STD003") == [(4, 10)]
    assert findings("; cantools-od: ignore STD003\n" + text, "STD003") == []


def test_table_is_consistent() -> None:
    seen: set[int] = set()
    for table in (definitions.DEFINITIONS, cia402.DEFINITIONS):
        for found in table:
            assert not seen & set(found.indices), f"{found.index:04X} defined twice"
            seen.update(found.indices)
            assert found.subs, found.name
            if found.kind in (ObjectKind.VAR, ObjectKind.DOMAIN):
                assert len(found.subs) == 1 and found.rest is None
            else:
                assert found.subs[0].data_type == definitions.UNSIGNED8


def test_table_covers_every_communication_object_of_the_corpus() -> None:
    if not CORPUS.is_dir():
        pytest.skip("../shared/eds-corpus is absent")
    header = re.compile(rb"^\s*\[(1[0-9a-f]{3})\]", re.IGNORECASE | re.MULTILINE)
    used = {int(m, 16) for path in CORPUS.iterdir() for m in header.findall(path.read_bytes())}
    assert len(used) > 100
    missing = {i for i in used if definitions.definition(i) is None and i not in definitions.NOT_STANDARD}
    assert missing == set(), [f"{i:04X}" for i in sorted(missing)]
