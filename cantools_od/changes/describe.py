"""Values as people read them in a diff: numbers with their hex, type and object names."""

from __future__ import annotations

import math

from ..model import DataType, NodeIdExpr, ObjectKind, RawValue, TimeValue, Value, ValueKind
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
    """`0x1A00`, `0x1A00 sub 1`, or empty for device-level changes."""
    if index is None:
        return ""
    return f"0x{index:04X}" if subindex is None else f"0x{index:04X} sub {subindex}"


def cob_id_text(value: Value | None) -> str:
    """A COB-ID with its valid bit spelled out."""
    if isinstance(value, int) and not isinstance(value, bool):
        return f"0x{value:X}" + (" (disabled)" if value & 0x80000000 else "")
    return value_text(value)


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
    if head.endswith("extra") or head.startswith("["):
        return f"{head.removesuffix('extra').rstrip('.')} key {tail}".strip()
    if head == "device_info.baud_rates":
        return f"{tail} kbit/s"
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
    else:
        what = label(change.field)
        if kind == "nodeid-form":
            what += " ($NODEID form)"
        text = f"{what}: {change.old_text} → {change.new_text}"
    return f"{text} ({change.note})" if change.note else text
