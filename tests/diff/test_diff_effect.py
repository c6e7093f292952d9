"""`diff` tells what a change does (issues #42 and #39), each case on the shape of a real revision pair, run as a
user runs it: the installed CLI on the pair's files in place, reports read as text or JSON."""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path
from typing import Any

import pytest
from diffkit import set_key

from support import ROOT, cli_command

HISTORY = ROOT.parent / "shared" / "eds-history"


def run(*args: str | Path, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*cli_command(), *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=120, check=False
    )


def history_pair(name: str) -> tuple[Path, Path]:
    folder = HISTORY / name
    if not folder.is_dir():
        pytest.skip(f"{name} is not in ../shared/eds-history")
    old, new = (next(p for p in folder.iterdir() if p.stem == stem) for stem in ("old", "new"))
    return old, new


def report(old: Path, new: Path, *options: str) -> tuple[dict[str, Any], subprocess.CompletedProcess[str]]:
    result = run("diff", old, new, "--format", "json", *options)
    assert result.returncode in (0, 1), result.stderr
    return json.loads(result.stdout), result


def changes(data: dict[str, Any]) -> list[dict[str, Any]]:
    found = list(data["device"])
    found += [change for obj in data["objects"] for change in obj["changes"]]
    found += [change for pdo in data["pdos"] for change in pdo["changes"]]
    return found


def test_supported_bit_rates_are_not_the_running_rate() -> None:
    """KITmedical kacanopen 1: [DeviceInfo] BaudRate_125=1 ... dropped. They say which rates the device supports."""
    old, new = history_pair("KITmedical__kacanopen__1")
    shown = run("diff", old, new).stdout
    assert "supported bit rate 125 kbit/s: yes → no (no longer able to run at 125 kbit/s)" in shown
    assert "running at" not in shown


def test_unreadable_types_are_compared_as_written() -> None:
    """KITmedical kacanopen 2: every DataType carries a comment (`0x0007 # UNSIGNED32`), which no reader takes;
    54 lines change, 7 of them from UNSIGNED32 to UNSIGNED8. A CI gate on any change must fail, and each of
    those is breaking for the bus and the code, told with the text as written."""
    old, new = history_pair("KITmedical__kacanopen__2")
    gate = run("diff", old, new, "--fail-on", "any")
    assert gate.returncode == 1, gate.stdout[:300]
    assert "compared as written" in gate.stderr
    data, _ = report(old, new, "--fail-on", "wire")
    told = changes(data)
    assert len(told) == 54
    narrowed = [c for c in told if c["old_text"] == "'0x0007 # UNSIGNED32' (unreadable)" and "0x0005" in c["new_text"]]
    assert len(narrowed) == 7 and all(c["breaks"] == ["wire", "code"] for c in narrowed)
    # The same type with another comment: told, as formatting of an unreadable key.
    comment_only = [c for c in told if c["kind"] == "data-type" and c["impact"] == "cosmetic"]
    assert comment_only and all("both mean" in c["note"] for c in comment_only)
    assert run("diff", old, new, "--fail-on", "wire").returncode == 1


def test_pdo_direction_taken_away() -> None:
    """sudriabotik carte_lidar_stm32 1: three objects go from PDOmapping="TPDO" to "RPDO" in the XDD; a master
    that mapped them into a TPDO can no longer."""
    old, new = history_pair("sudriabotik__carte_lidar_stm32__1")
    data, _ = report(old, new)
    told = {(c["index"], c["kind"], c["old_text"], c["new_text"], tuple(c["breaks"])) for c in changes(data)}
    for index in (0x2200, 0x2201, 0x2202):
        assert (index, "pdo-mapping", "TPDO", "RPDO", ("wire",)) in told


def _edited(tmp_path: Path, source: Path, name: str, edits: list[tuple[str, str, str | None]]) -> Path:
    """A copy of a real file with `[section] key=value` edits, as a firmware engineer makes them."""
    text = source.read_text(encoding="latin-1")
    for section, key, value in edits:
        text = set_key(text, section, key, value)
    target = tmp_path / name
    target.write_text(text, encoding="latin-1")
    return target


