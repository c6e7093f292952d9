"""Many files, one report: a file that is no device description is an EDS000 finding in the chosen format and every
other file is still checked; `--jobs N` gives the bytes `--jobs 1` gives; each file's configuration is found from
its own folder upwards, so the current folder changes nothing."""

from __future__ import annotations

import json
import shutil
import subprocess
from dataclasses import dataclass
from pathlib import Path

import pytest

from support import CORPUS, EXAMPLES, cli_command, corpus_files


@dataclass(frozen=True)
class Ran:
    returncode: int
    stdout: str
    stderr: str


def run(*args: str | Path, cwd: Path, timeout: float = 300) -> Ran:
    """The installed cantools-od, run in `cwd` as a user runs it."""
    done = subprocess.run([*cli_command(), *map(str, args)], cwd=cwd, capture_output=True, text=True, timeout=timeout)
    return Ran(done.returncode, done.stdout, done.stderr)


DRIVE = EXAMPLES / "cia402_drive.eds"
IO = EXAMPLES / "io_device.eds"


def _files(folder: Path) -> list[str]:
    """A file with one finding (EDS008), an empty one, a binary one and a good file, in that order."""
    (folder / "a.eds").write_bytes(DRIVE.read_bytes().replace(b"EDSVersion=4.0", b"EDSVersion=4.2", 1))
    (folder / "empty.eds").write_bytes(b"")
    (folder / "firmware.eds").write_bytes(b"\x7fELF\x02\x01\x01\x00" + bytes(range(256)))
    shutil.copy(IO, folder / "b.eds")
    return ["a.eds", "empty.eds", "firmware.eds", "b.eds"]


def test_json_over_many_files_is_one_document_with_eds000_for_what_is_no_device(tmp_path: Path) -> None:
    names = _files(tmp_path)
    ran = run("lint", "--format", "json", "--select", "EDS000,EDS008", *names, cwd=tmp_path)
    assert ran.returncode == 2, ran  # the worst of all files: one is no device description
    found = json.loads(ran.stdout)
    eds000 = {(f["file"], f["line"]) for f in found if f["code"] == "EDS000"}
    assert eds000 == {("empty.eds", 1), ("firmware.eds", 1)}
    assert {f["file"] for f in found} >= {"a.eds", "empty.eds", "firmware.eds"}
    assert ran.stderr == ""


@pytest.mark.parametrize("fmt", ["text", "sarif", "github"])
def test_every_format_reports_eds000_and_checks_the_rest(tmp_path: Path, fmt: str) -> None:
    names = _files(tmp_path)
    ran = run("lint", "--format", fmt, *names, cwd=tmp_path)
    assert ran.returncode == 2, ran
    assert ran.stdout.count("EDS000") >= 2 and "EDS008" in ran.stdout, ran
    if fmt == "text":
        assert "empty.eds:1:1: error: not an EDS/DCF file: the file is empty [EDS000]" in ran.stdout
        assert "4 files checked" in ran.stdout
    if fmt == "sarif":
        json.loads(ran.stdout)


def test_ignoring_eds000_leaves_the_other_files_verdict(tmp_path: Path) -> None:
    names = _files(tmp_path)
    ran = run("lint", "--ignore", "EDS000", "--select", "EDS000,EDS008", *names, cwd=tmp_path)
    assert ran.returncode == 0 and "EDS000" not in ran.stdout, ran


def test_fmt_check_reports_every_file(tmp_path: Path) -> None:
    names = _files(tmp_path)
    (tmp_path / "b.eds").write_text(IO.read_text().replace("\n", "\r\n"))
    ran = run("fmt", "--check", *names, cwd=tmp_path)
    assert ran.returncode == 2, ran
    lines = ran.stderr.splitlines()
    assert "empty.eds: error: not an EDS/DCF file: the file is empty [EDS000]" in lines
    assert "would reformat b.eds" in lines, ran


def test_whole_corpus_in_one_call_is_one_json_document(tmp_path: Path) -> None:
    files = corpus_files()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    ran = run("lint", "--format", "json", *files, cwd=tmp_path, timeout=900)
    assert ran.returncode == 2, ran.stderr  # the corpus holds an empty file
    found = json.loads(ran.stdout)
    reported = {f["file"] for f in found}
    assert any(f["code"] == "EDS000" for f in found)
    assert len(reported) >= len(files) - 3, sorted({str(p) for p in files} - reported)


