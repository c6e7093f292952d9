"""What a master's boot-up check compares (CiA 302-2 §4: 1F84h device type, 1F85h-1F88h identity), and the
value a description gives for each: the [DeviceInfo] number over the 1018h value, as lely's dcfgen fills them;
0 means "not checked"."""

from __future__ import annotations

from typing import TYPE_CHECKING

from .objects import (
    DEVICE_TYPE,
    IDENTITY,
    IDENTITY_PRODUCT_CODE,
    IDENTITY_REVISION,
    IDENTITY_SERIAL,
    IDENTITY_VENDOR_ID,
)
from .slots import as_int, slot

if TYPE_CHECKING:
    from ..device import Device

CHECKED_BY = {
    (DEVICE_TYPE, 0): 0x1F84,
    (IDENTITY, IDENTITY_VENDOR_ID): 0x1F85,
    (IDENTITY, IDENTITY_PRODUCT_CODE): 0x1F86,
    (IDENTITY, IDENTITY_REVISION): 0x1F87,
    (IDENTITY, IDENTITY_SERIAL): 0x1F88,
}


def device_info_number(device: Device, index: int, sub: int) -> int | None:
    """[DeviceInfo]'s VendorNumber, ProductNumber or RevisionNumber for that 1018h sub-index."""
    if index != IDENTITY:
        return None
    info = device.device_info
    numbers = {
        IDENTITY_VENDOR_ID: info.vendor_number,
        IDENTITY_PRODUCT_CODE: info.product_number,
        IDENTITY_REVISION: info.revision_number,
    }
    return numbers.get(sub)


def expected(device: Device, index: int, sub: int, node_id: int | None = None) -> int | None:
    """The value the description gives the master to compare: [DeviceInfo]'s number when not 0, else the
    entry's value (ParameterValue, else DefaultValue); None when it gives none or the entry is not checked."""
    if (index, sub) not in CHECKED_BY:
        return None
    number = device_info_number(device, index, sub)
    if number:
        return number
    found = slot(device, index, sub)
    return as_int(found.var.value(node_id)) if found is not None else None
