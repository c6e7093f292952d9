"""`simulate` and `probe` on python-can's `virtual` bus, inside this process: python-canopen as the master
of a simulated node (SDO with CiA 301 abort codes, boot-up, heartbeat, NMT, PDOs on SYNC, RPDOs, EMCY), and
`probe` of a simulation (nothing to report) and of descriptions that differ from it (exactly their finding).
tests/test_live_cli.py runs the installed commands between processes."""

from __future__ import annotations

import itertools
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import can
import canopen
import pytest
from can.interfaces.virtual import VirtualBus
from livekit import received_on_sync

from cantools_od.api import load, loads
from cantools_od.lint import examples as ex
from cantools_od.live.probe import NoAnswer, ProbeOptions, Prober, ProbeResult
from cantools_od.live.simulator import CannotServe, Simulator
from cantools_od.model import Device

from support import EXAMPLES, corpus_params

DRIVE = EXAMPLES / "cia402_drive.eds"
NODE = 5
CHANNELS = itertools.count()


def _network(channel: str) -> canopen.Network:
    network = canopen.Network(can.Bus(interface="virtual", channel=channel))
    network.NOTIFIER_CYCLE = 0.05
    return network


@contextmanager
def served(device: Device, start: bool = True) -> Iterator[tuple[Simulator, canopen.Network]]:
    """The simulated node of `device`, and a master's network on the same virtual bus."""
    channel = f"live-{next(CHANNELS)}"
    node_side, master = _network(channel), _network(channel)
    simulator = Simulator(device, NODE, node_side)
    node_side.connect()
    master.connect()
    try:
        if start:
            simulator.start()
        yield simulator, master
    finally:
        simulator.stop()
        master.disconnect()
        node_side.disconnect()


def probed(served_device: Device, described: Device, check_writes: bool = False) -> ProbeResult:
    with served(served_device) as (_, master):
        return Prober(described, NODE, master, ProbeOptions(timeout=0.5, check_writes=check_writes)).run()


def _abort(call: object) -> int:
    with pytest.raises(canopen.SdoAbortedError) as aborted:
        call()  # type: ignore[operator]
    return int(aborted.value.code)


LIMITED = ex.frame(
    ex.section(
        "2000", ParameterName="Speed", ObjectType="0x7", DataType="0x0006", AccessType="rw",
        DefaultValue=5, LowLimit=1, HighLimit=100, PDOMapping=0,
    )
)  # fmt: skip


def test_sdo_answers_by_access_type_and_limits_with_cia_301_abort_codes() -> None:
    device = loads(LIMITED, source="limited.eds")
    with served(device) as (_, master):
        node = master.add_node(NODE, canopen.ObjectDictionary())
        sdo = node.sdo
        assert sdo.upload(0x2000, 0) == (5).to_bytes(2, "little")
        assert sdo.upload(0x1018, 1) == (1).to_bytes(4, "little")  # the frame's VendorNumber
        assert _abort(lambda: sdo.upload(0x2001, 0)) == 0x06020000
        assert _abort(lambda: sdo.upload(0x1018, 9)) == 0x06090011
        assert _abort(lambda: sdo.download(0x1000, 0, bytes(4))) == 0x06010002
        assert _abort(lambda: sdo.download(0x2000, 0, bytes(4))) == 0x06070010
        assert _abort(lambda: sdo.download(0x2000, 0, (101).to_bytes(2, "little"))) == 0x06090031
        assert _abort(lambda: sdo.download(0x2000, 0, (0).to_bytes(2, "little"))) == 0x06090032
        sdo.download(0x2000, 0, (42).to_bytes(2, "little"))
        assert sdo.upload(0x2000, 0) == (42).to_bytes(2, "little")


