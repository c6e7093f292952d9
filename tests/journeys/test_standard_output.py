"""Standard output that cannot be written, as a user meets it: `> /dev/full` (a full disk) and a reader that
stops early (`| head`). One line and exit 2 for the first, no message for the second, never a traceback; and
the program's output, when it can be written, is all there (the program ends without tearing itself down,
cantools_od/cli/__init__.py `leave`, after flushing)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from support import EXAMPLES, cli_command

# each prints its output to stdout
COMMANDS = [
    ["lint", "drive.eds"],
    ["lint", "--format", "json", "drive.eds"],
    ["dump", "drive.eds"],
    ["pdo", "drive.eds"],
]


@pytest.fixture
def folder(tmp_path: Path) -> Path:
    (tmp_path / "drive.eds").write_bytes((EXAMPLES / "cia402_drive.eds").read_bytes())
    return tmp_path


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full here")
@pytest.mark.parametrize("args", COMMANDS, ids=" ".join)
def test_full_output_is_one_line_and_exit_2(folder: Path, args: list[str]) -> None:
    with open("/dev/full", "w") as full:
        ran = subprocess.run([*cli_command(), *args], cwd=folder, stdout=full, stderr=subprocess.PIPE, text=True)
    assert ran.returncode == 2, ran.stderr
    assert ran.stderr == "cantools-od: error: cannot write standard output: No space left on device\n"


@pytest.mark.parametrize("args", COMMANDS[1:3], ids=" ".join)  # larger than a pipe holds: JSON findings, the table
def test_reader_that_stops_early_gets_no_message(folder: Path, args: list[str]) -> None:
    big = folder / "big.eds"
    big.write_bytes(_large_device())
    words = [("big.eds" if word == "drive.eds" else word) for word in args]
    process = subprocess.Popen([*cli_command(), *words], cwd=folder, stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    assert process.stdout is not None and process.stderr is not None
    assert len(process.stdout.read(10)) == 10
    process.stdout.close()
    stderr = process.stderr.read().decode()
    # 1: lint's findings, or the closed pipe seen by click or `run`; 0: the pipe closed during a write the kernel
    # reports as partly done, after which the program (like 36cca88) writes no more
    assert process.wait(timeout=120) in (0, 1), stderr
    assert "Traceback" not in stderr and "Exception ignored" not in stderr, stderr


@pytest.mark.parametrize("args", COMMANDS, ids=" ".join)
def test_output_is_complete(folder: Path, args: list[str]) -> None:
    # the same bytes through a pipe as through a file: nothing is lost when the program ends
    piped = subprocess.run([*cli_command(), *args], cwd=folder, capture_output=True)
    with open(folder / "out.txt", "wb") as out:
        filed = subprocess.run([*cli_command(), *args], cwd=folder, stdout=out, stderr=subprocess.PIPE)
    assert filed.returncode == piped.returncode
    assert (folder / "out.txt").read_bytes() == piped.stdout
    assert piped.stdout.endswith(b"\n")


def _large_device() -> bytes:
    """A device whose output is larger than a pipe holds (64 KiB), so that the writer meets the closed pipe."""
    lines = [(EXAMPLES / "cia402_drive.eds").read_text(encoding="utf-8")]
    for n in range(3000):
        index = 0x2000 + n
        lines.append(
            f"\n[{index:04X}]\nParameterName=Manufacturer value {n} with a long name to fill the output\n"
            "ObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=70000\nHighLimit=10\nPDOMapping=1\n"
        )
    return "".join(lines).encode()
