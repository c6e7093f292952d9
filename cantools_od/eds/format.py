"""Model values → CiA 306 text, in the project's canonical spelling (docs/portability.md says why).

Every spelling here is one that python-canopen, lely's dcfchk and our own reader all read as the same
value where such a spelling exists. Integers take the radix the writer's `IntStyle` asks for; `hint`
is the text the entry had in the file it was read from, when there was one.
"""

from __future__ import annotations

import math
import re
import struct
from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum

from ..model import AccessType, DataType, Dialect, NodeIdExpr, ObjectKind, RawValue, TimeValue, Value, ValueKind
from .dialect import quote
from .values import format_real

# Integer keys written in hex, with their digit count.
HEX_KEYS = {
    "VendorNumber": 8,
    "ProductNumber": 8,
    "RevisionNumber": 8,
    "LSS_SerialNumber": 8,
    "DataType": 4,
    "ObjectType": 1,
    "ObjFlags": 1,
    "CompactPDO": 2,
}


class Radix(StrEnum):
    """How an integer is spelled: by the canonical rules, as the file had it, or always one radix."""

    CANONICAL = "canonical"
    AS_WRITTEN = "as-written"
    HEX = "hex"
    DECIMAL = "decimal"


@dataclass(frozen=True)
class IntStyle:
    """The radix of each integer key (`DefaultValue`, `DataType`, ...); `default` for keys not named."""

    default: Radix = Radix.CANONICAL
    by_key: Mapping[str, Radix] = field(default_factory=dict)

    def radix(self, key: str) -> Radix:
        return self.by_key.get(key, self.default)


CANONICAL = IntStyle()

_HEX_TEXT = re.compile(r"[ \t]*-?[ \t]*0[xX]([0-9a-fA-F]+)")
DECIMAL_INTEGER = re.compile(r"[ \t]*-?[ \t]*(?:[1-9][0-9]*|0)[ \t]*\Z")
_NODEID_TERM = re.compile(r"\$nodeid", re.IGNORECASE)


def _written_radix(hint: str | None) -> tuple[Radix, int]:
    """The radix a number was written in (and its hex digit count); CANONICAL when neither is plain."""
    if hint is None:
        return Radix.CANONICAL, 0
    number = _NODEID_TERM.sub("", hint).strip(" \t+")
    match = _HEX_TEXT.match(number)
    if match is not None:
        return Radix.HEX, len(match.group(1))
    if DECIMAL_INTEGER.match(number):
        return Radix.DECIMAL, 0
    return Radix.CANONICAL, 0  # octal, C suffixes, sums: not a spelling worth keeping


def reads_hint(value: object, radix: Radix) -> bool:
    """Whether formatting `value` with `radix` looks at the text it was read from (`hint`): an integer to keep its
    radix as written or a negative one its two's complement, a REAL or TIME value always. The writer asks for the
    text only then."""
    return radix is Radix.AS_WRITTEN or isinstance(value, float | TimeValue) or (isinstance(value, int) and value < 0)


def format_int(value: int, radix: Radix, width: int, hint: str | None = None) -> str:
    """An integer: `width` is the hex digit count of the canonical form (0: canonical is decimal)."""
    if radix is Radix.AS_WRITTEN:
        radix, digits = _written_radix(hint)
        width = digits if radix is Radix.HEX else width
    if radix is Radix.CANONICAL:
        radix = Radix.HEX if width else Radix.DECIMAL
    if radix is Radix.HEX:
        return hex_int(value, width)
    return str(value)


def format_key(key: str, value: object, radix: Radix = Radix.CANONICAL, hint: str | None = None) -> str:
    """A non-typed key's value: strings as they are, numbers by HEX_KEYS, booleans 0/1."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, ObjectKind):
        return format_int(int(value), radix, 1, hint)
    if isinstance(value, AccessType):
        return value.value
    if isinstance(value, int):
        return format_int(value, radix, HEX_KEYS.get(key, 0), hint)
    return str(value)


def hex_int(value: int, width: int) -> str:
    return f"0x{value:0{width}X}" if value >= 0 else f"-0x{-value:0{width}X}"


def format_nodeid(value: NodeIdExpr, radix: Radix = Radix.CANONICAL, hint: str | None = None) -> str:
    """`$NODEID+n`: the one form python-canopen, lely and CANopenNode all evaluate. A bare `$NODEID` is
    written `$NODEID+0x0`, since python-canopen reads no value from it; a negative offset keeps the
    author's spelling, since no form of it reads alike everywhere."""
    if value.offset < 0:
        return value.text or f"$NODEID-0x{-value.offset:X}"
    return "$NODEID+" + format_int(value.offset, radix, 1, hint)


