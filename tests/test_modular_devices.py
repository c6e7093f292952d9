"""Modular devices (CiA 306 section 6): a bus coupler whose default PDO mappings name objects only its modules
create. The EDS and DCF are written from the standard's module concept: [SupportedModules] with three modules,
their [M<x>FixedObjects] and [M<x>SubExtends] lists and object sections, and a DCF that lists its
[ConnectedModules]. lint, pdo and fmt run as installed, in tmp_path."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

from pykit import eds_text, pdo, var

from support import cli_command

_MODULES = """\
[SupportedModules]
NrOfEntries=3

[M1ModuleInfo]
ProductName=8 digital inputs
ProductVersion=1
ProductRevision=0
OrderCode=DI-8

[M1SubExtends]
NrOfEntries=1
1=0x6000

[M1SubExt6000]
ParameterName=Read input 8-bit
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=0
PDOMapping=1
Count=1

[M2ModuleInfo]
ProductName=8 digital outputs
ProductVersion=1
ProductRevision=0
OrderCode=DO-8

[M2SubExtends]
NrOfEntries=1
1=0x6200

[M2SubExt6200]
ParameterName=Write output 8-bit
ObjectType=0x7
DataType=0x0005
AccessType=rww
DefaultValue=0
PDOMapping=1
Count=1

[M3ModuleInfo]
ProductName=2 analogue inputs
ProductVersion=1
ProductRevision=0
OrderCode=AI-2

[M3FixedObjects]
NrOfEntries=1
1=0x6423

[M3Fixed6423]
ParameterName=Analogue input global interrupt enable
ObjectType=0x7
DataType=0x0001
AccessType=rw
DefaultValue=0
PDOMapping=0

[M3SubExtends]
NrOfEntries=2
1=0x6401
2=0xA0

[M3SubExt6401]
ParameterName=Read analogue input 16-bit
ObjectType=0x7
DataType=0x0003
AccessType=ro
DefaultValue=0
PDOMapping=1
Count=2

