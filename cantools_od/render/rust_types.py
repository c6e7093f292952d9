"""Rust spellings of CiA 301 types and values: `u32`, `0x00000180`, `-1.5_f32`, `f32::NAN`, `*b"abc"`.

Every literal returned is valid for its Rust type and free of compiler and clippy warnings
(no out-of-range literal, no excessive float precision, no look-alike of `PI` or `E`).
"""

from __future__ import annotations

import math
import struct

from ..model import DataType, ValueKind

# Rust type of each fixed-size kind and size; 24/40/48/56-bit types live in the next larger one.
_CONTAINER = {8: 8, 16: 16, 24: 32, 32: 32, 40: 64, 48: 64, 56: 64, 64: 64}

# Constants clippy's `approx_constant` recognises (std::f64::consts), with its minimum digit counts.
_KNOWN = (
    (math.e, 4),
    (1 / math.pi, 4),
    (math.sqrt(0.5), 5),
    (2 / math.pi, 5),
    (2 / math.sqrt(math.pi), 5),
    (math.pi / 2, 5),
    (math.pi / 3, 5),
    (math.pi / 4, 5),
    (math.pi / 6, 5),
    (math.pi / 8, 5),
    (math.log(2), 5),
    (math.log(10), 5),
    (math.log2(10), 5),
    (math.log2(math.e), 5),
    (math.log10(2), 5),
    (math.log10(math.e), 5),
    (math.pi, 3),
    (math.sqrt(2), 5),
    (math.tau, 3),
)


def rust_type(dtype: DataType | None) -> str | None:
    """The Rust type of a fixed-size number or boolean; None for anything else."""
    if dtype is None or dtype.bits is None:
        return None
    if dtype.kind is ValueKind.BOOL:
        return "bool"
    if dtype.kind is ValueKind.REAL:
        return f"f{dtype.bits}" if dtype.bits in (32, 64) else None
    if dtype.kind in (ValueKind.UNSIGNED, ValueKind.SIGNED) and dtype.bits in _CONTAINER:
        return f"{'u' if dtype.kind is ValueKind.UNSIGNED else 'i'}{_CONTAINER[dtype.bits]}"
    return None


def zero(ty: str) -> str:
    """The zero value of a scalar Rust type."""
    return "false" if ty == "bool" else f"0.0_{ty}" if ty.startswith("f") else "0"


def int_literal(value: int, dtype: DataType) -> str | None:
    """An integer of `dtype` (bits ≥ 32 unsigned in padded hex); None when it is out of range."""
    bounds = dtype.int_range()
    if bounds is None or not bounds[0] <= value <= bounds[1] or dtype.bits is None:
        return None
    ty = rust_type(dtype) or ""
    if dtype.kind is ValueKind.UNSIGNED:
        return f"0x{value:0{dtype.bits // 4}X}" if dtype.bits >= 32 else str(value)
    if dtype.bits == _CONTAINER[dtype.bits] and value == bounds[0]:
        return f"{ty}::MIN"
    return str(value)


def _shortest(value: float, bits: int) -> str:
    """The shortest decimal that reads back as `value` in an IEEE float of `bits` bits."""
    if bits == 64:
        return repr(value)
    target = struct.pack("<f", value)
    for digits in range(1, 18):
        text = f"{value:.{digits}g}"
        try:
            if struct.pack("<f", float(text)) == target:
                return text
        except OverflowError:  # rounded up beyond the largest REAL32
            continue
    return repr(value)  # pragma: no cover - 9 digits always suffice


def _looks_like_constant(digits: str) -> bool:
    """Whether clippy's `approx_constant` would take these digits (no sign, no exponent) for a constant."""
    for constant, minimum in _KNOWN:
        if len(digits) <= minimum:
            continue
        spelled = repr(constant)
        if spelled.startswith(digits) or f"{constant:.{len(digits) - 2}f}" == digits:
            return True
    return False


