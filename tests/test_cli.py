"""The command line, run as a user runs it: a separate process, exit codes, stdout/stderr."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest

from support import EXAMPLES, cli_command


def run(*args: str | Path, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=120)


def test_version() -> None:
    # Start-up time is measured by bench/bench_lint.py, not asserted here: a loaded CI machine is no stopwatch.
    result = run("--version")
    assert result.returncode == 0 and result.stdout.startswith("cantools-od, version ")


def test_python_dash_m() -> None:
    import sys

    result = subprocess.run([sys.executable, "-m", "cantools_od", "--help"], capture_output=True, text=True)
    assert result.returncode == 0 and "dump" in result.stdout


def test_dump_text_and_json() -> None:
    result = run("dump", EXAMPLES / "cia402_drive.eds")
    assert result.returncode == 0, result.stderr
    assert "6041" in result.stdout and "Statusword" in result.stdout
    data = json.loads(run("dump", EXAMPLES / "io_device.eds", "--format", "json").stdout)
    assert "4096" in data["objects"]


def test_unreadable_input_exits_2() -> None:
    result = run("dump", "does-not-exist.eds")
    assert result.returncode == 2
    assert "does-not-exist.eds: error: cannot read" in result.stderr
    assert "Traceback" not in result.stderr


def test_usage_error_exits_2() -> None:
    assert run("dump").returncode == 2
    assert run("nonsense").returncode == 2


def test_bad_content_gives_located_diagnostics(tmp_path: Path) -> None:
    bad = tmp_path / "bad.eds"
    bad.write_text("[2000]\nParameterName=X\nDataType=0x0005\nAccessType=ro\nDefaultValue=zz\n")
    result = run("dump", bad)
    assert result.returncode == 1
    assert f"{bad}:5:14: error: " in result.stderr and "[EDS030]" in result.stderr
    assert "Traceback" not in result.stderr


def test_fmt_check_diff_and_write(tmp_path: Path) -> None:
    target = tmp_path / "x.eds"  # in a folder of its own: no [tool.cantools-od] style applies
    target.write_bytes(b"[2000]\r\nParameterName=X\r\nAccessType=RO\r\nDataType=5\r\n")
    check = run("fmt", "--check", target, cwd=tmp_path)
    assert check.returncode == 1 and "would reformat" in check.stderr
    diff = run("fmt", "--diff", target, cwd=tmp_path)
    assert diff.returncode == 1 and "+DataType=0x0005" in diff.stdout
    assert target.read_bytes().startswith(b"[2000]\r\n")  # --check and --diff change nothing
    assert run("fmt", target, cwd=tmp_path).returncode == 0
    assert target.read_bytes() == b"[2000]\nParameterName=X\nDataType=0x0005\nAccessType=ro\n"
    mtime = target.stat().st_mtime_ns
    assert run("fmt", "--check", target, cwd=tmp_path).returncode == 0
    assert run("fmt", target, cwd=tmp_path).returncode == 0 and target.stat().st_mtime_ns == mtime


def test_convert_between_formats(tmp_path: Path) -> None:
    source = tmp_path / "io.eds"
    shutil.copy(EXAMPLES / "io_device.eds", source)
    assert run("convert", source, "-o", tmp_path / "io.json").returncode == 0
    assert run("convert", tmp_path / "io.json", "-o", tmp_path / "back.eds").returncode == 0
    assert run("convert", source, "-o", tmp_path / "same.eds").returncode == 0
    assert (tmp_path / "same.eds").read_bytes() == source.read_bytes()  # same format keeps the layout
    no_node = run("convert", source, "-o", tmp_path / "io.dcf")
    assert no_node.returncode == 2 and "node-ID" in no_node.stderr
    assert run("convert", source, "-o", tmp_path / "io.dcf", "--node-id", "5").returncode == 0
    dcf = (tmp_path / "io.dcf").read_text()
    assert "NodeID=5" in dcf and "ParameterValue=0x00000185" in dcf


def test_pdo_json_shape() -> None:
    result = run("pdo", EXAMPLES / "cia402_drive.eds", "--format", "json", "--node-id", "5")
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    assert set(data) == {"pdos"}
    for pdo in data["pdos"]:
        assert set(pdo) == {"direction", "number", "cob_id", "transmission_type", "entries"}
        assert pdo["direction"] in ("rx", "tx") and isinstance(pdo["cob_id"], int)
        for entry in pdo["entries"]:
            assert set(entry) == {"index", "subindex", "name", "data_type", "bit_offset", "bit_length", "identifier"}
    tpdo1 = next(p for p in data["pdos"] if p["direction"] == "tx" and p["number"] == 1)
    assert tpdo1["cob_id"] == 0x185
    assert [e["index"] for e in tpdo1["entries"]] == [0x6041, 0x6061]


def test_pdo_json_needs_node_id_for_symbolic_cob_ids() -> None:
    result = run("pdo", EXAMPLES / "cia402_drive.eds", "--format", "json")
    assert result.returncode == 2 and "--node-id" in result.stderr


@pytest.mark.parametrize("example", ["io_device.eds", "cia402_drive.eds"])
def test_pdo_text_draws_layouts(example: str) -> None:
    result = run("pdo", EXAMPLES / example)
    assert result.returncode == 0, result.stderr
    assert "TPDO1" in result.stdout and "+---+---+" in result.stdout and "$NODEID+0x180" in result.stdout


def test_pinned_identifiers_survive_a_rename(tmp_path: Path) -> None:
    eds = tmp_path / "drive.eds"
    shutil.copy(EXAMPLES / "cia402_drive.eds", eds)
    pins = run("ids", eds)
    assert pins.returncode == 0 and '"6041" = "statusword"' in pins.stdout
    (tmp_path / "drive.ids.toml").write_text(pins.stdout.replace('"6041" = "statusword"', '"6041" = "status"'))
    eds.write_text(eds.read_text().replace("ParameterName=Statusword", "ParameterName=Status word (renamed)"))
    data = json.loads(run("pdo", eds, "--format", "json", "--node-id", "1").stdout)
    names = {e["index"]: e["identifier"] for p in data["pdos"] for e in p["entries"]}
    assert names[0x6041] == "status"
    assert names[0x6064] == "position_actual_value"
    (tmp_path / "bad.toml").write_text("[identifiers]\n'6041' = 'Not Valid'\n")
    bad = run("pdo", eds, "--pins", tmp_path / "bad.toml")
    assert bad.returncode == 2 and "bad.toml" in bad.stderr and "Traceback" not in bad.stderr
