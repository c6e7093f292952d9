"""The Rust target's output, byte for byte, and `cantools-od gen -t rust` on the command line.

When a change of the output is intended, regenerate the golden files and review their diff:

    UPDATE_GOLDEN=1 python -m pytest tests/gen/test_rust_golden.py
"""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner, Result
from rustkit import EXAMPLES, eds_text, render_rust, var

from cantools_od.cli.gen import command

from support import assert_golden

GOLDEN = Path(__file__).resolve().parent / "golden" / "rust"

# golden file → (example, node-ID)
CASES = {
    "cia402_drive": ("cia402_drive.eds", None),
    "io_device": ("io_device.eds", None),
    "io_device_node5": ("io_device.eds", 5),
}


def gen(*args: str | Path) -> Result:
    """`cantools-od gen ARGS`, in-process."""
    return CliRunner().invoke(command, [str(a) for a in args], catch_exceptions=True)


@pytest.mark.parametrize("name", sorted(CASES))
def test_output_matches_golden_file(name: str) -> None:
    example, node_id = CASES[name]
    _, text = render_rust(EXAMPLES / example, name, node_id)
    golden = GOLDEN / f"{name}.rs"
    assert_golden(golden, text)


@pytest.mark.parametrize("name", sorted(CASES))
def test_output_is_deterministic(name: str) -> None:
    example, node_id = CASES[name]
    assert render_rust(EXAMPLES / example, name, node_id)[1] == render_rust(EXAMPLES / example, name, node_id)[1]


def test_cli_writes_the_golden_files_once(tmp_path: Path) -> None:
    out = tmp_path / "out"
    for example in ("cia402_drive", "io_device"):
        result = gen(EXAMPLES / f"{example}.eds", "-t", "rust", "-o", out)
        assert result.exit_code == 0, result.output
        assert (out / f"{example}.rs").read_text("utf-8") == (GOLDEN / f"{example}.rs").read_text("utf-8")
    written = (out / "io_device.rs").stat().st_mtime_ns
    result = gen(EXAMPLES / "io_device.eds", "-t", "rust", "-o", out, "--node-id", "5", "--name", "io_device_node5")
    assert result.exit_code == 0, result.output
    assert (out / "io_device_node5.rs").read_text("utf-8") == (GOLDEN / "io_device_node5.rs").read_text("utf-8")
    gen(EXAMPLES / "io_device.eds", "-t", "rust", "-o", out)
    assert (out / "io_device.rs").stat().st_mtime_ns == written  # unchanged output is not rewritten
    assert sorted(p.name for p in out.iterdir()) == ["cia402_drive.rs", "io_device.rs", "io_device_node5.rs"]


def _write(
    folder: Path, name: str, objects: dict[int, dict[str, str]], pdos: dict[tuple[str, int], list[tuple[int, int, int]]]
) -> Path:
    path = folder / f"{name}.eds"
    path.write_text(eds_text(f"{name}.eds", objects, pdos, name), encoding="utf-8")
    return path


@pytest.mark.parametrize(
    ("objects", "pdos", "message"),
    [
        ({0x2000: var("Text", 0x0009, "abc")}, {("tx", 1): [(0x2000, 0, 24)]}, "has no fixed size"),
        ({0x2000: var("Word", 0x0006, "0")}, {("tx", 1): [(0x2000, 0, 8)]}, "with 8 bits, but its type"),
        ({}, {("tx", 1): [(0x2000, 0, 8)]}, "which does not exist"),
        (
            {0x2000: var("Long", 0x001B, "0")},
            {("tx", 1): [(0x2000, 0, 64), (0x2000, 0, 64)]},
            "exceed the 64-bit frame",
        ),
    ],
)
def test_cli_refuses_pdos_it_cannot_lay_out(
    tmp_path: Path,
    objects: dict[int, dict[str, str]],
    pdos: dict[tuple[str, int], list[tuple[int, int, int]]],
    message: str,
) -> None:
    eds = _write(tmp_path, "refused", objects, pdos)
    result = gen(eds, "-t", "rust", "-o", tmp_path / "out")
    assert result.exit_code == 1
    assert isinstance(result.exception, SystemExit)  # not a traceback
    assert "GEN001" in result.stderr and message in result.stderr
    assert not (tmp_path / "out").exists()


def test_can_fd_allows_long_pdos(tmp_path: Path) -> None:
    eds = _write(
        tmp_path, "long_pdo", {0x2000: var("Long", 0x001B, "0")}, {("tx", 1): [(0x2000, 0, 64), (0x2000, 0, 64)]}
    )
    result = gen(eds, "-t", "rust", "-o", tmp_path / "out", "--can-fd")
    assert result.exit_code == 0, result.output
    text = (tmp_path / "out" / "long_pdo.rs").read_text("utf-8")
    assert "pub long_: u64," in text and "pub long_2: u64," in text  # `long` is reserved; mapped twice
    assert "const _: () = assert!(Tpdo1::LEN <= 64);" in text
