"""`convert` from an XDD to an EDS writes the object lists CiA 306 requires. CiA 311 has no lists, so the EDS
writer makes them from the objects: without them our own `lint` refused the output (EDS012 on every object) and
lely's dcfchk crashed on some (a KeyError on the missing section). Every XDD/XDC/XPD of ../shared, read in place."""

from __future__ import annotations

import json
import subprocess
from pathlib import Path

import pytest
from peermatrix import dcfchk_verdict

from support import cli_command, shared_files

XML_FILES = shared_files((".xdd", ".xdc", ".xpd"))


def _run(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *args], cwd=cwd, capture_output=True, text=True)


@pytest.mark.parametrize("source", XML_FILES, ids=lambda p: p.name)
def test_the_eds_of_an_xdd_lists_every_object_once(tmp_path: Path, source: Path) -> None:
    converted = _run(tmp_path, "convert", str(source), "-o", "out.eds")
    if converted.returncode != 0:
        pytest.skip(f"convert refuses {source.name}: {converted.stderr.strip().splitlines()[-1]}")
    linted = _run(tmp_path, "lint", "--format", "json", "--select", "objlists", "out.eds")
    assert json.loads(linted.stdout) == [], linted.stdout
    # dcfchk may refuse the file for other reasons (REAL defaults, python-canopen's Description key), not crash on it
    assert "Objects'" not in (dcfchk_verdict(tmp_path / "out.eds", node_id=1) or "")


def test_the_demo_devices_lists_are_in_cia_306_order(tmp_path: Path) -> None:
    demo = next((p for p in XML_FILES if p.name == "canopendemo__demoDevice.xdd"), None)
    if demo is None:
        pytest.skip("../shared has no canopendemo__demoDevice.xdd")
    assert _run(tmp_path, "convert", str(demo), "-o", "demo.eds").returncode == 0
    text = (tmp_path / "demo.eds").read_text(encoding="utf-8")
    assert "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n" in text
    assert "[ManufacturerObjects]\nSupportedObjects=" in text and "1=0x2100\n" in text
