"""COB-ID and PDO communication rules (cantools_od/lint/cobid.py) with exact locations."""

from __future__ import annotations

import pytest
from lintkit import VALUE_COLUMN, at, comm, eds, mapping, record, section, var, where
from lintkit import code_findings as findings

from cantools_od.lint import LintOptions
from cantools_od.model import Severity

STATUS = var(0x6041, "Statusword", 0x0006, "ro")
CONTROL = var(0x6040, "Controlword", 0x0006, "rw")


def tpdo(number: int, cob: str, tt: object = 255, **extra: object) -> tuple[str, str]:
    return comm(0x1800 + number - 1, cob, tt, **extra), mapping(0x1A00 + number - 1, "0x60410010")


def rpdo(number: int, cob: str, tt: object = 255, **extra: object) -> tuple[str, str]:
    return comm(0x1400 + number - 1, cob, tt, **extra), mapping(0x1600 + number - 1, "0x60400010")


def cob_at(text: str, name: str) -> tuple[int, int]:
    return where(text, name, "DefaultValue"), VALUE_COLUMN


def as_dcf(text: str, node_id: int) -> str:
    return text.replace("[DeviceInfo]", f"[DeviceComissioning]\nNodeID={node_id}\n\n[DeviceInfo]")


def emcy(value: str) -> str:
    return section("1014", ParameterName="COB-ID EMCY", DataType="0x0007", AccessType="rw", DefaultValue=value)


# --- COB-IDs --------------------------------------------------------------------------------------


def test_cob001_high_bits_in_an_11_bit_cob_id() -> None:
    text = eds(*tpdo(1, "0x00000981"), STATUS, emcy("$NODEID+0x80"))
    (found,) = findings(text, "COB001")
    assert found.message == "TPDO1: COB-ID 0x981 sets bits 28-11 of an 11-bit CAN-ID (bit 29 is 0)"
    assert at(found) == cob_at(text, "1800sub1")
    assert findings(eds(*tpdo(1, "0x20000981"), STATUS), "COB001") == []  # a 29-bit CAN-ID


def test_cob001_names_the_first_failing_node_id() -> None:
    text = eds(*tpdo(1, "$NODEID+0x7C0"), STATUS)
    (found,) = findings(text, "COB001")
    assert found.message.startswith("TPDO1: COB-ID $NODEID+0x7C0 (0x800 for node-ID 64) sets bits 28-11")
    assert findings(text, "COB001", LintOptions(node_id=5)) == []


def test_cob004_restricted_ids_for_some_node_ids() -> None:
    text = eds(*tpdo(1, "$NODEID+0x6C0"), STATUS)
    (found,) = findings(text, "COB004")
    assert found.message == "TPDO1: COB-ID $NODEID+0x6C0 (0x6E0 for node-ID 32) is a restricted CAN-ID"
    assert at(found) == cob_at(text, "1800sub1")
    assert findings(text, "COB004", LintOptions(node_id=5)) == []
    commissioned = as_dcf(text, 40)
    assert [f.message for f in findings(commissioned, "COB004", source="t.dcf")] == [
        "TPDO1: COB-ID $NODEID+0x6C0 (0x6E8 for node-ID 40) is a restricted CAN-ID"
    ]


def test_cob004_literal_and_invalid() -> None:
    text = eds(*rpdo(1, "0x00000601"), CONTROL)
    assert [f.message for f in findings(text, "COB004")] == ["RPDO1: COB-ID 0x601 is a restricted CAN-ID"]
    assert findings(eds(*rpdo(1, "0x80000601"), CONTROL), "COB004") == []  # not valid: bit 31 set


def test_cob005_sync_emcy_time_ids() -> None:
    text = eds(*tpdo(1, "0x00000090"), STATUS)
    (found,) = findings(text, "COB005")
    assert found.message == "TPDO1: COB-ID 0x90 is the CAN-ID of SYNC, EMCY or TIME"
    assert (found.severity, at(found)) == (Severity.WARNING, cob_at(text, "1800sub1"))
    assert findings(eds(*tpdo(1, "$NODEID+0x180"), STATUS), "COB005") == []


