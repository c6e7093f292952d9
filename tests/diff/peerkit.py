"""What python-canopen reads from a file, flattened to (index, sub-index, attribute) → value, for the
differential test of `diff`. A VAR's entry has sub-index None, as in our change records."""

from __future__ import annotations

from pathlib import Path
from typing import Any

from peermatrix import canopen_objects, canopen_od

ENTRY_ATTRIBUTES = ("name", "data_type", "access_type", "pdo_mappable", "default", "value", "min", "max", "relative")
DEVICE_ATTRIBUTES = (
    "vendor_name", "vendor_number", "product_name", "product_number", "revision_number", "order_code",
    "simple_boot_up_master", "simple_boot_up_slave", "granularity", "dynamic_channels_supported",
    "group_messaging", "nr_of_RXPDO", "nr_of_TXPDO", "LSS_supported",
)  # fmt: skip

Reading = dict[tuple[int | None, int | None, str], Any]

# Signed types by python-canopen data-type code → bits: it reads a hex value such as 0xFD of an INTEGER8
# as 253 where CiA 306 (and we) read the two's complement -3; compare them modulo 2**bits.
_SIGNED_BITS = {0x2: 8, 0x3: 16, 0x4: 32, 0x10: 24, 0x12: 40, 0x13: 48, 0x14: 56, 0x15: 64}


def read(path: Path) -> Reading | None:
    """python-canopen's reading of a file, None when it cannot read it (python-canopen fails in its own
    ways on some real files; those pairs are skipped)."""
    od = canopen_od(path)
    if isinstance(od, str):
        return None
    reading: Reading = {}
    for index, obj, subs in canopen_objects(od):
        if subs is None:
            reading[index, None, "exists"] = "var"
            _variable(reading, index, None, obj)
            continue
        reading[index, None, "exists"] = type(obj).__name__
        reading[index, None, "name"] = obj.name
        for sub, var in subs.items():
            reading[index, sub, "exists"] = True
            _variable(reading, index, sub, var)
    info = od.device_information
    for attribute in DEVICE_ATTRIBUTES:
        reading[None, None, attribute] = getattr(info, attribute)
    reading[None, None, "allowed_baudrates"] = frozenset(info.allowed_baudrates)
    reading[None, None, "node_id"] = od.node_id
    reading[None, None, "bitrate"] = od.bitrate
    return reading


def configured(reading: Reading, index: int, sub: int | None, other: Reading) -> Any:
    """The value python-canopen would configure: ParameterValue, else the default resolved for the node-ID
    (the other file's when this one states none, as `diff` does)."""
    value, default = reading.get((index, sub, "value")), reading.get((index, sub, "default"))
    if value is not None:
        return value
    if isinstance(default, tuple):  # ("$NODEID", offset)
        node = reading.get((None, None, "node_id"))
        node = node if node is not None else other.get((None, None, "node_id"))
        return None if node is None else default[1] + node
    return default


def _variable(reading: Reading, index: int, sub: int | None, var: Any) -> None:
    from canopen.objectdictionary.eds import _convert_variable

    for attribute in ENTRY_ATTRIBUTES:
        value = getattr(var, attribute)
        if isinstance(value, int) and not isinstance(value, bool) and var.data_type in _SIGNED_BITS:
            value %= 1 << _SIGNED_BITS[var.data_type]
        if attribute == "value" and value in ("", b""):
            value = None  # an empty ParameterValue: python-canopen reads "", we read no value
        reading[index, sub, attribute] = repr(value) if isinstance(value, float) else value
    if var.relative and isinstance(getattr(var, "default_raw", None), str):
        # python-canopen adds a DCF's NodeID to `$NODEID+n` (or gives None without one): keep n, which
        # is what the file says, by letting python-canopen read the formula for node-ID 0.
        reading[index, sub, "default"] = ("$NODEID", _convert_variable(0, var.data_type, var.default_raw))
