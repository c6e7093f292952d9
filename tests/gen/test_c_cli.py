"""`cantools-od gen -t c` and `cantools-od cmake-dir` through the installed console script."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

from ckit import EXAMPLES, cli_command, write_odd_eds


def cantools_od(*args: str, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *args], capture_output=True, text=True, cwd=cwd, timeout=120)


def test_gen_writes_header_source_and_depfile(tmp_path: Path) -> None:
    eds = EXAMPLES / "cia402_drive.eds"
    out, depfile = tmp_path / "out dir", tmp_path / "deps" / "drive.d"
    result = cantools_od("gen", str(eds), "-t", "c", "-o", str(out), "--name", "drive", "--node-id", "5",
                         "--depfile", str(depfile))  # fmt: skip
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in out.iterdir()) == ["drive.c", "drive.h"]
    header = (out / "drive.h").read_text("utf-8")
    assert "#define DRIVE_NODE_ID 5u" in header
    assert "#define DRIVE_TPDO1_COB_ID(node_id) ((uint32_t)((uint32_t)(node_id) + 0x180u))" in header
    escaped = str(out).replace(" ", "\\ ")
    assert depfile.read_text("utf-8") == f"{escaped}/drive.h {escaped}/drive.c: {eds}\n"


def test_gen_rewrites_nothing_that_did_not_change(tmp_path: Path) -> None:
    args = ("gen", str(EXAMPLES / "io_device.eds"), "-t", "c", "-o", str(tmp_path))
    assert cantools_od(*args).returncode == 0
    stamps = {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()}
    assert sorted(stamps) == ["io_device.c", "io_device.h"]
    for path in tmp_path.iterdir():
        path.touch()
        old = path.stat().st_mtime_ns
        stamps[path.name] = old
    assert cantools_od(*args).returncode == 0
    assert {p.name: p.stat().st_mtime_ns for p in tmp_path.iterdir()} == stamps


def test_gen_refuses_a_pdo_longer_than_the_frame(tmp_path: Path) -> None:
    eds = write_odd_eds(tmp_path / "eds")
    out = tmp_path / "out"
    result = cantools_od("gen", str(eds), "-t", "c", "-o", str(out))
    assert result.returncode == 1
    assert "Traceback" not in result.stderr
    diagnostics = re.findall(r"^(.+):(\d+):(\d+): error: (.+) \[GEN001\]$", result.stderr, re.MULTILINE)
    assert [(Path(file), "-bit frame" in message) for file, _, _, message in diagnostics] == [(eds, True)] * 2
    assert "error: nothing generated: errors touch RPDO4" in result.stderr.splitlines()[-1]
    assert not out.exists()
    fd = cantools_od("gen", str(eds), "-t", "c", "-o", str(out), "--can-fd")
    assert fd.returncode == 0, fd.stderr
    assert "#define ODD_BITS_PDO_MAX_DLC 64u" in (out / "odd_bits.h").read_text("utf-8")


def test_cmake_dir_names_the_cmake_package() -> None:
    result = cantools_od("cmake-dir")
    assert result.returncode == 0, result.stderr
    folder = Path(result.stdout.strip())
    assert folder.is_absolute()
    assert {"cantools_odConfig.cmake", "cantools_odConfigVersion.cmake", "cantools_od.cmake"} <= {
        p.name for p in folder.iterdir()
    }
