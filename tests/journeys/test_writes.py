"""What a command that writes leaves behind: the user's modes, a symbolic link still a link,
nothing rewritten that did not change, and on any failure to write, one line, exit 2, and every
output as it was (no partial set, no temporary file)."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from kit import GOOD, NOBODY, assert_failed_cleanly, non_writer, open_folder, run, snapshot, temp_files

UNFORMATTED = GOOD.replace(b"DataType=0x0007", b"DataType=7")
FIXABLE = (
    b"[1014]\nParameterName=COB-ID EMCY\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x80+$NODEID\n"
)
GEN = ["-t", "c", "-t", "markdown"]


def writes(folder: Path) -> dict[str, list[str]]:
    """One command per way of writing, each of which changes or creates a file in `folder`."""
    (folder / "drive.eds").write_bytes(UNFORMATTED)
    (folder / "emcy.eds").write_bytes(FIXABLE)
    return {
        "fmt": ["fmt", "drive.eds"],
        "lint --fix": ["lint", "--select", "EDS033", "--fix", "--unsafe-fixes", "emcy.eds"],  # EDS033 is unsafe
        "convert": ["convert", "drive.eds", "-o", "drive.json"],
        "gen": ["gen", "drive.eds", *GEN, "-o", "out", "--depfile", "out/drive.d"],
    }


@pytest.mark.parametrize("mode", [0o664, 0o640, 0o755, 0o600])
def test_rewrites_keep_the_mode(tmp_path: Path, mode: int) -> None:
    """Why: every file the tool wrote ended up 0600, whatever it had been."""
    commands = writes(tmp_path)
    (tmp_path / "drive.json").write_bytes(b"{}")  # an existing output with a mode of its own
    out = tmp_path / "out"
    out.mkdir()
    for name in ("drive.h", "drive.c", "drive.md", "drive.d"):
        (out / name).write_text("old\n")
    targets = [tmp_path / "drive.eds", tmp_path / "emcy.eds", tmp_path / "drive.json", *out.iterdir()]
    for path in targets:
        path.chmod(mode)
    for command in commands.values():
        ran = run(*command, cwd=tmp_path)
        assert ran.returncode == 0, ran
    for path in targets:
        assert path.read_bytes() not in (UNFORMATTED, FIXABLE, b"{}", b"old\n"), f"{path.name} not rewritten"
        assert path.stat().st_mode & 0o7777 == mode, f"{path.name}: {oct(path.stat().st_mode & 0o7777)}"
    assert temp_files(tmp_path) == []


@pytest.mark.parametrize("umask", [0o022, 0o002, 0o077])
def test_new_files_follow_the_umask(tmp_path: Path, umask: int) -> None:
    for command in writes(tmp_path).values():
        assert run(*command, cwd=tmp_path, umask=umask).returncode == 0
    created = [tmp_path / "drive.json", *(tmp_path / "out").iterdir()]
    assert len(created) == 5
    for path in created:
        assert path.stat().st_mode & 0o777 == 0o666 & ~umask, f"{path.name}: {oct(path.stat().st_mode)}"


def test_unchanged_outputs_are_not_rewritten(tmp_path: Path) -> None:
    commands = writes(tmp_path)
    for command in commands.values():
        assert run(*command, cwd=tmp_path).returncode == 0
    stamps = {p: p.stat().st_mtime_ns for p in tmp_path.rglob("*") if p.is_file()}
    for command in commands.values():
        assert run(*command, cwd=tmp_path).returncode == 0
    assert {p: p.stat().st_mtime_ns for p in stamps} == stamps


def test_a_symlinked_output_is_written_through(tmp_path: Path) -> None:
    """The link stays a link (a repository may link its EDS from elsewhere); its target gets the content."""
    real = tmp_path / "shared" / "drive.eds"
    real.parent.mkdir()
    real.write_bytes(UNFORMATTED)
    real.chmod(0o644)
    link = tmp_path / "drive.eds"
    link.symlink_to(Path("shared") / "drive.eds")
    assert run("fmt", "drive.eds", cwd=tmp_path).returncode == 0
    assert link.is_symlink() and link.readlink() == Path("shared") / "drive.eds"
    assert real.read_bytes() != UNFORMATTED and real.stat().st_mode & 0o777 == 0o644
    (tmp_path / "out.json").symlink_to("shared/model.json")  # a dangling link: its target is created
    assert run("convert", "drive.eds", "-o", "out.json", cwd=tmp_path).returncode == 0
    assert (tmp_path / "out.json").is_symlink() and (tmp_path / "shared" / "model.json").is_file()
    assert temp_files(tmp_path) == []


@pytest.mark.parametrize("which", ["convert", "gen-output", "gen-depfile", "import-table-report"])
def test_an_output_that_is_a_folder(tmp_path: Path, which: str) -> None:
    writes(tmp_path)
    (tmp_path / "table.csv").write_text("Index,Sub,Name,Type,Access\n0x2000,0,Speed,UNSIGNED16,rw\n")
    (tmp_path / "out").mkdir()
    folder = {
        "convert": "drive.json",
        "gen-output": "out/drive.h",
        "gen-depfile": "out/drive.d",
        "import-table-report": "report.md",
    }[which]
    (tmp_path / folder).mkdir()
    command = {
        "convert": ["convert", "drive.eds", "-o", "drive.json"],
        "gen-output": ["gen", "drive.eds", *GEN, "-o", "out"],
        "gen-depfile": ["gen", "drive.eds", *GEN, "-o", "out", "--depfile", "out/drive.d"],
        "import-table-report": ["import-table", "table.csv", "-o", "imported.eds", "--report", "report.md"],
    }[which]
    before = snapshot(tmp_path)
    ran = run(*command, cwd=tmp_path)
    assert_failed_cleanly(ran)
    assert ran.returncode == 2 and folder in ran.stderr, ran
    assert snapshot(tmp_path) == before, "a partial set of outputs was written"
    assert temp_files(tmp_path) == []


def test_unwritable_places_fail_in_one_line_and_write_nothing() -> None:
    """Why: a read-only output folder ended in a PermissionError traceback, and with --depfile the
    .c/.h were already written when the depfile failed."""
    user = non_writer()
    with open_folder() as folder:
        commands = writes(folder)
        (folder / "table.csv").write_text("Index,Sub,Name,Type,Access\n0x2000,0,Speed,UNSIGNED16,rw\n")
        (folder / "locked").mkdir()
        (folder / "out").mkdir(mode=0o777)
        (folder / "out").chmod(0o777)
        cases = [
            commands["fmt"],  # fmt and --fix rewrite in place, and the folder is read-only
            commands["lint --fix"],
            commands["convert"],
            ["convert", "drive.eds", "-o", "locked/drive.json"],
            ["gen", "drive.eds", *GEN, "-o", "locked/out"],
            ["gen", "drive.eds", *GEN, "-o", "out", "--depfile", "locked/drive.d"],
            ["import-table", "table.csv", "-o", "locked/imported.eds"],
        ]
        folder.chmod(0o555)
        (folder / "locked").chmod(0o555)
        before = snapshot(folder)
        for command in cases:
            ran = run(*command, cwd=folder, user=user)
            assert_failed_cleanly(ran)
            assert ran.returncode == 2 and "cannot write" in ran.stderr and "ermission denied" in ran.stderr, ran
            assert snapshot(folder) == before, f"written although it failed:\n{ran}"
        assert temp_files(folder) == []
        assert list((folder / "out").iterdir()) == []  # the depfile failed: no .c/.h either


def test_a_rewrite_keeps_the_owner(tmp_path: Path) -> None:
    """root formatting a user's file (a CI job, a shared checkout) leaves it the user's."""
    if os.geteuid() != 0:
        pytest.skip("only root may give a file to another user")
    writes(tmp_path)
    path = tmp_path / "drive.eds"
    os.chown(path, NOBODY, NOBODY)
    assert run("fmt", "drive.eds", cwd=tmp_path).returncode == 0
    assert path.read_bytes() != UNFORMATTED
    assert (path.stat().st_uid, path.stat().st_gid) == (NOBODY, NOBODY)


def test_the_python_api_saves_the_same_way(tmp_path: Path) -> None:
    """`cantools_od.save` goes through the same writer: mode kept, refusal as an exception, no temp file."""
    from cantools_od import load, save
    from cantools_od.files import CannotWrite

    path = tmp_path / "drive.eds"
    path.write_bytes(GOOD)
    path.chmod(0o640)
    device = load(path)
    device.objects[0x1017].default = 250
    assert save(device, path) and path.stat().st_mode & 0o777 == 0o640
    assert not save(device, path)  # unchanged: not rewritten
    (tmp_path / "folder.eds").mkdir()
    with pytest.raises(CannotWrite, match=r"cannot write .*folder\.eds: it is a folder"):
        save(device, tmp_path / "folder.eds")
    assert temp_files(tmp_path) == []
