"""Real ros2_canopen networks of public repositories (not ros2_canopen's own examples), generated here and as
ros2_canopen's build makes them (its cogen, then `dcfgen -rS`: ros2build.py), compared entry by entry.

Each repository's bus.yml and the EDS/DCF files beside it are read from this machine's snapshot
(tests/mirrors.py; skipped when absent) at the commit named here, and never copied into this project. The
repositories and their licences are their authors'; the manifest names each. Every difference from dcfgen is
one of the kinds below, stated per network:

- DISABLED_MIRRORS: dcfgen mirrors in master.dcf a PDO the YAML disables (`enabled: false`); we do not.
- PARAMETER_VALUES: the node's file is a DCF whose ParameterValues differ from its defaults; we write them at
  boot (a device only gets them so), dcfgen takes them as held. With --no-parameter-values the .bin files are
  dcfgen's, and each extra write is a ParameterValue of the DCF.
A network with a real mistake is refused in one line, quoted here with the mistake.
"""

from __future__ import annotations

import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import mirrors
import pytest
import ros2build

from cantools_od.api import load
from cantools_od.model.cia301.master import read_concise_dcf
from cantools_od.model.cia301.slots import slot

from support import cli_command

INSTALLED = "/opt/ros/share/robot/config/bus"  # what @BUS_CONFIG_PATH@ stands for, in both builds
DISABLED_MIRRORS = "disabled mirrors"
PARAMETER_VALUES = "parameter values"


@dataclass(frozen=True)
class Net:
    repo: str
    commit: str
    folder: str
    differences: tuple[str, ...] = ()
    warnings: tuple[str, ...] = ()
    """What our run says on stderr (each a part of one line), beside the files."""
    refused: str = ""
    """The one line of a refusal, for a real mistake in the file."""
    dcfgen_fails: str = field(default="")


NETWORKS = [
    # A TMCM-1270 stepper; its sdo list writes 6083h twice ("acceleration", "deceleration": 6084h was meant).
    Net("hellantos/trinamic_pd42_can", "f6cb0c3bd098a80dec0b07810eb65bc6a598b674", "config/single-pd42",
        warnings=("bus.yml:20: warning: trinamic_pd42: 6083sub0 is written again (first on line 19)",)),
    # The same drive twice (defaults + nodes), the same 6083h twice in `defaults`, TPDOs 3 and 4 disabled.
    Net("hellantos/robby_description", "a4c32356426c91f121d5fb144d91f286a4eb8a2a", "config/robby",
        differences=(DISABLED_MIRRORS,),
        warnings=("bus.yml:23: warning: left_drive: 6083sub0 is written again (first on line 22)",
                  "bus.yml:23: warning: right_drive: 6083sub0 is written again (first on line 22)")),
    # Five proxy nodes; the master's heartbeat_consumer is a table of node names (dcfgen crashes on the nodes'
    # `eds:` key, which it does not know, after taking the table as true).
    Net("vsi5004/RDJ-ROS", "823941dced9135fbbae36ee84f65903d9e7c2503", "config",
        refused="bus.yml:14: error: master: heartbeat_consumer must be true or false, not {'x_axis': 250,",
        dcfgen_fails="KeyError: 'dcf'"),
    # Four Nanotec PD4 steppers of two EDS files.
    Net("MatHelio314/stepper_motor_ws", "efa6e312e67a1ad8a05bd65bc4a16d5da2897005",
        "stepper_motor_control/config/robot_control"),
    # A differential drive: two wheels of one EDS, TPDOs 3 and 4 disabled.
    Net("MustaEssam/diff_robot_canopen", "6cf1983f66028169626fe7cc136992da6c81d1e0", "config/robot_control",
        differences=(DISABLED_MIRRORS,)),
    # A Roboteq motor controller, its RPDO4 disabled.
    Net("jclinton830/canopen_test", "9ca3317ae64b54fcd5cba0911c0dc5a1147a24db", "config/canopen_system",
        differences=(DISABLED_MIRRORS,)),
    # A proxy device whose EDS maps nothing the master configures: no .bin at all.
    Net("b-robotized/diff_canopen_system", "f3887917e8c0eb47ad34340b869547281959cfcc",
        "config/test_diff_canopen_system"),
    Net("Hansimer/lifting_platform_canopen", "17e639e2595aaee1372674ba9b3fcbdff25fbcc0", "config/lifting_platform"),
    # Seven joints of a Panda arm, one EDS.
    Net("lucasmluza/ros2_moveit_canopen_example", "015ede52917ce9cde095f520f3abc04af140f345",
        "panda_canopen/config/cia402"),
    # Six joints of a PRBT arm from one DCF with configured values; TPDOs 3 and 4 disabled in `defaults`.
    Net("hellantos/prbt_robot", "a7ab41104fc2eee883ac580c907f61ca7e5fc726", "prbt_robot_support/config/prbt",
        differences=(DISABLED_MIRRORS, PARAMETER_VALUES)),
]  # fmt: skip


