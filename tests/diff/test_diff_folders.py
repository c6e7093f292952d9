"""`cantools-od diff OLD_FOLDER NEW_FOLDER` as a reviewer runs it on the real revision histories
(../shared/eds-history): every pair by relative path, in processes (`--jobs`) with the bytes of a serial run, only
changed pairs reported, each report what `diff OLD NEW` of that pair says; unreadable files named, never fatal to
the others; inputs untouched."""

from __future__ import annotations

import json
import shutil
import subprocess
from pathlib import Path

import pytest
from diffkit import BASE, drop_section

from cantools_od.resources import resource_dir

from support import ROOT, cli_command

HISTORY = ROOT.parent / "shared" / "eds-history"

# Its tests share the folders of the whole history: one worker makes them once.
pytestmark = pytest.mark.xdist_group("diff_folders")


def run(*args: str | Path, cwd: Path) -> subprocess.CompletedProcess[str]:
    command = [*cli_command(), *map(str, args)]
    return subprocess.run(command, capture_output=True, text=True, cwd=cwd, timeout=600)


def _snapshot(folder: Path) -> dict[str, tuple[bytes, int]]:
    return {
        p.relative_to(folder).as_posix(): (p.read_bytes(), p.stat().st_mode) for p in folder.rglob("*") if p.is_file()
    }