def _pdo_lines(old: Path, new: Path) -> dict[tuple[int, int | None], tuple[str, str]]:
    """(index, sub-index) → (tag, note) of every PDO change."""
    data, _ = report(old, new)
    return {
        (c["index"], c["subindex"]): ("+".join(c["breaks"]) or c["impact"], c["note"])
        for pdo in data["pdos"]
        for c in pdo["changes"]
    }


def test_event_driven_tpdo_made_synchronous() -> None:
    """samsamfire gocanopen 2: TPDO1's transmission type 254 → 1. A master without SYNC no longer receives it."""
    lines = _pdo_lines(*history_pair("samsamfire__gocanopen__2"))
    assert lines[(0x1800, 2)] == ("wire", "sent on every SYNC instead of on change")


def test_event_timer_and_inhibit_time_given_to_an_event_driven_tpdo() -> None:
    """KITmedical kacanopen 4: TPDO2 (0x1801) gets inhibit time 500 (50 ms) and event timer 100 ms; every PDO's
    transmission type goes 254 → 255, which keeps them event-driven."""
    lines = _pdo_lines(*history_pair("KITmedical__kacanopen__4"))
    assert lines[(0x1801, 5)] == ("wire", "now every 100 ms, also on change")
    assert lines[(0x1801, 3)] == ("wire", "now at most every 50 ms, where it was sent on every change")
    assert lines[(0x1801, 2)][0] == "value"


def test_dcf_parameter_value_is_what_the_bus_sees(tmp_path: Path) -> None:
    """ros_canopen 1's DCF configures TPDO1 synchronous by `ParameterValue=0x1` over `DefaultValue=255`: against
    the same file without that line, and then made acyclic (0); a third revision swaps inhibit time and event
    timer."""
    _, dcf = history_pair("ros-industrial__ros_canopen__1")
    unconfigured = _edited(tmp_path, dcf, "default.dcf", [("1800sub2", "ParameterValue", None)])
    acyclic = _edited(tmp_path, dcf, "acyclic.dcf", [("1800sub2", "ParameterValue", "0")])
    assert _pdo_lines(unconfigured, dcf)[(0x1800, 2)] == ("wire", "sent on every SYNC instead of on change")
    assert _pdo_lines(dcf, acyclic)[(0x1800, 2)] == ("wire", "sent on the SYNC after a change instead of on every SYNC")
    event = [("1800sub2", "ParameterValue", "255")]
    timed = [*event, ("1800sub3", "ParameterValue", "1000"), ("1800sub5", "ParameterValue", "100")]
    swapped = [*event, ("1800sub3", "ParameterValue", "100"), ("1800sub5", "ParameterValue", "1000")]
    lines = _pdo_lines(_edited(tmp_path, dcf, "t.dcf", timed), _edited(tmp_path, dcf, "s.dcf", swapped))
    assert lines[(0x1800, 3)] == (
        "wire",
        "now at most every 10 ms instead of every 100 ms; inhibit time and event timer swapped",
    )
    assert lines[(0x1800, 5)] == (
        "wire",
        "now every 1000 ms instead of every 100 ms; inhibit time and event timer swapped",
    )


def test_sync_start_value_of_a_cyclic_tpdo(tmp_path: Path) -> None:
    """gocanopen 2's synchronous TPDO1 (type 1) given a SYNC start value: first sent at that counter value."""
    _, eds = history_pair("samsamfire__gocanopen__2")
    lines = _pdo_lines(eds, _edited(tmp_path, eds, "start.eds", [("1800sub6", "DefaultValue", "3")]))
    assert lines[(0x1800, 6)] == ("wire", "first sent when the SYNC counter is 3")


def test_sub_objects_moved_are_moves_not_renames() -> None:
    """zylos146 CANFuck 1 (XDD): in 0x2110 "Demand Current" goes from sub-index 10 to 7 and "Demand Position" from
    9 to 8; what stood at 7 and 8 is gone, two new entries take 9 and 10. Code built against the old file still
    compiles (demand_current exists) and reads sub-index 10."""
    data, _ = report(*history_pair("zylos146__CANFuck__1"))
    told = {(c["subindex"], c["kind"], c["name"], tuple(c["breaks"])) for c in changes(data) if c["index"] == 0x2110}
    assert (7, "sub-moved", "Demand Current", ("wire", "code")) in told
    assert (8, "sub-moved", "Demand Position", ("wire", "code")) in told
    assert (7, "sub-removed", "Actual Current", ("wire", "code")) in told
    assert (9, "sub-added", "Model Temp", ()) in told and (10, "sub-added", "Real Temp", ()) in told
    assert not any(kind == "name" for _, kind, _, _ in told)
    note = next(c["note"] for c in changes(data) if c["kind"] == "sub-moved" and c["subindex"] == 7)
    assert note.startswith("demand_current now at sub-index 7, was 10")


