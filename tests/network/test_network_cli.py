"""`cantools-od network` as users run it: hostile bus descriptions, refusals in one line, all or nothing,
the network checks at file:line, bus load against hand-computed frames."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from cantools_od.model.cia301.master import read_concise_dcf
from cantools_od.network.load import fd_frame_time, frame_bits

from support import EXAMPLES, cli_command

BUS = """\
options:
  dcf_path: "@INSTALL@"
master:
  node_id: 1
  sync_period: 10000
drive:
  node_id: 2
  dcf: cia402_drive.eds
  tpdo:
    1:
      cob_id: auto
      transmission: 1
      mapping:
        - {index: 0x6041, sub_index: 0}
        - {index: 0x6064, sub_index: 0}
  rpdo:
    1:
      cob_id: auto
      mapping:
        - {index: 0x6040, sub_index: 0}
  sdo:
    - {index: 0x6060, sub_index: 0, value: 1}
io:
  node_id: 3
  dcf: io_device.eds
"""


def run(*args: str | Path, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*cli_command(), "network", *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=120
    )


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    for name in ("cia402_drive.eds", "io_device.eds"):
        shutil.copy(EXAMPLES / name, tmp_path / name)
    (tmp_path / "bus.yml").write_text(BUS)
    return tmp_path


def test_generates_master_and_concise_dcfs(folder: Path) -> None:
    before = {p.name: (p.read_bytes(), p.stat().st_mode) for p in folder.iterdir()}
    result = run(folder / "bus.yml", "-o", folder / "out", "--define", "INSTALL=/opt/cfg")
    assert result.returncode == 0, result.stderr
    assert {p.name: (p.read_bytes(), p.stat().st_mode) for p in folder.iterdir() if p.is_file()} == before
    writes = read_concise_dcf((folder / "out" / "drive.bin").read_bytes())
    # TPDO1: disable (COB-ID with bit 31), transmission type, mapping 0, two entries, count, enable; then the sdo list
    assert writes[0] == (0x1400, 1, (0x80000202).to_bytes(4, "little"))  # RPDOs first, as dcfgen
    assert (0x1800, 1, (0x80000182).to_bytes(4, "little")) in writes
    assert (0x1A00, 1, (0x60410010).to_bytes(4, "little")) in writes
    assert (0x1A00, 2, (0x60640020).to_bytes(4, "little")) in writes
    assert writes[-1] == (0x6060, 0, b"\x01")
    master = (folder / "out" / "master.dcf").read_text()
    assert "UploadFile=/opt/cfg/drive.bin" in master and "DefaultValue=0x00000182" in master
    assert (folder / "out" / "drive.dcf").is_file() and (folder / "out" / "io.dcf").is_file()
    assert (
        subprocess.run([*cli_command(), "lint", str(folder / "out" / "drive.dcf")], capture_output=True).returncode == 0
    )


@pytest.mark.parametrize(
    ("edit", "message"),
    [
        (
            ("  sync_period: 10000", "  sync_periode: 10000"),
            "bus.yml:5: error: unknown key 'sync_periode' in master; did you mean sync_period",
        ),
        (
            ("cob_id: auto\n      transmission", "cob_id: auto\n      transmision"),
            "bus.yml:12: error: unknown key 'transmision' in drive.tpdo.1; did you mean transmission",
        ),
        (("node_id: 3", "node_id: 200"), "bus.yml:24: error: io: node_id 200 is not 1-127"),
        (("dcf: io_device.eds", "dcf: nowhere.eds"), "bus.yml:25: error: io: dcf 'nowhere.eds' is not in"),
        (("  node_id: 2\n", "  node_id: 2\n  node_id: 4\n"), "bus.yml:8: error: not YAML: key 'node_id' written twice"),
        (("master:\n", "master: [\n"), "error: not YAML"),
    ],
)
def test_refusals_are_one_line(folder: Path, edit: tuple[str, str], message: str) -> None:
    text = BUS.replace(*edit)
    assert text != BUS
    (folder / "bus.yml").write_text(text)
    result = run(folder / "bus.yml", "-o", folder / "out", "--define", "INSTALL=/x", cwd=folder)
    assert result.returncode == 2 and result.stderr.count("\n") == 1, result.stderr
    assert message in result.stderr and "Traceback" not in result.stderr
    assert not (folder / "out").exists()


def test_sdo_entries_checked_at_their_lines(folder: Path) -> None:
    extra = "    - {index: 0x6F60, value: 3}\n    - {index: 0x6041, value: 3}\n    - {index: 0x6060, value: 300}\n"
    (folder / "bus.yml").write_text(BUS.replace("value: 1}\n", "value: 1}\n" + extra))
    for command in (["network", "bus.yml", "-o", "out"], ["lint", "--network", "bus.yml"]):
        args = [*cli_command(), *command, "--define", "INSTALL=/x"]
        result = subprocess.run(args, capture_output=True, text=True, cwd=folder, timeout=120)
        assert result.returncode == 1 and not (folder / "out").exists()
        found = result.stderr + result.stdout
        assert "bus.yml:23:1: error: drive: object 6F60sub0 does not exist in cia402_drive.eds [COB011]" in found
        assert "bus.yml:24:1: error: drive: object 6041sub0 is ro: the master cannot write it [COB011]" in found
        assert "bus.yml:25:1: error: drive: 6060sub0 is INTEGER8: 300 is out of its range -128..127 [COB011]" in found


def test_lint_takes_a_bus_description_with_network_only(folder: Path) -> None:
    result = subprocess.run([*cli_command(), "lint", "bus.yml"], capture_output=True, text=True, cwd=folder)
    assert (
        result.returncode == 2
        and result.stderr == "bus.yml: error: a bus description is checked as a network: add --network\n"
    )
    clean = subprocess.run(
        [*cli_command(), "lint", "--network", "bus.yml", "--define", "INSTALL=/x"],
        capture_output=True,
        text=True,
        cwd=folder,
    )
    assert clean.returncode == 0, clean.stdout + clean.stderr


def test_placeholder_needs_a_define(folder: Path) -> None:
    result = run("bus.yml", "-o", "out", cwd=folder)
    assert (
        result.returncode == 2
        and result.stderr == "bus.yml:2: error: @INSTALL@ is not defined: give --define INSTALL=VALUE\n"
    )


def test_all_or_nothing(folder: Path) -> None:
    out = folder / "out"
    out.mkdir()
    (out / "master.dcf").write_text("old")
    (out / "drive.bin").mkdir()  # a folder where a file must go: nothing is written
    result = run(folder / "bus.yml", "-o", out, "--define", "INSTALL=/x")
    assert result.returncode == 2 and result.stderr.count("\n") == 1 and "drive.bin" in result.stderr
    assert (out / "master.dcf").read_text() == "old" and sorted(p.name for p in out.iterdir()) == [
        "drive.bin",
        "master.dcf",
    ]


def test_collision_unfed_and_length_mismatch_at_their_lines(folder: Path) -> None:
    bus = BUS.replace(
        "  sdo:\n", "    2:\n      cob_id: 0x183\n      mapping:\n        - {index: 0x6040, sub_index: 0}\n  sdo:\n"
    )
    bus += "  rpdo:\n    1:\n      cob_id: 0x182\n"
    (folder / "bus.yml").write_text(bus)
    result = run(folder / "bus.yml", "-o", folder / "out", "--define", "INSTALL=/x")
    assert result.returncode == 1 and not (folder / "out").exists()
    lines = result.stderr.splitlines()
    collision = ":32:1: error: the master: its mirror of io's RPDO1 sends CAN-ID 182h, which drive (TPDO1) sends too"
    assert any(collision in line for line in lines), lines
    assert any(
        ":22:1: error: drive: RPDO2 maps 16 bits, but io's TPDO1 sends 40 bits [COB011]" in line for line in lines
    )


def test_unfed_rpdo_warned(folder: Path) -> None:
    bus = BUS.replace(
        "  sdo:\n", "    2:\n      cob_id: 0x383\n      mapping:\n        - {index: 0x6040, sub_index: 0}\n  sdo:\n"
    )
    (folder / "bus.yml").write_text(bus)
    result = run(folder / "bus.yml", "-o", folder / "out", "--define", "INSTALL=/x")
    assert result.returncode == 0, result.stderr
    assert ":22:1: warning: drive: RPDO2 listens to CAN-ID 383h (io's TPDO3), which io does not send" in result.stderr


def test_frame_bits_by_hand() -> None:
    # 11-bit identifier: 34 stuffed bits + 8 per byte, a stuff bit per 4 after the first, 13 unstuffed
    assert [frame_bits(n) for n in (0, 1, 3, 8)] == [55, 65, 85, 135]
    assert frame_bits(8, extended=True) == 160


def test_fd_frame_time_by_hand() -> None:
    # 16 bytes, 1000/4000 kbit/s: 17 arbitration bits + 4 stuff bits + CRC delimiter + 12 tail bits at
    # 1 µs (34 µs); 5 control + 128 data + 33 more stuff bits + 4 stuff count + 17 CRC + 6 fixed stuff
    # bits at 0.25 µs (48.25 µs)
    assert fd_frame_time(16, 1000, 4000) == 34 + 48.25
    # 10 bytes travel in a 12-byte frame; 64 bytes have a 21-bit CRC and 7 fixed stuff bits
    assert fd_frame_time(10, 500, 500) == fd_frame_time(12, 500, 500)
    assert fd_frame_time(64, 1000, 1000) == 34 + 5 + 512 + (17 + 5 + 512 - 1) // 4 - 4 + 4 + 21 + 7


def test_load_counts_a_long_pdo_as_can_fd(folder: Path) -> None:
    long_pdo = "    2:\n      transmission: 1\n      mapping:\n" + "        - {index: 0x6064, sub_index: 0}\n" * 3
    (folder / "bus.yml").write_text(BUS.replace("  rpdo:\n", long_pdo + "  rpdo:\n"))
    result = run(folder / "bus.yml", "--load", "--data-bitrate", "4000", "--define", "INSTALL=/x", "--no-check")
    assert result.returncode == 0, result.stderr
    # 3 x 32 bits: a 12-byte CAN FD frame; 34 bits at 1 µs, 5 + 96 + 25 stuff + 4 + 17 + 6 bits at 0.25 µs:
    # 72.25 µs, 73 bit times at 1000 kbit/s
    assert "drive TPDO2 (282h)             73     100.0" in result.stdout


def test_load_report(folder: Path) -> None:
    result = run(folder / "bus.yml", "--load", "--define", "INSTALL=/x")
    assert result.returncode == 0, result.stderr
    # TPDO1 maps 16 + 32 bits: 6 bytes, 34 + 48 stuffed bits, 20 stuff bits, 13 more: 115 bit times
    assert "drive TPDO1 (182h)            115     100.0  every 1. SYNC" in result.stdout
    # per second: SYNC 55*100, drive TPDO1 115*100, TPDO2 135*100, master's RPDO2 115*100, heartbeats 65*2 + 65*1,
    # io TPDO1 105*100 (inhibit 10 ms), TPDO2 135*200 (inhibit 5 ms): 79695 bits of 1000000
    assert "load per second: 8.0 %" in result.stdout
    # the worst SYNC period of 10 ms holds SYNC 55 and the synchronous PDOs 115 + 135 + 115 once, each
    # heartbeat once (500 and 1000 ms apart: 65 + 65), io TPDO1 once (inhibit time 10 ms: 105) and io TPDO2
    # twice (5 ms: 2 x 135): 925 bits, 925 µs of 10000 at 1000 kbit/s
    assert f"load in the worst SYNC period (10000 µs): {925 / 10000 * 100:.1f} %" in result.stdout
    assert "io TPDO2 (283h)               135     200.0  events, inhibit time 5000 µs (2 in a SYNC period)" in (
        result.stdout
    )
    assert "not counted: EMCY, SDO and NMT frames" in result.stdout
    assert "not counted: master → io RPDO1 (203h): event-driven" in result.stdout
    high = run(folder / "bus.yml", "--load", "--define", "INSTALL=/x", "--threshold", "5")
    assert high.returncode == 1 and "warning: bus load 9.2 % is above 5 %" in high.stdout


def test_worst_sync_period_is_never_below_the_average(folder: Path) -> None:
    """Heartbeats and event-driven PDOs count in the worst SYNC period (they counted 0, issue 43)."""
    slow = BUS.replace("sync_period: 10000", "sync_period: 100000").replace("transmission: 1", "transmission: 10")
    (folder / "bus.yml").write_text(slow)
    result = run(folder / "bus.yml", "--load", "--define", "INSTALL=/x")
    lines = {line.split(":")[0].strip(): line for line in result.stdout.splitlines()}
    per_second = float(lines["load per second"].split()[-2])
    worst = float(lines["load in the worst SYNC period (100000 µs)"].split()[-2])
    # 100 ms: SYNC 55, TPDO1 115 (every 10th SYNC, once), TPDO2 135 and the master's RPDO2 115 (every SYNC),
    # heartbeats 65 + 65, io TPDO1 10 x 105, io TPDO2 20 x 135: 4300 bits of 100000
    assert worst == round(4300 / 100000 * 100, 1) and worst >= per_second


def as_dcf(eds: str, node_id: int, values: dict[str, str]) -> str:
    """The EDS text as a DCF for `node_id`, with ParameterValue=... after the DefaultValue of each named section."""
    text = eds.replace("[DeviceInfo]", f"[DeviceComissioning]\nNodeID={node_id}\nBaudrate=500\n\n[DeviceInfo]", 1)
    for section, value in values.items():
        head = text.index(f"[{section}]\n")
        default = text.index("DefaultValue=", head)
        end = text.index("\n", default)
        text = text[: end + 1] + f"ParameterValue={value}\n" + text[end + 1 :]
    return text


def test_dcf_parameter_values_become_boot_writes(folder: Path) -> None:
    """A DCF's configured values reach the device only when the master writes them (ros2_canopen #351)."""
    eds = (folder / "io_device.eds").read_text()
    (folder / "io.dcf").write_text(as_dcf(eds, 3, {"1017": "250", "6200sub1": "0x0F", "1800sub2": "1"}))
    (folder / "bus.yml").write_text("master:\n  node_id: 1\n  sync_period: 1000\nio:\n  dcf: io.dcf\n")
    result = run("bus.yml", "-o", "out", cwd=folder)
    assert result.returncode == 0, result.stderr
    writes = read_concise_dcf((folder / "out" / "io.bin").read_bytes())
    assert (0x1017, 0, (250).to_bytes(2, "little")) in writes
    assert (0x6200, 1, b"\x0f") in writes
    # TPDO1's transmission type goes through the PDO sequence: disabled, set, enabled again
    tpdo = [w for w in writes if w[0] == 0x1800]
    assert tpdo == [
        (0x1800, 1, (0x80000183).to_bytes(4, "little")),
        (0x1800, 2, b"\x01"),
        (0x1800, 1, (0x183).to_bytes(4, "little")),
    ]
    assert "NodeID=3" in (folder / "out" / "io.dcf").read_text()
    plain = run("bus.yml", "-o", "plain", "--no-parameter-values", cwd=folder)
    assert plain.returncode == 0 and not (folder / "plain" / "io.bin").exists()  # nothing left to write: no .bin
    assert "UploadFile" not in (folder / "plain" / "master.dcf").read_text()


