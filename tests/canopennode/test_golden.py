"""The canopennode target's output, byte for byte, for examples/canopennode/blank_device.eds.

When a change of the output is intended, regenerate and review the diff:

    UPDATE_GOLDEN=1 python -m pytest tests/canopennode/test_golden.py
"""

from __future__ import annotations

from pathlib import Path

from cnokit import gen

from support import ROOT, assert_golden

GOLDEN = Path(__file__).resolve().parent / "golden"


def test_blank_device_matches_the_golden_files(tmp_path: Path) -> None:
    result = gen(ROOT / "examples" / "canopennode" / "blank_device.eds", tmp_path)
    assert result.returncode == 0, result.stderr
    files = {p.name: p.read_text(encoding="utf-8") for p in sorted(tmp_path.iterdir())}
    assert sorted(files) == ["OD.c", "OD.h"]
    for name, text in files.items():
        assert_golden(GOLDEN / name, text)
