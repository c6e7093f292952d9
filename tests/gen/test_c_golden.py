"""The C target's output, byte for byte, for the example files and the crafted odd-layout EDS.

When a change of the output is intended, regenerate the golden files and review their diff:

    UPDATE_GOLDEN=1 python -m pytest tests/gen/test_c_golden.py
"""

from __future__ import annotations

from pathlib import Path

import pytest
from ckit import EXAMPLES, GOLDEN, compile_checks, generate, tool, write, write_odd_eds

from support import assert_golden

# golden name → (input, node-ID, CAN FD)
CASES = {
    "cia402_drive": ("cia402_drive.eds", None, False),
    "io_device": ("io_device.eds", 5, False),
    "odd_bits": ("odd_bits.eds", None, True),
}


def source(name: str, tmp_path: Path) -> Path:
    filename = CASES[name][0]
    return write_odd_eds(tmp_path / "eds") if filename == "odd_bits.eds" else EXAMPLES / filename


@pytest.mark.parametrize("name", sorted(CASES))
def test_output_matches_golden_files(name: str, tmp_path: Path) -> None:
    _, node_id, can_fd = CASES[name]
    files = generate(source(name, tmp_path), name, node_id, can_fd)
    assert sorted(files) == [f"{name}.c", f"{name}.h"]
    for filename, text in files.items():
        assert_golden(GOLDEN / filename, text)


@pytest.mark.parametrize("name", sorted(CASES))
def test_output_is_deterministic(name: str, tmp_path: Path) -> None:
    _, node_id, can_fd = CASES[name]
    path = source(name, tmp_path)
    assert generate(path, name, node_id, can_fd) == generate(path, name, node_id, can_fd)


@pytest.mark.parametrize("name", sorted(CASES))
def test_golden_files_compile_as_c99_and_cxx11(name: str, tmp_path: Path) -> None:
    tool("gcc")
    tool("g++")
    write(tmp_path, {f: (GOLDEN / f).read_text("utf-8") for f in (f"{name}.h", f"{name}.c")})
    assert compile_checks(tmp_path, name) == []
