"""The runtime of every generated Python module: SDO access, value packing and PDO layouts.

`gen -t python` copies everything below the RUNTIME marker verbatim into each module it writes
(templates/python/module.py.j2 places it), so this one file is what ruff and mypy check. The
imports above the marker are the ones the generated module makes itself.
"""

from __future__ import annotations

import struct
from typing import Final, NamedTuple, Protocol, runtime_checkable

# Defined by each generated module after the runtime: every variable by (index, sub-index).
_BY_ADDRESS: dict[tuple[int, int], _Var] = {}

# --- RUNTIME: below this line, copied into each generated module -------------------------------------------
# CiA 301 data types (the indices python-canopen's objectdictionary.datatypes has).
BOOLEAN: Final = 0x0001
INTEGER8: Final = 0x0002
INTEGER16: Final = 0x0003
INTEGER32: Final = 0x0004
UNSIGNED8: Final = 0x0005
UNSIGNED16: Final = 0x0006
UNSIGNED32: Final = 0x0007
REAL32: Final = 0x0008
VISIBLE_STRING: Final = 0x0009
OCTET_STRING: Final = 0x000A
UNICODE_STRING: Final = 0x000B
TIME_OF_DAY: Final = 0x000C
TIME_DIFFERENCE: Final = 0x000D
DOMAIN: Final = 0x000F
INTEGER24: Final = 0x0010
REAL64: Final = 0x0011
INTEGER40: Final = 0x0012
INTEGER48: Final = 0x0013
INTEGER56: Final = 0x0014
INTEGER64: Final = 0x0015
UNSIGNED24: Final = 0x0016
UNSIGNED40: Final = 0x0018
UNSIGNED48: Final = 0x0019
UNSIGNED56: Final = 0x001A
UNSIGNED64: Final = 0x001B

# data type → (bits, kind); bits 0: variable length
_TYPES: Final[dict[int, tuple[int, str]]] = {
    BOOLEAN: (1, "bool"),
    INTEGER8: (8, "signed"),
    INTEGER16: (16, "signed"),
    INTEGER24: (24, "signed"),
    INTEGER32: (32, "signed"),
    INTEGER40: (40, "signed"),
    INTEGER48: (48, "signed"),
    INTEGER56: (56, "signed"),
    INTEGER64: (64, "signed"),
    UNSIGNED8: (8, "unsigned"),
    UNSIGNED16: (16, "unsigned"),
    UNSIGNED24: (24, "unsigned"),
    UNSIGNED32: (32, "unsigned"),
    UNSIGNED40: (40, "unsigned"),
    UNSIGNED48: (48, "unsigned"),
    UNSIGNED56: (56, "unsigned"),
    UNSIGNED64: (64, "unsigned"),
    REAL32: (32, "real"),
    REAL64: (64, "real"),
    VISIBLE_STRING: (0, "string"),
    UNICODE_STRING: (0, "unicode"),
    OCTET_STRING: (0, "bytes"),
    DOMAIN: (0, "bytes"),
    TIME_OF_DAY: (48, "bytes"),
    TIME_DIFFERENCE: (48, "bytes"),
}


class _NodeId(NamedTuple):
    """A value relative to the node-ID: `$NODEID+offset`."""

    offset: int


_Value = int | float | str | bytes | _NodeId | None


class _Obj(NamedTuple):
    idx: int
    kind: str  # "var", "array" or "record"
    name: str


class _Var(NamedTuple):
    """A VAR or sub-object: what python-canopen's ODVariable holds."""

    idx: int
    sub: int
    data_type: int
    access: str
    pdo: bool
    name: str
    default: _Value = None
    value: _Value = None  # ParameterValue of a DCF
    low: int | float | None = None
    high: int | float | None = None


class _Field(NamedTuple):
    """A PDO entry: the bits of one dataclass field."""

    name: str
    offset: int
    bits: int
    kind: str  # "bool", "signed", "unsigned" or "real"


