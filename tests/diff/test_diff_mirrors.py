"""`diff` on revisions of public projects read from this machine's snapshots (tests/mirrors.py; skipped when a
snapshot is absent, never committed): kinds of change ../shared/eds-history lacks, such as XDD edits by
CANopenEditor."""

from __future__ import annotations

import itertools
import json

import mirrors
import pytest
from test_diff_history import rendered

from cantools_od import loads
from cantools_od.changes import DeviceDiff, compare, jsonout, text

DEMO = "CANopenNode/CANopenDemo"
DEMO_XDD = "demo/demoDevice.xdd"
# demoDevice.xdd at three commits: the initial one, an update of the demo OD, and CANopenEditor v4.1-1's rewrite
DEMO_COMMITS = ("ad1c189", "355a573", "ae81d72")


def _diff(repo: str, path: str, old: str, new: str) -> DeviceDiff:
    name = path.rpartition("/")[2]
    before = loads(mirrors.show(repo, old, path), source=f"{old}:{name}")
    after = loads(mirrors.show(repo, new, path), source=f"{new}:{name}")
    return compare(before, after)


@pytest.mark.parametrize(("old", "new"), list(itertools.pairwise(DEMO_COMMITS)))
def test_demo_device_revisions_render_both_ways(old: str, new: str) -> None:
    forward, backward = _diff(DEMO, DEMO_XDD, old, new), _diff(DEMO, DEMO_XDD, new, old)
    rendered(forward)
    rendered(backward)
    assert json.loads(jsonout.render(forward))["old"] == f"{old}:demoDevice.xdd"


def test_demo_device_rewritten_by_canopeneditor() -> None:
    """355a573 → ae81d72: the product code of 1018h set, the SDO client disabled, and sub-index 0 of six objects
    no longer PDO-mappable (which a master that maps them sees); vendor-ID and product code now stated; read-only
    entries say TPDO where they said optional."""
    result = _diff(DEMO, DEMO_XDD, "355a573", "ae81d72")
    found = {(c.kind.value, text.tag(c), c.index, c.subindex, c.field) for c in result.changes()}
    unmappable = {
        ("pdo-mapping", "wire", index, 0, "pdo_mapping") for index in (0x2110, 0x2111, 0x2112, 0x6200, 0x6401, 0x6411)
    }
    # PDOmapping "optional" → "TPDO" on read-only entries: the word changes, the PDOs it can be mapped into do not.
    restated = {("pdo-mapping", "cosmetic", 0x1001, None, "pdo_mapping")} | {
        ("pdo-mapping", "cosmetic", 0x6401, sub, "pdo_mapping") for sub in range(1, 17)
    }
    assert found == unmappable | restated | {
        ("device-info", "cosmetic", None, None, "device_info.vendor_name"),
        ("identity", "compatible", None, None, "device_info.vendor_number"),  # stated now: nothing to break
        ("identity", "compatible", None, None, "device_info.product_number"),
        ("file-info", "cosmetic", None, None, "file_info.creation_time"),
        ("file-info", "cosmetic", None, None, "file_info.modification_time"),
        ("file-info", "cosmetic", None, None, "file_info.modification_date"),
        ("default", "wire", 0x1018, 2, "default"),  # product code 0 → 1: a master checks it at boot
        ("default", "value", 0x1018, 4, "default"),  # serial number
        ("canopennode", "wire+code", 0x1280, None, "canopennode.disabled"),
    }
