"""Sweeps of `diff` over every pair of ../shared/eds-history against judges outside our reader.

A plain text diff of each object's section (tests/diff/textsweep.py): every changed line is told by `diff` or is
formatting.
"""

from __future__ import annotations

from pathlib import Path

import pytest
import textsweep
from test_diff_history import device, pair_params, side

from cantools_od.changes import compare


@pytest.mark.parametrize("pair", pair_params())
def test_every_changed_line_of_an_object_is_told(pair: Path) -> None:
    old, new = side(pair, "old"), side(pair, "new")
    if old is None or new is None:
        pytest.skip("a file new in this commit: every object is added")
    result = compare(device(old), device(new))
    missed = [(f"0x{m.entry[0]:04X}", m.entry[1], m.key, m.old, m.new) for m in textsweep.misses(old, new, result)]
    assert not missed, missed[:5]
