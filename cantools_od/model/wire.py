"""Values as CANopen sends them (SDO and PDO data: little-endian, CiA 301 §7.1.4), read into the model's values."""

from __future__ import annotations

import struct

from .datatypes import ValueKind
from .values import TimeValue


def decoded(kind: ValueKind, data: bytes) -> int | float | str | bytes | TimeValue:
    """The model's value of `data` sent for an entry of this kind (OCTET_STRING, DOMAIN and unknown: the bytes)."""
    if kind is ValueKind.SIGNED:
        return int.from_bytes(data, "little", signed=True)
    if kind in (ValueKind.UNSIGNED, ValueKind.BOOL):
        return int.from_bytes(data, "little")
    if kind is ValueKind.REAL and len(data) in (4, 8):
        return float(struct.unpack("<f" if len(data) == 4 else "<d", data)[0])
    if kind is ValueKind.STRING:
        return data.decode("latin-1").rstrip("\0")
    if kind is ValueKind.UNICODE:
        return data.decode("utf-16-le", errors="replace").rstrip("\0")
    if kind is ValueKind.TIME:
        return TimeValue.from_bits(int.from_bytes(data, "little"))
    return data
