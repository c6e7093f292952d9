"""One file, one set of PDOs: `lint`, `pdo --format json` and `gen` read hostile mappings the same way.

Each case is a mapping as a user may meet it (oversized or flagged length bytes, dummy entries,
missing objects, multiplexed-PDO counts, CAN FD sizes), with the one reading CiA 301 gives it:
entries as (index, sub-index, bit offset, bit length). The installed CLI is run three times on
the same file: `pdo --format json` must draw exactly those entries, `gen -t markdown` must lay
them out at the same bits (or refuse with GEN001 when code cannot be generated from them), and
`lint` must see the same total length (PDO046 names it whenever it exceeds the frame).
"""

from __future__ import annotations

import json
import re
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from lintkit import comm, eds, mapping, record, var

from support import cli_command

U8_OUT = var(0x6200, "Output byte", 0x0005, "rw")
U8_OUTPUTS = record(0x6200, "Write output 8-bit", {1: ("Outputs 1 to 8", 0x0005, 0)})
U16_STATUS = var(0x6041, "Statusword", 0x0006, "ro")
I32_POSITION = var(0x6064, "Position actual value", 0x0004, "ro")


@dataclass(frozen=True)
class Case:
    parts: tuple[str, ...]
    entries: tuple[tuple[int, int, int, int], ...]  # (index, sub-index, bit offset, bit length) of the one PDO
    lint_codes: tuple[str, ...] = ()  # codes lint must report besides PDO046
    gen_refuses: bool = False
    can_fd: bool = False
    dummies: str = "0002,0003,0004,0005,0006,0007"
    extra: dict[str, str] = field(default_factory=dict)

    @property
    def total(self) -> int:
        return sum(entry[3] for entry in self.entries)

    @property
    def frame(self) -> int:
        return 512 if self.can_fd else 64


def rpdo(*entries: str, count: object = None) -> tuple[str, str]:
    return comm(0x1400, "$NODEID+0x200"), mapping(0x1600, *entries, count=count)


def tpdo(*entries: str, count: object = None) -> tuple[str, str]:
    return comm(0x1800, "$NODEID+0x180"), mapping(0x1A00, *entries, count=count)


CASES = {
    # A length byte of 88h is 136 bits (CiA 301: bits 7-0 are the length); not 8 bits with a flag.
    "oversized-length": Case((*rpdo("0x62000188"), U8_OUTPUTS), ((0x6200, 1, 0, 136),), ("PDO045", "PDO053"), True),
    "flagged-length": Case((*tpdo("0x60410090"), U16_STATUS), ((0x6041, 0, 0, 144),), ("PDO045", "PDO053"), True),
    "oversized-on-can-fd": Case(
        (*rpdo("0x62000188"), U8_OUTPUTS), ((0x6200, 1, 0, 136),), ("PDO045",), gen_refuses=True, can_fd=True
    ),
    "dummy-then-object": Case((*rpdo("0x00050008", "0x62000008"), U8_OUT), ((0x0005, 0, 0, 8), (0x6200, 0, 8, 8))),
    "dummy-not-enabled": Case(
        (*rpdo("0x00060010", "0x62000008"), U8_OUT), ((0x0006, 0, 0, 16), (0x6200, 0, 16, 8)), ("PDO062",), dummies=""
    ),
    "dummy-of-wrong-length": Case(  # a device refuses it (PDO045), so gen does too
        (*rpdo("0x00050010", "0x62000008"), U8_OUT), ((0x0005, 0, 0, 16), (0x6200, 0, 16, 8)), ("PDO045",), True
    ),
    "dummy-with-a-sub-index": Case(  # CiA 301 7.4.7.1: a data type is mapped at sub-index 0 (PDO050)
        (*rpdo("0x00050108", "0x62000008"), U8_OUT), ((0x0005, 1, 0, 8), (0x6200, 0, 8, 8)), ("PDO050",), True
    ),
    "missing-object": Case(
        (*rpdo("0x21000010", "0x62000008"), U8_OUT), ((0x2100, 0, 0, 16), (0x6200, 0, 16, 8)), ("PDO042",), True
    ),
    "hole": Case((*rpdo("0x00000000", "0x62000008"), U8_OUT), ((0x6200, 0, 0, 8),), ("PDO041",)),
    "sam-mpdo": Case((*tpdo("0x60410010", count=0xFE), U16_STATUS), ()),
    "dam-mpdo": Case((*rpdo("0x62000008", count=0xFF), U8_OUT), ()),
    "count-above-64": Case((*rpdo("0x62000008", count=65), U8_OUT), (), ("PDO040",), True),
    "over-classic-frame": Case(
        (*tpdo("0x60640020", "0x60640020", "0x60410010"), I32_POSITION, U16_STATUS),
        ((0x6064, 0, 0, 32), (0x6064, 0, 32, 32), (0x6041, 0, 64, 16)),
        ("PDO049",),
        True,
    ),
    "fits-can-fd": Case(
        (*tpdo("0x60640020", "0x60640020", "0x60410010"), I32_POSITION, U16_STATUS),
        ((0x6064, 0, 0, 32), (0x6064, 0, 32, 32), (0x6041, 0, 64, 16)),
        ("PDO049",),
        can_fd=True,
    ),
    "over-can-fd-frame": Case(
        (*tpdo(*["0x60640020"] * 17), I32_POSITION),
        tuple((0x6064, 0, 32 * n, 32) for n in range(17)),
        ("PDO049",),
        True,
        can_fd=True,
    ),
}