def checkout(net: Net, into: Path) -> Path:
    """The bus.yml and the files beside it, at the manifest's commit; the bus.yml's path."""
    mirrors.require(net.repo)
    prefix = net.folder + "/"
    paths = [p for p in mirrors.files(net.repo, net.commit) if p.startswith(prefix) and "/" not in p[len(prefix) :]]
    mirrors.materialize(net.repo, net.commit, paths, into)
    return into / net.folder / "bus.yml"


def ours(bus: Path, out: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    args = [*cli_command(), "network", "bus.yml", "-r", "-o", str(out), "--define", f"BUS_CONFIG_PATH={INSTALLED}"]
    return subprocess.run([*args, *extra], capture_output=True, text=True, cwd=bus.parent, timeout=300)


def bins(folder: Path) -> dict[str, list[tuple[int, int, bytes]]]:
    return {p.name: read_concise_dcf(p.read_bytes()) for p in sorted(folder.glob("*.bin"))}


def test_at_least_ten_repositories() -> None:
    assert len({net.repo for net in NETWORKS}) >= 10


@pytest.mark.parametrize("net", NETWORKS, ids=[net.repo for net in NETWORKS])
def test_real_network_against_ros2_canopens_build(net: Net, tmp_path: Path) -> None:
    bus = checkout(net, tmp_path / "src")
    before = bus.read_bytes()
    result = ours(bus, tmp_path / "ours", "--write-bus", str(tmp_path / "installed.yml"))
    assert bus.read_bytes() == before
    theirs = ros2build.ros2_build(bus, tmp_path / "ros2", INSTALLED, tmp_path)
    if net.refused:
        assert result.returncode == 2 and result.stderr.count("\n") == 1, result.stderr
        assert result.stderr.startswith(net.refused) and not (tmp_path / "ours").exists()
        assert theirs.returncode != 0 and theirs.stderr.strip().splitlines()[-1] == net.dcfgen_fails
        return
    assert result.returncode == 0, result.stderr
    assert [line for line in result.stderr.splitlines() if line] == [
        line for line in result.stderr.splitlines() if any(warning in line for warning in net.warnings)
    ]
    assert all(warning in result.stderr for warning in net.warnings), result.stderr
    assert theirs.returncode == 0, theirs.stderr
    # the bus.yml ros2_canopen installs beside master.dcf (cogen's expansion, the path replaced)
    assert (tmp_path / "installed.yml").read_text() == (tmp_path / "ros2" / "bus.yml").read_text()
    mine, built = bins(tmp_path / "ours"), bins(tmp_path / "ros2")
    if PARAMETER_VALUES in net.differences:
        _parameter_values(bus, mine, built, tmp_path)
    else:
        assert mine == built
    _master_dcf(
        net, bus, (tmp_path / "ours" / "master.dcf").read_text(), (tmp_path / "ros2" / "master.dcf").read_text()
    )


def _parameter_values(bus: Path, mine: dict[str, list[tuple[int, int, bytes]]], built: dict, tmp_path: Path) -> None:
    """As dcfgen with --no-parameter-values; each write more by default is a ParameterValue of the node's DCF."""
    plain = ours(bus, tmp_path / "plain", "--no-parameter-values")
    assert plain.returncode == 0 and bins(tmp_path / "plain") == built
    assert mine.keys() == built.keys()
    dcfs = {p.stem: p for p in bus.parent.glob("*.dcf")}
    assert dcfs
    device = load(next(iter(dcfs.values())))
    for name, writes in mine.items():
        extra = [write for write in writes if write not in built[name]]
        assert extra, name
        for index, sub, _ in extra:
            found = slot(device, index, sub)
            assert found is not None and found.var.parameter_value is not None, (name, hex(index), sub)


def _master_dcf(net: Net, bus: Path, mine: str, theirs: str) -> None:
    if DISABLED_MIRRORS not in net.differences:
        assert mine == theirs
        return
    extra = ros2build.mirrored_cobs(theirs) - ros2build.mirrored_cobs(mine)
    assert ros2build.mirrored_cobs(mine) <= ros2build.mirrored_cobs(theirs)
    assert extra and {cob & 0x7FF for cob in extra} <= ros2build.disabled_cobs(bus)
