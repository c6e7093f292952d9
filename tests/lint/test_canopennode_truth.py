"""What lint says of CANopenNode/CANopenEditor projects and commissioned DCFs is what the device does (issue #41).

Each test reads a real project file of ../shared in place (or a copy in a scratch folder, edited as the test says)
through the installed CLI, as a user meets it.
"""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from lintkit import comm, eds, mapping, where

from support import SHARED, cli_command

# EvgenyDD/sh_gateway's CANopenEditor project: 1020h-1026h are kept in the project with CO_disabled.
GATEWAY = SHARED / "eds-history" / "EvgenyDD__sh_gateway__3" / "new.xdd"


def _need(path: Path) -> Path:
    if not path.is_file():
        pytest.skip(f"{path} is absent")
    return path


def _lint(path: Path, *args: str) -> list[dict[str, object]]:
    done = subprocess.run(
        [*cli_command(), "lint", "-j1", "--format", "json", *args, str(path)], capture_output=True, text=True
    )
    assert done.returncode in (0, 1), done.stderr
    found: list[dict[str, object]] = json.loads(done.stdout)
    return found


def _lines_of(text: str, unique_id: str) -> range:
    """The lines (from 1) of the <parameter> whose uniqueID is `unique_id`."""
    lines = text.splitlines()
    start = next(n for n, line in enumerate(lines) if f'uniqueID="{unique_id}"' in line)
    end = next(n for n in range(start, len(lines)) if "</q1:parameter>" in lines[n])
    return range(start + 1, end + 2)


def test_a_co_disabled_object_is_outside_the_device_for_every_rule() -> None:
    text = _need(GATEWAY).read_text(encoding="utf-8")
    found = _lint(GATEWAY)
    disabled = [
        line
        for uid in ("UID_OBJ_1022", "UID_OBJ_1026", "UID_SUB_102602", "UID_SUB_102603")
        for line in _lines_of(text, uid)
    ]
    assert [f for f in found if f["line"] in disabled or "1022" in str(f["message"])] == []
    # the rules still judge the objects the device has (CiA 302-3 gives 1F51h sub-index 1 UNSIGNED8)
    assert any(f["code"] == "STD003" and "[1F51sub1]" in str(f["message"]) for f in found)


def _edit(text: str, unique_id: str, old: str, new: str) -> str:
    """`text` with `old` replaced by `new` inside the <parameter> whose uniqueID is `unique_id`."""
    where = _lines_of(text, unique_id)
    lines = text.splitlines(keepends=True)
    edited = [line.replace(old, new) for line in lines[where.start - 1 : where.stop]]
    return "".join(lines[: where.start - 1] + edited + lines[where.stop :])


def test_store_format_as_unsigned16_follows_the_peers_and_is_not_an_error(tmp_path: Path) -> None:
    # 1022h enabled: CiA 301 says UNSIGNED8, CANopenEditor/objdictgen/kacanopen UNSIGNED16; the file follows them.
    text = _edit(_need(GATEWAY).read_text(encoding="utf-8"), "UID_OBJ_1022", 'value="true"', 'value="false"')
    copy = tmp_path / "profile.xdd"
    copy.write_text(text, encoding="utf-8")
    assert [f for f in _lint(copy) if "1022" in str(f["message"])] == []
    # a type neither the standard nor a peer gives is still reported
    copy.write_text(_edit(text, "UID_OBJ_1022", "<UINT />", "<UDINT />"), encoding="utf-8")
    assert [f["code"] for f in _lint(copy) if "[1022]" in str(f["message"])] == ["STD003"]


# Commissioned DCFs of ../shared: maxon's EPOS4 node 1 (30AEh: 64 sub-indices, sub0 ParameterValue=64) and Sevcon's
# template, uploaded from a device (1001h Error register, ro, ParameterValue=0x91).
EPOS4 = SHARED / "eds-corpus" / "eds" / "maxon__epos4_50_15_can_ec90flat_gp52c_mile800_node1_demo.dcf"
SEVCON = SHARED / "eds-corpus" / "eds" / "sevcon__template.dcf"


def _edit_section(path: Path, section: str, old: str, new: str, into: Path) -> Path:
    """A copy of `path` in `into` with `old` replaced by `new` in [section] only (line ends kept)."""
    text = _need(path).read_bytes().decode("latin-1")
    start = text.index(f"[{section}]")
    end = text.find("\n[", start)
    end = len(text) if end < 0 else end
    assert old in text[start:end]
    copy = into / path.name
    copy.write_bytes((text[:start] + text[start:end].replace(old, new, 1) + text[end:]).encode("latin-1"))
    return copy


def _at(found: list[dict[str, object]], code: str) -> list[str]:
    return [str(f["message"]) for f in found if f["code"] == code]


