"""`cantools-od import-table`: exit codes, diagnostics, report, JSON with manual line numbers."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

from .test_tables import HEADER, ROWS, write_csv
from support import cli_command


def run(*args: object, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*cli_command(), *[str(a) for a in args]], capture_output=True, text=True, timeout=120, cwd=cwd
    )


def test_writes_eds_and_report(tmp_path: Path) -> None:
    source = write_csv(tmp_path / "od.csv", ROWS)
    result = run("import-table", source, "-o", tmp_path / "out.eds", "--report", tmp_path / "report.md")
    assert result.returncode == 0, result.stderr
    assert "out.eds: 6 objects" in result.stderr
    assert "[1000]" in (tmp_path / "out.eds").read_text()
    report = (tmp_path / "report.md").read_text()
    assert report.startswith("# Import report") and "## Conflicts" in report
    lint = run("lint", tmp_path / "out.eds")
    assert "Traceback" not in lint.stderr + lint.stdout


def test_json_output_keeps_manual_lines_for_dump(tmp_path: Path) -> None:
    source = write_csv(tmp_path / "od.csv", ROWS)
    assert run("import-table", source, "-o", tmp_path / "out.json").returncode == 0
    model = json.loads((tmp_path / "out.json").read_text())
    assert model["objects"]["4096"]["origin"]["file"] == str(source)
    dump = run("dump", tmp_path / "out.json")
    assert dump.returncode == 0
    row = next(line for line in dump.stdout.splitlines() if line.startswith("1000"))
    assert row.split()[-1] == "od.csv:2"  # the CSV file and line of 1000h, not a line of the EDS


def test_unreadable_source_exits_2(tmp_path: Path) -> None:
    result = run("import-table", tmp_path / "missing.txt", "-o", tmp_path / "out.eds")
    assert result.returncode == 2
    assert "[IMP001]" in result.stderr and "Traceback" not in result.stderr
    assert not (tmp_path / "out.eds").exists()


def test_bad_overrides_exit_2_with_location(tmp_path: Path) -> None:
    source = write_csv(tmp_path / "od.csv", ROWS)
    overrides = tmp_path / "o.toml"
    overrides.write_text("[objects\n", encoding="utf-8")
    result = run("import-table", source, "-o", tmp_path / "out.eds", "--overrides", overrides)
    assert result.returncode == 2
    assert f"{overrides}:1:1: error:" in result.stderr and "[IMP003]" in result.stderr


def test_nothing_found_exits_2(tmp_path: Path) -> None:
    source = tmp_path / "prose.txt"
    source.write_text("Just some text.\nNo tables here.\n", encoding="utf-8")
    result = run("import-table", source, "-o", tmp_path / "out.eds")
    assert result.returncode == 2 and "[IMP002]" in result.stderr


def test_strict_fails_on_policy_resolved_conflicts(tmp_path: Path) -> None:
    rows = [row[:] for row in ROWS]
    rows[1][5] = "RW"
    first = write_csv(tmp_path / "a.csv", rows)
    second = write_csv(tmp_path / "b.csv", ROWS)
    assert run("import-table", first, second, "-o", tmp_path / "out.eds").returncode == 0
    strict = run("import-table", first, second, "-o", tmp_path / "out.eds", "--strict")
    assert strict.returncode == 1 and "[IMP020]" in strict.stderr
    overrides = tmp_path / "o.toml"
    overrides.write_text('[objects."0x1001"]\naccess = "ro"\nreason = "datasheet"\n', encoding="utf-8")
    resolved = run("import-table", first, second, "-o", tmp_path / "out.eds", "--strict", "--overrides", overrides)
    assert resolved.returncode == 0, resolved.stderr
    assert (
        "; override: datasheet" in (tmp_path / "out.eds").read_text()
        or "resolved by override" in (tmp_path / "out.eds").read_text()
    )


def test_forced_layout(tmp_path: Path) -> None:
    source = tmp_path / "od.dat"  # no telling extension
    source.write_text("\n".join("\t".join(r) for r in [HEADER, *ROWS]) + "\n", encoding="utf-8")
    forced = run("import-table", source, "-o", tmp_path / "a.eds", "--layout", "tsv")
    assert forced.returncode == 0, forced.stderr
    wrong = run("import-table", source, "-o", tmp_path / "b.eds", "--layout", "csv")
    assert wrong.returncode == 2  # read as CSV, no table is found


def test_help_lists_the_command() -> None:
    result = run("--help")
    assert "import-table" in result.stdout


def test_a_manual_block_with_a_bad_index_is_reported_once(tmp_path: Path) -> None:
    """A block of a manual's text is read as the object's and the sub-object's entries: one warning."""
    block = "Index\t{}\nName\tSpeed\nObject code\tVAR\nData type\tUNSIGNED16\nAccess\trw\n"
    (tmp_path / "manual.txt").write_text(block.format("1000h") + "\n" + block.format("20xxh"), encoding="utf-8")
    result = subprocess.run(
        [*cli_command(), "import-table", "manual.txt", "-o", "device.eds"], cwd=tmp_path, capture_output=True, text=True
    )
    assert result.returncode == 0, result.stderr
    assert result.stderr.count("[IMP011]") == 1, result.stderr