def test_permutation_keeps_the_symbols_and_swaps_their_meaning(tmp_path: Path) -> None:
    """The names of zylos146's 0x2110:07 and 0x2110:08 traded places (the shape of the real revision, closed):
    the symbol set is the same, each symbol addresses the other quantity."""
    _, xdd = history_pair("zylos146__CANFuck__1")
    text = xdd.read_text(encoding="utf-8")
    swapped = text.replace('"Demand Current"', "\0").replace('"Demand Position"', '"Demand Current"')
    permuted = tmp_path / "permuted.xdd"
    permuted.write_text(swapped.replace("\0", '"Demand Position"'), encoding="utf-8")
    data, _ = report(xdd, permuted)
    moved = {c["subindex"]: c for c in changes(data) if c["kind"] == "sub-moved"}
    assert set(moved) == {7, 8} and all(c["breaks"] == ["wire", "code"] for c in moved.values())
    assert moved[7]["note"].startswith("meaning swapped: demand_position now at sub-index 7, was 8")
    assert moved[8]["note"].startswith("meaning swapped: demand_current now at sub-index 8, was 7")
    # Their descriptions stayed with the sub-indices (the edit moved the names only): cosmetic, nothing else.
    assert {(c["kind"], c["impact"]) for c in changes(data)} == {("sub-moved", "breaking"), ("extra-key", "cosmetic")}


def _shifted(text: str, indices: dict[int, int]) -> str:
    """Sections and [ManufacturerObjects] entries of the objects at `indices` moved to their new index."""

    def section(match: re.Match[str]) -> str:
        index = int(match[1], 16)
        return f"[{indices.get(index, index):04X}{match[2]}"

    def listed(match: re.Match[str]) -> str:
        index = int(match[2], 16)
        return f"{match[1]}0x{indices.get(index, index):04X}"

    text = re.sub(r"^\[([0-9A-Fa-f]{4})(sub|\])", section, text, flags=re.MULTILINE)
    return re.sub(r"^(\d+=)0x([0-9A-Fa-f]{4})$", listed, text, flags=re.MULTILINE)


def test_shifted_block_is_moves(tmp_path: Path) -> None:
    """KITmedical kacanopen 4's 13 objects 0x5510-0x551C moved up by one index: 13 moves, nothing else."""
    _, eds = history_pair("KITmedical__kacanopen__4")
    shifted = tmp_path / "shifted.eds"
    shifted.write_text(_shifted(eds.read_text(encoding="latin-1"), {i: i + 1 for i in range(0x5510, 0x551D)}))
    data, _ = report(eds, shifted)
    told = changes(data)
    assert {(c["kind"], c["old"], c["new"]) for c in told} == {
        ("object-moved", i, i + 1) for i in range(0x5510, 0x551D)
    }
    assert all(c["note"].startswith("one of 13 objects shifted by +1") for c in told)


def test_objects_that_trade_indices_swap_meaning(tmp_path: Path) -> None:
    """KITmedical kacanopen 4's 0x5500 and 0x5501 traded indices: the same objects, each where the other was."""
    _, eds = history_pair("KITmedical__kacanopen__4")
    swapped = tmp_path / "swapped.eds"
    swapped.write_text(_shifted(eds.read_text(encoding="latin-1"), {0x5500: 0x5501, 0x5501: 0x5500}))
    data, _ = report(eds, swapped)
    told = changes(data)
    assert [(c["kind"], c["old"], c["new"], c["breaks"]) for c in told] == [
        ("object-moved", 0x5501, 0x5500, ["wire", "code"]),
        ("object-moved", 0x5500, 0x5501, ["wire", "code"]),
    ]
    assert all(c["note"].startswith("meaning swapped: ") for c in told)


