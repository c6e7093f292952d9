"""The vendor EDS files shipped in eds/tableimport: produced by the importer, clean, generating code."""

from __future__ import annotations

import shutil
import subprocess
import tomllib
from pathlib import Path

import pytest
from manualkit import MANUALS, SEEDS

from cantools_od import load
from cantools_od.api import dumps
from cantools_od.lint import lint
from cantools_od.tableimport import import_tables

from support import EXAMPLES, cli_command

SHIPPED_DIR = EXAMPLES / "tableimport"
SHIPPED = {
    "elmo_simpliq": ["000", "001"],
    "sanyo_sanmotion_r": ["002"],
    "moons_canopen": ["003"],
    "nidec_si_canopen": ["004"],
}


def test_every_shipped_file_is_listed() -> None:
    assert sorted(p.stem for p in SHIPPED_DIR.glob("*.eds")) == sorted(SHIPPED)
    for name in SHIPPED:
        assert (SHIPPED_DIR / f"{name}.overrides.toml").is_file()
        assert (SHIPPED_DIR / f"{name}.report.md").is_file()


@pytest.mark.parametrize("name", sorted(SHIPPED))
def test_loads_and_lints_clean_or_explained(name: str) -> None:
    device = load(SHIPPED_DIR / f"{name}.eds")
    assert [d.format() for d in device.diagnostics if d.severity.value == "error"] == []
    explained = tomllib.loads((SHIPPED_DIR / f"{name}.overrides.toml").read_text(encoding="utf-8")).get("lint", {})
    findings = [f for f in lint(device) if f.severity.value in ("error", "warning")]
    unexplained = [f.format() for f in findings if f.code not in explained]
    assert unexplained == []


@pytest.mark.parametrize("name", sorted(SHIPPED))
def test_regenerates_identically(name: str) -> None:
    sources = []
    for prefix in SHIPPED[name]:
        path = SEEDS / MANUALS[prefix]
        if not path.is_file():
            pytest.skip("../shared/seeds is absent")
        sources.append(Path("..") / "shared" / "seeds" / MANUALS[prefix])
    root = EXAMPLES.parent
    overrides = Path("eds") / "tableimport" / f"{name}.overrides.toml"
    import os

    here = Path.cwd()
    os.chdir(root)  # the EDS names its sources relative to the project root
    try:
        result = import_tables(sources, overrides=overrides, output_name=f"{name}.eds")
    finally:
        os.chdir(here)
    assert dumps(result.device, "eds", "canonical") == (SHIPPED_DIR / f"{name}.eds").read_bytes()
    assert result.report() == (SHIPPED_DIR / f"{name}.report.md").read_text(encoding="utf-8")


@pytest.mark.parametrize("name", sorted(SHIPPED))
def test_generates_compiling_c(name: str, tmp_path: Path) -> None:
    result = subprocess.run(
        [*cli_command(), "gen", str(SHIPPED_DIR / f"{name}.eds"), "-t", "c", "-o", str(tmp_path)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stderr
    compiler = shutil.which("cc") or shutil.which("gcc")
    if compiler is None:
        pytest.skip("no C compiler")
    sources = sorted(tmp_path.glob("*.c"))
    assert sources
    built = subprocess.run(
        [compiler, "-std=c99", "-Wall", "-Wextra", "-Werror", "-c", *map(str, sources)],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert built.returncode == 0, built.stderr