def test_sub_index_0_is_judged_by_the_value_the_dcf_configures(tmp_path: Path) -> None:
    # The device holds ParameterValue=64 for its 64 entries; the template's DefaultValue=44 is not what it has.
    copy = _edit_section(EPOS4, "30AEsub0", "DefaultValue=64", "DefaultValue=44", tmp_path)
    assert [m for m in _at(_lint(copy), "EDS026") if "30AE" in m] == []
    # configured too low, it hides entries: said of the ParameterValue
    copy = _edit_section(EPOS4, "30AEsub0", "ParameterValue=64", "ParameterValue=0x36", tmp_path)
    assert [m for m in _at(_lint(copy), "EDS026") if "30AE" in m] == [
        "[30AEsub0]: ParameterValue=54 but sub-index 64 exists"
    ]


def test_the_uploaded_parameter_value_of_a_read_only_entry_is_not_a_configuration(tmp_path: Path) -> None:
    copy = _edit_section(SEVCON, "1001", "HighLimit=0xFF", "HighLimit=0x7F", tmp_path)
    assert [m for m in _at(_lint(copy), "EDS061") if "1001" in m] == []
    # a writable entry's ParameterValue is downloaded at boot-up: outside its limits, the configuration fails
    (tmp_path / "rw").mkdir()
    writable = _edit_section(copy, "1001", "AccessType=ro", "AccessType=rw", tmp_path / "rw")
    assert len([m for m in _at(_lint(writable), "EDS061") if "1001" in m]) == 1


HISTORY = SHARED / "eds-history"


def test_a_fixed_pdo_cob_id_of_another_nodes_pdo_is_a_link_not_advised_nodeid() -> None:
    # zylos146/CANFuck: RPDO1 on 1BFh consumes TPDO1 of node 63, TPDO1 on 23Fh feeds its RPDO1.
    found = _at(_lint(_need(HISTORY / "zylos146__CANFuck__1" / "new.xdd")), "COB006")
    links = [m for m in found if m.startswith(("RPDO1:", "TPDO1:"))]
    assert links == [
        "RPDO1: default COB-ID 0x1BF is the pre-defined CAN-ID of TPDO1 of node-ID 63: likely a link to another "
        "node's PDO, which $NODEID+0x200 would break; keep it if so",
        "TPDO1: default COB-ID 0x23F is the pre-defined CAN-ID of RPDO1 of node-ID 63: likely a link to another "
        "node's PDO, which $NODEID+0x180 would break; keep it if so",
    ]
    # sudriabotik/carte_lidar_stm32: RPDO1 on 281h (TPDO2 of node 1) is a link; TPDO1 on 183h is this node's own
    found = _at(_lint(_need(HISTORY / "sudriabotik__carte_lidar_stm32__1" / "new.xdd")), "COB006")
    assert [m for m in found if m.startswith("RPDO1:")] == [
        "RPDO1: default COB-ID 0x281 is the pre-defined CAN-ID of TPDO2 of node-ID 1: likely a link to another "
        "node's PDO, which $NODEID+0x200 would break; keep it if so"
    ]
    assert [m for m in found if m.startswith("TPDO1:")] == [
        "TPDO1: default COB-ID 0x183 fits one node-ID only; write $NODEID+0x180"
    ]


# node-canopen's test EDS, written for CANopenNode (its ;StorageLocation= lines): TPDO1 stores the base 0x180.
NODE_CANOPEN = SHARED / "eds-corpus" / "eds" / "node-canopen__test.eds"


def test_a_canopennode_base_cob_id_is_what_other_tools_read_literally(tmp_path: Path) -> None:
    found = [f for f in _lint(_need(NODE_CANOPEN)) if f["code"] == "COB004" and "TPDO1" in str(f["message"])]
    assert [(f["message"], f["fix"]) for f in found] == [
        (
            "TPDO1: COB-ID 0x180 is the pre-defined base: CANopenNode sends on it + node-ID, but every other tool "
            "reads the restricted CAN-ID 180h; write $NODEID+0x180",
            {"message": "write $NODEID+0x180", "safe": False},
        )
    ]
    assert [m for m in _at(_lint(NODE_CANOPEN), "COB006") if m.startswith("TPDO1:")] == []  # one cause, one finding
    # the same file without CANopenNode's marks is read literally by everyone: a restricted CAN-ID
    plain = tmp_path / NODE_CANOPEN.name
    lines = NODE_CANOPEN.read_bytes().split(b"\n")
    plain.write_bytes(b"\n".join(line for line in lines if not line.startswith(b";StorageLocation=")))
    assert [m for m in _at(_lint(plain), "COB004") if m.startswith("TPDO1:")] == [
        "TPDO1: COB-ID 0x180 is a restricted CAN-ID"
    ]