# --- values ------------------------------------------------------------------------------------------------


def _int_range(kind: str, bits: int) -> tuple[int, int]:
    if kind == "signed":
        return -(1 << (bits - 1)), (1 << (bits - 1)) - 1
    return 0, (1 << bits) - 1


def _real_bits(value: float, bits: int) -> int:
    try:
        data = struct.pack("<f" if bits == 32 else "<d", value)
    except (OverflowError, struct.error):
        raise ValueError(f"{value} is outside the range of REAL{bits}") from None
    return int.from_bytes(data, "little")


def _check_number(what: str, value: object, kind: str, bits: int, low: float | None, high: float | None) -> None:
    """Raise TypeError or ValueError unless `value` fits the type and the limits LowLimit..HighLimit."""
    if kind == "real":
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise TypeError(f"{what} takes a float, not {type(value).__name__}")
        _real_bits(float(value), bits)
        if value != value and (low is not None or high is not None):
            raise ValueError(f"{what}: NaN is not within the limits{_limits(low, high)}")
        checks = [(low, "LowLimit"), (high, "HighLimit")]
    elif kind == "bool":
        if not isinstance(value, int) or value not in (0, 1):
            raise TypeError(f"{what} takes a bool, not {value!r}")
        return
    else:
        if isinstance(value, bool) or not isinstance(value, int):
            raise TypeError(f"{what} takes an int, not {type(value).__name__}")
        smallest, largest = _int_range(kind, bits)
        checks = [(smallest, f"the {kind} {bits}-bit minimum"), (largest, f"the {kind} {bits}-bit maximum")]
        checks += [(low, "LowLimit"), (high, "HighLimit")]
    for number, (limit, name) in enumerate(checks):
        if limit is not None and (value < limit if number % 2 == 0 else value > limit):
            where = "below" if number % 2 == 0 else "above"
            raise ValueError(f"{what}: {value} is {where} {limit}, {name}{_limits(low, high)}")


def _limits(low: float | None, high: float | None) -> str:
    if low is None and high is None:
        return ""
    return f" (limits {'-inf' if low is None else low}..{'inf' if high is None else high})"


# --- SDO -----------------------------------------------------------------------------------------------------


class SdoChannel(Protocol):
    """What `Device` needs of python-canopen's SDO client (`RemoteNode.sdo`) or server (`LocalNode.sdo`)."""

    def upload(self, index: int, subindex: int) -> bytes: ...

    def download(self, index: int, subindex: int, data: bytes, force_segment: bool = False) -> None: ...


@runtime_checkable
class Node(Protocol):
    """A python-canopen `RemoteNode` or `LocalNode`."""

    @property
    def sdo(self) -> SdoChannel: ...


def _what(var: _Var) -> str:
    return f"0x{var.idx:04X}:{var.sub:02X} {var.name!r}"


def _upload(sdo: SdoChannel, idx: int, sub: int) -> tuple[_Var, bytes, int, str]:
    var = _BY_ADDRESS[idx, sub]
    bits, kind = _TYPES.get(var.data_type, (0, "bytes"))
    data = sdo.upload(idx, sub)
    size = (bits + 7) // 8
    if len(data) < size:
        raise ValueError(f"{_what(var)}: {len(data)} bytes received, {size} expected")
    return var, data, size, kind


def _read_int(sdo: SdoChannel, idx: int, sub: int) -> int:
    _, data, size, kind = _upload(sdo, idx, sub)
    return int.from_bytes(data[:size], "little", signed=kind == "signed")


def _read_bool(sdo: SdoChannel, idx: int, sub: int) -> bool:
    _, data, _, _ = _upload(sdo, idx, sub)
    return data[0] != 0


def _read_real(sdo: SdoChannel, idx: int, sub: int) -> float:
    _, data, size, _ = _upload(sdo, idx, sub)
    value: float = struct.unpack("<f" if size == 4 else "<d", data[:size])[0]
    return value


