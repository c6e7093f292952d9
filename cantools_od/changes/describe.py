"""Values as people read them in a diff: numbers with their hex, type and object names."""

from __future__ import annotations

import math

from ..model import DataType, NodeIdExpr, ObjectKind, RawValue, TimeValue, Value, ValueKind
from ..model.cia301.cobid import BASE_11BIT, BASE_29BIT, EXTENDED, RTR, VALID
from ..model.cia301.objects import (
    COB_ID_EMCY,
    COB_ID_SYNC,
    COB_ID_TIME,
    CONSUMER_HEARTBEAT,
    ERROR_BEHAVIOR,
    PRODUCER_HEARTBEAT,
    RPDO_COMM,
    SDO_CLIENTS,
    SDO_SERVERS,
    TPDO_COMM,
)
from .records import Change


def value_text(value: Value | None, dtype: DataType | None = None) -> str:
    """`250`, `0x180 (384)`, `$NODEID+0x180`, `"text"`, `0x0A0B` (octets); `-` for absent."""
    if value is None:
        return "-"
    if isinstance(value, NodeIdExpr):
        return value.canonical()
    if isinstance(value, RawValue):
        return f"{value.text!r} (unreadable)"
    if isinstance(value, TimeValue):
        return f"day {value.days} + {value.ms} ms"
    if isinstance(value, bool):
        return "1 (true)" if value else "0 (false)"
    if isinstance(value, int):
        return _int_text(value, dtype)
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else str(value)
    if isinstance(value, bytes):
        return "0x" + value.hex().upper() if value else "(empty)"
    return _quoted(value)


def _int_text(value: int, dtype: DataType | None) -> str:
    if value < 10 or (dtype is not None and dtype.kind is ValueKind.SIGNED):
        return str(value)
    return f"0x{value:X} ({value})"


def _quoted(text: str) -> str:
    return '"' + text.replace("\\", "\\\\").replace('"', '\\"') + '"'


def text(value: object) -> str:
    """Any other field: names quoted, flags yes/no, absent `-`."""
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, str):
        return _quoted(value)
    return str(value)


def object_type_text(kind: ObjectKind) -> str:
    return f"{kind.name} (0x{kind.value:X})"


def address(index: int | None, subindex: int | None) -> str:
    """`0x1A00`, `0x1A00:01` (index:sub-index), or empty for device-level changes."""
    if index is None:
        return ""
    return f"0x{index:04X}" if subindex is None else f"0x{index:04X}:{subindex:02X}"


def cob_id_text(value: Value | None, role: str = "PDO") -> str:
    """A COB-ID with its bits spelled out (CiA 301 §7.5.2): `0x80000185 (not valid, CAN-ID 185h)`,
    `$NODEID+0x180 (CAN-ID node-ID + 180h)`. `role` is PDO, SDO, EMCY, SYNC or TIME: bits 31 and 30 differ."""
    if isinstance(value, NodeIdExpr):
        bits, written, base = value.offset, value.canonical(), "node-ID + "
    elif isinstance(value, int) and not isinstance(value, bool):
        bits, written, base = value, f"0x{value:X}", ""
    else:
        return value_text(value)
    extended = bool(bits & EXTENDED)
    parts = [f"CAN-ID {base}{bits & (BASE_29BIT if extended else BASE_11BIT):03X}h" + (" (29-bit)" if extended else "")]
    return f"{written} ({', '.join([*_cob_flags(bits, role), *parts])})"


def _cob_flags(bits: int, role: str) -> list[str]:
    if role == "SYNC":
        return ["produces SYNC" if bits & RTR else "consumes SYNC"]
    if role == "TIME":
        roles = [role for role, bit in (("consumes", VALID), ("produces", RTR)) if bits & bit]
        return [" and ".join(roles) + " TIME" if roles else "TIME off"]
    flags = ["not valid"] if bits & VALID else []
    return flags + (["no RTR"] if role == "PDO" and bits & RTR else [])


_COB_ROLES = {COB_ID_SYNC: "SYNC", COB_ID_TIME: "TIME", COB_ID_EMCY: "EMCY"}
_ERROR_BEHAVIOUR = {0: "pre-operational", 1: "no state change", 2: "stopped"}