def test_the_base_cob_id_fix_writes_what_the_stack_sends_and_nothing_else(tmp_path: Path) -> None:
    copy = tmp_path / NODE_CANOPEN.name
    before = _need(NODE_CANOPEN).read_bytes()
    copy.write_bytes(before)
    done = subprocess.run(
        [*cli_command(), "lint", "-j1", "--select", "COB004", "--fix", "--unsafe-fixes", str(copy)], capture_output=True
    )
    assert done.returncode == 0, done.stderr
    changed = [(a, b) for a, b in zip(before.split(b"\n"), copy.read_bytes().split(b"\n"), strict=True) if a != b]
    assert changed == [(b"DefaultValue=0x00000180\r", b"DefaultValue=$NODEID+0x180\r")]


# zylos146/CANFuck's CANopenEditor project: 51 entries (the PDO communication records among them) with
# access="noAccess", as CANopenEditor writes an entry whose access type it does not know.
CANFUCK = HISTORY / "zylos146__CANFuck__1" / "new.xdd"


def test_an_xdd_no_access_entry_is_said_as_such_not_an_empty_access_type() -> None:
    found = [f for f in _lint(_need(CANFUCK)) if f["code"] == "EDS020"]
    assert len(found) == 51
    assert {f["severity"] for f in found} == {"warning"}
    assert found[0]["message"] == (
        '[1400sub0]: access="noAccess": no SDO reads or writes it, and an EDS has no AccessType for it '
        "(CANopenEditor writes noAccess where it does not know the access type)"
    )