def _as_float(value: float, bits: int) -> float:
    """`value` rounded to the float type; ±inf when it overflows a REAL32."""
    if bits == 64 or not math.isfinite(value):
        return value
    try:
        rounded: float = struct.unpack("<f", struct.pack("<f", value))[0]
    except OverflowError:
        return math.copysign(math.inf, value)
    return rounded


def float_literal(value: float, bits: int) -> str:
    """A REAL32/REAL64 value: `1.0_f32`, `-2.5e-7_f64`, `f32::NAN`, `f32::from_bits(0x40490FDB)`."""
    ty = f"f{bits}"
    value = _as_float(float(value), bits)
    if math.isnan(value):
        return f"{ty}::NAN"
    if math.isinf(value):
        return f"{ty}::INFINITY" if value > 0 else f"{ty}::NEG_INFINITY"
    text = _shortest(value, bits)
    mantissa, _, exponent = text.lstrip("-").partition("e")
    if _looks_like_constant(mantissa):
        raw = struct.pack("<f" if bits == 32 else "<d", value)
        return f"{ty}::from_bits(0x{int.from_bytes(raw, 'little'):0{bits // 4}X})"
    if "." not in mantissa:
        mantissa += ".0"
    if exponent:
        sign = "-" if exponent.startswith("-") else ""
        mantissa += f"e{sign}{exponent.lstrip('+-').lstrip('0') or '0'}"
    return f"{'-' if text.startswith('-') else ''}{mantissa}_{ty}"


def scalar_literal(value: object, dtype: DataType) -> str | None:
    """`value` as a literal of `dtype`'s Rust type; None when it is not one or does not fit."""
    if dtype.kind is ValueKind.BOOL:
        if isinstance(value, bool) or (isinstance(value, int) and value in (0, 1)):
            return "true" if value else "false"
        return None
    if isinstance(value, bool):
        value = int(value)
    if dtype.kind is ValueKind.REAL and dtype.bits in (32, 64) and isinstance(value, (int, float)):
        return float_literal(value, dtype.bits)
    if dtype.is_integer and isinstance(value, int):
        return int_literal(value, dtype)
    return None


def in_type_range(value: int | float, dtype: DataType) -> bool:
    """Whether a limit restricts `dtype`'s values: inside its range but not at its bound."""
    bounds = dtype.int_range()
    if dtype.kind is ValueKind.REAL:
        return math.isfinite(value)
    return bounds is not None and isinstance(value, int) and bounds[0] <= value <= bounds[1]


def byte_string(data: bytes) -> str:
    """A Rust byte string literal `b"..."`: printable ASCII as is, every other byte as `\\xNN`."""
    out = []
    for byte in data:
        char = chr(byte)
        if char in '"\\':
            out.append("\\" + char)
        elif 0x20 <= byte < 0x7F:
            out.append(char)
        else:
            out.append(f"\\x{byte:02X}")
    return 'b"' + "".join(out) + '"'


def node_expr(ty: str, offset: int) -> str:
    """`node_id` plus `offset` as a value of `ty`, for a node-ID 1..=127 (wrapping when it cannot fit)."""
    base = "node_id" if ty == "u8" else f"node_id as {ty}"
    if ty.startswith("f"):
        return f"{base} + {float_literal(float(offset), int(ty[1:]))}" if offset else base
    if offset == 0:
        return base
    bits = int(ty[1:])
    low, high = (0, (1 << bits) - 1) if ty.startswith("u") else (-(1 << (bits - 1)), (1 << (bits - 1)) - 1)
    spell = (lambda n: f"0x{n:X}") if ty.startswith("u") else str
    if low <= offset + 1 and offset + 127 <= high:
        return f"{base} + {spell(offset)}" if offset > 0 else f"{base} - {spell(-offset)}"
    receiver = base if ty == "u8" else f"({base})"
    if ty.startswith("u"):
        return f"{receiver}.wrapping_add({spell(offset % (1 << bits))})"
    wrapped = (offset - low) % (1 << bits) + low
    return f"{receiver}.wrapping_add({f'{ty}::MIN' if wrapped == low else wrapped})"
