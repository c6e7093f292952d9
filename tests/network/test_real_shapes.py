"""`cantools-od network` on the shapes real bus descriptions and EDS files have (issue 43): each test
builds the shape in a scratch folder from this project's example EDS files and runs the installed CLI."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest

from cantools_od.model.cia301.master import read_concise_dcf

from support import EXAMPLES, cli_command

IO = (EXAMPLES / "io_device.eds").read_text()


def run(*args: str | Path, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*cli_command(), "network", *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=120
    )


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    shutil.copy(EXAMPLES / "cia402_drive.eds", tmp_path / "cia402_drive.eds")
    (tmp_path / "io_device.eds").write_text(IO)
    return tmp_path


def test_emcy_cob_id_without_default_is_80h_plus_node_id(folder: Path) -> None:
    """[1014] with no DefaultValue: the device sends EMCY on CiA 301's 80h + node-ID, not on 000h (NMT)."""
    written = "[1014]\nParameterName=COB-ID EMCY\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
    assert written + "DefaultValue=$NODEID+0x80\n" in IO
    (folder / "io_device.eds").write_text(IO.replace(written + "DefaultValue=$NODEID+0x80\n", written))
    bus = (
        "master:\n  node_id: 1\nio_a:\n  node_id: 2\n  dcf: io_device.eds\nio_b:\n  node_id: 3\n  dcf: io_device.eds\n"
    )
    (folder / "bus.yml").write_text(bus)
    result = run("bus.yml", "-o", "out", cwd=folder)
    assert result.returncode == 0 and "COB011" not in result.stderr, result.stderr
    master = (folder / "out" / "master.dcf").read_text()
    consumers = master.split("[1028Value]\n", 1)[1].split("\n\n", 1)[0]
    assert consumers == "NrOfEntries=2\n2=0x00000082\n3=0x00000083"
    lint = subprocess.run([*cli_command(), "lint", "--network", "bus.yml"], capture_output=True, text=True, cwd=folder)
    assert lint.returncode == 0 and "COB011" not in lint.stdout + lint.stderr


COGEN_BUS = """\
options:
  dcf_path: "@BUS_CONFIG_PATH@"
master:
  node_id: 1
  sync_period: 10000
  heartbeat_producer: 200
defaults:
  heartbeat_producer: 500
  heartbeat_consumer: true
nodes:
  z_io:
    node_id: 2
    dcf: io_device.eds
    heartbeat_producer: 100
    tpdo:
      2:
        transmission: 1
        mapping:
          - {index: 0x6000, sub_index: 2}
      1:
        transmission: 1
        mapping:
          - {index: 0x6000, sub_index: 1}
  a_io:
    node_id: 3
    dcf: io_device.eds
"""


def test_defaults_and_order_follow_ros2_canopens_cogen(folder: Path, tmp_path: Path) -> None:
    """ros2_canopen's cogen copies `defaults` over each node and dumps the nodes (and PDO tables) sorted:
    ours equals what its build (cogen, then dcfgen -rS) makes, .bin by .bin and master.dcf byte for byte."""
    import ros2build

    (folder / "bus.yml").write_text(COGEN_BUS)
    (folder / "io_device.eds").write_text(IO.replace("DefaultValue=1.0", "DefaultValue=0"))  # dcfgen reads no REAL
    install = "/opt/ros/share/cfg"
    result = run("bus.yml", "-r", "-o", "out", "--define", f"BUS_CONFIG_PATH={install}", cwd=folder)
    assert result.returncode == 0, result.stderr
    assert "bus.yml:14: warning: z_io: heartbeat_producer is replaced by `defaults` (line 8)" in result.stderr
    theirs = ros2build.ros2_build(folder / "bus.yml", tmp_path / "ros2", install, tmp_path)
    assert theirs.returncode == 0, theirs.stderr
    mine, built = folder / "out", tmp_path / "ros2"
    assert sorted(p.name for p in mine.glob("*.bin")) == sorted(p.name for p in built.glob("*.bin"))
    for binary in built.glob("*.bin"):
        assert read_concise_dcf((mine / binary.name).read_bytes()) == read_concise_dcf(binary.read_bytes())
    assert (mine / "master.dcf").read_text() == (built / "master.dcf").read_text()
    drive = read_concise_dcf((mine / "z_io.bin").read_bytes())
    assert (0x1017, 0, (500).to_bytes(2, "little")) in drive  # the default's value, as cogen makes it
    assert [w[0] for w in drive if w[1] == 1 and w[0] in (0x1800, 0x1801)][:2] == [0x1800, 0x1800]


def test_no_cogen_keeps_the_nodes_own_keys_and_order(folder: Path) -> None:
    (folder / "bus.yml").write_text(COGEN_BUS)
    result = run("bus.yml", "-o", "out", "--no-cogen", "--define", "BUS_CONFIG_PATH=/x", cwd=folder)
    assert result.returncode == 0 and "warning" not in result.stderr, result.stderr
    drive = read_concise_dcf((folder / "out" / "z_io.bin").read_bytes())
    assert (0x1017, 0, (100).to_bytes(2, "little")) in drive
    assert [w[0] for w in drive if w[1] == 1 and w[0] in (0x1800, 0x1801)][:2] == [0x1801, 0x1801]
    master = (folder / "out" / "master.dcf").read_text()
    assert master.index("z_io.bin") < master.index("a_io") if "a_io.bin" in master else True
    consumers = master.split("[1016Value]\n", 1)[1].split("\n\n", 1)[0].splitlines()
    assert consumers[1].startswith("1=0x0002") and consumers[2].startswith("2=0x0003")


