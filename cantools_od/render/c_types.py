"""C storage types and constant spellings for the C target.

Every constant is spelled so that a C99 compiler and a C++11 compiler accept it
without a warning under ``-Wall -Wextra -pedantic``: integer literals carry the
suffix their size needs (``u``, ``l``, ``ll``, ``ull``), the smallest value of a
signed type is written as ``(-MAX - 1)``, REAL32 constants end in ``f``, and a
value the type cannot hold is not spelled at all: callers get the reason instead
and write it as a comment.
"""

from __future__ import annotations

import math
import struct
from dataclasses import dataclass

from ..eds.values import format_real
from ..model import DataType, NodeIdExpr, ValueKind
from ..model.datatypes import DOMAIN


@dataclass(frozen=True)
class Storage:
    """How a value is held in C: `ctype name dims`, e.g. `char name[12]`."""

    ctype: str
    dims: tuple[int, ...] = ()
    bits: int = 0  # CANopen size in bits; 0 when variable
    length: int = 0  # of a string: bytes (UTF-16 units for UNICODE_STRING) of the default

    @property
    def suffix(self) -> str:
        return "".join(f"[{n}]" for n in self.dims)

    @property
    def sizeof(self) -> str:
        return f"sizeof({self.ctype}{self.suffix})"

    @property
    def is_array(self) -> bool:
        return bool(self.dims)


@dataclass(frozen=True)
class Constant:
    """A C constant, or why there is none (`text` is empty then)."""

    text: str = ""
    reason: str = ""
    params: str = ""  # "(node_id)" for a macro of the node-ID


def storage_bits(ctype: str) -> int:
    return {"bool": 1, "float": 32, "double": 64}.get(ctype) or int("".join(c for c in ctype if c.isdigit()))


def scalar_type(dtype: DataType | None) -> str | None:
    """The C type of a BOOLEAN, integer or REAL; None for any other type."""
    if dtype is None or dtype.bits is None:
        return None
    if dtype.kind is ValueKind.BOOL:
        return "bool"
    if dtype.kind is ValueKind.REAL:
        return {32: "float", 64: "double"}.get(dtype.bits)
    if dtype.kind not in (ValueKind.UNSIGNED, ValueKind.SIGNED) or not 0 < dtype.bits <= 64:
        return None
    width = next(w for w in (8, 16, 32, 64) if dtype.bits <= w)
    return f"{'u' if dtype.kind is ValueKind.UNSIGNED else ''}int{width}_t"


def storage(dtype: DataType | None, default: object) -> Storage | None:
    """Where an entry's value lives in `struct NAME_od`; None for DOMAIN and types without a C form."""
    if dtype is None:
        return None
    scalar = scalar_type(dtype)
    if scalar is not None:
        return Storage(scalar, (), dtype.bits or 0)
    if dtype.kind is ValueKind.TIME:
        return Storage("uint64_t", (), 48)
    if dtype.kind is ValueKind.STRING:
        size = len(default.encode("utf-8")) if isinstance(default, str) else 0
        return Storage("char", (max(size, 1),), 8 * size, size)
    if dtype.kind is ValueKind.OCTETS and dtype.index != DOMAIN.index:
        size = len(default) if isinstance(default, bytes) else 0
        return Storage("uint8_t", (max(size, 1),), 8 * size, size)
    if dtype.kind is ValueKind.UNICODE:
        units = len(utf16_units(default)) if isinstance(default, str) else 0
        return Storage("uint16_t", (max(units, 1),), 16 * units, units)
    return None


def utf16_units(text: str) -> list[int]:
    data = text.encode("utf-16-le", "surrogatepass")
    return [data[i] | data[i + 1] << 8 for i in range(0, len(data), 2)]


def int_range(ctype: str) -> tuple[int, int]:
    bits = storage_bits(ctype)
    if ctype == "bool":
        return 0, 1
    if ctype.startswith("u"):
        return 0, (1 << bits) - 1
    return -(1 << (bits - 1)), (1 << (bits - 1)) - 1


