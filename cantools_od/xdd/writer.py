"""Writes a device as XDD/XDC: over the bytes it was read from where it can, else canonically.

The preserving writer reads the original again and compares: an unchanged
device gives the original bytes back; a changed value of an object or
sub-object is written into the attribute that held it (or added to its
CANopenObject), leaving every other byte alone. The result is read back and
must describe the device; other changes fall back to the canonical layout.
"""

from __future__ import annotations

from ..eds.format import format_value
from ..model import AccessType, Device, DeviceInfo, Dialect, NodeIdExpr, Object, Origin, Variable
from .canonical import canonical_xml, pdo_mapping_text
from .context import ReadContext
from .locations import attribute_spans
from .reader import read_with_context, refused
from .safe import Element
from .vocabulary import ACCESS_NAME, ELEMENT_OF_TYPE
from .xmltext import escape, quoteattr

_KEYS = {
    "name": ("ParameterName", "name"),
    "object_type": ("ObjectType", "objectType"),
    "data_type": ("DataType", "dataType"),
    "access": ("AccessType", "accessType"),
    "default": ("DefaultValue", "defaultValue"),
    "low_limit": ("LowLimit", "lowLimit"),
    "high_limit": ("HighLimit", "highLimit"),
    "pdo_mapping": ("PDOMapping", "PDOmapping"),
    "obj_flags": ("ObjFlags", "objFlags"),
    "sub_number": ("SubNumber", "subNumber"),
    "parameter_value": ("ParameterValue", "actualValue"),
    "denotation": ("Denotation", "denotation"),
}
_VALUE_ELEMENTS = ("defaultValue", "actualValue", "minValue", "maxValue")
_EDITABLE = ("objects", "device_info")
# DeviceInfo fields the reader marks where they are written: model field → EDS key.
_INFO_KEYS = {
    "vendor_name": "VendorName",
    "vendor_number": "VendorNumber",
    "product_name": "ProductName",
    "product_number": "ProductNumber",
    "revision_number": "RevisionNumber",
    "order_code": "OrderCode",
    "granularity": "Granularity",
    "nr_of_rx_pdo": "NrOfRXPDO",
    "nr_of_tx_pdo": "NrOfTXPDO",
    "lss_supported": "LSS_Supported",
    "group_messaging": "GroupMessaging",
    "dynamic_channels_supported": "DynamicChannelsSupported",
    "simple_boot_up_slave": "SimpleBootUpSlave",
    "simple_boot_up_master": "SimpleBootUpMaster",
}

Edit = tuple[int, int, bytes]


class _Unsupported(Exception):
    """A change this writer cannot make in place."""


def dumps_xml(device: Device, xdc: bool = False, preserve: bool = True) -> bytes:
    if xdc and not device.is_dcf and device.node_id is None:
        raise ValueError("an XDC describes one node: give its node-ID")
    original = device._original
    if original is not None and refused(device):
        return original  # not read as a device description: never replaced by what little was read
    if preserve and original is not None and device.file_format == "xdd" and _same_kind(device, xdc):
        kept = _preserve(device, original)
        if kept is not None:
            return kept
    return canonical_xml(device, xdc).encode("utf-8")


def _same_kind(device: Device, xdc: bool) -> bool:
    """Whether the bytes read can stand for the file asked for: an XDC for a configured device, an XDD
    for a description; an .xdd file stating a commissioning (as CANopenEditor writes them) is read as
    configured and is still the XDD it was."""
    if xdc == device.is_dcf:
        return True
    return not xdc and not device.source.lower().endswith(".xdc")


def _preserve(device: Device, original: bytes) -> bytes | None:
    before, ctx = read_with_context(original, device.source, dcf=device.is_dcf)
    target = _spelled(device)
    if _spelled(before) == target:
        return original
    try:
        edits = _edits(before, device, ctx)
    except _Unsupported:
        return None
    out = bytearray(original)
    for start, end, text in sorted(edits, reverse=True):
        out[start:end] = text
    result = bytes(out)
    check = read_with_context(result, device.source, dcf=device.is_dcf)[0]
    return result if _spelled(check) == target else None


def _spelled(device: Device) -> object:
    """The device's content, with `$NODEID` formulas as spelled (a respelling is a change to write)."""
    data = device.model_dump(mode="json", exclude={"diagnostics", "source", "dialect", "file_format"})
    return _without_origins(data)


def _without_origins(data: object) -> object:
    if isinstance(data, dict):
        if "nodeid" in data and not data.get("text"):  # made in code: written in the canonical spelling
            return {**data, "text": NodeIdExpr(offset=data["nodeid"]).canonical()}
        return {key: _without_origins(value) for key, value in data.items() if key != "origin"}
    if isinstance(data, list):
        return [_without_origins(item) for item in data]
    return data


