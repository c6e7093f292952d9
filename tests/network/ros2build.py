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


def mirrored_cobs(master_dcf: str) -> set[int]:
    """The COB-IDs of the master's mirrored PDOs (the DefaultValue after each `COB-ID used by` name)."""
    lines = master_dcf.splitlines()
    found = set()
    for number, line in enumerate(lines):
        if line.startswith("ParameterName=COB-ID used by"):
            value = next(v for v in lines[number:] if v.startswith("DefaultValue="))
            found.add(int(value.split("=", 1)[1], 0))
    return found


PREDEFINED_BASES = {"tpdo": 0x180, "rpdo": 0x200}


def disabled_cobs(bus: Path) -> set[int]:
    """The pre-defined COB-IDs of the PDOs (1-4) the YAML disables (`enabled: false`), read as cogen
    expands it (defaults over each node): dcfgen still mirrors them, we do not."""
    data = yaml.safe_load(bus.read_text(encoding="utf-8"))
    nodes = data.get("nodes") or {k: v for k, v in data.items() if isinstance(v, dict) and "dcf" in v}
    found = set()
    for node in nodes.values():
        merged = {**node, **(data.get("defaults") or {})} if "nodes" in data else node
        for direction, base in PREDEFINED_BASES.items():
            for number, pdo in (merged.get(direction) or {}).items():
                if pdo.get("enabled") is False and int(number) <= 4:
                    found.add(base + 0x100 * (int(number) - 1) + int(merged["node_id"]))
    return found