def run(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *args], capture_output=True, text=True, timeout=120)


def drawn(path: Path) -> list[tuple[int, int, int, int]]:
    result = run("pdo", str(path), "--format", "json", "--node-id", "5")
    assert result.returncode in (0, 1), result.stderr
    (pdo,) = json.loads(result.stdout)["pdos"]
    return [(e["index"], e["subindex"], e["bit_offset"], e["bit_length"]) for e in pdo["entries"]]


def generated(path: Path, out: Path, can_fd: bool) -> tuple[bool, list[tuple[int, int]], str]:
    """(generated, [(bit offset, bit length)] of the Markdown PDO table, stderr)."""
    result = run("gen", str(path), "-t", "markdown", "-o", str(out), "--name", "dev", *(["--can-fd"] if can_fd else []))
    if result.returncode != 0:
        return False, [], result.stderr
    text = (out / "dev.md").read_text(encoding="utf-8")
    rows = re.findall(r"^\| \d+ \| (\d+)\.\.(\d+) \| (\d+) \|", text, re.MULTILINE)
    assert all(int(last) - int(first) + 1 == int(length) for first, last, length in rows)
    return True, [(int(first), int(length)) for first, _, length in rows], result.stderr


def linted(path: Path, can_fd: bool) -> list[dict[str, object]]:
    result = run("lint", str(path), "--format", "json", "--node-id", "5", *(["--can-fd"] if can_fd else []))
    assert result.returncode in (0, 1), result.stderr
    found: list[dict[str, object]] = json.loads(result.stdout)
    return found


@pytest.mark.parametrize("name", sorted(CASES))
def test_lint_pdo_and_gen_read_one_mapping(name: str, tmp_path: Path) -> None:
    case = CASES[name]
    path = tmp_path / "t.eds"
    path.write_text(eds(*case.parts, dummies=case.dummies), encoding="utf-8")

    assert drawn(path) == list(case.entries)

    ok, layout, stderr = generated(path, tmp_path / "out", case.can_fd)
    assert ok is not case.gen_refuses, stderr
    if ok:
        assert layout == [(offset, length) for _, _, offset, length in case.entries]
    else:
        assert "GEN001" in stderr

    findings = linted(path, case.can_fd)
    codes = {str(f["code"]) for f in findings}
    assert set(case.lint_codes) <= codes, findings
    over = [str(f["message"]) for f in findings if f["code"] == "PDO046"]
    if case.total > case.frame:
        assert len(over) == 1 and f"the mapping is {case.total} bits" in over[0]
    else:
        assert over == []
    if case.gen_refuses:  # what gen cannot build is an error to lint too
        assert any(f["severity"] == "error" and str(f["code"]).startswith("PDO") for f in findings), findings