def _edits(before: Device, after: Device, ctx: ReadContext) -> list[Edit]:
    old, new = before.content(), after.content()
    if {k: v for k, v in old.items() if k not in _EDITABLE} != {k: v for k, v in new.items() if k not in _EDITABLE}:
        raise _Unsupported
    if before.objects.keys() != after.objects.keys():
        raise _Unsupported
    edits = _device_info_edits(before.device_info, after.device_info, ctx)
    for index, obj in after.objects.items():
        was = before.objects[index]
        if was.subs.keys() != obj.subs.keys():
            raise _Unsupported
        pairs: list[tuple[Variable, Variable]] = [(was, obj), *((was.subs[i], s) for i, s in obj.subs.items())]
        for old_var, new_var in pairs:
            edits += _var_edits(after, obj, old_var, new_var, ctx)
    return edits


def _device_info_edits(old: DeviceInfo, new: DeviceInfo, ctx: ReadContext) -> list[Edit]:
    """Identity elements and NMT feature attributes, where the file states them."""
    if old.model_dump(exclude={"origin", *_INFO_KEYS}) != new.model_dump(exclude={"origin", *_INFO_KEYS}):
        raise _Unsupported
    edits: list[Edit] = []
    for field, key in _INFO_KEYS.items():
        value = getattr(new, field)
        if getattr(old, field) == value:
            continue
        bound = ctx.marks.get(id(old.origin), {}).get(key) if old.origin is not None else None
        if bound is None or value is None:
            raise _Unsupported
        element, attr = bound
        if isinstance(value, bool):
            text = "true" if value else "false"
        elif isinstance(value, int) and attr is None:
            text = f"0x{value:08X}"
        else:
            text = str(value)
        if attr is None:
            edits.append((element.content_start, element.content_end, escape(text).encode("utf-8")))
        else:
            _, start, end = attribute_spans(ctx.data, element)[attr]
            edits.append((start, end, quoteattr(text)[1:-1].encode("utf-8")))
    return edits


def _var_edits(device: Device, owner: Object, old: Variable, new: Variable, ctx: ReadContext) -> list[Edit]:
    unchanged = old.model_dump(exclude={"origin", "subs", *_KEYS}) == new.model_dump(exclude={"origin", "subs", *_KEYS})
    if not unchanged or old.origin is None:
        raise _Unsupported
    edits: list[Edit] = []
    inserted: list[str] = []
    for field, (key, attr) in _KEYS.items():
        was, now = getattr(old, field, None), getattr(new, field, None)
        if was == now and not (isinstance(now, NodeIdExpr) and isinstance(was, NodeIdExpr) and was.text != now.text):
            continue
        text = _text(device, owner, new, field)
        edits += _edit(ctx, old.origin, key, attr, text, inserted)
    if inserted:
        element = ctx.elements[id(old.origin)]
        tail = element.content_start - (
            2 if ctx.data[element.content_start - 2 : element.content_start] == b"/>" else 1
        )
        while ctx.data[tail - 1 : tail].isspace():
            tail -= 1
        edits.append((tail, tail, "".join(inserted).encode("utf-8")))
    return edits


def _edit(ctx: ReadContext, origin: Origin, key: str, attr: str, text: str | None, inserted: list[str]) -> list[Edit]:
    bound = ctx.marks.get(id(origin), {}).get(key)
    if bound is None:
        if text is not None:
            inserted.append(f" {attr}={quoteattr(text)}")
        return []
    element, where = bound
    if where is None:
        return _element_edit(ctx, origin, element, key, attr, text, inserted)
    start, value_start, value_end = attribute_spans(ctx.data, element)[where]
    if text is None:
        if element.local in _VALUE_ELEMENTS:
            return [_remove_element(ctx.data, element)]
        begin = start
        while ctx.data[begin - 1 : begin].isspace():
            begin -= 1
        return [(begin, value_end + 1, b"")]
    if where == "access":
        text = ACCESS_NAME.get(AccessType(text)) if text in AccessType.__members__.values() else None
        if text is None:
            raise _Unsupported
    return [(value_start, value_end, quoteattr(text)[1:-1].encode("utf-8"))]


def _element_edit(
    ctx: ReadContext, origin: Origin, element: Element, key: str, attr: str, text: str | None, inserted: list[str]
) -> list[Edit]:
    if key != "DataType" or text is None:
        raise _Unsupported
    name = ELEMENT_OF_TYPE.get(int(text, 16))
    if name is None:
        inserted.append(f" {attr}={quoteattr(text)}")  # the object's dataType wins over the parameter's element
        return []
    start = element.start + 1 + len(element.name) - len(element.local)
    return [(start, start + len(element.local), name.encode("ascii"))]


def _remove_element(data: bytes, element: Element) -> Edit:
    begin = element.start
    while data[begin - 1 : begin] in (b" ", b"\t"):
        begin -= 1
    end = element.end
    if data[begin - 1 : begin] == b"\n" and data[end : end + 1] in (b"\n", b"\r"):
        begin -= 1
    return (begin, end, b"")


def _text(device: Device, owner: Object, var: Variable, field: str) -> str | None:
    value = getattr(var, field, None)
    if value is None:
        return None
    if field in ("default", "low_limit", "high_limit", "parameter_value"):
        return format_value(value, device.entry_type(var, owner), Dialect.CIA306, as_written=True)
    if field == "access":
        return str(value.value)
    if field == "pdo_mapping":
        return pdo_mapping_text(var)
    if field in ("data_type", "obj_flags"):
        return f"{value:04X}"
    if field == "object_type":
        return str(int(value))
    return str(value)
