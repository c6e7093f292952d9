"""Capacities a vendor manual states in prose ("Up to 8 objects can be mapped to a single RPDO", "Sub-indices 1 to
4 define ..."): the importer creates the entries the manual's lists leave out, with the type and access of the
last listed one, and reports them as inferred with the sentence quoted. Then every capacity sentence of the five
real manuals holds in what their import creates."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from manualkit import MANUALS, SEEDS

from cantools_od import load
from cantools_od.model.cia301.pdo import MAP_BASE, PDO_SPAN, RX, TX
from cantools_od.tableimport import import_tables
from cantools_od.tableimport.capacity import read_capacities
from cantools_od.tableimport.text import read_text

from support import cli_command

# The shape of a manual's object blocks (Elmo's): a range of mapping records listing sub-index 0 and 1 only,
# then a note with the capacity; an ARRAY listing sub-index 1, then a sentence giving the range.
MANUAL = """Objects 0x1600 - 0x1601: Receive PDO mapping

These objects contain the mapping for the PDOs the drive receives.

- Object description:

Index	1600h - 1601h
Name	Receive PDO Mapping
Object code	RECORD
Data type	PDO Mapping

- Entry description:

Sub-index	0
Description	Number of mapped objects
Access	Read/Write
PDO mapping	No
Value range	UNSIGNED8
Default value	1

Sub-index	1
Description	First mapped object
Access	Read/Write
PDO mapping	No
Value range	UNSIGNED32
Default value	0x60400010

Notes:

- Up to 4 objects can be mapped to a single RPDO.
- Dummy entries are supported.

Object 0x2F20: Event selection

- Object description:

Index	2F20h
Name	Event selection
Object code	ARRAY
Data type	UNSIGNED32

- Entry description:

Sub-index	0
Description	Highest sub-index supported
Access	Read only
PDO mapping	No
Value range	UNSIGNED8
Default value	3

Sub-index	1
Description	Events of TPDO1
Access	Read/Write
PDO mapping	No
Value range	UNSIGNED32
Default value	0

Sub-indices 1 to 3 define the events of TPDO1, TPDO2 and TPDO3.
"""


def _import(folder: Path, text: str) -> tuple[subprocess.CompletedProcess[str], str]:
    (folder / "manual.txt").write_text(text, encoding="utf-8")
    args = ["import-table", "manual.txt", "-o", "device.eds", "--report", "report.md"]
    result = subprocess.run([*cli_command(), *args], cwd=folder, capture_output=True, text=True)
    return result, (folder / "report.md").read_text(encoding="utf-8") if result.returncode == 0 else ""


def test_prose_capacity_creates_the_entries(tmp_path: Path) -> None:
    result, report = _import(tmp_path, MANUAL)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "manual.txt").read_text(encoding="utf-8") == MANUAL
    device = load(tmp_path / "device.eds")
    for index in (0x1600, 0x1601):
        subs = device.objects[index].subs
        assert sorted(subs) == [0, 1, 2, 3, 4]
        for sub in (2, 3, 4):
            assert (subs[sub].data_type, subs[sub].access, subs[sub].pdo_mapping) == (
                subs[1].data_type,
                subs[1].access,
                subs[1].pdo_mapping,
            )
            assert subs[sub].default == 0  # an unused mapping entry
    assert sorted(device.objects[0x2F20].subs) == [0, 1, 2, 3]
    quoted = '"Up to 4 objects can be mapped to a single RPDO." (manual.txt:30)'
    assert f"| 1601h sub 4 | exists | entry created as sub 1: {quoted} |" in report
    assert '"Sub-indices 1 to 3 define the events of TPDO1, TPDO2 and TPDO3." (manual.txt:58)' in report


def test_a_capacity_the_lists_already_reach_creates_nothing(tmp_path: Path) -> None:
    result, report = _import(tmp_path, MANUAL.replace("Up to 4 objects", "Up to 1 objects"))
    assert result.returncode == 0, result.stderr
    assert sorted(load(tmp_path / "device.eds").objects[0x1600].subs) == [0, 1]
    assert "RPDO." not in report


def _targets(device_indices: set[int], scope: str) -> set[int]:
    directions = (RX, TX) if scope == "pdo" else (scope,)
    return {i for i in device_indices for d in directions if MAP_BASE[d] <= i < MAP_BASE[d] + PDO_SPAN}


@pytest.mark.parametrize("prefix", sorted(MANUALS))
def test_every_capacity_a_manual_states_holds_in_its_import(prefix: str) -> None:
    path = SEEDS / MANUALS[prefix]
    if not path.is_file():
        pytest.skip(f"{path} is absent")
    capacities = read_capacities(str(path), read_text(path.read_bytes()))
    device = import_tables([path]).device
    for capacity in capacities:
        if capacity.scope == "near":
            continue  # tied to the object above it: checked by the shipped examples' reports
        for index in _targets(set(device.objects), capacity.scope):
            subs = device.objects[index].subs
            assert set(range(capacity.count + 1)) <= set(subs), (f"{index:04X}h", capacity.quote())