def entry_value_text(index: int, subindex: int | None, value: Value | None, dtype: DataType | None) -> str:
    """A value of an entry, decoded where CiA 301 defines its bits: COB-IDs, heartbeat consumer and producer
    times, error behaviour; any other entry as `value_text`."""
    role = _cob_role(index, subindex)
    if role is not None:
        return cob_id_text(value, role)
    if not isinstance(value, int) or isinstance(value, bool):
        return value_text(value, dtype)
    if index == CONSUMER_HEARTBEAT and subindex:
        node, time = (value >> 16) & 0x7F, value & 0xFFFF
        return f"{value_text(value, dtype)} (node {node}, {time} ms)" if time else f"{value_text(value, dtype)} (off)"
    if index == PRODUCER_HEARTBEAT:
        return f"{value} ms" if value else "0 (off)"
    if index == ERROR_BEHAVIOR and subindex and value in _ERROR_BEHAVIOUR:
        return f"{value} ({_ERROR_BEHAVIOUR[value]})"
    return value_text(value, dtype)


def _cob_role(index: int, subindex: int | None) -> str | None:
    if index in _COB_ROLES and not subindex:
        return _COB_ROLES[index]
    if (index in RPDO_COMM or index in TPDO_COMM) and subindex == 1:
        return "PDO"
    if (index in SDO_SERVERS or index in SDO_CLIENTS) and subindex in (1, 2):
        return "SDO"
    return None


_LABELS = {
    "name": "name",
    "identifier": "identifier",
    "flat_identifier": "flat identifier",
    "object_type": "object type",
    "data_type": "data type",
    "access": "access",
    "pdo_mapping": "PDO mapping",
    "low_limit": "low limit",
    "high_limit": "high limit",
    "default": "default",
    "parameter_value": "parameter value",
    "obj_flags": "ObjFlags",
    "denotation": "denotation",
    "param_refd": "ParamRefd",
    "upload_file": "UploadFile",
    "download_file": "DownloadFile",
    "cob_id": "COB-ID",
    "transmission_type": "transmission type",
    "mapping": "mapping",
    "links": "object links",
    "device_info.vendor_number": "vendor-ID (VendorNumber)",
    "device_info.product_number": "product code (ProductNumber)",
    "device_info.revision_number": "revision number (RevisionNumber)",
    "device_info.nr_of_rx_pdo": "number of RPDOs (NrOfRXPDO)",
    "device_info.nr_of_tx_pdo": "number of TPDOs (NrOfTXPDO)",
    "device_info.lss_supported": "LSS supported",
    "commissioning.node_id": "node-ID",
}


def label(field: str) -> str:
    """A field as people call it: `data type`, `device_info.vendor_number` → `vendor number`."""
    if field in _LABELS:
        return _LABELS[field]
    head, _, tail = field.rpartition(".")
    if head.endswith("spelling"):
        return "section name as written" if tail == "section" else f"key {tail} as written"
    if head.endswith("extra") or head.startswith("["):
        return f"{head.removesuffix('extra').rstrip('.')} key {tail}".strip()
    if head == "device_info.baud_rates":
        return f"supported bit rate {tail} kbit/s"
    if head == "dummy_usage":
        return f"dummy usage of type 0x{tail}"
    return tail.replace("_", " ") if tail else field.replace("_", " ")


_ADDED = frozenset({"object-added", "sub-added", "pdo-added"})
_REMOVED = frozenset({"object-removed", "sub-removed", "pdo-removed"})


def sentence(change: Change) -> str:
    """What changed, in one line without the entry's address: `access rw → ro (no longer writable)`."""
    kind = change.kind.value
    if kind in _ADDED:
        text = f"added: {change.new_text}"
    elif kind in _REMOVED:
        text = f"removed: {change.old_text}"
    elif kind == "not-comparable":
        text = f"{label(change.field)}: not comparable"
    elif kind in ("object-moved", "sub-moved"):
        text = f"moved from {change.old_text} to {change.new_text}"
    else:
        what = label(change.field)
        if kind == "nodeid-form":
            what += " ($NODEID form)"
        text = f"{what}: {change.old_text} → {change.new_text}"
    return f"{text} ({change.note})" if change.note else text