def test_dbc_of_the_network(folder: Path) -> None:
    import cantools

    result = run(folder / "bus.yml", "--dbc", folder / "bus.dbc", "--define", "INSTALL=/x")
    assert result.returncode == 0, result.stderr
    database = cantools.database.load_file(str(folder / "bus.dbc"))
    tpdo1 = database.get_message_by_frame_id(0x182)
    assert tpdo1.name == "drive_TPDO1" and tpdo1.senders == ["drive"] and tpdo1.length == 6
    assert [(s.start, s.length, s.is_signed) for s in tpdo1.signals] == [(0, 16, False), (16, 32, True)]
    rpdo1 = database.get_message_by_frame_id(0x202)
    assert rpdo1.senders == ["master"]


IO = "master: {node_id: 1}\nio: {dcf: io_device.eds, node_id: 3, "
HOSTILE = {
    "a list": "- master\n- slave\n",
    "a scalar": "just text\n",
    "empty": "",
    "binary": "\x00\x01\x02master:\n",
    "tabs": "master:\n\tnode_id: 1\n",
    "master a list": "master: [1, 2]\n",
    "node a number": "master:\n  node_id: 1\nio: 5\n",
    "tpdo a number": IO + "tpdo: 5}\n",
    "tpdo key text": IO + "tpdo: {first: {enabled: true}}}\n",
    "pdo 513": IO + "tpdo: {513: {enabled: true}}}\n",
    "pdo absent": IO + "tpdo: {40: {cob_id: auto}}}\n",
    "mapping a map": IO + "tpdo: {1: {mapping: {index: 1}}}}\n",
    "mapping without index": IO + "tpdo: {1: {mapping: [{sub_index: 1}]}}}\n",
    "mapping a domain": IO + "tpdo: {1: {mapping: [{index: 0x1008}]}}}\n",
    "sdo a map": IO + "sdo: {index: 1}}\n",
    "sdo value a list": IO + "sdo: [{index: 0x1017, value: [1]}]}\n",
    "bool as number": "master: {node_id: true}\n",
    "text as bool": "master: {node_id: 1, start: 'no'}\nio: {dcf: io_device.eds, node_id: 3}\n",
    "no dcf": "master: {node_id: 1}\nio: {node_id: 3}\n",
    "dcf a folder": "master: {node_id: 1}\nio: {dcf: ., node_id: 3}\n",
    "dcf not a device": "master: {node_id: 1}\nio: {dcf: bus.yml, node_id: 3}\n",
    "no node-ID": "master: {node_id: 1}\nio: {dcf: io_device.eds}\n",
    "master 0": "master: {node_id: 0}\n",
    "auto exhausted": IO + "tpdo: {5: {cob_id: auto}}}\n",
    "anchors": "a: &x [*x]\n",
}


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_hostile_bus_descriptions(folder: Path, name: str) -> None:
    (folder / "bus.yml").write_text(HOSTILE[name], encoding="utf-8")
    result = run("bus.yml", "-o", "out", "--load", "--dbc", "out.dbc", cwd=folder)
    assert "Traceback" not in result.stderr
    assert result.returncode == 2, result.stdout + result.stderr
    assert result.stderr.count("\n") == 1 and result.stderr.startswith("bus.yml"), result.stderr
    assert not (folder / "out").exists() and not (folder / "out.dbc").exists()


