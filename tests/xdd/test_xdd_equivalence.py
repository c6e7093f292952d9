"""An XDD and the EDS/DCF its editor exported from it load to the same model.

CANopenEditor writes both formats from one project, so its pairs are the judge:
objects, sub-objects, types, access, PDO flags, limits and values must agree.
Fields that legitimately differ are listed (and compared in their own way) below.

Corpus XDD files whose EDS namesake is not an export of the same project are
not pairs: canopen-device-simulator (the EDS is another revision: 1029h only there,
other array sizes), python-canopen sample (the XDD was corrected by hand, says its
header), emec-demaclenko (the EDS is revision 09, the XDD older), eds-dcf-net sample
(two independent hand-written fixtures).
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest
from xddkit import CANOPENNODE_EXAMPLE, DEMO, SHARED, shared_file

from cantools_od import api
from cantools_od.model import Device, Variable

CORPUS = SHARED / "eds-corpus"
PAIRS = [
    (DEMO / "demoDevice.xdd", DEMO / "demoDevice.eds"),
    (CANOPENNODE_EXAMPLE / "DS301_profile.xpd", CANOPENNODE_EXAMPLE / "DS301_profile.eds"),
    (CORPUS / "xdd" / "canopendemo__demoDevice.xdd", CORPUS / "eds" / "canopendemo__demoDevice.eds"),
    (CORPUS / "xdd" / "damiao__dm4310_slave.xdd", CORPUS / "eds" / "damiao__dm4310_slave.eds"),
    (CORPUS / "xdd" / "odrive__odrive-canopen-cia402.xdd", CORPUS / "eds" / "odrive__odrive-canopen-cia402.dcf"),
]
FIELDS = (
    "name",
    "object_type",
    "data_type",
    "access",
    "pdo_mapping",
    "default",
    "low_limit",
    "high_limit",
    "obj_flags",
    "parameter_value",
    "sub_number",
)
# Device facts both formats state. Not compared, because they legitimately differ:
# - file name, dates and times: CiA 311 writes ISO 8601 (2020-11-28, 12:37:54+01:00), CiA 306
#   MM-DD-YYYY and h:mmAM; the EDS export names the .eds file;
# - FileRevision, EDSVersion, LastEDS: CiA 306 keys with no CiA 311 counterpart;
# - RevisionNumber: CANopenEditor writes 0 into the EDS where its XDD has no revision element;
# - CompactPDO: an EDS key CiA 311 has no attribute for.
DEVICE_FIELDS = (
    "vendor_name",
    "vendor_number",
    "product_name",
    "product_number",
    "baud_rates",
    "granularity",
    "nr_of_rx_pdo",
    "nr_of_tx_pdo",
    "lss_supported",
    "simple_boot_up_master",
    "simple_boot_up_slave",
    "dynamic_channels_supported",
    "group_messaging",
)


def _pairs() -> list[Any]:
    return [pytest.param(x, e, id=x.name + "-" + e.suffix[1:]) for x, e in PAIRS]


def _facts(var: Variable) -> dict[str, Any]:
    facts = {field: getattr(var, field, None) for field in FIELDS}
    # A DCF writes `Denotation=` even when empty; CiA 311 leaves the denotation out: both mean none.
    facts["denotation"] = var.denotation or None
    # The EDS carries the storage group as ;StorageLocation=, written by CANopenEditor on every
    # section and spelled out even for the stack's default RAM; the XDD states CO_storageGroup on
    # objects, and only where it is not RAM.
    return facts


def _storage(var: Variable) -> str:
    return (var.canopennode.storage_group if var.canopennode else None) or "RAM"


def _enabled(device: Device) -> dict[int, Any]:
    # CANopenEditor leaves CO_disabled objects out of its EDS export: they are in the XDD only.
    return {i: o for i, o in device.objects.items() if not (o.canopennode and o.canopennode.disabled)}


@pytest.mark.parametrize(("xdd_path", "eds_path"), _pairs())
def test_xdd_and_its_eds_describe_the_same_device(xdd_path: Path, eds_path: Path) -> None:
    xdd = api.load(shared_file(xdd_path))
    eds = api.load(shared_file(eds_path))
    disabled = set(xdd.objects) - set(_enabled(xdd))
    assert set(_enabled(xdd)) == set(eds.objects)
    assert disabled.isdisjoint(eds.objects)
    for index, obj in _enabled(xdd).items():
        twin = eds.objects[index]
        assert set(obj.subs) == set(twin.subs), f"{index:04X}"
        assert _facts(obj) == _facts(twin), f"{index:04X}"
        assert _storage(obj) == _storage(twin), f"{index:04X}"
        for subindex, sub in obj.subs.items():
            assert _facts(sub) == _facts(twin.subs[subindex]), f"{index:04X}sub{subindex}"
    for field in DEVICE_FIELDS:
        assert _device_fact(xdd, field) == _device_fact(eds, field), field
    assert xdd.dummy_usage is not None and eds.dummy_usage is not None
    assert xdd.dummy_usage.enabled == eds.dummy_usage.enabled
    assert (xdd.file_info.description or None) == (eds.file_info.description or None)


def _device_fact(device: Device, field: str) -> Any:
    value = getattr(device.device_info, field)
    if field == "baud_rates":  # an EDS lists unsupported rates as BaudRate_x=0; CiA 311 lists supported ones
        return {rate for rate, supported in value.items() if supported}
    return value