def _read_str(sdo: SdoChannel, idx: int, sub: int) -> str:
    _, data, _, kind = _upload(sdo, idx, sub)
    return data.decode("utf-16-le" if kind == "unicode" else "ascii", errors="replace").rstrip("\x00")


def _read_bytes(sdo: SdoChannel, idx: int, sub: int) -> bytes:
    return _upload(sdo, idx, sub)[1]


def _write_number(sdo: SdoChannel, idx: int, sub: int, value: float) -> None:
    """Check `value` against the type and LowLimit/HighLimit, then send it; nothing is sent when it does not fit."""
    var = _BY_ADDRESS[idx, sub]
    bits, kind = _TYPES[var.data_type]
    _check_number(_what(var), value, kind, bits, var.low, var.high)
    if kind == "real":
        data = _real_bits(float(value), bits).to_bytes(bits // 8, "little")
    else:
        data = int(value).to_bytes((bits + 7) // 8, "little", signed=kind == "signed")
    sdo.download(idx, sub, data)


def _write_str(sdo: SdoChannel, idx: int, sub: int, value: str) -> None:
    var = _BY_ADDRESS[idx, sub]
    if not isinstance(value, str):
        raise TypeError(f"{_what(var)} takes a str, not {type(value).__name__}")
    if _TYPES[var.data_type][1] == "unicode":
        sdo.download(idx, sub, value.encode("utf-16-le"))
        return
    try:
        data = value.encode("ascii")
    except UnicodeEncodeError:
        raise ValueError(f"{_what(var)}: a VISIBLE_STRING holds ASCII only, not {value!r}") from None
    sdo.download(idx, sub, data)


def _write_bytes(sdo: SdoChannel, idx: int, sub: int, value: bytes) -> None:
    var = _BY_ADDRESS[idx, sub]
    if not isinstance(value, (bytes, bytearray)):
        raise TypeError(f"{_what(var)} takes bytes, not {type(value).__name__}")
    bits = _TYPES.get(var.data_type, (0, "bytes"))[0]
    if bits and len(value) != bits // 8:
        raise ValueError(f"{_what(var)}: {bits // 8} bytes expected, not {len(value)}")
    sdo.download(idx, sub, bytes(value))


def _write_only(idx: int, sub: int) -> AttributeError:
    return AttributeError(f"{_what(_BY_ADDRESS[idx, sub])} is write-only")


# --- PDO -----------------------------------------------------------------------------------------------------


def _pack(layout: tuple[_Field, ...], values: tuple[object, ...], size: int, pdo: str) -> bytes:
    frame = 0
    for field, value in zip(layout, values, strict=True):
        _check_number(f"{pdo}.{field.name}", value, field.kind, field.bits, None, None)
        assert isinstance(value, (int, float))
        mask = (1 << field.bits) - 1
        frame |= (_real_bits(float(value), field.bits) if field.kind == "real" else int(value) & mask) << field.offset
    return frame.to_bytes(size, "little")


def _frame(data: bytes | bytearray, size: int, pdo: str) -> int:
    if len(data) < size:
        raise ValueError(f"{pdo} has {size} bytes, not {len(data)}")
    return int.from_bytes(data[:size], "little")


def _unsigned(frame: int, offset: int, bits: int) -> int:
    return (frame >> offset) & ((1 << bits) - 1)


def _signed(frame: int, offset: int, bits: int) -> int:
    raw = (frame >> offset) & ((1 << bits) - 1)
    return raw - (1 << bits) if raw >> (bits - 1) else raw


def _bool(frame: int, offset: int) -> bool:
    return bool((frame >> offset) & 1)


def _real(frame: int, offset: int, bits: int) -> float:
    raw = (frame >> offset) & ((1 << bits) - 1)
    value: float = struct.unpack("<f" if bits == 32 else "<d", raw.to_bytes(bits // 8, "little"))[0]
    return value