def test_boot_up_heartbeat_and_reset_as_a_master_sees_them() -> None:
    device = load(DRIVE)
    with served(device, start=False) as (simulator, master):
        node = master.add_node(NODE, canopen.ObjectDictionary())
        booted = _boot_up_seen(master)
        simulator.start()
        assert booted.wait(2)
        node.sdo.download(0x1017, 0, (50).to_bytes(2, "little"))
        assert node.nmt.wait_for_heartbeat(1) == "PRE-OPERATIONAL"
        node.nmt.state = "OPERATIONAL"
        time.sleep(0.15)
        assert node.nmt.wait_for_heartbeat(1) == "OPERATIONAL"
        booted.clear()
        node.nmt.state = "RESET"
        assert booted.wait(2)
        default = device.objects[0x1017].default
        assert int.from_bytes(node.sdo.upload(0x1017, 0), "little") == default  # the reset restored it


def _boot_up_seen(master: canopen.Network) -> object:
    import threading

    seen = threading.Event()
    master.subscribe(0x700 + NODE, lambda can_id, data, ts: seen.set() if bytes(data) == b"\0" else None)
    return seen


def test_tpdo_on_sync_rpdo_into_the_dictionary_and_emcy() -> None:
    with served(load(DRIVE)) as (simulator, master):
        node = master.add_node(NODE, str(DRIVE))
        node.tpdo.read(from_od=True)
        node.rpdo.read(from_od=True)
        node.nmt.state = "OPERATIONAL"
        time.sleep(0.1)
        simulator.set(0x6041, 0, 0x0237)
        simulator.set(0x6064, 0, -1234)
        synchronous = next(p for p in node.tpdo.map.values() if p.enabled and p.trans_type == 1)
        assert received_on_sync(master, synchronous)
        assert synchronous["Statusword"].raw == 0x0237
        assert synchronous["Position actual value"].raw == -1234
        event = next(p for p in node.rpdo.map.values() if p.enabled and p.trans_type >= 254)
        event["Controlword"].raw = 0x000F
        event.transmit()
        time.sleep(0.2)
        assert simulator.get(0x6040) == 0x000F
        simulator.emcy(0x8130, 0x11)
        assert node.emcy.wait(0x8130, 1) is not None


def test_probe_of_its_own_simulation_reads_every_entry_and_finds_nothing() -> None:
    device = load(DRIVE)
    result = probed(device, device, check_writes=True)
    assert result.findings == []
    entries = sum(len(obj.subs) or 1 for obj in device.objects.values())
    assert result.read == entries
    assert result.transfers > entries  # the writes back


def _mutated(old: str, new: str) -> Device:
    text = DRIVE.read_text(encoding="utf-8")
    assert old in text
    return loads(text.replace(old, new, 1), source="mutated.eds")


SPEED = ex.var(0x2100, "Extra", 0x0006, "rw", 0, 0)


@pytest.mark.parametrize(
    ("served_old", "served_new", "described_old", "described_new", "code"),
    [
        pytest.param("", "", "[1000]", SPEED + "\n[1000]", "PRB001", id="missing object"),
        pytest.param(
            "", "", "[1018sub3]", "[1018sub5]\nParameterName=Extra\nDataType=0x0007\nAccessType=ro\n\n[1018sub3]",
            "PRB001", id="missing sub-index",
        ),
        pytest.param(
            "", "", "ParameterName=Modes of operation\nObjectType=0x7\nDataType=0x0002",
            "ParameterName=Modes of operation\nObjectType=0x7\nDataType=0x0003", "PRB002", id="wrong type size",
        ),
        pytest.param("ParameterName=Controlword\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\n",
                     "ParameterName=Controlword\nObjectType=0x7\nDataType=0x0006\nAccessType=wo\n", "", "",
                     "PRB003", id="read refused"),
        pytest.param("", "", "VendorNumber=0x00000CA7", "VendorNumber=0x00000CA8", "PRB004", id="wrong identity"),
        pytest.param("", "", "[1017]\nParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0006\n"
                     "AccessType=rw\nDefaultValue=", "[1017]\nParameterName=Producer heartbeat time\nObjectType=0x7\n"
                     "DataType=0x0006\nAccessType=rw\nDefaultValue=1", "PRB006", id="communication value"),
    ],
)  # fmt: skip
def test_each_difference_gives_exactly_its_finding(
    served_old: str, served_new: str, described_old: str, described_new: str, code: str
) -> None:
    device = _mutated(served_old, served_new) if served_old else load(DRIVE)
    described = _mutated(described_old, described_new) if described_old else load(DRIVE)
    result = probed(device, described)
    assert [finding.code for finding in result.findings] == [code], [f.format() for f in result.findings]
    assert result.findings[0].location.file == described.source and result.findings[0].location.line > 0