def _without_objects(eds: str, indices: set[int]) -> str:
    """An EDS without these objects' sections, as CANopenEditor exports one beside its XDD (CANopenDemo's
    demoDevice.eds leaves out the object its demoDevice.xdd disables)."""
    kept = []
    for block in re.split(r"(?m)^(?=\[)", eds):
        name = re.match(r"\[([0-9A-Fa-f]{4})(?:sub[0-9A-Fa-f]+|Name|Value)?\]", block)
        if name is None or int(name[1], 16) not in indices:
            kept.append(block)
    return "".join(kept)


def test_disabled_objects_are_outside_the_device_on_both_sides(tmp_path: Path) -> None:
    """EvgenyDD sh_node 4's XDD disables 29 objects (CO_disabled); the EDS exported beside it has none of
    them. Neither device has them: nothing is removed or added for the bus or the code."""
    _, xdd = history_pair("EvgenyDD__sh_node__4")
    disabled = {int(i, 16) for i in re.findall(r'index="([0-9A-F]{4})"', xdd.read_text(encoding="utf-8"))}
    converted = tmp_path / "profile.eds"
    assert run("convert", xdd, "-o", converted).returncode == 0
    from cantools_od import load

    disabled = {i for i in disabled if (c := load(xdd).objects[i].canopennode) is not None and c.disabled}
    assert len(disabled) == 29
    exported = tmp_path / "exported.eds"
    exported.write_text(_without_objects(converted.read_text(encoding="utf-8"), disabled), encoding="utf-8")
    for old, new in ((xdd, exported), (exported, xdd)):
        data, result = report(old, new, "--fail-on", "breaking")
        assert result.returncode == 0, [c for c in changes(data) if c["impact"] == "breaking"][:3]
        whole = [c for c in changes(data) if c["kind"] in ("object-added", "object-removed")]
        assert {c["index"] for c in whole} == disabled
        assert all(c["impact"] == "cosmetic" and "outside the device" in c["note"] for c in whole)


def test_enabled_and_disabled_by_what_the_od_gains_or_loses() -> None:
    """EvgenyDD sh_gateway 3: the first RPDO and TPDO enabled (CO_disabled dropped): the OD gains them."""
    old, new = history_pair("EvgenyDD__sh_gateway__3")
    data, _ = report(old, new)
    enabled = [c for c in changes(data) if c["field"] == "canopennode.disabled"]
    assert {c["index"] for c in enabled} == {0x1400, 0x1600, 0x1800, 0x1A00}
    assert all(c["impact"] == "compatible" and c["note"].startswith("enabled") for c in enabled)
    back, _ = report(new, old)
    disabled = [c for c in changes(back) if c["field"] == "canopennode.disabled"]
    assert all(c["breaks"] == ["wire", "code"] and c["note"].startswith("disabled") for c in disabled)


def test_key_spelling_python_canopen_reads_differently(tmp_path: Path) -> None:
    """dianhuaeven Eyou_Canopen_master 2's DCF writes `Baudrate=1000` in [DeviceComissioning]; spelled
    `BaudRate=1000`, CiA 306 and lely read the same, python-canopen no bit rate (DIA018). The change is told."""
    _, dcf = history_pair("dianhuaeven__Eyou_Canopen_master__2")
    respelled = _edited(tmp_path, dcf, "respelled.dcf", [("DeviceComissioning", "Baudrate", None)])
    respelled.write_text(
        set_key(respelled.read_text(encoding="latin-1"), "DeviceComissioning", "BaudRate", "1000"), encoding="latin-1"
    )
    from canopen import import_od

    assert (import_od(str(respelled)).bitrate, import_od(str(dcf)).bitrate) == (None, 1_000_000)
    gate = run("diff", respelled, dcf, "--fail-on", "any")
    assert gate.returncode == 1, gate.stdout
    data, _ = report(respelled, dcf)
    (told,) = [c for c in changes(data) if c["kind"] == "peer-reading"]
    assert (told["old_text"], told["new_text"]) == ("BaudRate", "Baudrate")
    assert told["note"] == "python-canopen now reads this key in [DeviceComissioning]: it did not before"
