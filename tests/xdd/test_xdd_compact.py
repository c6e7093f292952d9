"""An EDS's compact forms survive XDD and XDC: an array written with `CompactSubObj=N` (CiA 306 §4.6.3.4.2)
and the PDOs `CompactPDO` implies (§4.6.3.4.1) come back compact in the EDS/DCF written from the XDD/XDC,
so that python-canopen reads the same entries from EDS → XDD → EDS as from the EDS itself. It reads a
compact array by rules of its own (sub-index 0 "Number of entries", rw, no default; sub-index 1 the array
itself, limits included) and implies no PDO from CompactPDO: the explicit sub-objects and PDO records an
XDD lists read otherwise when the EDS written from it lists them too."""

from __future__ import annotations

import os
import re
import subprocess
from pathlib import Path

import pytest
from lintkit import BASE
from xddkit import peer_differences, peer_entries

from cantools_od import dumps, load

from support import cli_command


def _section(name: str) -> str:
    found = re.search(rf"^\[{name}\]\n.*?\n\n", BASE, re.M | re.S)
    assert found is not None
    return found.group()


# lintkit's file header and standard objects, with one RPDO that CompactPDO implies
HEADER = (
    BASE.split("[DummyUsage]")[0].replace("NrOfRXPDO=0", "NrOfRXPDO=1\nCompactPDO=0x03")
    + "[MandatoryObjects]\nSupportedObjects=2\n1=0x1000\n2=0x1001\n\n"
    + _section("1000")
    + _section("1001")
    + """[OptionalObjects]
SupportedObjects=1
1=0x1003

[1003]
ParameterName=Pre-defined error field
ObjectType=0x8
DataType=0x0007
AccessType=ro
PDOMapping=0
CompactSubObj=254

[ManufacturerObjects]
SupportedObjects=2
1=0x2000
2=0x2001

[2000]
ParameterName=Gains
ObjectType=0x8
DataType=0x0006
AccessType=rw
DefaultValue=7
LowLimit=1
HighLimit=100
PDOMapping=1
CompactSubObj=8

[2001]
ParameterName=Offsets
ObjectType=0x8
DataType=0x0003
AccessType=ro
DefaultValue=-3
PDOMapping=0
CompactSubObj=3

[2001Name]
NrOfEntries=2
1=First offset
2=Middle offset
"""
)


def convert(source: Path, target: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), "convert", str(source), "-o", str(target)], capture_output=True, text=True)


@pytest.mark.parametrize("xml", ["xdd", "xdc"])
def test_compact_arrays_and_pdos_come_back_through_xml(tmp_path: Path, xml: str) -> None:
    ini = "eds" if xml == "xdd" else "dcf"
    source = tmp_path / f"compact.{ini}"
    text = HEADER + ("\n[DeviceComissioning]\nNodeID=5\nBaudrate=500\n" if ini == "dcf" else "")
    source.write_text(text, encoding="ascii")
    os.chmod(source, 0o640)
    first = convert(source, tmp_path / f"compact.{xml}")
    assert first.returncode == 0, first.stderr
    second = convert(tmp_path / f"compact.{xml}", tmp_path / f"back.{ini}")
    assert second.returncode == 0, second.stderr
    assert source.read_text(encoding="ascii") == text and source.stat().st_mode & 0o777 == 0o640
    back = (tmp_path / f"back.{ini}").read_text(encoding="ascii")
    for index, count in (("1003", 254), ("2000", 8), ("2001", 3)):
        assert f"[{index}]" in back and f"CompactSubObj={count}" in back.split(f"[{index}]")[1].split("\n\n")[0]
    assert "[2000sub" not in back and "[1400]" not in back and "CompactPDO=0x03" in back
    assert peer_differences(source, tmp_path / f"back.{ini}") == []


def test_an_edited_array_is_written_as_the_xdd_says(tmp_path: Path) -> None:
    """An XDD whose array no longer lists what CompactSubObj implies (a sub-object removed, one made
    read-only) is not written compactly: the EDS says what the XDD says."""
    source = tmp_path / "compact.eds"
    source.write_text(HEADER, encoding="ascii")
    assert convert(source, tmp_path / "compact.xdd").returncode == 0
    device = load(tmp_path / "compact.xdd")
    device.objects[0x2000].subs.pop(8)
    device.objects[0x2001].subs[2].access = device.objects[0x1000].access  # ro -> ro: stays compact
    device.objects[0x2001].subs[3].default = 5
    (tmp_path / "edited.xdd").write_bytes(dumps(device, "xdd"))
    result = convert(tmp_path / "edited.xdd", tmp_path / "back.eds")
    assert result.returncode == 0, result.stderr
    back = (tmp_path / "back.eds").read_text(encoding="ascii")
    gains = back.split("[2000]")[1].split("\n\n")[0]
    assert "CompactSubObj" not in gains and "SubNumber=8" in gains and "[2000sub7]" in back
    assert "[2000sub8]" not in back
    assert "CompactSubObj=3" in back and "[2001sub3]" in back and "[2001sub2]" not in back
    peer = peer_entries(tmp_path / "back.eds")
    assert peer[(0x2000, 0)][:4] == ("NrOfObjects", 5, "ro", 8) and peer[(0x2001, 3)][3] == 5


def test_convert_names_the_arrays_an_xdd_cannot_keep_compact(tmp_path: Path) -> None:
    """A compact array whose elements state no AccessType: an XDD gives each parameter an access (CiA 311's
    default), so the elements no longer follow the array and the EDS written from the XDD lists them.
    `convert` says so for exactly that object, and not for the array that stays compact."""
    text = HEADER.replace("AccessType=rw\nDefaultValue=7", "DefaultValue=7")
    source = tmp_path / "compact.eds"
    source.write_text(text, encoding="ascii")
    result = convert(source, tmp_path / "compact.xdd")
    assert result.returncode == 0, result.stderr
    said = [line for line in result.stderr.splitlines() if "Compact" in line]
    assert len(said) == 1 and "CompactSubObj form of 2000 is not kept in XDD" in said[0], result.stderr
    assert source.read_text(encoding="ascii") == text
