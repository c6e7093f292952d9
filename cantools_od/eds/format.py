"""Model values → CiA 306 text, in the project's canonical spelling."""

from __future__ import annotations

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


def format_key(key: str, value: object) -> str:
    """A non-typed key's value: strings as they are, numbers by HEX_KEYS, booleans 0/1."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, ObjectKind):
        return f"0x{int(value):X}"
    if isinstance(value, AccessType):
        return value.value
    if isinstance(value, int):
        width = HEX_KEYS.get(key)
        return str(value) if width is None else hex_int(value, width)
    return str(value)


def hex_int(value: int, width: int) -> str:
    return f"0x{value:0{width}X}" if value >= 0 else f"-0x{-value:0{width}X}"


def format_value(value: Value | None, dtype: DataType | None, dialect: Dialect, as_written: bool = False) -> str:
    """A typed value (DefaultValue, limits, ParameterValue) in canonical form.

    `as_written` keeps a `$NODEID` formula spelled as it was read.
    """
    if value is None:
        return ""
    if isinstance(value, RawValue):
        return value.text
    if isinstance(value, NodeIdExpr):
        return value.text if as_written and value.text else value.canonical()
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, int):
        if dtype is not None and dtype.kind is ValueKind.UNSIGNED and value >= 0 and dtype.bits:
            return hex_int(value, dtype.bits // 4)
        return str(value)
    if isinstance(value, float):
        bits = dtype.bits if dtype is not None and dtype.bits in (32, 64) else 64
        return format_real(value, bits, as_bits=dialect is Dialect.LELY)
    if isinstance(value, bytes):
        return value.hex().upper()
    if isinstance(value, TimeValue):
        return f"{value.days} {value.ms}"
    if dialect is Dialect.LELY and dtype is not None and dtype.kind is ValueKind.STRING:
        return quote(value)
    return value
