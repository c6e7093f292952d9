"""Sweeps of `diff` over every pair of ../shared/eds-history against judges outside our reader.

A plain text diff of each object's section (tests/diff/textsweep.py): every changed line is told by `diff` or is
formatting. python-canopen's reading of both files (tests/diff/peerkit.py): every entry and device attribute it
reads differently is told.
"""

from __future__ import annotations

from pathlib import Path

import peerkit
import pytest
import textsweep
from test_diff_corpus import _missed
from test_diff_history import device, pair_params, side

from cantools_od.changes import DeviceDiff, compare


@pytest.mark.parametrize("pair", pair_params())
def test_every_changed_line_of_an_object_is_told(pair: Path) -> None:
    old, new = side(pair, "old"), side(pair, "new")
    if old is None or new is None:
        pytest.skip("a file new in this commit: every object is added")
    result = compare(device(old), device(new))
    missed = [(f"0x{m.entry[0]:04X}", m.entry[1], m.key, m.old, m.new) for m in textsweep.misses(old, new, result)]
    assert not missed, missed[:5]


# python-canopen's device-level attributes → the fields of our changes that tell them.
DEVICE_FIELDS = {
    "node_id": "commissioning.",
    "bitrate": "commissioning.",
    "allowed_baudrates": "device_info.baud_rates",
    "nr_of_RXPDO": "device_info.nr_of_rx_pdo",
    "nr_of_TXPDO": "device_info.nr_of_tx_pdo",
}


def _device_missed(before: peerkit.Reading, after: peerkit.Reading, result: DeviceDiff) -> list[object]:
    """python-canopen's device-level differences ([DeviceInfo], NodeID, bit rate) no change of ours tells."""
    fields = [change.field.lower() for change in result.device]
    missed = []
    for key in set(before) | set(after):
        index, _, attribute = key
        if index is not None or before.get(key) == after.get(key):
            continue
        wanted = DEVICE_FIELDS.get(attribute, f"device_info.{attribute.lower()}")
        if not any(field.startswith(wanted) for field in fields):
            missed.append((attribute, before.get(key), after.get(key)))
    return missed


@pytest.mark.parametrize("pair", pair_params())
def test_every_difference_python_canopen_reads_is_told(pair: Path) -> None:
    """python-canopen's reading of both files (EDS/DCF; it reads no XDD): every entry and device attribute it
    reads differently is in our change list, allowing for what it reads otherwise (docs/diff.md)."""
    old, new = side(pair, "old"), side(pair, "new")
    if old is None or new is None or new.suffix.lower() not in (".eds", ".dcf"):
        pytest.skip("python-canopen compares EDS and DCF files of both revisions")
    before, after = peerkit.read(old), peerkit.read(new)
    if before is None or after is None:
        pytest.skip("python-canopen cannot read one of the files")
    result = compare(device(old), device(new))
    missed = _missed(device(old), device(new), before, after, result) + _device_missed(before, after, result)
    assert not missed, missed[:5]
