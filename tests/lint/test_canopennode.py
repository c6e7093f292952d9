"""The canopennode lint profile (cantools_od/lint/canopennode.py): what the CANopenNode stack refuses."""

from __future__ import annotations

from pathlib import Path

from cantools_od import loads
from cantools_od.canopennode.profile import StackConfig
from cantools_od.lint import LintOptions, lint
from cantools_od.model import CanopenNodeInfo

CODES = ("CNO001", "CNO002", "CNO003", "CNO004", "CNO005", "CNO006", "CNO007", "CNO008", "CNO009")


def var(index: int, name: str, dtype: int, access: str = "ro", default: str = "0", sub: int | None = None) -> str:
    header = f"{index:04X}" + (f"sub{sub:X}" if sub is not None else "")
    return (
        f"[{header}]\nParameterName={name}\nObjectType=0x7\nDataType=0x{dtype:04X}\nAccessType={access}\n"
        f"DefaultValue={default}\nPDOMapping=0\n\n"
    )


def record(index: int, name: str, kind: int, subs: list[str]) -> str:
    return f"[{index:04X}]\nParameterName={name}\nObjectType=0x{kind:X}\nSubNumber={len(subs)}\n\n" + "".join(subs)


REQUIRED = (
    var(0x1000, "Device type", 7)
    + var(0x1001, "Error register", 5)
    + var(0x1014, "COB-ID EMCY", 7, "rw", "$NODEID+0x80")
    + var(0x1017, "Producer heartbeat time", 6, "rw")
    + "[1003]\nParameterName=Pre-defined error field\nObjectType=0x8\nSubNumber=2\n\n"
    + var(0x1003, "Number of errors", 5, "rw", sub=0)
    + var(0x1003, "Standard error field", 7, default="", sub=1)
    + "[1016]\nParameterName=Consumer heartbeat time\nObjectType=0x8\nSubNumber=2\n\n"
    + var(0x1016, "Highest sub-index supported", 5, default="1", sub=0)
    + var(0x1016, "Consumer heartbeat time", 7, "rw", sub=1)
)


def codes(text: str, profile: str | None = "canopennode") -> list[tuple[str, str]]:
    device = loads(text, "eds")
    found = lint(device, LintOptions(profile=profile))
    return [(f.code, f.message) for f in found if f.code.startswith("CNO")]


def test_a_stack_ready_device_passes_and_the_rules_need_the_profile() -> None:
    assert codes(REQUIRED) == []
    assert codes(var(0x2000, "Mapping", 0x21), profile=None) == []


def test_required_objects_missing() -> None:
    found = codes(var(0x1000, "Device type", 7) + var(0x1001, "Error register", 5))
    assert [c for c, _ in found] == ["CNO005"] * 4
    assert "EM_PROD" in found[0][1] and "HB_CONS" in found[1][1] and "HB_PROD" in found[2][1]
    assert found[3][1].startswith("1001h counts as EM, so CANopen.c also uses 1003h when built with CO_CONFIG_EM")
    sync = codes(REQUIRED + var(0x1005, "COB-ID SYNC", 7, "rw", "0x80"))
    assert [c for c, _ in sync] == ["CNO005"] and sync[0][1].startswith(
        "1005h counts as SYNC, so CANopen.c also uses 1006h when built with CO_CONFIG_SYNC & CO_CONFIG_SYNC_ENABLE"
    )


def test_required_objects_follow_the_declared_stack_configuration() -> None:
    device = loads(var(0x1000, "Device type", 7) + var(0x1001, "Error register", 5), "eds")

    def found(stack: StackConfig | None) -> list[tuple[str, str]]:
        return [(f.severity.value, f.message.split(":")[0]) for f in
                lint(device, LintOptions(profile="canopennode", stack=stack)) if f.code == "CNO005"]  # fmt: skip

    unknown = found(None)  # nothing declared: only what every build needs is an error
    assert [s for s, _ in unknown] == ["warning", "warning", "error", "warning"]
    assert "HB_PROD" in unknown[2][1]
    assert [s for s, _ in found(StackConfig(declared=True))] == ["error"] * 4  # the stack's defaults
    lean = StackConfig((("CO_CONFIG_EM", 0), ("CO_CONFIG_HB_CONS", 0)), declared=True)
    assert found(lean) == [("error", "no object counts as HB_PROD (usually 1017h)")]


