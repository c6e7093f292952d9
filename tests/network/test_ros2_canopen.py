"""Every bus description of ros2_canopen, generated here and by lely's dcfgen, compared.

Reads ros-industrial/ros2_canopen's `canopen_tests/config/*/bus.yml` and `canopen_core/test/bus_configs/*.yml`
with the EDS files beside them, from this machine's snapshot (tests/mirrors.py; skipped when absent).
ros2_canopen is licensed under the Apache License 2.0 (Copyright ROS-Industrial and its contributors); its files
are read in place and never copied into this project.

ros2_canopen builds a configuration by copying `defaults` over each of `nodes` (its `cogen`, run here from the
snapshot), replacing `@BUS_CONFIG_PATH@` and running `dcfgen -rS` in the configuration's folder (ros2build.py);
the test runs `cantools-od network -r --define BUS_CONFIG_PATH=...` on the file as written.
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import mirrors
import pytest
import ros2build
import yaml

from cantools_od.model.cia301.master import read_concise_dcf

from support import cli_command

REPO = "ros-industrial/ros2_canopen"
CONFIGS = "canopen_tests/config"
FRAGMENTS = "canopen_core/test/bus_configs"
INSTALLED = "/opt/ros/share/config"  # what @BUS_CONFIG_PATH@ stands for, in both tools
# canopen_core's fragments test ros2_canopen's loader, not a bus: each is refused, for its reason.
REFUSED = {
    "bad_driver_duplicate.yml": "key 'proxy_device_1' written twice",
    "bad_driver_no_driver.yml": "proxy_device_1: no `driver`",
    "bad_driver_no_id.yml": "proxy_device_1: no `node_id`",
    "bad_driver_no_package.yml": "proxy_device_1: no `package`",
    "bad_master_no_driver.yml": "master: no `driver`",
    "bad_master_no_id.yml": "master: no `node_id`",
    "bad_master_no_package.yml": "master: no `package`",
    "bad_no_master.yml": "no `master` section",
    "good_driver.yml": "no `master` section",  # a driver alone: ros2_canopen's loader test, no network
}
# The one example whose EDS the repository does not hold.
MISSING_EDS = {"cia402_multichannel_system": "dcf 'cia402_slave_multichannel.eds' is not in"}


@pytest.fixture(scope="module")
def checkout(tmp_path_factory: pytest.TempPathFactory) -> Path:
    paths = [p for p in mirrors.files(REPO) if p.startswith((CONFIGS + "/", "canopen_core/test/"))]
    root = tmp_path_factory.mktemp("ros2_canopen")
    mirrors.materialize(REPO, "HEAD", paths, root)
    return root


def ours(bus: Path, out: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    args = [*cli_command(), "network", str(bus), "-r", "-o", str(out), "--define", f"BUS_CONFIG_PATH={INSTALLED}"]
    return subprocess.run([*args, *extra], capture_output=True, text=True, timeout=120)


def dcfgen(bus: Path, out: Path) -> subprocess.CompletedProcess[str]:
    """dcfgen as ros2_canopen's cogen_dcf runs it: its cogen, the path replaced, `dcfgen -rS`."""
    return ros2build.ros2_build(bus, out, INSTALLED, out.parent.parent)


def mirrored_cobs(master_dcf: str) -> set[int]:
    """The COB-IDs of the master's mirrored PDOs (the DefaultValue after each `COB-ID used by` name)."""
    lines = master_dcf.splitlines()
    found = set()
    for number, line in enumerate(lines):
        if line.startswith("ParameterName=COB-ID used by"):
            value = next(v for v in lines[number:] if v.startswith("DefaultValue="))
            found.add(int(value.split("=", 1)[1], 0))
    return found


def disabled_cobs(bus: Path) -> set[int]:
    """The pre-defined COB-IDs of the TPDOs the YAML disables, which dcfgen still mirrors."""
    data = yaml.safe_load(bus.read_text())
    nodes = data.get("nodes") or {k: v for k, v in data.items() if isinstance(v, dict) and "dcf" in v}
    found = set()
    for node in nodes.values():
        merged = {**(data.get("defaults") or {}), **node}
        for number, pdo in (merged.get("tpdo") or {}).items():
            if pdo.get("enabled") is False and number <= 4:
                found.add(0x180 + 0x100 * (number - 1) + merged["node_id"])
    return found


