"""A configuration built as ros2_canopen's CMake builds it (lely_core_libraries' `cogen_dcf`): its `cogen`
rewrites bus.yml (defaults copied over each node, `yaml.dump`), `@BUS_CONFIG_PATH@` is replaced, then
lely's `dcfgen -rS` runs in the configuration's folder. A file without `nodes` is built by
`generate_dcf` (no cogen: it refuses such a file). cogen.py is run from the snapshot of ros2_canopen
(tests/mirrors.py), dcfgen from this venv (dcf-tools)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import mirrors
import pytest
import yaml

ROS2_CANOPEN = "ros-industrial/ros2_canopen"
COGEN = "lely_core_libraries/cogen/cogen.py"


def tool(name: str) -> Path:
    found = Path(sys.executable).parent / name
    if not found.exists():
        pytest.skip(f"{name} (dcf-tools) is not installed")
    return found


def ros2_build(bus: Path, out: Path, install: str, scratch: Path) -> subprocess.CompletedProcess[str]:
    """master.dcf and the .bin files into `out` as ros2_canopen's build makes them; `install` is
    what @BUS_CONFIG_PATH@ stands for."""
    out.mkdir(parents=True)
    source = bus
    if "nodes" in (yaml.safe_load(bus.read_text(encoding="utf-8")) or {}):
        script = scratch / "cogen.py"
        if not script.exists():
            mirrors.materialize(ROS2_CANOPEN, "HEAD", [COGEN], scratch / "ros2_canopen")
            script.write_bytes((scratch / "ros2_canopen" / COGEN).read_bytes())
        source = out / "preprocessed_bus.yml"
        args = [sys.executable, str(script), "--input-file", str(bus), "--output-file", str(source)]
        subprocess.run(args, check=True, capture_output=True, timeout=120)
    flat = out / "bus.yml"
    flat.write_text(source.read_text(encoding="utf-8").replace("@BUS_CONFIG_PATH@", install), encoding="utf-8")
    args = [str(tool("dcfgen")), "-d", str(out), "-rS", str(flat)]
    return subprocess.run(args, capture_output=True, text=True, cwd=bus.parent, timeout=120)
