"""Every command on every hostile input: exit 1 or 2 with a reason, no traceback, the input
unchanged byte for byte and mode for mode, and nothing written beside it."""

from __future__ import annotations

from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import pytest
from kit import GOOD, HOSTILE, HUGE_LINE, assert_failed_cleanly, non_writer, open_folder, run, snapshot

COMMANDS: dict[str, list[str]] = {
    "lint": ["lint", "{}"],
    "lint --fix": ["lint", "--fix", "{}"],
    "fmt": ["fmt", "{}"],
    "fmt --check": ["fmt", "--check", "{}"],
    "convert": ["convert", "{}", "-o", "out.json"],
    "gen": ["gen", "{}", "-t", "c", "-t", "rust", "-t", "python", "-t", "markdown", "-o", "out", "--depfile", "out.d"],
    "dump": ["dump", "{}"],
    "pdo": ["pdo", "{}"],
    "ids": ["ids", "{}"],
    "import-table": ["import-table", "{}", "-o", "imported.eds"],
}
REFUSED_BY_EVERY_READER = {"binary.eds", "empty.eds", "blank.eds", "nul-in-name.eds"}
"""import-table reads vendor tables (text), not device descriptions: only these are hostile to it."""


def args_for(command: str, name: str) -> list[str]:
    return [name if word == "{}" else word for word in COMMANDS[command]]


@pytest.mark.parametrize("name", sorted(HOSTILE))
def test_hostile_input(tmp_path: Path, name: str) -> None:
    """Every command on one hostile input, each in a folder of its own, a few at a time."""
    commands = [c for c in COMMANDS if c != "import-table" or name in REFUSED_BY_EVERY_READER]
    with ThreadPoolExecutor(max_workers=3) as pool:
        failures = [f for found in pool.map(lambda c: run_on(tmp_path / c, c, name), commands) for f in found]
    assert not failures, "\n\n".join(failures)


def run_on(folder: Path, command: str, name: str) -> list[str]:
    """What went wrong running `command` on hostile input `name` in `folder`."""
    folder.mkdir()
    source = folder / name
    source.write_bytes(HOSTILE[name])
    source.chmod(0o640)
    before = snapshot(folder)
    ran = run(*args_for(command, name), cwd=folder)
    try:
        assert_failed_cleanly(ran, one_line=command != "import-table")
        assert snapshot(folder) == before, f"files changed or appeared:\n{ran}"
    except AssertionError as failure:
        return [str(failure)]
    return []


def test_a_megabyte_long_name_is_read_whole_with_a_warning(tmp_path: Path) -> None:
    (tmp_path / "huge-line.eds").write_bytes(HUGE_LINE)
    ran = run("lint", "huge-line.eds", cwd=tmp_path)
    assert ran.returncode == 0, ran
    assert "huge-line.eds:528:256: warning: line has 1000014 characters; CiA 306 allows 255 [EDS001]" in ran.stdout
    assert run("dump", "huge-line.eds", cwd=tmp_path).returncode == 0
    assert (tmp_path / "huge-line.eds").read_bytes() == HUGE_LINE


FAMILY = {"firmware.eds": "an EDS/DCF file", "firmware.xdd": "an XDD/XDC (CiA 311) file"}
"""What the refusal says the file is not: what its name promised."""


@pytest.mark.parametrize("name", sorted(FAMILY))
@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_refusal_is_one_line_naming_the_reason(tmp_path: Path, command: str, name: str) -> None:
    if command == "import-table":
        pytest.skip("import-table reads vendor tables, not device descriptions")
    (tmp_path / name).write_bytes(HOSTILE["binary.eds"])
    ran = run(*args_for(command, name), cwd=tmp_path)
    assert ran.returncode == 2, ran
    reason = f"error: not {FAMILY[name]}: binary data (a NUL byte on line 1) [EDS000]"
    if command.startswith("lint"):  # a finding in lint's report, like any other, in the format chosen
        assert ran.stderr == "" and ran.stdout.startswith(f"{name}:1:1: {reason}\n"), ran
        return
    assert ran.stderr == f"{name}: {reason}\n"


def test_unreadable_input(tmp_path: Path) -> None:
    user = non_writer()
    with open_folder() as folder:
        source = folder / "secret.eds"
        source.write_bytes(GOOD)
        source.chmod(0o600 if user else 0o000)  # root's file: nobody may read it
        before = snapshot(folder)
        for command in COMMANDS:
            ran = run(*args_for(command, "secret.eds"), cwd=folder, user=user)
            assert_failed_cleanly(ran)
            said = ran.stdout if command.startswith("lint") else ran.stderr  # lint: a finding in its report
            assert ran.returncode == 2 and "secret.eds" in said, ran
            assert "ermission denied" in said or "not readable" in said, ran
            assert snapshot(folder) == before, ran


def test_garbage_findings_are_summed_up(tmp_path: Path) -> None:
    """A text file of 5000 stray lines: a few lines per code and a count, not 5000 lines."""
    (tmp_path / "noise.eds").write_bytes(b"[2000]\nParameterName=X\nDataType=0x0007\n" + b"garbage\n" * 5000)
    for args in (["lint", "noise.eds"], ["dump", "noise.eds"], ["gen", "noise.eds", "-t", "c", "-o", "out"]):
        ran = run(*args, cwd=tmp_path)
        assert ran.returncode == 1, ran
        output = ran.stdout + ran.stderr
        assert output.count("[EDS101]") == 10, ran
        assert "noise.eds: note: 4990 more EDS101 findings not shown" in output, ran
        assert len(output.splitlines()) < 30, ran
    summary = run("lint", "noise.eds", cwd=tmp_path).stdout.splitlines()[-1]
    assert summary.startswith("1 file checked: 50"), summary  # every finding counted
