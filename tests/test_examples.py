"""The example files the project ships: clean, and read the same way by python-canopen."""

from __future__ import annotations

from pathlib import Path

import canopen
import pytest

from cantools_od import load
from cantools_od.lint import lint
from cantools_od.views.pdo import pdo_map

from support import EXAMPLES

FILES = sorted(EXAMPLES.glob("*.eds"))


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_example_reads_and_lints_clean(path: Path) -> None:
    device = load(path)
    assert device.diagnostics == []
    assert [f.format() for f in lint(device)] == []


@pytest.mark.parametrize("path", FILES, ids=lambda p: p.name)
def test_pdo_map_matches_python_canopen(path: Path) -> None:
    node_id = 5
    node = canopen.RemoteNode(node_id, canopen.import_od(str(path), node_id))
    canopen.Network().add_node(node)  # PDO maps subscribe to a network; no bus is needed
    theirs = {}
    for kind, maps in (("rx", node.rpdo), ("tx", node.tpdo)):
        maps.read(from_od=True)
        for number, pdo in maps.map.items():
            if pdo.enabled or len(pdo.map):
                theirs[(kind, number)] = (pdo.cob_id, [(v.index, v.subindex, v.length) for v in pdo.map])
    ours = {
        (p.direction, p.number): (p.cob_id, [(e.index, e.subindex, e.bit_length) for e in p.entries])
        for p in pdo_map(load(path), node_id)
    }
    assert ours == theirs
