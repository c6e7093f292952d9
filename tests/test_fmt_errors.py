"""A file with errors is left as it is: what `lint FILE` reports as an error (with the file's configuration) makes
`fmt`, `fmt --check` and `convert` leave the file alone and exit 1, naming the errors; the configuration's `ignore`
of the code is how a user opts out. Before, only the reader's own errors counted, so `fmt` rewrote a file `lint`
failed."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from support import EXAMPLES, cli_command

# [DeviceInfo] says another product than 1018h: an error of lint's (EDS040), none of the reader's.
WRONG_PRODUCT = (EXAMPLES / "cia402_drive.eds").read_bytes().replace(b"ProductNumber=0x00000402", b"ProductNumber=0x1")


def run(*args: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *args], cwd=cwd, capture_output=True, text=True, timeout=120)


@pytest.mark.parametrize(
    ("args", "verb"),
    [(("fmt", "drive.eds"), "formatted"), (("fmt", "--check", "drive.eds"), "formatted"),
     (("convert", "drive.eds", "-o", "out.xdd"), "converted")],
    ids=["fmt", "fmt --check", "convert"],
)  # fmt: skip
def test_a_file_lint_finds_an_error_in_is_left_as_it_is(tmp_path: Path, args: tuple[str, ...], verb: str) -> None:
    (tmp_path / "drive.eds").write_bytes(WRONG_PRODUCT)
    linted = run("lint", "drive.eds", cwd=tmp_path)
    assert linted.returncode == 1 and "[EDS040]" in linted.stdout, linted.stdout
    ran = run(*args, cwd=tmp_path)
    assert ran.returncode == 1, ran.stderr
    assert "[EDS040]" in ran.stderr
    assert f"drive.eds: error: not {verb}: 1 error to fix first" in ran.stderr
    assert (tmp_path / "drive.eds").read_bytes() == WRONG_PRODUCT
    assert sorted(p.name for p in tmp_path.iterdir()) == ["drive.eds"]


def test_the_configuration_ignoring_the_code_opts_out(tmp_path: Path) -> None:
    (tmp_path / "drive.eds").write_bytes(WRONG_PRODUCT)
    (tmp_path / "pyproject.toml").write_text('[tool.cantools-od]\nignore = ["EDS040"]\n')
    assert run("lint", "drive.eds", cwd=tmp_path).returncode == 0
    converted = run("convert", "drive.eds", "-o", "out.xdd", cwd=tmp_path)
    assert converted.returncode == 0 and (tmp_path / "out.xdd").is_file(), converted.stderr
    formatted = run("fmt", "drive.eds", cwd=tmp_path)
    assert formatted.returncode == 0 and formatted.stderr == "reformatted drive.eds\n", formatted.stderr
    assert (tmp_path / "drive.eds").read_bytes() != WRONG_PRODUCT