def test_unsupported_type_and_unstorable_default() -> None:
    found = codes(REQUIRED + var(0x2000, "Mapping", 0x21, default="") + var(0x2001, "Huge", 8, default="1e40"))
    assert [c for c, _ in found] == ["CNO001", "CNO007"]
    assert "PDO_MAPPING" in found[0][1]


def test_sub0_type_and_array_elements() -> None:
    subs = [var(0x2000, "Count", 7, default="2", sub=0), var(0x2000, "A", 7, "rw", sub=1), var(0x2000, "B", 6, sub=2)]
    found = codes(REQUIRED + record(0x2000, "Values", 8, subs))
    assert [c for c, _ in found] == ["CNO002", "CNO003"]
    assert "DataType differs" in found[1][1]


def test_array_gaps_and_empty_records() -> None:
    subs = [var(0x2000, "Count", 5, default="3", sub=0), var(0x2000, "A", 7, sub=1), var(0x2000, "C", 7, sub=3)]
    empty = [var(0x2001, "Count", 5, default="0", sub=0)]
    found = codes(REQUIRED + record(0x2000, "Values", 8, subs) + record(0x2001, "Nothing", 9, empty))
    assert found == [
        ("CNO004", "2000h: ARRAY sub-index 2h is missing"),
        ("CNO004", "2001h (RECORD) has no sub-index above 0"),
    ]


def pdo(index: int) -> str:
    subs = [var(index, "Highest", 5, default="1", sub=0), var(index, "COB-ID", 7, "rw", "$NODEID+0x200", sub=1)]
    return record(index, "RPDO communication parameter", 9, subs)


def test_counts_consecutive_and_paired() -> None:
    mapping = record(0x1600, "RPDO mapping", 9, [var(0x1600, "Count", 5, "rw", sub=0)])
    found = codes(REQUIRED + pdo(0x1400) + pdo(0x1402) + mapping)
    assert sorted(c for c, _ in found) == ["CNO004", "CNO006"]
    assert any("1402h is not" in message for _, message in found)
    assert codes(REQUIRED + pdo(0x1400))[0] == (
        "CNO006",
        "1400h has no mapping object 1600h; the stack pairs them by position",
    )


def test_count_limits_and_c_names() -> None:
    device = loads(REQUIRED + var(0x1005, "COB-ID SYNC", 7, "rw", "0x80"), "eds")
    device.objects[0x1005].canopennode = CanopenNodeInfo(count_label="HB_PROD", storage_group="MY GROUP")
    found = [(f.code, f.message) for f in lint(device, LintOptions(profile="canopennode")) if f.code.startswith("CNO")]
    assert ("CNO006", "2 objects count as HB_PROD; the stack allows exactly 1") in found
    assert ("CNO006", "1005h: storage group 'MY GROUP' is not a C identifier") in found


def test_nodeid_outside_the_stack_managed_cob_ids_and_strings_without_memory() -> None:
    found = codes(REQUIRED + var(0x2000, "Reply", 7, "rw", "$NODEID+0x700") + var(0x2001, "Name", 9, "rw", ""))
    assert found == [
        ("CNO008", "2000h: $NODEID+0x700 is stored as 0x700; no node-ID is added here"),
        ("CNO009", "2001h: writable VISIBLE_STRING with no default and no string_length_min: no memory"),
    ]
    assert codes(REQUIRED + var(0x2001, "Name", 9, "ro", "")) == []


def test_every_code_has_a_test() -> None:
    text = Path(__file__).read_text(encoding="utf-8")
    assert all(text.count(code) >= 2 for code in CODES)