def test_jobs_give_the_bytes_one_job_gives(tmp_path: Path) -> None:
    names = _files(tmp_path)
    names += [str(p) for p in sorted(CORPUS.glob("*.eds"))[:6]] if CORPUS.is_dir() else []
    for args in (["lint"], ["lint", "--format", "sarif"], ["fmt", "--check", "--diff"]):
        serial = run(*args, "--jobs", "1", *names, cwd=tmp_path)
        parallel = run(*args, "--jobs", "3", *names, cwd=tmp_path)
        default = run(*args, *names, cwd=tmp_path)
        assert serial.stdout, serial
        for other in (parallel, default):
            assert (other.returncode, other.stdout, other.stderr) == (serial.returncode, serial.stdout, serial.stderr)


def _project(root: Path, config: str, in_pyproject: bool = True) -> Path:
    """A project whose configuration ignores EDS008 and keeps integers as written; its eds/ holds one file that
    has an EDS008 finding and hex numbers `fmt` would otherwise respell."""
    (root / "eds").mkdir(parents=True)
    if in_pyproject:
        (root / "pyproject.toml").write_text(f'[project]\nname = "x"\n\n[tool.cantools-od]\n{config}')
    else:
        (root / "cantools-od.toml").write_text(config)
    text = DRIVE.read_bytes().replace(b"EDSVersion=4.0", b"EDSVersion=4.2", 1)
    (root / "eds" / "drive.eds").write_bytes(text)
    return root / "eds" / "drive.eds"


CONFIG = 'ignore = ["EDS008"]\ninteger-radix = "hex"\n'


@pytest.mark.parametrize("in_pyproject", [True, False], ids=["pyproject", "cantools-od.toml"])
def test_configuration_is_found_from_the_file_not_the_current_folder(tmp_path: Path, in_pyproject: bool) -> None:
    project = tmp_path / "project"
    eds = _project(project, CONFIG, in_pyproject)
    other = tmp_path / "elsewhere"
    other.mkdir()
    (other / "pyproject.toml").write_text('[tool.cantools-od]\nselect = ["EDS008"]\n')
    for command in (["lint"], ["fmt", "--check"]):
        at_root = run(*command, "eds/drive.eds", cwd=project)
        for folder in (Path("/"), other, project / "eds"):
            ran = run(*command, eds, cwd=folder)
            assert (ran.returncode, ran.stdout.replace(str(eds), "eds/drive.eds")) == (
                at_root.returncode,
                at_root.stdout,
            ), (folder, ran)
    assert "EDS008" not in run("lint", eds, cwd=Path("/")).stdout


def test_a_pyproject_without_the_table_does_not_stop_the_search(tmp_path: Path) -> None:
    eds = _project(tmp_path, CONFIG)
    (tmp_path / "eds" / "pyproject.toml").write_text('[project]\nname = "inner"\n')
    assert "EDS008" not in run("lint", eds, cwd=Path("/")).stdout


def test_config_option_overrides_what_each_file_finds(tmp_path: Path) -> None:
    eds = _project(tmp_path, CONFIG)
    chosen = tmp_path / "strict.toml"
    chosen.write_text('select = ["EDS008"]\n')
    ran = run("lint", "--config", chosen, eds, cwd=Path("/"))
    assert ran.returncode == 0 and "EDS008" in ran.stdout, ran
    bad = tmp_path / "bad.toml"
    bad.write_text("selekt = []\n")
    ran = run("lint", "--config", bad, eds, cwd=Path("/"))
    assert ran.returncode == 2 and "bad.toml" in ran.stderr and "Traceback" not in ran.stderr, ran


def test_this_projects_eds_folder_checks_the_same_from_anywhere(tmp_path: Path) -> None:
    files = sorted(str(p) for p in EXAMPLES.rglob("*.eds"))
    root = EXAMPLES.parent
    for command in (["fmt", "--check"], ["lint"]):
        here = run(*command, *files, cwd=root)
        there = run(*command, *files, cwd=Path("/"))
        assert (here.returncode, here.stdout, here.stderr) == (there.returncode, there.stdout, there.stderr)
    assert run("fmt", "--check", *files, cwd=Path("/")).returncode == 0
