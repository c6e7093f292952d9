"""Helpers for the CANopenNode target tests: the real stack from ../shared, compilers, the OD walk."""

from __future__ import annotations

import re
import shutil
import subprocess
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest

from cantools_od.api import load
from cantools_od.canopennode.profile import StackConfig
from cantools_od.lint.canopennode import profile_findings
from cantools_od.lint.runner import has_errors
from cantools_od.model import Device
from cantools_od.render.canopennode import render_node_view
from cantools_od.sniff import NotADeviceDescription
from cantools_od.views.canopennode import build_node_view

from support import ROOT, cli_command

SHARED = ROOT.parent / "shared" / "third_party"
STACK = SHARED / "CANopenNode"
# The blank driver's CO_driver_target.h sets no CO_CONFIG_*: the stack's defaults, declared.
STACK_DEFAULTS = StackConfig(declared=True)
DEMO = SHARED / "CANopenDemo-demo"
HERE = Path(__file__).resolve().parent
WARNINGS = ["-Wall", "-Wextra", "-Werror"]
WORKERS = 2


def stack() -> Path:
    if not (STACK / "301" / "CO_ODinterface.h").is_file():
        pytest.skip("../shared/third_party/CANopenNode is absent")
    for tool in ("gcc", "g++"):
        if shutil.which(tool) is None:
            pytest.skip(f"{tool} is not installed")
    return STACK


def includes(*folders: Path) -> list[str]:
    """-I for the OD's folder(s), the stack root and the blank driver's CO_driver_target.h."""
    return [f"-I{f}" for f in (*folders, STACK, STACK / "example")]


def run(command: list[str], cwd: Path | None = None, timeout: float = 120) -> subprocess.CompletedProcess[str]:
    result = subprocess.run(command, cwd=cwd, capture_output=True, text=True, timeout=timeout)
    assert result.returncode == 0, f"{' '.join(map(str, command))}\n{result.stdout}\n{result.stderr}"
    return result


def gen(source: Path, outdir: Path, *args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    """`cantools-od gen -t canopennode` as a user runs it."""
    return subprocess.run(
        [*cli_command(), "gen", str(source), "-t", "canopennode", "-o", str(outdir), *args],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=cwd,
    )


def accepted(device: Device) -> bool:
    return not has_errors(profile_findings(device))


def write_od(device: Device, folder: Path, name: str = "OD") -> None:
    """The generated files, in process (the same code `gen -t canopennode` runs), for corpus sweeps."""
    folder.mkdir(parents=True, exist_ok=True)
    for filename, text in render_node_view(build_node_view(device, name, Path(device.source).name)).items():
        (folder / filename).write_text(text, encoding="utf-8")


def groups_of(header: Path, name: str = "OD") -> list[str]:
    """The storage groups a generated (or CANopenEditor's) header declares."""
    return re.findall(rf"^extern \w+ {name}_(\w+)_t {name}_\w+;", header.read_text(encoding="utf-8"), re.M)


@dataclass(frozen=True)
class Sub:
    attribute: int
    length: int
    group: str  # "-" without memory
    data: bytes | None


@dataclass(frozen=True)
class Entry:
    index: int
    sub_count: int
    kind: int  # ODT_VAR 1, ODT_ARR 2, ODT_REC 3
    subs: dict[int, Sub]


def walk(od_dir: Path, work: Path) -> dict[int, Entry]:
    """Build od_walk.c with the OD in `od_dir` and the stack's CO_ODinterface.c, run it, parse its report."""
    work.mkdir(parents=True, exist_ok=True)
    groups = " ".join(f"G({g})" for g in groups_of(od_dir / "OD.h"))
    exe = work / "od_walk"
    run(["gcc", *WARNINGS, f"-DOD_GROUPS={groups}", *includes(od_dir), "-o", str(exe),
         str(HERE / "od_walk.c"), str(od_dir / "OD.c"), str(STACK / "301" / "CO_ODinterface.c")])  # fmt: skip
    return parse_walk(run([str(exe)]).stdout)


def parse_walk(text: str) -> dict[int, Entry]:
    entries: dict[int, Entry] = {}
    current: Entry | None = None
    for line in text.splitlines():
        part = line.split()
        if part[0] == "O":
            current = Entry(int(part[1], 16), int(part[2]), int(part[3]), {})
            entries[current.index] = current
        else:
            assert current is not None
            data = None if part[5] == "-" else bytes.fromhex(part[5])
            current.subs[int(part[1])] = Sub(int(part[2]), int(part[3]), part[4], data)
    return entries


def parallel(function: Any, items: list[Any]) -> list[Any]:
    with ThreadPoolExecutor(WORKERS) as pool:
        return list(pool.map(function, items))


def load_accepted(paths: list[Path], stack: StackConfig | None = None) -> tuple[list[Device], dict[str, list[str]]]:
    """The devices the canopennode profile accepts (for the declared `stack` configuration, or none), and for the
    others their error codes."""
    kept, refused = [], {}
    for path in paths:
        try:
            device = load(str(path))
        except NotADeviceDescription as refusal:
            refused[path.name] = [refusal.code]
            continue
        findings = profile_findings(device, stack=stack)
        if has_errors(findings):
            refused[path.name] = sorted({f.code for f in findings if f.severity.value == "error"})
        else:
            kept.append(device)
    return kept, refused