def test_a_manufacturer_value_that_differs_is_information() -> None:
    described = _mutated("ParameterName=Modes of operation\nObjectType=0x7\nDataType=0x0002\nAccessType=rw\n"
                         "DefaultValue=0", "ParameterName=Modes of operation\nObjectType=0x7\nDataType=0x0002\n"
                         "AccessType=rw\nDefaultValue=8")  # fmt: skip
    findings = probed(load(DRIVE), described).findings
    assert [(f.code, f.severity.value) for f in findings] == [("PRB005", "info")]
    assert findings[0].message == "[6060] Modes of operation: the device holds 0, the file's DefaultValue is 8"


def test_an_entry_the_device_does_not_answer() -> None:
    device = load(DRIVE)
    with served(device) as (simulator, master):
        simulator.silence(0x6041)
        result = Prober(device, NODE, master, ProbeOptions(timeout=0.3)).run()
    assert [(f.code, f.message) for f in result.findings] == [
        ("PRB008", "[6041] Statusword: the device does not answer the read")
    ]


def test_a_node_that_stops_answering_ends_the_probe() -> None:
    device = load(DRIVE)
    with served(device) as (simulator, master):
        for sub in range(4):
            simulator.silence(0x1018, sub)
        with pytest.raises(NoAnswer, match=r"node 5 stopped answering SDO \(from 1018sub2 on\)"):
            Prober(device, NODE, master, ProbeOptions(timeout=0.2)).run()


@pytest.mark.filterwarnings("error::pytest.PytestUnhandledThreadExceptionWarning")  # a traceback
def test_a_bus_that_fails_during_the_probe_is_one_line_and_2(monkeypatch: pytest.MonkeyPatch) -> None:
    """The adapter fails after some frames (unplugged, bus-off): one line, exit 2, as the user sees it."""
    from click.testing import CliRunner

    from cantools_od.cli import main

    channel = f"live-{next(CHANNELS)}"
    sent = itertools.count()
    original = VirtualBus.send

    def failing(bus: can.BusABC, message: can.Message, timeout: float | None = None) -> None:
        if message.arbitration_id == 0x600 + NODE and next(sent) > 20:
            raise can.CanOperationError("Transmit buffer full")
        original(bus, message, timeout)

    node_side = _network(channel)
    simulator = Simulator(load(DRIVE), NODE, node_side)
    node_side.connect()
    simulator.start()
    try:
        monkeypatch.setattr(VirtualBus, "send", failing)
        args = ["probe", str(DRIVE), "--node-id", str(NODE), "-i", "virtual", "-c", channel]
        result = CliRunner().invoke(main, args)
    finally:
        simulator.stop()
        node_side.disconnect()
    assert result.exit_code == 2, result.output
    assert result.output.strip().splitlines()[-1] == "probe: error: the CAN bus failed: Transmit buffer full"
    assert "Traceback" not in result.output


@pytest.mark.filterwarnings("error::pytest.PytestUnhandledThreadExceptionWarning")  # a traceback
def test_a_bus_that_fails_under_simulate_is_one_line_and_2(monkeypatch: pytest.MonkeyPatch) -> None:
    from click.testing import CliRunner

    from cantools_od.cli import main

    def failing(bus: can.BusABC, timeout: float | None) -> None:
        raise can.CanOperationError("the adapter is gone")

    monkeypatch.setattr(VirtualBus, "_recv_internal", failing)
    args = ["simulate", str(DRIVE), "--node-id", str(NODE), "-i", "virtual", "-c", f"live-{next(CHANNELS)}"]
    result = CliRunner().invoke(main, [*args, "--duration", "5"])
    assert result.exit_code == 2, result.output
    assert result.output.strip().splitlines()[-1] == "simulate: error: the adapter is gone"
    assert "Traceback" not in result.output