def test_convert_writes_no_empty_access_type_and_says_what_it_cannot_keep(tmp_path: Path) -> None:
    out = tmp_path / "canfuck.eds"
    done = subprocess.run(
        [*cli_command(), "convert", str(_need(CANFUCK)), "-o", str(out)], capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    assert 'access="noAccess" of 1400sub0, 1400sub1, 1400sub2, 1401sub0, 1401sub1 ... is not kept in EDS' in done.stderr
    text = out.read_text(encoding="utf-8")
    assert "AccessType=\n" not in text
    assert text.split("[1400sub1]\n", 1)[1].split("\n\n", 1)[0].count("AccessType=ro") == 1
    assert _at(_lint(out), "EDS020") == []  # our own lint accepts what convert wrote


# sudriabotik/carte_lidar_stm32 (CANopenEditor v4.0): 2000h is access="readWriteInput" beside PDOmapping="RPDO";
# the project's OD.c gives it ODA_RPDO (the stack follows PDOmapping).
SUDRIABOTIK = HISTORY / "sudriabotik__carte_lidar_stm32__1" / "new.xdd"


def test_an_inverted_canopeneditor_access_says_which_word_the_stack_follows(tmp_path: Path) -> None:
    copy = tmp_path / "DS301_profile.xdd"
    text = _need(SUDRIABOTIK).read_text(encoding="utf-8")
    copy.write_text(_edit(text, "UID_SUB_160001", "0x22000010", "0x20000010"), encoding="utf-8")  # RPDO1 maps 2000h
    found = [f for f in _lint(copy) if f["code"] == "PDO044" and "2000sub0" in str(f["message"])]
    assert [(f["severity"], f["message"]) for f in found] == [
        (
            "warning",
            "RPDO1 writes 2000sub0 (ACTION_ID), whose access is rwr beside PDOmapping=RPDO: CANopenNode follows "
            "PDOmapping (CANopenEditor v4.0 wrote the access inverted; its OD.c maps the entry into RPDOs), tools "
            "that read the access do not",
        )
    ]


def test_an_xdd_device_descriptions_node_id_0_is_a_placeholder_not_an_error() -> None:
    # oresat-firmware's CANopenEditor project: <deviceCommissioning nodeID="0" .../> in a .xdd
    found = [
        f for f in _lint(_need(HISTORY / "oresat__oresat-firmware__6" / "new.xdd")) if f["code"] in ("EDS062", "EDS063")
    ]
    assert [(f["code"], f["severity"]) for f in found] == [("EDS063", "info")]


def test_a_pdo_communication_sub0_above_the_subs_described_is_reported() -> None:
    # zylos146/CANFuck: 1400h and 1401h count 6 sub-indices and describe sub0-sub2 (an RPDO's end at sub5)
    found = [m for m in _at(_lint(_need(CANFUCK)), "PDO010")]
    assert found == [
        "RPDO1: 1400sub0 is 6, but only sub0-sub2 are described: reading sub6 fails",
        "RPDO2: 1401sub0 is 6, but only sub0-sub2 are described: reading sub6 fails",
    ]


def test_a_disabled_default_sdo_server_is_reported() -> None:
    # oresat-firmware's EDS: 1200h sub1/sub2 = 0x80000000; CiA 301 fixes them (CANopenNode rewrites them at start-up)
    found = _at(_lint(_need(HISTORY / "oresat__oresat-firmware__13" / "old.eds")), "COB012")
    assert found == [
        "SDO server 1200h sub1: 0x80000000 disables it; CiA 301 fixes the default SDO server at 0x600 + node-ID",
        "SDO server 1200h sub2: 0x80000000 disables it; CiA 301 fixes the default SDO server at 0x580 + node-ID",
    ]


def test_a_moved_default_sdo_server_in_a_dcf_is_reported(tmp_path: Path) -> None:
    # maxon's EPOS4 DCF (NodeID=1): 1200h sub1 ParameterValue=0x00000601, as CiA 301 fixes it
    assert _at(_lint(_need(EPOS4)), "COB012") == []
    copy = _edit_section(EPOS4, "1200sub1", "ParameterValue=0x00000601", "ParameterValue=0x00000611", tmp_path)
    assert _at(_lint(copy), "COB012") == [
        "SDO server 1200h sub1: 0x611 is not 0x601 for node-ID 1; CiA 301 fixes the default SDO server at 0x600 "
        "+ node-ID"
    ]


def test_an_rpdo_on_a_can_id_the_device_sends_is_reported(tmp_path: Path) -> None:
    # sudriabotik/carte_lidar_stm32 sends TPDO1 on 183h; its RPDO1 moved there would wait for its own frames
    copy = tmp_path / "DS301_profile.xdd"
    text = _need(SUDRIABOTIK).read_text(encoding="utf-8")
    copy.write_text(_edit(text, "UID_SUB_140001", 'value="0x281"', 'value="0x183"'), encoding="utf-8")
    found = [(f["severity"], f["message"]) for f in _lint(copy) if f["code"] == "COB013"]
    assert found == [("error", "RPDO1 receives on 183h, which this device sends as TPDO1")]
    # oresat's GPS consumes node 1's TPDO1 on 181h and sends its own on $NODEID+0x180: it cannot be node 1
    gps = [(f["severity"], f["message"]) for f in _lint(_need(SHARED / "eds-corpus" / "xdd" / "oresat__gps.xdd"))]
    assert [m for m in gps if "COB013" in m[1] or "receives on" in m[1]] == [
        ("warning", "RPDO1 receives on 181h, which this device sends as TPDO1 if it is node-ID 1")
    ]


PILZ = SHARED / "eds-corpus" / "eds" / "pilz__prbt_0_1.dcf"


def test_a_const_entry_configured_otherwise_in_a_dcf_is_reported(tmp_path: Path) -> None:
    # Pilz's PRBT DCF: 6098h homing_method is const, DefaultValue=0, ParameterValue=0
    assert _at(_lint(_need(PILZ)), "EDS064") == []
    copy = _edit_section(PILZ, "6098", "ParameterValue=0", "ParameterValue=35", tmp_path)
    assert _at(_lint(copy), "EDS064") == ["[6098] is const: ParameterValue=35, but it holds 0"]


# Apach200/0_F407's CANopenEditor project: TPDO2 (valid, 280h + node-ID) pads its frame with a one-byte dummy
# between three entries of 6038h.
PADDED = SHARED / "eds-history" / "Apach200__0_F407__2" / "new.xdd"


def test_a_dummy_in_a_canopennode_tpdo_is_sent_as_zeros_not_an_error(tmp_path: Path) -> None:
    # CANopenNode maps a TPDO's dummy entry to a reader that sends zeros (301/CO_PDO.c, OD_read_dummy): a
    # portability warning, since other stacks may refuse the mapping
    found = [f["severity"] for f in _lint(_need(PADDED)) if f["code"] == "PDO051"]
    assert found and set(found) == {"warning"}
    # the same mapping in an EDS: with the canopennode profile the device is CANopenNode's, without it no stack
    # is named and CiA 301 has no dummy mapping for a TPDO
    plain = tmp_path / "padded.eds"
    plain.write_text(eds(comm(0x1801, "$NODEID+0x280"), mapping(0x1A01, "0x60000108", "0x00020008")))
    assert [f["severity"] for f in _lint(plain, "--profile", "canopennode") if f["code"] == "PDO051"] == ["warning"]
    assert [(f["line"], f["message"]) for f in _lint(plain) if f["code"] == "PDO051"] == [
        (where(plain.read_text(), "1A01sub2", "DefaultValue"), "TPDO2: dummy entry 0x00020008 in a TPDO")
    ]
