"""BOOLEAN mapped as a whole byte, as CANopenNode and its editors write it: generated, not refused."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from pykit import canopen_bytes, canopen_pdos, eds_text, generated_module, pdo, var

from cantools_od import loads
from cantools_od.render import renderer
from cantools_od.views.codegen import build_view

EDS = eds_text(
    [
        var(0x2000, "Output enable", 0x0001, "rw", "0"),
        var(0x2001, "Setpoint", 0x0003, "rw", "0"),
        pdo("rx", 1, [(0x2000, 0, 8), (0x2001, 0, 16)]),
    ]
)


def test_view_accepts_a_byte_wide_boolean() -> None:
    view = build_view(loads(EDS.encode(), source="b.eds"), "b")
    assert view.problems == ()
    assert [(e.bit_offset, e.bit_length) for e in view.pdos[0].entries] == [(0, 8), (8, 16)]


@pytest.mark.parametrize("values", [[True, -2], [False, 300], [True, 0]])
def test_python_bytes_equal_python_canopen(tmp_path: Path, values: list[object]) -> None:
    eds = tmp_path / "b.eds"
    eds.write_text(EDS)
    module = generated_module(eds, tmp_path, "b")
    ours = module.Rpdo1(*values).pack()
    assert ours == canopen_bytes(canopen_pdos(eds, 1)["Rpdo1"], values)  # type: ignore[arg-type]
    assert module.Rpdo1.unpack(ours) == module.Rpdo1(*values)


def test_c_compiles_and_packs_a_byte(tmp_path: Path) -> None:
    files = renderer("c")(build_view(loads(EDS.encode(), source="b.eds"), "b"))
    for name, text in files.items():
        (tmp_path / name).write_text(text)
    (tmp_path / "main.c").write_text(
        '#include "b.h"\nint main(void) {\n    struct b_rpdo1 in = {0}, out;\n    uint8_t frame[8];\n'
        "    in.output_enable = true;\n    in.setpoint = -2;\n"
        "    if (b_rpdo1_pack(frame, &in, sizeof frame) != 3) return 1;\n"
        "    if (frame[0] != 1u || frame[1] != 0xFEu || frame[2] != 0xFFu) return 2;\n"
        "    if (b_rpdo1_unpack(&out, frame, 3) != 3 || !out.output_enable || out.setpoint != -2) return 3;\n"
        "    return 0;\n}\n"
    )
    flags = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
    built = subprocess.run(["gcc", *flags, "main.c", "b.c", "-o", "t"], cwd=tmp_path, capture_output=True, text=True)
    assert built.returncode == 0, built.stderr
    assert subprocess.run([str(tmp_path / "t")]).returncode == 0
