"""The canonical form reads the same in every peer: one crafted file per value kind, judged by python-canopen
and lely's dcfchk (docs/portability.md states the rules these check)."""

from __future__ import annotations

from pathlib import Path

import pytest
from peermatrix import NODE_ID, canopen_reading, dcfchk_verdict, differences, probe_file

from cantools_od import dumps, loads

device_file = probe_file


# (case id, data type, the entries as an author wrote them). Each is a value kind whose canonical spelling once
# changed what a peer reads.
CASES = [
    ("empty-string-default", "0x0009", "DefaultValue=\nPDOMapping=0"),
    ("empty-octets-default", "0x000A", "DefaultValue=\nPDOMapping=0"),
    ("empty-integer-default", "0x0007", "DefaultValue=\nPDOMapping=0"),
    ("empty-limits", "0x0006", "LowLimit=\nHighLimit=\nDefaultValue=0x10\nPDOMapping=0"),
    ("nodeid-plus-zero", "0x0005", "DefaultValue=$NODEID+0x00\nPDOMapping=0"),
    ("number-before-nodeid", "0x0007", "DefaultValue=0x180+$NODEID\nPDOMapping=0"),
    ("real32-zero", "0x0008", "DefaultValue=0\nPDOMapping=0"),
    ("real32-integer", "0x0008", "DefaultValue=1\nPDOMapping=0"),
    ("real32-integer-limit-beyond-precision", "0x0008", "HighLimit=2147483647\nDefaultValue=0\nPDOMapping=0"),
    ("real64-zero", "0x0011", "DefaultValue=0\nPDOMapping=0"),
    ("decimal-unsigned", "0x0007", "DefaultValue=1000\nPDOMapping=0"),
    ("time-of-day-as-one-integer", "0x000C", "DefaultValue=123456789\nPDOMapping=0"),
    ("signed-decimal-limits", "0x0003", "LowLimit=-100\nHighLimit=100\nDefaultValue=-5\nPDOMapping=0"),
]


@pytest.mark.parametrize(("data_type", "entries"), [pytest.param(t, e, id=i) for i, t, e in CASES])
def test_canonical_reads_alike_in_every_peer(tmp_path: Path, data_type: str, entries: str) -> None:
    original = tmp_path / "original.eds"
    original.write_text(device_file(entries, data_type))
    canonical = tmp_path / "canonical.eds"
    canonical.write_bytes(dumps(loads(original.read_bytes()), "eds", style="canonical"))
    for node_id in (None, NODE_ID):
        before, after = canopen_reading(original, node_id), canopen_reading(canonical, node_id)
        assert not isinstance(before, str), before
        assert not isinstance(after, str), after
        assert [str(d) for d in differences(before, after)] == []
    verdict = dcfchk_verdict(original, NODE_ID)
    if verdict is None:
        assert dcfchk_verdict(canonical, NODE_ID) is None


def test_nodeid_formula_is_evaluated_by_python_canopen(tmp_path: Path) -> None:
    """A bare `$NODEID` reads as no value in python-canopen; the canonical `$NODEID+0x0` reads as the node-ID."""
    original = tmp_path / "original.eds"
    original.write_text(device_file("DefaultValue=$NODEID\nPDOMapping=0", "0x0005"))
    text = dumps(loads(original.read_bytes()), "eds", style="canonical").decode()
    assert "DefaultValue=$NODEID+0x0\n" in text
    canonical = tmp_path / "canonical.eds"
    canonical.write_text(text)
    reading = canopen_reading(canonical, NODE_ID)
    assert not isinstance(reading, str)
    assert reading[(0x2000, 0)]["default"] == NODE_ID
    assert dcfchk_verdict(canonical, NODE_ID) is None


def test_signed_hex_default_keeps_the_hex_python_canopen_reads(tmp_path: Path) -> None:
    """CiA 306 reads 0xFFFF of an INTEGER16 as -1 (two's complement); python-canopen reads the hex as 65535. The
    canonical form keeps the author's hex: `-1` would make python-canopen read another value than it did."""
    original = tmp_path / "original.eds"
    original.write_text(device_file("DefaultValue=0xFFFF\nLowLimit=0xFF00\nPDOMapping=0", "0x0003"))
    canonical = tmp_path / "canonical.eds"
    text = dumps(loads(original.read_bytes()), "eds", style="canonical").decode()
    assert "DefaultValue=0xFFFF\n" in text and "LowLimit=0xFF00\n" in text
    canonical.write_text(text)
    before, after = canopen_reading(original, None), canopen_reading(canonical, None)
    assert not isinstance(before, str) and not isinstance(after, str)
    assert before[(0x2000, 0)]["default"] == after[(0x2000, 0)]["default"] == 0xFFFF
    assert differences(before, after) == []