@pytest.fixture(scope="module")
def releases(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """old/ and new/ holding each history pair's two sides under the pair's name (nested by project), as two
    releases of a repository of device files; a side a pair lacks is absent from that folder."""
    if not HISTORY.is_dir():
        pytest.skip("../shared/eds-history is absent")
    root = tmp_path_factory.mktemp("releases")
    for pair in sorted(p for p in HISTORY.iterdir() if p.is_dir()):
        project, _, number = pair.name.rpartition("__")
        for side in pair.iterdir():
            target = root / side.stem / project / f"{number}{side.suffix}"
            target.parent.mkdir(parents=True, exist_ok=True)
            shutil.copyfile(side, target)
    return root


@pytest.fixture(scope="module")
def serial(releases: Path) -> subprocess.CompletedProcess[str]:
    """The history's two folders compared one pair after the other (text), shared by the tests below."""
    return run("diff", "--jobs", "1", "old", "new", cwd=releases)


def test_parallel_run_is_the_serial_run(releases: Path, serial: subprocess.CompletedProcess[str]) -> None:
    before = _snapshot(releases)
    parallel = run("diff", "--jobs", "2", "old", "new", cwd=releases)
    assert serial.returncode == 0, serial.stderr
    assert (parallel.returncode, parallel.stdout, parallel.stderr) == (0, serial.stdout, serial.stderr)
    assert _snapshot(releases) == before, "inputs must stay untouched"
    headers = [line[4:] for line in serial.stdout.splitlines() if line.startswith("--- ")]
    assert len(headers) > 40  # most pairs of the history change something
    olds = [h for h in headers if h != "/dev/null"]
    assert olds == sorted(olds), "reports come in path order"
    assert "Traceback" not in serial.stdout + serial.stderr


def test_each_report_is_the_diff_of_its_pair(releases: Path, serial: subprocess.CompletedProcess[str]) -> None:
    sides = {p.relative_to(releases / "old") for p in (releases / "old").rglob("*.*")}
    names = sorted(str(name) for name in sides if (releases / "new" / name).is_file())[:6]
    for name in names:
        alone = run("diff", f"old/{name}", f"new/{name}", cwd=releases)
        if alone.stdout.split("\n", 2)[2].startswith("0 breaking, 0 compatible, 0 value, 0 cosmetic"):
            assert f"--- old/{name}\n" not in serial.stdout  # an unchanged pair is not reported
        else:
            assert alone.stdout in serial.stdout


def test_json_is_an_array_of_reports(releases: Path) -> None:
    import jsonschema  # a test dependency (pyproject.toml)

    result = run("diff", "--jobs", "1", "--format", "json", "old", "new", cwd=releases)
    assert result.returncode == 0, result.stderr
    reports = json.loads(result.stdout)
    schema = json.loads((resource_dir("schemas") / "diff.schema.json").read_text())
    validator = jsonschema.Draft202012Validator(schema)
    assert isinstance(reports, list) and len(reports) > 40
    assert [list(validator.iter_errors(report))[:1] for report in reports] == [[]] * len(reports)


def test_a_file_on_one_side_is_added_or_removed(tmp_path: Path) -> None:
    (tmp_path / "old").mkdir()
    (tmp_path / "new" / "sub").mkdir(parents=True)
    (tmp_path / "old" / "gone.eds").write_text(BASE)
    (tmp_path / "new" / "sub" / "came.eds").write_text(drop_section(BASE, "1017"))
    result = run("diff", "--fail-on", "breaking", "old", "new", cwd=tmp_path)
    assert result.returncode == 1, result.stderr  # a removed file breaks what used it
    assert "--- /dev/null\n+++ new/sub/came.eds\n" in result.stdout
    assert "--- old/gone.eds\n+++ /dev/null\n" in result.stdout
    assert result.stdout.index("gone.eds") < result.stdout.index("came.eds")  # by relative path: gone < sub/came
    assert "\n\n--- /dev/null\n+++ new/sub/came.eds\n" in result.stdout  # a blank line between reports


def test_unchanged_folders_report_nothing(tmp_path: Path) -> None:
    for side in ("old", "new"):
        (tmp_path / side).mkdir()
        (tmp_path / side / "device.eds").write_text(BASE)
    text = run("diff", "--fail-on", "any", "old", "new", cwd=tmp_path)
    assert (text.returncode, text.stdout, text.stderr) == (0, "", "")
    assert json.loads(run("diff", "--format", "json", "old", "new", cwd=tmp_path).stdout) == []


def test_an_unreadable_file_is_named_and_the_rest_compared(tmp_path: Path) -> None:
    for side in ("old", "new"):
        (tmp_path / side).mkdir()
        (tmp_path / side / "device.eds").write_text(BASE if side == "old" else drop_section(BASE, "1017"))
    (tmp_path / "old" / "binary.eds").write_bytes(b"\x00\x01\x02" * 100)
    (tmp_path / "new" / "binary.eds").write_bytes(b"")
    (tmp_path / "new" / "notes.json").write_text("{}")  # not a device description: a JSON model only when named
    before = _snapshot(tmp_path)
    result = run("diff", "old", "new", cwd=tmp_path)
    assert result.returncode == 2
    assert "--- old/device.eds\n+++ new/device.eds\n" in result.stdout
    errors = result.stderr.splitlines()
    assert len(errors) == 1 and errors[0].startswith("old/binary.eds: error: ") and errors[0].endswith("[EDS000]")
    assert "Traceback" not in result.stderr and "notes.json" not in result.stdout + result.stderr
    assert _snapshot(tmp_path) == before


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (("empty1", "empty2"), "error: no device description (.eds, .dcf, .xdd, .xdc, .xpd) under empty1 or empty2"),
        (("empty1", "file.eds"), "error: give two files or two folders as OLD and NEW"),
        (("--old-pins", "p.toml", "empty1", "empty2"), "error: --old-pins and --new-pins name the pin file of one"),
    ],
)
def test_refusals_are_one_line(tmp_path: Path, args: tuple[str, ...], message: str) -> None:
    (tmp_path / "empty1").mkdir()
    (tmp_path / "empty2").mkdir()
    (tmp_path / "file.eds").write_text(BASE)
    result = run("diff", *args, cwd=tmp_path)
    assert result.returncode == 2 and result.stdout == ""
    assert len(result.stderr.splitlines()) == 1 and result.stderr.startswith(message)


def test_markdown_titles_name_the_relative_path(tmp_path: Path) -> None:
    """Two nodes' files of one name in two folders: each title tells which (the file name alone would not)."""
    for side in ("old", "new"):
        for node in ("node1", "node2"):
            (tmp_path / side / node).mkdir(parents=True)
            text = BASE if side == "old" else drop_section(BASE, "1017" if node == "node1" else "1018")
            (tmp_path / side / node / "device.eds").write_text(text)
    result = run("diff", "--format", "markdown", "old", "new", cwd=tmp_path)
    titles = [line for line in result.stdout.splitlines() if line.startswith("## ")]
    assert titles == [
        "## Object dictionary changes: `node1/device.eds` → `node1/device.eds`",
        "## Object dictionary changes: `node2/device.eds` → `node2/device.eds`",
    ]
