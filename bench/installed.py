"""Imported first by each benchmark that runs cantools-od inside its own process, before anything of cantools_od:
the figures are then the installed package's, as users run it (with the compiled extension modules the wheel
carries), not the source tree's, which `PYTHONPATH=.` would put first and which has none compiled. A benchmark
stops with one line when the installed package is not the source tree (bench_scale.refuse_stale)."""

from __future__ import annotations

import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

sys.path[:] = [entry for entry in sys.path if Path(entry or os.curdir).resolve() != ROOT]
sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_scale import refuse_stale  # noqa: E402

refuse_stale()