OPTIONS_BUS = """\
options:
  heartbeat_multiplier: 2.5
  retry_factor: 5
master:
  node_id: 1
  heartbeat_producer: 100
  sync_period: 5000
  start_all_nodes: true
  boot_time: 3000
  error_behavior: {1: 1}
drive:
  dcf: cia402_drive.eds
  node_id: 2
  heartbeat_consumer: true
  heartbeat_producer: 200
  mandatory: true
  reset_communication: false
  revision_number: 7
  serial_number: 1234
  software_version: 9
  tpdo:
    2:
      transmission: 254
      inhibit_time: 100
      event_timer: 50
second:
  dcf: cia402_drive.eds
  node_id: 3
  heartbeat_producer: 1000
  guard_time: 100
  boot: false
"""


def test_options_agree_with_dcfgen(folder: Path) -> None:
    """Heartbeats, NMT flags, identity checks, software version, PDO timing: the same files as dcfgen's."""
    tool = Path(sys.executable).parent / "dcfgen"
    if not tool.exists():
        pytest.skip("dcfgen (dcf-tools) is not installed")
    (folder / "bus.yml").write_text(OPTIONS_BUS)
    (folder / "theirs").mkdir()
    theirs = subprocess.run([str(tool), "-d", "theirs", "-S", "bus.yml"], capture_output=True, text=True, cwd=folder)
    assert theirs.returncode == 0, theirs.stderr
    ours = run("bus.yml", "-o", "ours", "--no-check", cwd=folder)
    assert ours.returncode == 0, ours.stderr
    assert "bus.yml:14: warning: drive: no object 1016h" in ours.stderr  # dcfgen: "object 0x1016 does not exist"
    names = sorted(p.name for p in (folder / "theirs").iterdir() if p.suffix == ".bin")
    assert names == ["drive.bin", "master.bin", "second.bin"]
    for name in [*names, "master.dcf"]:
        assert (folder / "ours" / name).read_bytes() == (folder / "theirs" / name).read_bytes(), name