def test_cob006_predefined_defaults() -> None:
    sdo = record(0x1200, "SDO server", {1: ("rx", 0x0007, "$NODEID+0x600"), 2: ("tx", 0x0007, "0x581")}, "ro")
    text = eds(emcy("0x81"), sdo, *rpdo(1, "$NODEID+0x300"), *tpdo(1, "0x181"), STATUS, CONTROL)
    found = findings(text, "COB006")
    assert [(f.message, at(f)) for f in found] == [
        (
            "EMCY: default COB-ID 0x81 fits one node-ID only; write $NODEID+0x80",
            cob_at(text, "1014"),
        ),
        (
            "SDO server 1200h (tx): default COB-ID 0x581 fits one node-ID only; write $NODEID+0x580",
            cob_at(text, "1200sub2"),
        ),
        ("RPDO1: default COB-ID $NODEID+0x300 is not the pre-defined $NODEID+0x200", cob_at(text, "1400sub1")),
        (
            "TPDO1: default COB-ID 0x181 fits one node-ID only; write $NODEID+0x180",
            cob_at(text, "1800sub1"),
        ),
    ]
    assert findings(as_dcf(text, 1), "COB006", source="t.dcf") == []  # a DCF is for one node


@pytest.mark.parametrize("value", ["$NODEID+0x180", "$NODEID+0x40000180", "$NODEID+0x80000180", "0x80000000"])
def test_cob006_accepted_defaults(value: str) -> None:
    assert findings(eds(*tpdo(1, value), STATUS), "COB006") == []


def test_cob006_keeps_the_flags_in_its_suggestion() -> None:
    (found,) = findings(eds(*tpdo(1, "0xC0000185"), STATUS), "COB006")
    assert "write $NODEID+0xC0000180" in found.message


def test_cob007_pdo_above_4_valid_by_default() -> None:
    text = eds(*rpdo(5, "0x00000222"), *rpdo(6, "0x80000000"), CONTROL)
    (found,) = findings(text, "COB007")
    assert found.message == "RPDO5: default COB-ID 0x222 is valid; PDOs above 4 have no pre-defined CAN-ID (set bit 31)"
    assert at(found) == cob_at(text, "1404sub1")


def test_cob009_two_tpdos_collide_for_one_node_id() -> None:
    text = eds(*tpdo(1, "$NODEID+0x180"), *tpdo(2, "0x00000181"), STATUS)
    (found,) = findings(text, "COB009")
    assert found.message == "TPDO1 and TPDO2 both use CAN-ID 181h for node-ID 1"
    assert at(found) == cob_at(text, "1801sub1")
    assert findings(text, "COB009", LintOptions(node_id=5)) == []
    assert findings(eds(*tpdo(1, "$NODEID+0x180"), *tpdo(2, "0x80000181"), STATUS), "COB009") == []


def test_cob009_tpdo_against_emcy_and_heartbeat() -> None:
    text = eds(*tpdo(1, "0x00000085"), emcy("$NODEID+0x80"), STATUS)
    (found,) = findings(text, "COB009")
    assert found.message == "TPDO1 and EMCY both use CAN-ID 085h for node-ID 5"
    assert at(found) == cob_at(text, "1014")
    beat = eds(*tpdo(1, "0x00000705"), STATUS)
    (found,) = findings(beat, "COB009", LintOptions(node_id=5))
    assert found.message == "TPDO1 and NMT error control (heartbeat) both use CAN-ID 705h for node-ID 5"
    assert at(found) == cob_at(beat, "1800sub1")


def test_cob010_rpdos_sharing_an_id_is_information() -> None:
    text = eds(*rpdo(1, "0x00000201"), *rpdo(2, "0x00000201"), CONTROL)
    (found,) = findings(text, "COB010")
    assert (found.severity, found.message) == (Severity.INFO, "RPDO1 and RPDO2 both use CAN-ID 201h")
    assert at(found) == cob_at(text, "1401sub1")


# --- communication parameters -------------------------------------------------------------------


def test_pdo010_sub0_below_highest_sub() -> None:
    text = eds(comm(0x1800, "$NODEID+0x180", timer=100, sub0=2), mapping(0x1A00, "0x60410010"), STATUS)
    (found,) = findings(text, "PDO010")
    assert found.message == "TPDO1: 1800sub0 is 2, but sub5 is described"
    assert at(found) == cob_at(text, "1800sub0")
    assert findings(eds(*tpdo(1, "$NODEID+0x180", timer=100), STATUS), "PDO010") == []


def test_pdo011_inhibit_time_on_rpdo() -> None:
    text = eds(*rpdo(1, "$NODEID+0x200", inhibit=100), CONTROL)
    (found,) = findings(text, "PDO011")
    assert found.message == "RPDO1: inhibit time 100 has no effect on an RPDO"
    assert at(found) == cob_at(text, "1400sub3")
    assert findings(eds(*rpdo(1, "$NODEID+0x200", inhibit=0), CONTROL), "PDO011") == []