[M3SubExtA0]
ParameterName=Module data type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0
PDOMapping=0
Count=1"""
COUPLER_EDS = eds_text(
    [
        "[MandatoryObjects]\nSupportedObjects=1\n1=0x1000",
        var(0x1000, "Device type", 0x0007, "ro"),
        pdo("rx", 1, [(0x6200, 1, 8), (0x6200, 2, 8)]),
        pdo("tx", 1, [(0x6000, 1, 8), (0x6000, 2, 8), (0x6401, 1, 16)]),
        _MODULES,
    ]
)
CONNECTED = "\n[DeviceComissioning]\nNodeID=5\nBaudrate=250\n\n[ConnectedModules]\nNrOfEntries=2\n1=1\n2=3\n"


def _run(folder: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *args], cwd=folder, capture_output=True, text=True)


def _write(folder: Path, name: str, text: str) -> Path:
    path = folder / name
    path.write_text(text, encoding="ascii")
    return path


def _module_sections(text: str) -> list[str]:
    """The module-concept sections as written, one string each (header and lines up to the next section)."""
    blocks = re.split(r"(?m)^(?=\[)", text)
    return [b.strip() for b in blocks if re.match(r"\[(M[0-9]+|SupportedModules|ConnectedModules)", b)]


def test_eds_default_mapping_may_name_objects_only_modules_create(tmp_path: Path) -> None:
    path = _write(tmp_path, "coupler.eds", COUPLER_EDS)
    result = _run(tmp_path, "lint", "--select", "PDO,EDS070", "coupler.eds")
    assert result.returncode == 0, result.stdout
    assert "[PDO042]" not in result.stdout and "[EDS070]" not in result.stdout
    assert path.read_text(encoding="ascii") == COUPLER_EDS


def test_eds_mapping_of_an_object_no_module_creates_is_still_an_error(tmp_path: Path) -> None:
    _write(tmp_path, "coupler.eds", COUPLER_EDS.replace("DefaultValue=0x62000208", "DefaultValue=0x71000208"))
    result = _run(tmp_path, "lint", "--select", "PDO,EDS070", "coupler.eds")
    assert result.returncode == 1
    assert re.findall(r"error: (.*) \[PDO042\]", result.stdout) == ["RPDO1: maps 7100sub2, which does not exist"]


def test_dcf_mapping_is_valid_up_to_the_first_object_no_connected_module_creates(tmp_path: Path) -> None:
    """Modules 1 and 3 are connected, module 2 (6200h) is not: RPDO1 is valid up to its first entry. One module 1
    extends 6000h by one sub-index (Count=1), so TPDO1 is valid up to 6000sub2; its 6401sub1 is not checked."""
    _write(tmp_path, "coupler.dcf", COUPLER_EDS + CONNECTED)
    result = _run(tmp_path, "lint", "--select", "PDO,EDS070", "coupler.dcf")
    assert result.returncode == 0, result.stdout
    found = re.findall(r"(warning|error): (.*) \[PDO042\]", result.stdout)
    tail = ", nor does a connected module create it: the mapping is valid up to here"
    assert found == [
        ("warning", f"RPDO1: maps 6200sub1, which does not exist{tail}"),
        ("warning", f"TPDO1: maps 6000sub2, which does not exist{tail}"),
    ]
    _write(
        tmp_path,
        "twice.dcf",
        COUPLER_EDS + CONNECTED.replace("NrOfEntries=2\n1=1\n2=3", "NrOfEntries=3\n1=1\n2=1\n3=3"),
    )
    result = _run(tmp_path, "lint", "--select", "PDO,EDS070", "twice.dcf")
    assert re.findall(r"maps (\w+), which", result.stdout) == ["6200sub1"]  # two modules 1: 6000sub1 and sub2


def test_module_section_names_are_asked_for_without_leading_zeros(tmp_path: Path) -> None:
    missing = COUPLER_EDS.replace("[M3SubExtA0]", "[M3Unrelated]")
    _write(tmp_path, "missing.eds", missing)
    result = _run(tmp_path, "lint", "--select", "EDS070", "missing.eds")
    assert "[M3SubExtends] 2=0x00A0: no [M3SubExtA0] section [EDS070]" in result.stdout
    _write(tmp_path, "zeros.eds", COUPLER_EDS.replace("[M3SubExtA0]", "[M3SubExt00A0]"))
    assert "[EDS070]" not in _run(tmp_path, "lint", "--select", "EDS070", "zeros.eds").stdout


def test_pdo_names_what_modules_create(tmp_path: Path) -> None:
    _write(tmp_path, "coupler.eds", COUPLER_EDS)
    result = _run(tmp_path, "pdo", "coupler.eds")
    assert result.returncode == 0, result.stderr
    assert "UNKNOWN" not in result.stdout and "dummy" not in result.stdout
    assert "6200sub1  bits   0-7    UNSIGNED8      Write output 8-bit (module 2)" in result.stdout
    assert "6401sub1  bits  16-31   INTEGER16      Read analogue input 16-bit (module 3)" in result.stdout


def test_module_sections_are_kept_byte_for_byte(tmp_path: Path) -> None:
    dcf_text = COUPLER_EDS + CONNECTED
    eds, dcf = _write(tmp_path, "coupler.eds", COUPLER_EDS), _write(tmp_path, "coupler.dcf", dcf_text)
    assert _run(tmp_path, "fmt", "coupler.eds", "coupler.dcf").returncode == 0
    assert _run(tmp_path, "convert", "coupler.eds", "-o", "made.dcf", "--node-id", "5").returncode == 0
    for original, written in ((COUPLER_EDS, eds), (dcf_text, dcf), (COUPLER_EDS, tmp_path / "made.dcf")):
        assert _module_sections(written.read_text(encoding="ascii")) == _module_sections(original)
    assert len(_module_sections(dcf_text)) == 14


def test_gen_says_which_module_creates_an_object_it_cannot_generate(tmp_path: Path) -> None:
    _write(tmp_path, "coupler.eds", COUPLER_EDS)
    result = _run(tmp_path, "gen", "coupler.eds", "-t", "c", "-o", "out")
    assert result.returncode == 1
    assert "RPDO1 maps 6200sub1, which does not exist in the device itself (module 2 creates it" in result.stderr
    assert "[GEN001]" in result.stderr and "Traceback" not in result.stderr
