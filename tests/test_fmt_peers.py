"""`fmt` is invisible to peers: run on every EDS/DCF of ../shared (corpus, both sides of the history pairs,
third_party), it changes nothing python-canopen reads: no entry's name, type, access, default, limits, PDO flag or
value, nor the node-ID, bit rate or [DeviceInfo], read without a node-ID and with one (peermatrix.peer_changes, the
oracle the fix-safety and peer-matrix tests judge by). A name python-canopen looks up keeps the file's spelling
(`[DeviceCommissioning]`, `NrOfRxPDO`), and a two's-complement hex value of a signed type its hex."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from peermatrix import peer_changes

from support import SHARED, cli_command, shared_files

# One process runs fmt over every file; the readings are shared with the other peer tests of the run.
pytestmark = pytest.mark.xdist_group("fmt_peers")


def test_fmt_changes_nothing_python_canopen_reads(tmp_path: Path) -> None:
    files = shared_files((".eds", ".dcf"))
    if not files:
        pytest.skip("../shared is absent")
    copies = {}
    for path in files:
        copy = tmp_path / path.relative_to(SHARED)
        copy.parent.mkdir(parents=True, exist_ok=True)
        copy.write_bytes(path.read_bytes())
        copies[path] = copy
    names = [str(copy.relative_to(tmp_path)) for copy in copies.values()]
    ran = subprocess.run(
        [*cli_command(), "fmt", "--jobs", "2", *names], cwd=tmp_path, capture_output=True, text=True, timeout=1800
    )
    assert "Traceback" not in ran.stderr, ran.stderr
    rewritten = [path for path, copy in copies.items() if copy.read_bytes() != path.read_bytes()]
    said = {line.removeprefix("reformatted ") for line in ran.stderr.splitlines() if line.startswith("reformatted ")}
    assert said == {str(copies[path].relative_to(tmp_path)) for path in rewritten}
    assert len(rewritten) > 50, "fmt rewrote too few files for the check to prove anything"
    changes = [
        f"{path.relative_to(SHARED)}: {change}" for path in rewritten for change in peer_changes(path, copies[path])
    ]
    assert changes == []


def test_the_commissioning_section_keeps_the_spelling_python_canopen_misses(tmp_path: Path) -> None:
    """The issue's case in small: `[DeviceCommissioning]` and `NodeId` are names python-canopen does not find, so it
    reads no node-ID (and no value of a `$NODEID` formula); CiA 306's spelling would make it read node-ID 5."""
    text = (
        "[DeviceCommissioning]\nNodeId=5\nBaudrate=500\n\n[DeviceInfo]\nVendorName=x\nNrOfRxPDO=0\nNrOfTXPDO=0\n\n"
        "[2000]\nParameterName=Offset\nObjectType=0x7\nDataType=0x0003\nAccessType=rw\nDefaultValue=0xFFFF\n"
        "PDOMapping=0\n\n"
        "[1014]\nParameterName=COB-ID EMCY\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
        "DefaultValue=$NODEID+0x80\nPDOMapping=0\n"
    )
    original, device = tmp_path / "original.dcf", tmp_path / "device.dcf"
    original.write_text(text)
    device.write_text(text)
    ran = subprocess.run([*cli_command(), "fmt", "device.dcf"], cwd=tmp_path, capture_output=True, text=True)
    assert ran.returncode == 0 and ran.stderr == "reformatted device.dcf\n", ran.stderr
    formatted = device.read_text()
    assert "[DeviceCommissioning]\nNodeId=5\n" in formatted and "NrOfRxPDO=0" in formatted
    assert "DefaultValue=0xFFFF" in formatted
    assert peer_changes(original, device) == []