def format_value(
    value: Value | None,
    dtype: DataType | None,
    dialect: Dialect,
    as_written: bool = False,
    radix: Radix = Radix.CANONICAL,
    hint: str | None = None,
) -> str:
    """A typed value (DefaultValue, limits, ParameterValue) in canonical form.

    `as_written` keeps a `$NODEID` formula spelled as it was read.
    """
    if value is None:
        return ""
    if isinstance(value, RawValue):
        return value.text
    if isinstance(value, NodeIdExpr):
        return value.text if as_written and value.text else format_nodeid(value, radix, hint)
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, int):
        if value < 0 and twos_complement(hint, value, dtype):
            return hint.strip() if hint is not None else ""
        unsigned = dtype is not None and dtype.kind is ValueKind.UNSIGNED and value >= 0
        width = (dtype.bits or 0) // 4 if unsigned and dtype is not None else 0
        return format_int(value, radix, width, hint)
    if isinstance(value, float):
        return _real(value, dtype, dialect, hint)
    if isinstance(value, bytes):
        return value.hex().upper()
    if isinstance(value, TimeValue):
        return _time(value, hint)
    if dialect is Dialect.LELY and dtype is not None and dtype.kind is ValueKind.STRING:
        return quote(value)
    return value


def twos_complement(hint: str | None, value: int, dtype: DataType | None) -> bool:
    """Whether the author wrote negative `value` as its type's two's complement in hex (`0xFFFF` for -1 of an
    INTEGER16): python-canopen reads such a default or value as the unsigned number, so it keeps that spelling."""
    found = _HEX_TEXT.fullmatch(hint.strip()) if hint is not None else None
    bits = dtype.bits if dtype is not None else None
    return (
        found is not None
        and "-" not in found.group(0)
        and bits is not None
        and int(found.group(1), 16) == value + (1 << bits)
    )


def _real(value: float, dtype: DataType | None, dialect: Dialect, hint: str | None) -> str:
    """REAL: lely's files keep IEEE bit patterns. Elsewhere a decimal, except that zero, and an integral
    value the author wrote as an integer, stay integers: lely's dcfchk reads REAL text with `int()` (as a
    bit pattern), so `0` is the one REAL spelling every peer reads alike, and an integer it accepted before
    must not become a decimal it rejects."""
    bits = dtype.bits if dtype is not None and dtype.bits in (32, 64) else 64
    if dialect is Dialect.LELY:
        return format_real(value, bits, as_bits=True)
    if hint is not None and DECIMAL_INTEGER.match(hint) and _as_real(int(hint), bits) == value:
        return str(int(hint))  # e.g. 2147483647 for REAL32: python-canopen reads REAL limits with int()
    pattern = _bit_pattern(hint, value, bits)
    if pattern is not None:  # HighLimit=0xFFFF: lely reads the pattern, python-canopen its integer, as before
        return f"0x{pattern:0{bits // 4}X}"
    if value == 0:
        return "0"
    return format_real(value, bits, as_bits=False)


def _bit_pattern(hint: str | None, value: float, bits: int) -> int | None:
    """The IEEE bit pattern the author wrote for `value` (a hex integer), None when the text was not one."""
    found = _HEX_TEXT.fullmatch(hint.strip()) if hint is not None else None
    if found is None or "-" in found.group(0):
        return None
    pattern = int(found.group(1), 16)
    if pattern >= 1 << bits:
        return None
    read = struct.unpack("<f" if bits == 32 else "<d", pattern.to_bytes(bits // 8, "little"))[0]
    return pattern if read == value or (math.isnan(read) and math.isnan(value)) else None


def _as_real(number: int, bits: int) -> float | None:
    try:
        return float(struct.unpack("<f", struct.pack("<f", number))[0]) if bits == 32 else float(number)
    except (OverflowError, struct.error):
        return None


def _time(value: TimeValue, hint: str | None) -> str:
    """TIME_OF_DAY / TIME_DIFFERENCE: `days ms`, unless the author wrote the bit pattern as one integer and it
    still reads as this value; python-canopen reads `days ms` as the two numbers' digits run together."""
    if hint is not None and (DECIMAL_INTEGER.match(hint) or _HEX_TEXT.fullmatch(hint.strip())):
        try:
            if TimeValue.from_bits(int(hint, 0)) == value:
                return hint.strip()
        except ValueError:
            pass
    return f"{value.days} {value.ms}"