@pytest.mark.parametrize(
    ("key", "where"),
    [
        ("reset_communication: true", "it belongs in a node's section (or `defaults`)"),
        ("dcf_path: /somewhere", "it belongs in `options`"),
    ],
)
def test_a_key_of_another_section_is_a_warning(folder: Path, key: str, where: str) -> None:
    """ros2_canopen's users write slave keys into `master` (dcfgen ignores them there): a warning, the network built."""
    bus = f"master:\n  node_id: 1\n  {key}\nio:\n  node_id: 3\n  dcf: io_device.eds\n"
    (folder / "bus.yml").write_text(bus)
    result = run("bus.yml", "-o", "out", cwd=folder)
    name = key.split(":")[0]
    assert result.returncode == 0, result.stderr
    assert result.stderr == f"bus.yml:3: warning: master: {name} has no effect here (dcfgen ignores it); {where}\n"
    assert (folder / "out" / "master.dcf").is_file()


def test_an_unknown_key_stays_an_error_with_did_you_mean(folder: Path) -> None:
    (folder / "bus.yml").write_text(
        "master:\n  node_id: 1\n  baud_rate: 500\nio:\n  node_id: 3\n  dcf: io_device.eds\n"
    )
    result = run("bus.yml", "-o", "out", cwd=folder)
    assert result.returncode == 2 and not (folder / "out").exists()
    assert result.stderr == "bus.yml:3: error: unknown key 'baud_rate' in master; did you mean baudrate?\n"


DRIVE = (EXAMPLES / "cia402_drive.eds").read_text()
STATUSWORD = DRIVE[DRIVE.index("[6041]\n") : DRIVE.index("[6060]\n")]


def test_an_eds_with_a_section_written_twice_is_refused(folder: Path) -> None:
    """`[6041]` twice, the second UNSIGNED32: which the device has is unknown; dcfgen refuses it too."""
    twice = STATUSWORD.replace("DataType=0x0006", "DataType=0x0007")
    assert twice != STATUSWORD
    (folder / "cia402_drive.eds").write_text(DRIVE.replace("[6060]\n", twice + "[6060]\n", 1))
    line = DRIVE.index("[6060]\n")
    first, again = DRIVE[: DRIVE.index("[6041]\n")].count("\n") + 1, DRIVE[:line].count("\n") + 1
    (folder / "bus.yml").write_text("master:\n  node_id: 1\ndrive:\n  node_id: 2\n  dcf: cia402_drive.eds\n")
    before = (folder / "cia402_drive.eds").read_bytes()
    result = run("bus.yml", "-o", "out", cwd=folder)
    assert result.returncode == 2 and result.stderr.count("\n") == 1 and not (folder / "out").exists()
    assert result.stderr.startswith("bus.yml:5: error: drive: ")
    assert f"line {again}: section [6041] given again (first on line {first}): which one" in result.stderr
    assert (folder / "cia402_drive.eds").read_bytes() == before


def test_a_node_removed_from_the_bus_loses_its_files_and_nothing_else(folder: Path) -> None:
    two = (
        "master:\n  node_id: 1\nio_a:\n  node_id: 2\n  dcf: io_device.eds\nio_b:\n  node_id: 3\n  dcf: io_device.eds\n"
    )
    (folder / "bus.yml").write_text(two)
    assert run("bus.yml", "-o", "out", cwd=folder).returncode == 0
    assert (folder / "out" / "io_b.dcf").is_file()
    (folder / "out" / "notes.txt").write_text("mine")
    (folder / "bus.yml").write_text(two.split("io_b:")[0])
    result = run("bus.yml", "-o", "out", cwd=folder)
    assert result.returncode == 0, result.stderr
    names = sorted(p.name for p in (folder / "out").iterdir())
    assert {".cantools-od-network", "io_a.dcf", "master.dcf", "notes.txt"} <= set(names)
    assert not [name for name in names if name.startswith("io_b")], names
    assert "out/io_b.dcf: removed" in result.stderr


def test_a_shared_node_id_comes_before_the_clashes_it_causes(folder: Path) -> None:
    bus = (
        "master:\n  node_id: 1\nio_a:\n  dcf: io_device.eds\n  node_id: 2\nio_b:\n  dcf: io_device.eds\n  node_id: 2\n"
    )
    (folder / "bus.yml").write_text(
        bus.replace("io_b:\n  dcf: io_device.eds", "io_b:\n  tpdo: {1: {transmission: 1}}\n  dcf: io_device.eds")
    )
    result = run("bus.yml", "-o", "out", cwd=folder)
    lines = result.stderr.splitlines()
    assert result.returncode == 1 and len(lines) > 2, result.stderr
    assert lines[0] == "bus.yml:9:1: error: io_b: node-ID 2 is also io_a's [COB011]"
    assert any("sends CAN-ID" in line for line in lines[1:])


def test_the_same_sdo_write_twice_is_a_warning(folder: Path) -> None:
    """A real bus.yml writes 6083h twice, commented as acceleration and deceleration (6084h was meant)."""
    sdo = (
        "  sdo:\n"
        "    - {index: 0x6083, sub_index: 0, value: 16000}   # acceleration\n"
        "    - {index: 0x6083, sub_index: 0, value: 16000}   # deceleration\n"
    )
    master = "master:\n  node_id: 1\n  sync_period: 10000\n"
    (folder / "bus.yml").write_text(master + "drive:\n  node_id: 2\n  dcf: cia402_drive.eds\n" + sdo)
    result = run("bus.yml", "-o", "out", cwd=folder)
    assert result.returncode == 0
    assert result.stderr == (
        "bus.yml:9: warning: drive: 6083sub0 is written again (first on line 8): the later value stays; "
        "another object meant?\n"
    )