def configs(root: Path) -> list[Path]:
    return sorted((root / CONFIGS).glob("*/bus.yml"))


def test_every_example_generates_and_matches_dcfgen(checkout: Path, tmp_path: Path) -> None:
    agreed, dcfgen_failed = [], []
    for bus in configs(checkout):
        name = bus.parent.name
        before = bus.read_bytes()
        result = ours(bus, tmp_path / "ours" / name)
        assert bus.read_bytes() == before
        if name in MISSING_EDS:
            assert result.returncode == 2 and MISSING_EDS[name] in result.stderr, result.stderr
            assert len(result.stderr.splitlines()) == 1 and not (tmp_path / "ours" / name).exists()
            continue
        assert result.returncode == 0, f"{name}: {result.stderr}"
        for written in sorted((tmp_path / "ours" / name).glob("*.dcf")):  # lely's own parser accepts each DCF
            check = subprocess.run([str(Path(sys.executable).parent / "dcfchk"), str(written)], capture_output=True)
            assert check.returncode == 0, f"{written.name}: {check.stderr.decode()}"
        theirs = dcfgen(bus, tmp_path / "dcfgen" / name)
        if theirs.returncode != 0:
            dcfgen_failed.append((name, theirs.stderr.strip().splitlines()[-1]))
            continue
        mine_dir, their_dir = tmp_path / "ours" / name, tmp_path / "dcfgen" / name
        their_bins = sorted(p.name for p in their_dir.glob("*.bin"))
        assert sorted(p.name for p in mine_dir.glob("*.bin")) == their_bins, name
        for binary in their_bins:
            mine = read_concise_dcf((mine_dir / binary).read_bytes())
            assert mine == read_concise_dcf((their_dir / binary).read_bytes()), f"{name}/{binary}"
        mine_dcf, their_dcf = (mine_dir / "master.dcf").read_text(), (their_dir / "master.dcf").read_text()
        if mine_dcf != their_dcf:  # dcfgen mirrors a PDO the YAML disables (`enabled: false`); we do not
            extra = mirrored_cobs(their_dcf) - mirrored_cobs(mine_dcf)
            assert mirrored_cobs(mine_dcf) <= mirrored_cobs(their_dcf), name
            assert extra and {cob & 0x7FF for cob in extra} <= disabled_cobs(bus), name
        agreed.append(name)
    # All ten examples with their EDS files: dcfgen accepts every one of them once cogen has expanded them.
    assert len(agreed) + len(dcfgen_failed) == len(configs(checkout)) - len(MISSING_EDS) == 10
    assert not dcfgen_failed, f"dcfgen failed where cantools-od worked: {dcfgen_failed}"


def test_fragments_refused_in_one_line(checkout: Path, tmp_path: Path) -> None:
    folder = checkout / FRAGMENTS
    generated = []
    for bus in sorted(folder.glob("*.yml")):
        out = tmp_path / bus.stem
        result = ours(bus, out, "--dcf-dir", str(folder.parent))
        if bus.name in REFUSED:
            assert result.returncode == 2, bus.name
            assert result.stderr.count("\n") == 1 and REFUSED[bus.name] in result.stderr, result.stderr
            assert "Traceback" not in result.stderr and not out.exists()
        else:
            assert result.returncode == 0, f"{bus.name}: {result.stderr}"
            generated.append(bus.name)
    assert generated == ["good_master.yml", "good_master_and_two_driver.yml"]


def test_dcfgen_fails_alone_where_we_work(checkout: Path, tmp_path: Path) -> None:
    """Run as written (no cogen expansion, no path replaced), dcfgen refuses the `nodes` layout; we read it."""
    bus = checkout / CONFIGS / "cia402_system" / "bus.yml"
    tool = Path(sys.executable).parent / "dcfgen"
    if not tool.exists() or shutil.which("git") is None:
        pytest.skip("dcfgen is not installed")
    (tmp_path / "d").mkdir()
    theirs = subprocess.run(
        [str(tool), "-d", str(tmp_path / "d"), "-rS", str(bus)], capture_output=True, text=True, cwd=bus.parent
    )
    assert theirs.returncode != 0 and "Traceback" in theirs.stderr
    assert ours(bus, tmp_path / "o").returncode == 0
