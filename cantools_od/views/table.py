"""The object dictionary as a plain-text table for `cantools-od dump`."""

from __future__ import annotations

from pathlib import Path

from ..model import Device, Object, Origin, RawValue, TimeValue, Value, Variable
from ..model.values import NodeIdExpr


def display(value: Value | None, node_id: int | None = None) -> str:
    """A value as a person reads it; a `$NODEID` formula with its value when the node-ID is known (given, or
    the DCF's), as the Markdown reference shows it."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return "1" if value else "0"
    if isinstance(value, int):
        return f"0x{value:X}" if value > 9 else str(value)
    if isinstance(value, bytes):
        return value.hex().upper()
    if isinstance(value, NodeIdExpr):
        return value.canonical() if node_id is None else f"0x{value.resolve(node_id):X} ({value.canonical()})"
    if isinstance(value, TimeValue):
        return f"{value.days} d {value.ms} ms"
    if isinstance(value, RawValue):
        return value.text
    return repr(value) if isinstance(value, str) else str(value)


def _row(device: Device, index: str, sub: str, var: Variable, owner: Object, kind: str) -> list[str]:
    dtype = device.entry_type(var, owner)
    type_name = kind or (dtype.name if dtype else (f"0x{var.data_type:04X}" if var.data_type is not None else ""))
    access = var.access.value if var.access else ""
    nid = device.node_id
    value = display(var.held, nid)
    limits = ""
    if var.low_limit is not None or var.high_limit is not None:
        limits = f"{display(var.low_limit, nid)}..{display(var.high_limit, nid)}"
    pdo = "yes" if var.pdo_mapping else ""
    origin = _where(device, var.origin or owner.origin)
    return [index, sub, var.name, type_name, access, pdo, value, limits, origin]


def _where(device: Device, origin: Origin | None) -> str:
    """The line a value comes from; with its file when that is not the one shown (an imported manual)."""
    if origin is None or not origin.line:
        return ""
    if origin.file and Path(origin.file).name != Path(device.source).name:
        return f"{Path(origin.file).name}:{origin.line}"
    return str(origin.line)


def render_table(device: Device) -> str:
    info = device.device_info
    head = [
        f"{device.source or '<input>'}: {info.product_name or '(no product name)'}"
        f" by {info.vendor_name or '(no vendor name)'}",
        f"vendor 0x{info.vendor_number or 0:08X}  product 0x{info.product_number or 0:08X}"
        f"  revision 0x{info.revision_number or 0:08X}  {len(device.objects)} objects"
        f"  dialect {device.dialect.value}",
        "",
    ]
    rows = [["Index", "Sub", "Name", "Type", "Access", "PDO", "Value", "Limits", "Source"]]
    for obj in device.objects.values():
        kind = obj.kind.name if obj.has_subs or obj.kind.name in ("DEFTYPE", "NULL") else ""
        rows.append(_row(device, f"{obj.index:04X}", "", obj, obj, kind))
        for subindex, sub in obj.subs.items():
            rows.append(_row(device, "", f"{subindex}", sub, obj, ""))
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    widths[2] = min(widths[2], 40)
    lines = [
        "  ".join(cell[:40].ljust(width) for cell, width in zip(row, widths, strict=True)).rstrip() for row in rows
    ]
    return "\n".join(head + lines)
