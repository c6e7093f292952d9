"""`network BUS.yml --svg`: the bus picture of every ros2_canopen example network, looked at in headless Chromium.

Every PDO a slave sends or receives has its row, each arrow starts at its producer's lifeline and ends at each
consumer's, and no two texts overlap. The networks come from this machine's snapshot of ros2_canopen (tests/mirrors.py),
read in place; the test skips where the snapshot or the browser is absent.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

import mirrors
import pytest
from browserkit import browser

from cantools_od.model.cia301.objects import RX, TX

from support import cli_command

pytestmark = pytest.mark.xdist_group("browser")

REPO = "ros-industrial/ros2_canopen"
CONFIGS = "canopen_tests/config"
MEASURE = (Path(__file__).parent / "measure_bus.js").read_text(encoding="utf-8")


def _networks(root: Path) -> list[Path]:
    return sorted(p for p in (root / CONFIGS).glob("*/bus.yml"))


def _expected_rows(bus: Path) -> set[tuple[str, str]]:
    """(CAN-ID, producer) of every PDO the slaves send, and of their RPDOs (from a slave or the master)."""
    from cantools_od.cli.network import load_network, make_plan

    network, devices = load_network(str(bus), ("BUS_CONFIG_PATH=/opt/ros",), ())
    plan = make_plan(network, devices, True)
    sent = {(f"{p.cob_id & 0x1FFFFFFF:03X}", s.slave.name) for s in plan.slaves for p in s.active(TX)}
    fed = {f"{p.cob_id & 0x1FFFFFFF:03X}" for s in plan.slaves for p in s.active(RX)}
    return sent | {(can_id, "master") for can_id in fed if not any(can_id == sid for sid, _ in sent)}


def test_bus_pictures_of_the_ros2_canopen_examples(tmp_path: Path) -> None:
    paths = [p for p in mirrors.files(REPO) if p.startswith(CONFIGS + "/")]
    mirrors.materialize(REPO, "HEAD", paths, tmp_path)
    drawn = 0
    with browser() as chrome:
        page = chrome.page()
        for bus in _networks(tmp_path):
            out = tmp_path / f"{bus.parent.name}.svg"
            command = [*cli_command(), "network", str(bus), "--svg", str(out), "--define", "BUS_CONFIG_PATH=/opt/ros"]
            run = subprocess.run(command, capture_output=True, text=True, cwd=bus.parent)
            if run.returncode == 2 and "is not in" in run.stderr:
                continue  # an example whose EDS the repository does not hold (test_ros2_canopen.py names it)
            assert run.returncode == 0, f"{bus.parent.name}: {run.stderr}"
            page.open(out)
            found = page.evaluate(MEASURE)
            where = bus.parent.name
            assert not found["overlaps"], f"{where}: {found['overlaps'][:3]}"
            assert not found["outside"], f"{where}: {found['outside'][:3]}"
            for row in found["rows"]:
                assert row["dotOnProducer"] and row["headsOnConsumers"], f"{where}: {row}"
                assert row["heads"] == len(row["consumers"]), f"{where}: {row}"
            rows = {(row["id"], row["producer"]) for row in found["rows"]}
            assert _expected_rows(bus) <= rows, f"{where}: missing {_expected_rows(bus) - rows}"
            drawn += 1
    assert drawn >= 8, "fewer ros2_canopen example networks drawn than there are"
