"""The package passes ruff and mypy --strict, as the project requires."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from support import ROOT


def tool(name: str) -> str:
    found = shutil.which(name, path=str(Path(sys.executable).parent)) or shutil.which(name)
    if found is None:
        pytest.skip(f"{name} is not installed")
    return found


def python_trees() -> list[str]:
    return [name for name in ("cantools_od", "tests", "bench") if (ROOT / name).is_dir()]


def test_ruff_check() -> None:
    result = subprocess.run([tool("ruff"), "check", *python_trees()], cwd=ROOT, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr


def test_ruff_format() -> None:
    result = subprocess.run(
        [tool("ruff"), "format", "--check", *python_trees()], cwd=ROOT, capture_output=True, text=True
    )
    assert result.returncode == 0, result.stdout + result.stderr


def test_mypy_strict() -> None:
    result = subprocess.run(
        [tool("mypy"), "--no-incremental", "cantools_od"], cwd=ROOT, capture_output=True, text=True, timeout=600
    )
    assert result.returncode == 0, result.stdout + result.stderr