def test_pdo012_comm_sub_type() -> None:
    subs = {1: ("COB-ID", 0x0007, "$NODEID+0x180"), 2: ("TT", 0x0005, 255), 5: ("Event timer", 0x0007, 0)}
    text = eds(record(0x1800, "TPDO1", subs), mapping(0x1A00, "0x60410010"), STATUS)
    (found,) = findings(text, "PDO012")
    assert found.message == "TPDO1: 1800sub5 is UNSIGNED32, expected UNSIGNED16"
    assert at(found) == (where(text, "1800sub5", "DataType"), 1)


def test_pdo013_comm_sub_mappable() -> None:
    text = eds(*tpdo(1, "$NODEID+0x180"), STATUS)
    text = text.replace("DefaultValue=$NODEID+0x180\nPDOMapping=0", "DefaultValue=$NODEID+0x180\nPDOMapping=1")
    (found,) = findings(text, "PDO013")
    assert found.message == "TPDO1: 1800sub1 is marked PDO-mappable"
    assert at(found) == (where(text, "1800sub1", "PDOMapping"), 1)


def test_pdo020_reserved_transmission_type() -> None:
    text = eds(*tpdo(1, "$NODEID+0x180", 245), STATUS)
    (found,) = findings(text, "PDO020")
    assert found.message == "TPDO1: transmission type 245 is reserved"
    assert at(found) == cob_at(text, "1800sub2")
    assert findings(eds(*tpdo(1, "$NODEID+0x180", 240), STATUS), "PDO020") == []


def test_pdo021_rtr_transmission_type_on_rpdo() -> None:
    text = eds(*rpdo(1, "$NODEID+0x200", 253), CONTROL)
    (found,) = findings(text, "PDO021")
    assert found.message == "RPDO1: transmission type 253 is for TPDOs only"
    assert at(found) == cob_at(text, "1400sub2")
    assert findings(eds(*tpdo(1, "$NODEID+0x180", 253), STATUS), "PDO021") == []


def test_pdo023_event_driven_without_timer_is_information() -> None:
    text = eds(*tpdo(1, "$NODEID+0x180", 255, timer=0), STATUS)
    (found,) = findings(text, "PDO023")
    assert found.severity is Severity.INFO
    assert found.message == "TPDO1: transmission type 255 with event timer 0 is sent only on application events"
    assert at(found) == cob_at(text, "1800sub5")
    assert findings(eds(*tpdo(1, "$NODEID+0x180", 255, timer=100), STATUS), "PDO023") == []
    assert findings(eds(*tpdo(1, "$NODEID+0x80000180", 255, timer=0), STATUS), "PDO023") == []  # not valid


def test_pdo024_sync_start_without_cyclic_sync() -> None:
    text = eds(*tpdo(1, "$NODEID+0x180", 255, sync=2), STATUS)
    (found,) = findings(text, "PDO024")
    assert found.message == "TPDO1: SYNC start value 2 has no effect with transmission type 255"
    assert at(found) == cob_at(text, "1800sub6")
    assert findings(eds(*tpdo(1, "$NODEID+0x180", 5, sync=2), STATUS), "PDO024") == []


def test_pdo032_event_timer_on_synchronous_tpdo() -> None:
    text = eds(*tpdo(1, "$NODEID+0x180", 1, timer=100), STATUS)
    (found,) = findings(text, "PDO032")
    assert found.message == "TPDO1: event timer 100 ms is ignored with transmission type 1"
    assert at(found) == cob_at(text, "1800sub5")
    assert findings(eds(*tpdo(1, "$NODEID+0x180", 254, timer=100), STATUS), "PDO032") == []


def test_pdo033_event_timer_below_inhibit_time() -> None:
    text = eds(*tpdo(1, "$NODEID+0x180", 255, inhibit=100, timer=5), STATUS)
    (found,) = findings(text, "PDO033")
    assert found.message == "TPDO1: event timer 5 ms is shorter than the inhibit time 10 ms"
    assert at(found) == cob_at(text, "1800sub5")
    assert findings(eds(*tpdo(1, "$NODEID+0x180", 255, inhibit=100, timer=10), STATUS), "PDO033") == []


def test_cob009_with_an_implicit_compact_pdo_locates_at_the_file() -> None:
    head = "CompactPDO=0x01\n"
    text = eds(comm(0x1800, "0x00000282"), mapping(0x1A00, "0x60410010"), STATUS, head=head)
    text = text.replace("NrOfTXPDO=0", "NrOfTXPDO=2")  # TPDO2 (1801h/1A01h) is implied by CompactPDO
    (found,) = findings(text, "COB009")
    assert found.message == "TPDO1 and TPDO2 both use CAN-ID 282h for node-ID 2"
    assert (found.location.file, *at(found)) == ("t.eds", 0, 0)
