"""PDO mapping and record rules (cantools_od/lint/pdo.py): PDO001-PDO064 with exact locations."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from lintkit import VALUE_COLUMN, at, comm, eds, load, mapping, record, section, var, where
from lintkit import code_findings as findings

from cantools_od import dumps
from cantools_od import load as load_file
from cantools_od.lint import LintOptions, lint
from cantools_od.model import Severity

from support import EXAMPLES, cli_command, corpus_params

STATUS = var(0x6041, "Statusword", 0x0006, "ro")
CONTROL = var(0x6040, "Controlword", 0x0006, "rw")
POSITION = var(0x6064, "Position actual value", 0x0004, "ro")
TARGET = var(0x607A, "Target position", 0x0004, "rw")


def tpdo(*entries: str, count: object = None, cob: str = "$NODEID+0x180") -> tuple[str, str]:
    return comm(0x1800, cob), mapping(0x1A00, *entries, count=count)


def rpdo(*entries: str, count: object = None, number: int = 1, cob: str | None = None) -> tuple[str, str]:
    base = (0x200, 0x300, 0x400, 0x500)[number - 1]
    return comm(0x1400 + number - 1, cob or f"$NODEID+0x{base:X}"), mapping(0x1600 + number - 1, *entries, count=count)


def value_at(text: str, name: str, key: str = "DefaultValue") -> tuple[int, int]:
    return where(text, name, key), VALUE_COLUMN if key == "DefaultValue" else len(key) + 2


# --- the examples and the corpus ---------------------------------------------------------------


@pytest.mark.parametrize("name", ["io_device.eds", "cia402_drive.eds"])
def test_examples_are_clean(name: str) -> None:
    families = ("PDO", "COB")
    found = [f.format() for f in lint(load((EXAMPLES / name).read_text(), name)) if f.code.startswith(families)]
    assert found == []


@pytest.mark.parametrize("path", corpus_params())
def test_no_rule_crashes_on_the_corpus(path: Path) -> None:
    crashes = [f.message for f in lint(load_file(path)) if f.code == "LNT001"]
    assert [m for m in crashes if m.startswith(("rule PDO", "rule COB"))] == []


# --- records -------------------------------------------------------------------------------------


def test_pdo001_comm_without_mapping_and_reverse() -> None:
    text = eds(comm(0x1400, "$NODEID+0x200"), STATUS, mapping(0x1A01, "0x60410010"))
    found = findings(text, "PDO001")
    assert [(f.message, at(f)) for f in found] == [
        ("RPDO1: 1400h has no mapping record 1600h", (where(text, "1400"), 1)),
        ("TPDO2: 1A01h has no communication record 1801h", (where(text, "1A01"), 1)),
    ]
    assert findings(eds(*tpdo("0x60410010"), STATUS), "PDO001") == []


def test_pdo002_comm_record_written_as_array() -> None:
    text = eds(comm(0x1800, "$NODEID+0x180", object_type="0x8"), mapping(0x1A00, "0x60410010"), STATUS)
    (found,) = findings(text, "PDO002")
    assert found.message == "TPDO1: 1800h is ARRAY, expected RECORD"
    assert at(found) == (where(text, "1800", "ObjectType"), 1)
    mapping_as_array = eds(comm(0x1800, "$NODEID+0x180"), mapping(0x1A00, "0x60410010", object_type="0x8"), STATUS)
    assert findings(mapping_as_array, "PDO002") == []  # tolerated for mapping records


def test_pdo060_record_without_mandatory_subs() -> None:
    partial = record(0x1400, "RPDO communication parameter", {1: ("COB-ID", 0x0007, "$NODEID+0x200")})
    text = eds(partial, mapping(0x1600, "0x60400010"), CONTROL)
    (found,) = findings(text, "PDO060")
    assert found.message == "RPDO1: 1400h has no sub2"
    assert at(found) == (where(text, "1400"), 1)
    assert findings(eds(*rpdo("0x60400010"), CONTROL), "PDO060") == []


def test_pdo060_ignores_compact_pdo_records() -> None:
    text = eds(head="CompactPDO=0x03\n").replace("NrOfRXPDO=0", "NrOfRXPDO=1")
    assert findings(text, "PDO060") == []
    assert findings(text, "PDO001") == []


# --- mapping record -----------------------------------------------------------------------------


def test_pdo064_entry_of_wrong_type() -> None:
    text = eds(comm(0x1800, "$NODEID+0x180"), mapping(0x1A00, "0x60410010", entry_type=0x0006), STATUS)
    (found,) = findings(text, "PDO064")
    assert found.message == "TPDO1: 1A00sub1 is UNSIGNED16, expected UNSIGNED32"
    assert at(found) == (where(text, "1A00sub1", "DataType"), 1)


def test_pdo064_write_only_count() -> None:
    text = eds(comm(0x1800, "$NODEID+0x180"), mapping(0x1A00, "0x60410010", count_access="wo"), STATUS)
    (found,) = findings(text, "PDO064")
    assert found.message == "TPDO1: 1A00sub0 is write-only"
    assert at(found) == (where(text, "1A00sub0", "AccessType"), 1)


def test_pdo040_count_above_entries_and_above_64() -> None:
    text = eds(*tpdo("0x60410010", count=2), STATUS)
    (found,) = findings(text, "PDO040")
    assert found.message == "TPDO1: 1A00sub0 counts 2 entries, but sub2 is not described"
    assert at(found) == value_at(text, "1A00sub0")
    too_many = eds(*tpdo("0x60410010", count=65), STATUS)
    assert [f.message for f in findings(too_many, "PDO040")] == ["TPDO1: 65 mapped objects, at most 64"]


def test_pdo040_accepts_multiplexed_pdos() -> None:
    for count in ("0xFE", "0xFF"):
        text = eds(*rpdo(count=count))
        assert findings(text, "PDO04") == []


def test_pdo041_hole_in_mapping() -> None:
    text = eds(*tpdo("0x60410010", "0x00000000", "0x60640020"), STATUS, POSITION)
    (found,) = findings(text, "PDO041")
    assert found.message == "TPDO1: sub0 counts 3 entries, but entry 2 is 0"
    assert at(found) == value_at(text, "1A00sub2")


def test_pdo041_all_entries_empty_is_reported_at_sub0() -> None:
    text = eds(*tpdo("0", "0", count=2))
    (found,) = findings(text, "PDO041")
    assert found.message == "TPDO1: sub0 counts 2 entries, but all of them are 0"
    assert at(found) == value_at(text, "1A00sub0")
    assert findings(eds(*tpdo("0", "0", count=0)), "PDO041") == []


def test_pdo042_mapped_object_missing() -> None:
    text = eds(*rpdo("0x21000010"))
    (found,) = findings(text, "PDO042")
    assert found.message == "RPDO1: maps 2100sub0, which does not exist"
    assert at(found) == value_at(text, "1600sub1")
    record_sub = eds(*tpdo("0x10180520"), record(0x1018, "Identity", {1: ("Vendor-ID", 0x0007, 1)}, "ro"))
    assert [f.message for f in findings(record_sub, "PDO042")] == ["TPDO1: maps 1018sub5, which does not exist"]


def test_pdo052_var_with_subindex() -> None:
    text = eds(*rpdo("0x60400110"), CONTROL)
    (found,) = findings(text, "PDO052")
    assert found.message == "RPDO1: maps 6040sub1, but 6040h is a VAR (sub-index 0 only)"
    assert at(found) == value_at(text, "1600sub1")
    assert findings(text, "PDO042") == []


def test_pdo043_not_mappable() -> None:
    text = eds(*tpdo("0x10010008"), var(0x1001, "Error register", 0x0005, "ro", mapping=0))
    (found,) = findings(text, "PDO043")
    assert found.message == "TPDO1: maps 1001sub0 (Error register), which is not PDO-mappable"
    assert at(found) == value_at(text, "1A00sub1")
    no_key = eds(*tpdo("0x10010008"), var(0x1001, "Error register", 0x0005, "ro", mapping=None))
    assert len(findings(no_key, "PDO043")) == 1  # a missing PDOMapping means 0


@pytest.mark.parametrize(
    ("direction", "access", "severity"),
    [
        ("rx", "ro", Severity.ERROR),
        ("rx", "const", Severity.ERROR),
        ("tx", "wo", Severity.ERROR),
        ("rx", "rwr", Severity.WARNING),
        ("tx", "rww", Severity.WARNING),
    ],
)
def test_pdo044_access_against_direction(direction: str, access: str, severity: Severity) -> None:
    pdo = rpdo("0x20000010") if direction == "rx" else tpdo("0x20000010")
    text = eds(*pdo, var(0x2000, "Value", 0x0006, access))
    (found,) = findings(text, "PDO044")
    assert found.severity is severity
    assert found.message.endswith(f"2000sub0 (Value), whose access is {access}")
    assert at(found) == value_at(text, "1600sub1" if direction == "rx" else "1A00sub1")


@pytest.mark.parametrize(
    ("direction", "access"), [("rx", "wo"), ("rx", "rww"), ("rx", "rw"), ("tx", "ro"), ("tx", "const"), ("tx", "rwr")]
)
def test_pdo044_fitting_access(direction: str, access: str) -> None:
    pdo = rpdo("0x20000010") if direction == "rx" else tpdo("0x20000010")
    assert findings(eds(*pdo, var(0x2000, "Value", 0x0006, access)), "PDO044") == []


def test_pdo045_length_and_its_unsafe_fix_changes_one_line() -> None:
    text = eds(*tpdo("0x60410010", "0x60640010"), STATUS, POSITION)
    device = load(text)
    (found,) = [f for f in lint(device) if f.code == "PDO045"]
    assert found.message == (
        "TPDO1: entry 0x60640010 maps 16 bits, but 6064sub0 (Position actual value) is INTEGER32 (32 bits)"
    )
    assert at(found) == value_at(text, "1A00sub2")
    # unsafe: every reader reads a new mapping, every later entry of the frame moves
    assert found.fix is not None and not found.fix.safe
    found.fix.apply(device)
    before, after = text.splitlines(), dumps(device).decode().splitlines()
    changed = [(n + 1, a, b) for n, (a, b) in enumerate(zip(before, after, strict=True)) if a != b]
    assert changed == [(found.location.line, "DefaultValue=0x60640010", "DefaultValue=0x60640020")]
    assert [f for f in lint(load(dumps(device).decode())) if f.code == "PDO045"] == []


def test_pdo045_fix_rewrites_a_compact_value_section() -> None:
    text = eds(
        comm(0x1800, "$NODEID+0x180"),
        section(
            "1A00", ParameterName="TPDO mapping", ObjectType="0x9", DataType="0x0007", AccessType="rw", CompactSubObj=2
        ),
        section("1A00Value", NrOfEntries=2, **{"1": "0x60410008", "2": "0x60640020"}),
        STATUS,
        POSITION,
    ).replace("[DeviceInfo]", "[DeviceComissioning]\nNodeID=2\n\n[DeviceInfo]")
    device = load(text, "t.dcf")
    (found,) = [f for f in lint(device) if f.code == "PDO045"]
    # no section of its own: the [1A00Value] entry that holds the value, at the value
    assert at(found) == (text.splitlines().index("1=0x60410008") + 1, 3)
    assert found.fix is not None and not found.fix.safe
    found.fix.apply(device)
    assert dumps(device, "dcf").decode() == text.replace("1=0x60410008", "1=0x60410010")


def test_pdo045_dummy_and_boolean_and_suspect_type() -> None:
    text = eds(*rpdo("0x00050010"))
    assert [f.message for f in findings(text, "PDO045")] == [
        "RPDO1: entry 0x00050010 maps 16 bits, but dummy entry is UNSIGNED8 (8 bits)"
    ]
    boolean = eds(*tpdo("0x20000008"), var(0x2000, "Flag", 0x0001, "ro"))
    (found,) = findings(boolean, "PDO045")
    assert found.severity is Severity.WARNING and found.fix is not None and not found.fix.safe
    suspect = eds(*tpdo("0x20000010"), var(0x2000, "Word", 0x0005, "ro", HighLimit="0xFFFF"))
    (found,) = findings(suspect, "PDO045")
    assert found.severity is Severity.ERROR and found.fix is not None and not found.fix.safe


def test_pdo046_classic_limit_and_can_fd() -> None:
    text = eds(*tpdo("0x60640020", "0x60640020", "0x60410010"), STATUS, POSITION)
    (found,) = findings(text, "PDO046")
    assert found.message == "TPDO1: the mapping is 80 bits, more than 64"
    assert at(found) == value_at(text, "1A00sub0")
    assert findings(text, "PDO046", LintOptions(can_fd=True)) == []
    wide = eds(*tpdo(*["0x60640020"] * 17), POSITION)
    assert [f.message for f in findings(wide, "PDO046", LintOptions(can_fd=True))] == [
        "TPDO1: the mapping is 544 bits, more than 512"
    ]


def test_pdo048_granularity() -> None:
    text = eds(*tpdo("0x20000001", "0x60410010"), var(0x2000, "Flag", 0x0001, "ro"), STATUS)
    (found,) = findings(text, "PDO048")
    assert found.message == "Granularity=8, but TPDO1 maps 2000sub0 at bit 0, 1 bits (and 1 more entries)"
    assert at(found) == (where(text, "DeviceInfo", "Granularity"), 1)
    assert findings(eds(*tpdo("0x20000001"), var(0x2000, "Flag", 0x0001, "ro"), granularity=1), "PDO048") == []


def test_pdo049_same_object_twice() -> None:
    text = eds(*tpdo("0x60410010", "0x60410010"), STATUS)
    (found,) = findings(text, "PDO049")
    assert found.message == "TPDO1: 6041sub0 is mapped again (first as entry 1)"
    assert at(found) == value_at(text, "1A00sub2")


def test_pdo054_same_object_in_two_rpdos_of_a_dcf() -> None:
    parts = (*rpdo("0x60400010"), *rpdo("0x60400010", number=2), CONTROL)
    text = eds(*parts).replace("[DeviceInfo]", "[DeviceComissioning]\nNodeID=3\n\n[DeviceInfo]")
    (found,) = findings(text, "PDO054", source="t.dcf")
    assert found.message == "RPDO2: 6040sub0 is also written by RPDO1"
    assert at(found) == value_at(text, "1601sub1")
    assert findings(eds(*parts), "PDO054") == []  # an EDS's defaults: CiA 402 does this
    disabled = text.replace("$NODEID+0x300", "0x80000300")
    assert findings(disabled, "PDO054", source="t.dcf") == []


# --- dummy entries ------------------------------------------------------------------------------


def test_pdo050_dummy_of_no_fixed_type() -> None:
    text = eds(*rpdo("0x00090008", "0x00050108"))
    found = findings(text, "PDO050")
    assert [(f.message, at(f)) for f in found] == [
        ("RPDO1: dummy entry 0x00090008 names 0009h, not a fixed-size data type", value_at(text, "1600sub1")),
        ("RPDO1: dummy entry 0x00050108 has sub-index 1, expected 0", value_at(text, "1600sub2")),
    ]


def test_pdo062_dummy_not_enabled() -> None:
    text = eds(*rpdo("0x00070020"), dummies="0005")
    (found,) = findings(text, "PDO062")
    assert found.message == "RPDO1: dummy entry 0x00070020 needs Dummy0007=1 in [DummyUsage]"
    assert at(found) == value_at(text, "1600sub1")
    assert findings(eds(*rpdo("0x00050008"), dummies="0005"), "PDO062") == []


def test_pdo051_dummy_in_tpdo() -> None:
    text = eds(*tpdo("0x00050008"))
    (found,) = findings(text, "PDO051")
    assert found.message == "TPDO1: dummy entry 0x00050008 in a TPDO"
    assert at(found) == value_at(text, "1A00sub1")
    assert findings(eds(*rpdo("0x00050008")), "PDO051") == []


def test_pdo051_on_a_canopennode_device_is_a_warning(tmp_path: Path) -> None:
    """Apach200/0_F407's CANopenEditor project (DS301_profile.xdd) maps a dummy 0x00020008 into TPDO2: the
    CANopenNode stack sends a zero byte for it (CO_PDO.c), so such a device does not misbehave; elsewhere the
    mapping may be refused and it stays an error."""
    plain = eds(*tpdo("0x00020008", "0x60410010"), STATUS)
    editor = plain.replace("ObjectType=", ";StorageLocation=RAM\nObjectType=")
    seen: dict[str, tuple[str, int, str]] = {}
    for name, text, options in (("plain", plain, []), ("profile", plain, ["--profile", "canopennode"]),
                                ("editor", editor, [])):  # fmt: skip
        path = tmp_path / f"{name}.eds"
        path.write_text(text, encoding="utf-8")
        done = subprocess.run([*cli_command(), "lint", "-j1", "--format", "json", "--select", "PDO051", *options,
                               str(path)], capture_output=True, text=True, check=False)  # fmt: skip
        (found,) = json.loads(done.stdout)
        seen[name] = (found["severity"], found["line"], found["message"])
    line = where(plain, "1A00sub1", "DefaultValue")
    assert seen["plain"] == ("error", line, "TPDO1: dummy entry 0x00020008 in a TPDO")
    stack = (
        "TPDO1: dummy entry 0x00020008 in a TPDO; the CANopenNode stack sends zeros for it, other stacks may refuse "
        "the mapping"
    )
    assert seen["profile"] == ("warning", line, stack)
    assert seen["editor"][0] == "warning" and seen["editor"][2] == stack


def test_pdo053_length_msb() -> None:
    text = eds(*tpdo("0x60410090"), STATUS)
    (found,) = findings(text, "PDO053")
    assert found.message == "TPDO1: entry 0x60410090 has the length byte's MSB set (0x90)"
    assert at(found) == value_at(text, "1A00sub1")
    # CiA 301 reads the whole byte as the length: 144 bits, the one reading lint, pdo and gen share
    (length,) = findings(text, "PDO045")
    assert "maps 144 bits" in length.message and length.fix is None  # clearing the flag is the author's call
    (total,) = findings(text, "PDO046")
    assert "144 bits" in total.message


# --- robustness -----------------------------------------------------------------------------------


def test_odd_values_do_not_break_the_rules() -> None:
    text = eds(
        *tpdo("$NODEID+0x60410010", "zz", count="$NODEID"),
        *rpdo("0x60400010", count="two"),
        record(0x1801, "TPDO2", {1: ("COB-ID", 0x0001, 1), 2: ("TT", 0x0005, "x")}),
        section("1A01", ParameterName="TPDO2 mapping", ObjectType="0x7", DataType="0x0007", AccessType="rw"),
        CONTROL,
    )
    found = lint(load(text))
    assert not [f for f in found if f.code == "LNT001"]
