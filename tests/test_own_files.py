"""The project's own EDS files pass its own checks, run the way a contributor runs them in this repository
(from the project root, so its `[tool.cantools-od]` applies)."""

from __future__ import annotations

import subprocess

import pytest

from support import EXAMPLES, ROOT, cli_command

OWN = sorted(EXAMPLES.rglob("*.eds"))


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *args], capture_output=True, text=True, cwd=ROOT, timeout=300)


def test_there_are_own_files() -> None:
    assert len(OWN) >= 6


def test_own_files_lint_without_error() -> None:
    result = run("lint", *(str(p.relative_to(ROOT)) for p in OWN))
    assert result.returncode == 0, result.stdout + result.stderr
    assert ": error:" not in result.stdout


@pytest.mark.parametrize("path", OWN, ids=lambda p: str(p.relative_to(EXAMPLES)))
def test_own_file_is_formatted(path: object) -> None:
    result = run("fmt", "--check", "--diff", str(path))
    assert result.returncode == 0, result.stdout + result.stderr
