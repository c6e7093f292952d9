"""What the user-journey tests share: the installed `cantools-od` run in a scratch folder as a
person runs it, hostile inputs, and the checks made after every run.

Every test here runs the console script of the environment under test in a subprocess, never
the code in-process, so that what is tested is what a user installs.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import subprocess
import tempfile
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path

import pytest

from support import EXAMPLES, cli_command

GOOD = (EXAMPLES / "io_device.eds").read_bytes()
NOBODY = 65534


HUGE_LINE = GOOD.replace(b"ParameterName=Device settings", b"ParameterName=" + b"M" * 1_000_000, 1)
"""A valid file whose one object name is a megabyte long: CiA 306 allows 255 characters a line, but python-canopen
and lely read the whole line, so it is no hostile input but a warning (EDS001, docs/rules.md's severity policy)."""


HOSTILE: dict[str, bytes] = {
    "binary.eds": b"\x7fELF\x02\x01\x01\x00" + bytes(range(256)) * 40,
    "empty.eds": b"",
    "blank.eds": b"  \r\n\t\n\n",
    "truncated.eds": GOOD[: len(GOOD) // 2],
    "nul-in-name.eds": GOOD.replace(b"ParameterName=Device settings", b"ParameterName=Manu\x00facturer", 1),
    "headerless.eds": b"ParameterName=Speed\nDataType=0x0007\nAccessType=rw\n",
    "device.xdd.eds": b'<?xml version="1.0" encoding="utf-8"?>\n<ISO15745ProfileContainer/>\n',
    "not-a-model.json": b'{"objects": {"x": 1}}\n',
}
"""Inputs no command may take for a device description it can use as it is."""


@dataclass(frozen=True)
class Ran:
    args: tuple[str, ...]
    returncode: int
    stdout: str
    stderr: str

    def __str__(self) -> str:
        return f"cantools-od {' '.join(self.args)} -> {self.returncode}\n{self.stdout[-2000:]}\n{self.stderr[-2000:]}"


def run(*args: str | Path, cwd: Path, user: Sequence[str] = (), umask: int | None = None, timeout: float = 120) -> Ran:
    """The installed cantools-od with `args` in `cwd`, as `user` (a command prefix) and `umask`."""
    words = tuple(str(a) for a in args)
    result = subprocess.run(
        [*user, *cli_command(), *words],
        cwd=cwd,
        capture_output=True,
        text=True,
        errors="replace",
        timeout=timeout,
        umask=-1 if umask is None else umask,
    )
    return Ran(words, result.returncode, result.stdout, result.stderr)


def snapshot(folder: Path) -> dict[str, tuple[str, int]]:
    """Every file under `folder` (hidden ones too): relative path → (sha256, mode)."""
    found: dict[str, tuple[str, int]] = {}
    for path in sorted(folder.rglob("*")):
        if path.is_symlink() or not path.is_file():
            continue
        mode = path.stat().st_mode & 0o7777
        try:
            digest = hashlib.sha256(path.read_bytes()).hexdigest()
        except PermissionError:
            digest = "unreadable"
        found[path.relative_to(folder).as_posix()] = (digest, mode)
    return found


def temp_files(folder: Path) -> list[str]:
    return sorted(p.relative_to(folder).as_posix() for p in folder.rglob("*") if p.name.endswith(".tmp"))


def assert_failed_cleanly(ran: Ran, one_line: bool = True) -> None:
    """Exit 1 or 2, a reason, and never a traceback; exit 2 (a refusal) says it in one line."""
    assert ran.returncode in (1, 2), ran
    assert "Traceback" not in ran.stderr + ran.stdout, ran
    assert "error" in (ran.stderr + ran.stdout).lower(), ran  # lint prints its findings to stdout
    if one_line and ran.returncode == 2:
        reasons = [line for line in ran.stderr.splitlines() if line.strip()]
        # lint reports a file that is no device description (EDS000, JSN001), or that it cannot read (EDS000), in its
        # report on stdout
        in_report = ":1:1: error: not " in ran.stdout or ":1:1: error: cannot read: " in ran.stdout
        assert len(reasons) == 1 or (not reasons and in_report), ran


def non_writer() -> list[str]:
    """A command prefix that runs a command as a user who cannot write into a folder of mode 0555.

    Tests run as root here, and root writes anywhere whatever the mode: there the command runs
    as `nobody` through setpriv. Skips when neither works."""
    if os.geteuid() != 0:
        return []
    setpriv = shutil.which("setpriv")
    if setpriv is None:
        pytest.skip("running as root without setpriv: no way to run as a user a folder's mode stops")
    prefix = [setpriv, f"--reuid={NOBODY}", f"--regid={NOBODY}", "--clear-groups"]
    probe = subprocess.run([*prefix, *cli_command(), "--version"], capture_output=True, text=True)
    if probe.returncode != 0:
        pytest.skip(f"cannot run cantools-od as uid {NOBODY}: {probe.stderr.strip()[:200]}")
    return prefix


@contextmanager
def open_folder() -> Iterator[Path]:
    """A scratch folder that another user can reach (pytest's tmp_path is private to its owner)."""
    folder = Path(tempfile.mkdtemp(prefix="cantools-od-journey-"))
    folder.chmod(0o755)
    try:
        yield folder
    finally:
        for path in [folder, *folder.rglob("*")]:
            if path.is_dir() and not path.is_symlink():
                path.chmod(0o755)
        shutil.rmtree(folder)
