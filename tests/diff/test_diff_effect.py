"""`diff` tells what a change does (issues #42 and #39), each case on the shape of a real revision pair, run as a
user runs it: the installed CLI on the pair's files in place, reports read as text or JSON."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path
from typing import Any

import pytest

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