def test_wrong_access_found_by_writing_back() -> None:
    device = _mutated("ParameterName=Controlword\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\n",
                      "ParameterName=Controlword\nObjectType=0x7\nDataType=0x0006\nAccessType=ro\n")  # fmt: skip
    described = load(DRIVE)
    assert probed(device, described).findings == []  # reading alone cannot tell
    written = probed(device, described, check_writes=True).findings
    assert [f.code for f in written] == ["PRB007"]
    assert "0601 0002h" in written[0].message


def test_a_node_that_does_not_answer_is_no_probe() -> None:
    device = load(DRIVE)
    network = _network(f"live-{next(CHANNELS)}")
    network.connect()
    try:
        started = time.monotonic()
        with pytest.raises(NoAnswer, match="node 5 does not answer"):
            Prober(device, NODE, network, ProbeOptions(timeout=0.2)).run()
        assert time.monotonic() - started < 2
    finally:
        network.disconnect()


@pytest.mark.parametrize("path", corpus_params())
def test_probe_of_a_corpus_simulation_finds_nothing(path: Path) -> None:
    """Every corpus device python-canopen can serve (about 0.4 s each: all 97 in 40 s on one core)."""
    device = load(path, node_id=NODE)
    try:
        result = probed(device, device)
    except CannotServe as refused:
        pytest.skip(str(refused))  # eds-dcf-net's full_features.dcf: an RPDO without its mapping record
    assert result.findings == [], [f.format() for f in result.findings[:3]]
    assert result.read > 0


BUS = """\
master:
  node_id: 1
drive:
  dcf: cia402_drive.eds
  node_id: 5
  heartbeat_producer: 100
  sdo:
    - {index: 0x6060, sub_index: 0, value: 1}
  tpdo:
    1:
      transmission: 1
      cob_id: auto
      mapping:
        - {index: 0x6041, sub_index: 0}
        - {index: 0x6064, sub_index: 0}
"""


def test_network_boot_writes_configure_a_simulated_slave(tmp_path: Path) -> None:
    """`network`'s concise DCF, written by SDO as the master does at boot, is taken by the simulated slave; the
    slave then holds what `network`'s DCF of it says (probe finds nothing) and sends the TPDO as remapped."""
    import shutil
    import subprocess

    from cantools_od.model.cia301.master import read_concise_dcf

    from support import cli_command

    shutil.copy(DRIVE, tmp_path / DRIVE.name)
    (tmp_path / "bus.yml").write_text(BUS, encoding="utf-8")
    made = subprocess.run([*cli_command(), "network", "bus.yml", "-o", "out"], cwd=tmp_path, capture_output=True)
    assert made.returncode == 0, made.stderr
    writes = read_concise_dcf((tmp_path / "out" / "drive.bin").read_bytes())
    configured = load(tmp_path / "out" / "drive.dcf")
    with served(load(DRIVE)) as (simulator, master):
        node = master.add_node(NODE, canopen.ObjectDictionary())
        for index, sub, data in writes:
            node.sdo.download(index, sub, data)
        simulator.set(0x6041, 0, 0x0237)
        frames: list[bytes] = []
        master.subscribe(0x180 + NODE, lambda can_id, data, ts: frames.append(bytes(data)))
        node.nmt.state = "OPERATIONAL"
        time.sleep(0.1)
        master.sync.transmit()
        time.sleep(0.3)
        assert frames and frames[-1][:2] == (0x0237).to_bytes(2, "little") and len(frames[-1]) == 6
        result = Prober(configured, NODE, master, ProbeOptions(timeout=0.5)).run()  # takes the node-ID over
        assert [f.format() for f in result.findings] == []
