"""The reference documents' words: what the Markdown and HTML pages say of a device, its objects and their
entries. Nothing here is markup: text taken from the file goes through the `escape` a renderer passes (the
Markdown page escapes it here, the HTML page in its template), so both pages say the same.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from ..model import DataType, Device, NodeIdExpr, Object, ObjectKind, RawValue, TimeValue, ValueKind, Variable
from ..model.datatypes import standard_type
from .codegen import DeviceView, EntryView, ObjectView

NONE = "\u2014"
TYPE_KINDS = (ObjectKind.NULL, ObjectKind.DEFTYPE)
"""The objects the code views leave out (they define types, hold no data)."""

Escape = Callable[[str], str]


def plain(text: str) -> str:
    return text


def source_name(view: DeviceView) -> str:
    return view.source_name or f"{view.name}.eds"


def summary(
    view: DeviceView, cell: Escape = plain, text: Escape = plain, code: Escape = plain
) -> list[tuple[str, str]]:
    """The device's identity and file facts, as (field, value) pairs: `cell` escapes a value that fills a cell,
    `text` a name within one, `code` marks a formula."""
    device = view.device
    info, file_info = device.device_info, device.file_info
    nid = view.node_id
    rates = [f"{rate}" for rate, on in sorted(info.baud_rates.items()) if on]
    return [
        ("File", cell(source_name(view))),
        ("FileName", cell(file_info.file_name or "")),
        ("Description", cell(file_info.description or "")),
        ("Vendor", named(info.vendor_name, info.vendor_number, text)),
        ("Product", named(info.product_name, info.product_number, text)),
        ("Revision number", hex32(info.revision_number)),
        ("Order code", cell(info.order_code or "")),
        ("File version", version(file_info.file_version, file_info.file_revision)),
        ("EDS version", cell(file_info.eds_version or "")),
        ("Kind", "DCF" if device.is_dcf else "EDS"),
        ("Node-ID", str(nid) if nid is not None else f"not given: COB-IDs are shown as {code('$NODEID+offset')}"),
        ("Baud rates", f"{', '.join(rates)} kbit/s" if rates else NONE),
        ("Objects", str(len(view.objects))),
    ]


def named(name: str | None, number: int | None, escape: Escape = plain) -> str:
    parts = [escape(name)] if name else []
    if number is not None:
        parts.append(f"({hex32(number)})" if parts else hex32(number))
    return " ".join(parts) or NONE


def hex32(number: int | None) -> str:
    return NONE if number is None else f"0x{number:08X}"


def version(major: int | None, revision: int | None) -> str:
    if major is None and revision is None:
        return NONE
    return f"{major if major is not None else '?'}.{revision if revision is not None else '?'}"


def variable(device: Device, entry: EntryView) -> tuple[Object, Variable]:
    obj = device.objects[entry.index]
    var = obj.entry(entry.subindex)
    return obj, var if var is not None else obj


def type_text(device: Device, entry: EntryView) -> str:
    if entry.data_type is not None:
        return entry.data_type.name
    _, var = variable(device, entry)
    return f"0x{var.data_type:04X} (unknown)" if var.data_type is not None else NONE


def value_text(view: DeviceView, entry: EntryView, escape: Escape = plain, cell: Escape = plain) -> str:
    """The value the device holds (ParameterValue, else DefaultValue), as the file means it."""
    _, var = variable(view.device, entry)
    value = var.held
    if value is None:
        return NONE
    if isinstance(value, RawValue):
        return escape(value.text) + " (unreadable)"
    if isinstance(value, TimeValue):
        return f"{value.days} days {value.ms} ms"
    if isinstance(value, NodeIdExpr):
        nid = view.node_id
        text = escape(value.canonical())
        return text if nid is None else f"0x{value.resolve(nid):X} ({text})"
    return number_text(value, entry.data_type, escape, cell)


def number_text(value: object, dtype: DataType | None, escape: Escape = plain, cell: Escape = plain) -> str:
    if dtype is not None and dtype.kind is ValueKind.BOOL and value in (0, 1):
        return "true" if value else "false"
    if isinstance(value, bool):
        return str(int(value))
    if isinstance(value, int):
        unsigned = dtype is not None and dtype.kind is ValueKind.UNSIGNED and (dtype.bits or 0) >= 32
        return f"0x{value:0{(dtype.bits or 32) // 4 if dtype else 8}X}" if unsigned and value > 9 else str(value)
    if isinstance(value, float):
        return escape(repr(value))
    if isinstance(value, bytes):
        return " ".join(f"{byte:02X}" for byte in value) or '""'
    if isinstance(value, str):
        return f'"{escape(value)}"'
    return cell(str(value))


def limits_text(entry: EntryView, escape: Escape = plain) -> str:
    low, high = entry.low_limit, entry.high_limit
    if low is None and high is None:
        return NONE
    if low is None:
        return f"max {escape(str(high))}"
    if high is None:
        return f"min {escape(str(low))}"
    return f"{escape(str(low))}..{escape(str(high))}"


def where_text(view: DeviceView, entry: EntryView, escape: Escape = plain) -> str:
    """`file:line` of the entry's section, "" when unknown; ` (compact)` for one CompactSubObj implies."""
    obj, var = variable(view.device, entry)
    origin = var.origin or obj.origin
    if origin is None or not origin.line:
        return ""
    # The origin names its own file: a model imported from a manual points into the manual.
    file = Path(origin.file).name if origin.file else source_name(view)
    return escape(f"{file}:{origin.line}") + (" (compact)" if entry.implicit else "")


def header_where(view: DeviceView, obj: ObjectView) -> str:
    """`file:line` of the object's own section, "" when unknown."""
    header = view.device.objects[obj.index].origin
    return f"{source_name(view)}:{header.line}" if header is not None and header.line else ""


def mapped_by(view: DeviceView) -> dict[tuple[int, int], list[str]]:
    """(index, sub-index) → the names of the PDOs that map it as configured."""
    found: dict[tuple[int, int], list[str]] = {}
    for pdo in view.pdos:
        for entry in pdo.fields:
            if entry.entry is not None:
                names = found.setdefault((entry.entry.index, entry.entry.subindex), [])
                if pdo.pdo.name not in names:
                    names.append(pdo.pdo.name)
    return found


def kind_text(obj: ObjectView) -> str:
    if obj.is_var:
        return obj.kind.name
    count = obj.entry_count
    return f"{obj.kind.name} with {count} sub-object{'s' if count != 1 else ''}"


def type_definition(obj: Object, escape: Escape = plain, cell: Escape = plain) -> tuple[str, str]:
    """A data-type area object's type name and value (for a DEFTYPE, its size in bits)."""
    known = standard_type(obj.data_type)
    type_name = known.name if known is not None else NONE
    if known is None and obj.data_type is not None:
        type_name = f"0x{obj.data_type:04X} (unknown)"
    value = NONE if obj.default is None else number_text(obj.default, known, escape, cell)
    if obj.kind is ObjectKind.DEFTYPE and isinstance(obj.default, int):
        value = f"{obj.default} bits"
    return type_name, value
