"""The C sources of the compiled extension modules (hatch_build.py builds them into the wheel) compile without a
warning under strict flags, each on its own."""

from __future__ import annotations

import shutil
import subprocess
import sysconfig
from pathlib import Path

import pytest

from support import ROOT

SOURCES = sorted((ROOT / "cantools_od").rglob("_*.c"))


@pytest.mark.skipif(shutil.which("gcc") is None, reason="gcc is not installed")
@pytest.mark.parametrize("source", SOURCES, ids=lambda p: p.relative_to(ROOT).as_posix())
def test_source_compiles_without_warnings(source: Path) -> None:
    include = sysconfig.get_paths()["include"]
    flags = ["-Wall", "-Wextra", "-Werror", "-Wconversion", "-Wshadow", "-fsyntax-only"]
    run = subprocess.run(["gcc", *flags, f"-I{include}", str(source)], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr


def test_both_readers_have_their_source() -> None:
    assert [p.relative_to(ROOT).as_posix() for p in SOURCES] == ["cantools_od/eds/_scan.c", "cantools_od/xdd/_tags.c"]
