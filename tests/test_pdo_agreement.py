"""lint and gen judge a PDO mapping alike: a PDO gen refuses (GEN001) is one lint reports an error about, and a
PDO lint finds no such error in is one gen generates. Dummy entries (CiA 301 7.4.7.1: a data type's index at
sub-index 0, its length the type's size) first, then every PDO of every real file."""

from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest
from pykit import eds_text, pdo, record, var

from cantools_od import api
from cantools_od.lint import lint
from cantools_od.model import Severity
from cantools_od.views.codegen import build_view

from support import cli_command, corpus_params

# The errors that leave a PDO without a layout: its count, a missing or ill-named object or dummy, a length
# that is not its type's, a frame too long.
_LAYOUT_CODES = {"PDO040", "PDO042", "PDO045", "PDO046", "PDO050", "PDO052"}


def _device_with(entry: int) -> str:
    objects = ["[MandatoryObjects]\nSupportedObjects=1\n1=0x1000", var(0x1000, "Device type", 0x0007, "ro")]
    objects += [record(0x2000, "Values", [("Byte", 0x5, "rw", "0")])]
    index, subindex, bits = entry >> 16, (entry >> 8) & 0xFF, entry & 0xFF
    return eds_text([*objects, pdo("rx", 1, [(0x2000, 1, 8), (index, subindex, bits)])])


def _run(tmp_path: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *args], cwd=tmp_path, capture_output=True, text=True)


@pytest.mark.parametrize(
    ("entry", "accepted"),
    [
        (0x00050008, True),  # UNSIGNED8 dummy: 0005h, sub-index 0, 8 bits
        (0x00070020, True),
        (0x00050108, False),  # sub-index 1: a data type has none
        (0x00050010, False),  # 16 bits of an 8-bit type
        (0x00090008, False),  # VISIBLE_STRING has no fixed size
    ],
    ids=lambda value: f"0x{value:08X}" if isinstance(value, int) and not isinstance(value, bool) else None,
)
def test_lint_and_gen_agree_on_a_dummy_entry(tmp_path: Path, entry: int, accepted: bool) -> None:
    path = tmp_path / "dev.eds"
    path.write_text(_device_with(entry), encoding="ascii")
    before = path.read_bytes()
    linted = _run(tmp_path, "lint", "--select", "PDO", "dev.eds")
    generated = _run(tmp_path, "gen", "dev.eds", "-t", "c", "-o", "out")
    assert path.read_bytes() == before
    assert (linted.returncode == 0) is accepted, linted.stdout + linted.stderr
    assert (generated.returncode == 0) is accepted, generated.stderr
    if not accepted:
        assert f"0x{entry:08X}" in linted.stdout + linted.stderr
        assert "[GEN001]" in generated.stderr and len(generated.stderr.strip().splitlines()) >= 1
        assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def _lint_refused(device: api.Device) -> set[str]:
    found = set()
    for finding in lint(device):
        named = re.match(r"[RT]PDO\d+", finding.message)
        if finding.code in _LAYOUT_CODES and finding.severity is Severity.ERROR and named:
            found.add(named.group())
    return found


@pytest.mark.parametrize("path", corpus_params())
def test_lint_and_gen_agree_on_every_pdo(path: Path) -> None:
    device = api.load(path)
    view = build_view(device, "device")
    assert set(view.failed_pdos) == _lint_refused(device)
