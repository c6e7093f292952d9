"""CiA 301 data types: indices, names, bit sizes and value kinds."""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass
from enum import StrEnum


class ValueKind(StrEnum):
    """How values of a data type are written and held."""

    BOOL = "bool"
    UNSIGNED = "unsigned"
    SIGNED = "signed"
    REAL = "real"
    STRING = "string"  # VISIBLE_STRING
    UNICODE = "unicode"  # UNICODE_STRING: no text form is specified
    OCTETS = "octets"  # OCTET_STRING and DOMAIN: hex byte pairs
    TIME = "time"  # TIME_OF_DAY, TIME_DIFFERENCE
    COMPLEX = "complex"  # record types, no scalar value


@dataclass(frozen=True)
class DataType:
    index: int
    name: str
    kind: ValueKind
    bits: int | None  # None: variable length (strings, DOMAIN) or record

    @property
    def is_numeric(self) -> bool:
        return self.kind in (ValueKind.BOOL, ValueKind.UNSIGNED, ValueKind.SIGNED, ValueKind.REAL)

    @property
    def is_integer(self) -> bool:
        return self.kind in (ValueKind.UNSIGNED, ValueKind.SIGNED)

    def int_range(self) -> tuple[int, int] | None:
        """Smallest and largest value of an integer or boolean type."""
        if self.bits is None:
            return None
        if self.kind is ValueKind.UNSIGNED or self.kind is ValueKind.BOOL:
            return 0, (1 << self.bits) - 1
        if self.kind is ValueKind.SIGNED:
            return -(1 << (self.bits - 1)), (1 << (self.bits - 1)) - 1
        return None

    def number_problem(self, value: int | float) -> str | None:
        """Why the number `value` is no value of this numeric type (outside an integer type's range,
        a finite number beyond REAL32), or None when it is one; None for types that are not numeric.
        NaN and the infinities are IEEE 754 values of both REAL types, which every target spells."""
        if self.kind is ValueKind.REAL:
            if math.isfinite(value) and self.bits == 32 and not _fits_real32(float(value)):
                return f"{value!r} is outside {self.name}"
            return None
        bounds = self.int_range()
        if bounds is None:
            return None
        if isinstance(value, float) and not value.is_integer():
            return f"{value!r} is not an integer"
        if not bounds[0] <= value <= bounds[1]:
            return f"{value} is outside {self.name} ({bounds[0]}..{bounds[1]})"
        return None


def _fits_real32(value: float) -> bool:
    try:
        narrowed: float = struct.unpack("<f", struct.pack("<f", value))[0]
    except OverflowError:
        return False
    return narrowed != 0.0 or value == 0.0


def _t(index: int, name: str, kind: ValueKind, bits: int | None) -> DataType:
    return DataType(index, name, kind, bits)


_U, _S = ValueKind.UNSIGNED, ValueKind.SIGNED

STANDARD_TYPES: dict[int, DataType] = {
    t.index: t
    for t in (
        _t(0x0001, "BOOLEAN", ValueKind.BOOL, 1),
        _t(0x0002, "INTEGER8", _S, 8),
        _t(0x0003, "INTEGER16", _S, 16),
        _t(0x0004, "INTEGER32", _S, 32),
        _t(0x0005, "UNSIGNED8", _U, 8),
        _t(0x0006, "UNSIGNED16", _U, 16),
        _t(0x0007, "UNSIGNED32", _U, 32),
        _t(0x0008, "REAL32", ValueKind.REAL, 32),
        _t(0x0009, "VISIBLE_STRING", ValueKind.STRING, None),
        _t(0x000A, "OCTET_STRING", ValueKind.OCTETS, None),
        _t(0x000B, "UNICODE_STRING", ValueKind.UNICODE, None),
        _t(0x000C, "TIME_OF_DAY", ValueKind.TIME, 48),
        _t(0x000D, "TIME_DIFFERENCE", ValueKind.TIME, 48),
        _t(0x000F, "DOMAIN", ValueKind.OCTETS, None),
        _t(0x0010, "INTEGER24", _S, 24),
        _t(0x0011, "REAL64", ValueKind.REAL, 64),
        _t(0x0012, "INTEGER40", _S, 40),
        _t(0x0013, "INTEGER48", _S, 48),
        _t(0x0014, "INTEGER56", _S, 56),
        _t(0x0015, "INTEGER64", _S, 64),
        _t(0x0016, "UNSIGNED24", _U, 24),
        _t(0x0018, "UNSIGNED40", _U, 40),
        _t(0x0019, "UNSIGNED48", _U, 48),
        _t(0x001A, "UNSIGNED56", _U, 56),
        _t(0x001B, "UNSIGNED64", _U, 64),
        _t(0x0020, "PDO_COMMUNICATION_PARAMETER", ValueKind.COMPLEX, None),
        _t(0x0021, "PDO_MAPPING", ValueKind.COMPLEX, None),
        _t(0x0022, "SDO_PARAMETER", ValueKind.COMPLEX, None),
        _t(0x0023, "IDENTITY", ValueKind.COMPLEX, None),
    )
}

BASIC_TYPE_RANGE = range(0x0001, 0x001C)
STATIC_TYPE_AREA = range(0x0001, 0x0020)  # 0001h-001Fh: the static types; the indices not assigned are reserved
INDEX_BY_NAME = {dtype.name: dtype.index for dtype in STANDARD_TYPES.values()}
BOOLEAN = STANDARD_TYPES[0x0001]
UNSIGNED8 = STANDARD_TYPES[0x0005]
UNSIGNED32 = STANDARD_TYPES[0x0007]
REAL32 = STANDARD_TYPES[0x0008]
OCTET_STRING = STANDARD_TYPES[0x000A]
TIME_OF_DAY = STANDARD_TYPES[0x000C]
DOMAIN = STANDARD_TYPES[0x000F]


def standard_type(index: int | None) -> DataType | None:
    """The CiA 301 type with this index, or None for custom or unknown indices."""
    if index is None:
        return None
    return STANDARD_TYPES.get(index)


def type_by_name(name: str) -> DataType | None:
    wanted = name.strip().upper().replace(" ", "_")
    for dtype in STANDARD_TYPES.values():
        if dtype.name == wanted:
            return dtype
    return None
