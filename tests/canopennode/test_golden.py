"""The canopennode target's output, byte for byte, for examples/canopennode/blank_device.eds.

When a change of the output is intended, regenerate and review the diff:

    UPDATE_GOLDEN=1 python -m pytest tests/canopennode/test_golden.py
"""

from __future__ import annotations

import os
from pathlib import Path

from cnokit import gen

from support import ROOT

GOLDEN = Path(__file__).resolve().parent / "golden"


def test_blank_device_matches_the_golden_files(tmp_path: Path) -> None:
    result = gen(ROOT / "examples" / "canopennode" / "blank_device.eds", tmp_path)
    assert result.returncode == 0, result.stderr
    files = {p.name: p.read_text(encoding="utf-8") for p in sorted(tmp_path.iterdir())}
    assert sorted(files) == ["OD.c", "OD.h"]
    if os.environ.get("UPDATE_GOLDEN") == "1":
        GOLDEN.mkdir(exist_ok=True)
        for name, text in files.items():
            (GOLDEN / name).write_text(text, encoding="utf-8")
    drifted = [n for n, text in files.items() if not (GOLDEN / n).is_file() or (GOLDEN / n).read_text("utf-8") != text]
    assert not drifted, f"{drifted} differ from {GOLDEN}; if intended, run with UPDATE_GOLDEN=1 and review the diff"