def integer_literal(value: int, ctype: str) -> str:
    """`value` as a literal of at least the size of `ctype` (an integer C type), without a cast."""
    bits = storage_bits(ctype)
    if ctype.startswith("u"):
        if bits > 32:
            return f"0x{value:016X}ull"
        return f"0x{value:0{bits // 4}X}u" if bits >= 32 else f"{value}u"
    suffix = "ll" if bits > 32 else "l" if bits == 32 else ""
    if value == -(1 << (bits - 1)):
        return f"(-{(1 << (bits - 1)) - 1}{suffix} - 1)"
    return f"{value}{suffix}"


def typed_integer(value: int, ctype: str) -> str:
    return f"(({ctype}){integer_literal(value, ctype)})"


def real_literal(value: float, bits: int) -> str | None:
    """A REAL32 (`f` suffix) or REAL64 literal, or None when the type cannot hold `value`."""
    if not math.isfinite(value):
        return None
    if bits == 32:
        try:
            narrowed = struct.unpack("<f", struct.pack("<f", value))[0]
        except OverflowError:
            return None
        if narrowed == 0.0 and value != 0.0:
            return None
        text = format_real(narrowed, 32, as_bits=False) + "f"
    else:
        text = repr(float(value))
    return f"({text})" if text.startswith("-") else text


def constant(dtype: DataType | None, value: object) -> Constant:
    """The C spelling of a default or limit of type `dtype`."""
    ctype = scalar_type(dtype)
    if dtype is None or ctype is None or dtype.bits is None:
        return Constant(reason="no C constant for this data type")
    if isinstance(value, NodeIdExpr):
        return _nodeid_constant(dtype, ctype, value)
    if dtype.kind is ValueKind.REAL:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            return Constant(reason=f"{value!r} is not a number")
        if not math.isfinite(value):
            return Constant(reason=f"{value!r} is not a finite number")
        text = real_literal(float(value), dtype.bits)
        return Constant(text) if text else Constant(reason=f"{value!r} is not representable as {dtype.name}")
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    if not isinstance(value, int):
        return Constant(reason=f"{value!r} is not an integer")
    low, high = dtype.int_range() or (0, 0)
    if not low <= value <= high:
        return Constant(reason=f"{value} is out of range for {dtype.name}")
    if dtype.kind is ValueKind.BOOL:
        return Constant("true" if value else "false")
    return Constant(typed_integer(value, ctype))


def _nodeid_constant(dtype: DataType, ctype: str, value: NodeIdExpr) -> Constant:
    if not dtype.is_integer:
        return Constant(reason=f"$NODEID cannot be a {dtype.name}")
    low, high = dtype.int_range() or (0, 0)
    if not (low <= 1 + value.offset and 127 + value.offset <= high):
        return Constant(reason=f"{value.canonical()} is out of range for {dtype.name}")
    node = f"({ctype})(node_id)"
    if value.offset == 0:
        return Constant(f"(({ctype})(node_id))", params="(node_id)")
    sign = "-" if value.offset < 0 else "+"
    magnitude = f"0x{abs(value.offset):X}u" if ctype.startswith("u") else integer_literal(abs(value.offset), ctype)
    return Constant(f"(({ctype})({node} {sign} {magnitude}))", params="(node_id)")


def limit_value(value: int | float | None, dtype: DataType | None, upper: bool) -> int | float | None:
    """A limit usable for a range check of `dtype`: integral for integer types (rounded inwards)."""
    if value is None or dtype is None:
        return None
    if dtype.kind is ValueKind.REAL:
        return float(value) if math.isfinite(value) else None
    if not dtype.is_integer:
        return None
    if isinstance(value, float):
        if not math.isfinite(value):
            return None
        return math.floor(value) if upper else math.ceil(value)
    return value
