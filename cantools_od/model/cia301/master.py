"""The objects of a CANopen manager (CiA 302-2, CiA 302-3) that a network's master configuration fills,
and the concise DCF format (CiA 302-3 §4.2: the SDO writes a manager makes to configure one slave)."""

from __future__ import annotations

import struct
from collections.abc import Iterable

CONCISE_DCF = 0x1F22  # per node-ID: the concise DCF to download at boot (DOMAIN)
CONFIGURATION_REQUEST = 0x1F25
EXPECTED_SOFTWARE = 0x1F55
PROGRAM_DATA = 0x1F58
NMT_STARTUP = 0x1F80
SLAVE_ASSIGNMENT = 0x1F81
REQUEST_NMT = 0x1F82
DEVICE_TYPE_IDENTIFICATION = 0x1F84
VENDOR_IDENTIFICATION = 0x1F85
PRODUCT_CODE = 0x1F86
REVISION_NUMBER = 0x1F87
SERIAL_NUMBER = 0x1F88
BOOT_TIME = 0x1F89
RESTORE_CONFIGURATION = 0x1F8A
NMT_INHIBIT_TIME = 0x102A
EMCY_CONSUMER = 0x1028
# Where lely's master keeps the application objects its mirrored PDOs carry (manufacturer area).
MIRRORED_RPDO_OBJECTS = 0x2000
MIRRORED_TPDO_OBJECTS = 0x2200
# lely's remote PDOs: the slave's PDO number and node-ID, and its mapping, for each mirrored PDO.
REMOTE_TPDO, REMOTE_TPDO_MAPPING, REMOTE_RPDO, REMOTE_RPDO_MAPPING = 0x5800, 0x5A00, 0x5C00, 0x5E00

# 1F80h bits (CiA 302-2 §7.2): the master is the NMT master, starts all nodes at once, does not
# start itself, does not start the slaves, resets all nodes / stops all nodes on a mandatory slave's error.
STARTUP_MASTER, STARTUP_ALL_NODES, STARTUP_NO_SELF_START, STARTUP_NO_SLAVE_START = 0x01, 0x02, 0x04, 0x08
STARTUP_RESET_ALL, STARTUP_STOP_ALL = 0x10, 0x40
# 1F81h bits: a slave, boot it, mandatory, no NMT reset communication, check software version,
# software update, restore configuration; retry factor in bits 8-15, guard time in bits 16-31.
ASSIGN_SLAVE, ASSIGN_BOOT, ASSIGN_MANDATORY, ASSIGN_NO_RESET = 0x01, 0x04, 0x08, 0x10
ASSIGN_CHECK_SOFTWARE, ASSIGN_UPDATE_SOFTWARE, ASSIGN_RESTORE = 0x20, 0x40, 0x80

_HEADER = struct.Struct("<I")
_WRITE = struct.Struct("<HBI")


def concise_dcf(writes: Iterable[tuple[int, int, bytes]]) -> bytes:
    """A concise DCF: the number of writes (UNSIGNED32), then index (UNSIGNED16), sub-index (UNSIGNED8),
    data size (UNSIGNED32) and the data of each, all little-endian."""
    chunks = [_WRITE.pack(index, sub, len(data)) + data for index, sub, data in writes]
    return _HEADER.pack(len(chunks)) + b"".join(chunks)


class NotConcise(ValueError):
    """Bytes that are no concise DCF."""


def read_concise_dcf(data: bytes) -> list[tuple[int, int, bytes]]:
    """The writes of a concise DCF; NotConcise when the bytes do not hold exactly what the count says."""
    if len(data) < _HEADER.size:
        raise NotConcise("shorter than its count")
    (count,) = _HEADER.unpack_from(data)
    writes = []
    offset = _HEADER.size
    for number in range(count):
        if offset + _WRITE.size > len(data):
            raise NotConcise(f"write {number + 1} of {count} is cut off")
        index, sub, size = _WRITE.unpack_from(data, offset)
        offset += _WRITE.size
        if offset + size > len(data):
            raise NotConcise(f"the data of write {number + 1} of {count} is cut off")
        writes.append((index, sub, data[offset : offset + size]))
        offset += size
    if offset != len(data):
        raise NotConcise(f"{len(data) - offset} bytes after the {count} writes")
    return writes
