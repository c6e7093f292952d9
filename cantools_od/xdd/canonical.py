"""Device → canonical CiA 311 v1.1 XDD/XDC text.

The layout is the one CANopenEditor reads and writes (and so CANopenNode users
keep in their projects): each object's data in an ApplicationProcess
`parameter` that its CANopenObject names by `uniqueIDRef`, CANopenNode
`property` elements, array and struct types in the dataTypeList. Types CiA 311
has no element for are written as BITSTRING with the exact CiA 301 type in the
object's `dataType` attribute. Kept fragments go back where they were read;
output is deterministic and reading it back gives the same text again.
"""

from __future__ import annotations

import re
from collections import defaultdict
from collections.abc import Sequence

from ..canopennode.info import PROPERTIES
from ..eds.format import DECIMAL_INTEGER, format_value
from ..eds.hints import Hints
from ..model import AccessType, Commissioning, Device, Dialect, Object, ObjectKind, Variable
from .compact_marks import compact_block
from .file_comments import comment_block
from .fragments import restore
from .reader import FEATURE_DEFAULTS, RAW_PREFIX
from .vocabulary import ACCESS_NAME, EDS_PROPERTY, ELEMENT_OF_TYPE, NS_1_1, XSI, standard_header
from .xmltext import escape, quoteattr

_TEXT = {"\n": "&#10;", "\r": "&#13;"}
_ILLEGAL = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ud800-\udfff\ufffe\uffff]")
_FILE_ATTRIBUTES = (
    ("fileName", "file_name"),
    ("fileCreator", "created_by"),
    ("fileCreationDate", "creation_date"),
    ("fileCreationTime", "creation_time"),
    ("fileModifiedBy", "modified_by"),
    ("fileModificationDate", "modification_date"),
    ("fileModificationTime", "modification_time"),
)
_GENERAL = (
    ("granularity", "granularity"),
    ("nrOfRxPDO", "nr_of_rx_pdo"),
    ("nrOfTxPDO", "nr_of_tx_pdo"),
    ("layerSettingServiceSlave", "lss_supported"),
    ("groupMessaging", "group_messaging"),
    ("dynamicChannels", "dynamic_channels_supported"),
    ("bootUpSlave", "simple_boot_up_slave"),
)
_COMMISSIONING = (
    ("nodeID", "node_id"),
    ("nodeName", "node_name"),
    ("actualBaudRate", "baudrate"),
    ("networkNumber", "net_number"),
    ("networkName", "network_name"),
    ("CANopenManager", "canopen_manager"),
)
# extra keys the reader fills from things this writer writes itself
_HANDLED_EXTRA = ("Description", "label", "dataTypeIDRef", "access", "PDOmapping")


def _attr(value: object) -> str:
    if isinstance(value, bool):
        return '"true"' if value else '"false"'
    return quoteattr(_legal(str(value)), _TEXT)


def _legal(text: str) -> str:
    """Text without the characters XML 1.0 cannot hold (control characters), which an EDS name may have."""
    return _ILLEGAL.sub("\ufffd", text)


def _text(text: str) -> str:
    return escape(_legal(text), _TEXT)


def _attrs(pairs: Sequence[tuple[str, object]]) -> str:
    """The attributes, each once: text kept because it could not be read (listed after the field it
    would have filled) takes the field's place, as XML allows an attribute only once."""
    chosen: dict[str, object] = {}
    for name, value in pairs:
        if value is not None:
            chosen[name] = value
    return "".join(f" {name}={_attr(value)}" for name, value in chosen.items())


class _Out:
    def __init__(self, device: Device) -> None:
        self.lines: list[str] = []
        self.hints = Hints.of(device)
        self.raw: dict[str, list[str]] = defaultdict(list)
        for section in device.other_sections:
            if section.name.startswith(RAW_PREFIX) and "xml" in section.entries:
                parent = section.name[len(RAW_PREFIX) :].rpartition(".")[0]
                self.raw[parent].append(section.entries["xml"])

    def add(self, depth: int, text: str) -> None:
        self.lines.append("  " * depth + text)

    def kept(self, depth: int, path: str) -> None:
        for text in self.raw.pop(path, []):
            self.add(depth, text)


def canonical_xml(device: Device, xdc: bool = False) -> str:
    out = _Out(device)
    out.lines.append('<?xml version="1.0" encoding="utf-8"?>')
    if device.comments is not None:  # CiA 311 has no element for them: an XML comment (see file_comments)
        out.lines.append(comment_block(device.comments))
    compact = compact_block(device)
    if compact is not None:  # nor for an EDS's CompactSubObj form: an XML comment too (see compact_marks)
        out.lines.append(compact)
    out.add(0, f'<ISO15745ProfileContainer xmlns:xsi="{XSI}" xmlns="{NS_1_1}">')
    _device_profile(out, device)
    _network_profile(out, device, xdc)
    for path in sorted(out.raw):  # fragments from places this layout has not: kept at the end
        for text in out.raw[path]:
            out.add(1, text)
    out.add(0, "</ISO15745ProfileContainer>")
    return "\n".join(out.lines) + "\n"


def _header(out: _Out, kind: str) -> None:
    kept = [text for text in out.raw.get(kind, []) if text.startswith("<ProfileHeader")]
    if kept:
        out.raw[kind].remove(kept[0])
    out.add(2, kept[0] if kept else standard_header(kind))


def _body_attributes(device: Device) -> str:
    info = device.file_info
    pairs: list[tuple[str, object]] = [(name, getattr(info, field)) for name, field in _FILE_ATTRIBUTES]
    pairs.append(("fileVersion", info.file_version))
    pairs += [(key[12:], value) for key, value in info.extra.items() if key.startswith("ProfileBody.")]
    return _attrs(pairs)


def _device_profile(out: _Out, device: Device) -> None:
    out.add(1, "<ISO15745Profile>")
    _header(out, "Device")
    attributes = f'xsi:type="q1:ProfileBody_Device_CANopen"{_body_attributes(device)}'
    out.add(2, f'<ProfileBody xmlns:q1="{NS_1_1}" {attributes} xmlns="">')
    _identity(out, device)
    out.kept(3, "Device")
    out.add(3, "<q1:ApplicationProcess>")
    out.add(4, "<q1:dataTypeList>")
    for obj in device.objects.values():
        _data_type(out, device, obj)
    out.kept(5, "Device.ApplicationProcess.dataTypeList")
    out.add(4, "</q1:dataTypeList>")
    out.add(4, "<q1:parameterList>")
    for obj in device.objects.values():
        _parameter(out, device, obj, obj, f"UID_OBJ_{obj.index:04X}")
        for subindex, sub in obj.subs.items():
            _parameter(out, device, sub, obj, f"UID_SUB_{obj.index:04X}{subindex:02X}")
    out.kept(5, "Device.ApplicationProcess.parameterList")
    out.add(4, "</q1:parameterList>")
    out.kept(4, "Device.ApplicationProcess")
    out.add(3, "</q1:ApplicationProcess>")
    out.add(2, "</ProfileBody>")
    out.add(1, "</ISO15745Profile>")


def _identity(out: _Out, device: Device) -> None:
    info = device.device_info
    out.add(3, "<q1:DeviceIdentity>")
    for element, value in (
        ("vendorName", info.vendor_name),
        ("vendorID", None if info.vendor_number is None else f"0x{info.vendor_number:08X}"),
        ("productName", info.product_name),
        ("productID", None if info.product_number is None else f"0x{info.product_number:08X}"),
        ("orderNumber", info.order_code),
        ("revisionNumber", None if info.revision_number is None else f"0x{info.revision_number:08X}"),
    ):
        kept = info.extra.get(f"DeviceIdentity.{element}")
        text = value if value is not None else kept
        if text is not None:
            out.add(4, f"<q1:{element}>{_text(text)}</q1:{element}>")
    if device.file_info.description is not None:
        description = _text(restore(device.file_info.description))
        out.add(4, f'<q1:productText><description lang="en">{description}</description></q1:productText>')
    out.kept(4, "Device.DeviceIdentity")
    out.add(3, "</q1:DeviceIdentity>")


def _type_element(var: Variable) -> str:
    return ELEMENT_OF_TYPE.get(var.data_type or -1, "BITSTRING")


def _data_type(out: _Out, device: Device, obj: Object) -> None:
    name = _attr(obj.name)
    if obj.kind is ObjectKind.ARRAY and obj.subs:
        element = next((s for i, s in obj.subs.items() if i > 0), None)
        out.add(5, f'<q1:array name={name} uniqueID="UID_ARR_{obj.index:04X}">')
        out.add(6, f'<q1:subrange lowerLimit="0" upperLimit="{max(obj.subs)}" />')
        out.add(6, f"<{_type_element(element or obj)} />")
        out.add(5, "</q1:array>")
    elif obj.kind in (ObjectKind.RECORD, ObjectKind.DEFSTRUCT) and obj.subs:
        out.add(5, f'<q1:struct name={name} uniqueID="UID_REC_{obj.index:04X}">')
        for subindex, sub in obj.subs.items():
            unique = f"UID_RECSUB_{obj.index:04X}{subindex:02X}"
            out.add(6, f"<q1:varDeclaration name={_attr(sub.name)} uniqueID={_attr(unique)}>")
            out.add(7, f"<{_type_element(sub)} />")
            out.add(6, "</q1:varDeclaration>")
        out.add(5, "</q1:struct>")


def _value(out: _Out, device: Device, var: Variable, owner: Object, value: object, key: str) -> str:
    """A value as CiA 311 writes it: decimal REALs, but a REAL the source wrote as an integer stays one
    (python-canopen reads REAL limits with `int()`; an EDS written from this XDD keeps the integer)."""
    dtype = device.entry_type(var, owner)
    hint = out.hints.text(var, key) if isinstance(value, float) else None
    kept = hint if hint is not None and DECIMAL_INTEGER.match(hint) else None
    return format_value(value, dtype, Dialect.CIA306, hint=kept)  # type: ignore[arg-type]


def _parameter(out: _Out, device: Device, var: Variable, owner: Object, unique: str) -> None:
    access = var.access
    kept = var.extra.get("access") if access is None else None  # e.g. noAccess: no SDO reaches the entry
    if access is None and kept is None and not (var is owner and owner.has_subs):
        access = AccessType.RO  # CiA 311's default, written out so the text reads back the same
    pairs: list[tuple[str, object]] = [("uniqueID", unique), ("access", ACCESS_NAME.get(access) if access else kept)]
    pairs += [(key[10:], value) for key, value in var.extra.items() if key.startswith("parameter@")]
    out.add(5, f"<q1:parameter{_attrs(pairs)}>")
    label = restore(var.extra["label"]) if "label" in var.extra else var.name  # only kept labels are escaped
    out.add(6, f'<label lang="en">{_text(label)}</label>')
    if "Description" in var.extra:
        out.add(6, f'<description lang="en">{_text(restore(var.extra["Description"]))}</description>')
    if var is owner and owner.has_subs:
        kind = "ARR" if owner.kind is ObjectKind.ARRAY else "REC"
        out.add(6, f'<q1:dataTypeIDRef uniqueIDRef="UID_{kind}_{owner.index:04X}" />')
    elif var.data_type is not None:
        out.add(6, f"<{_type_element(var)} />")
    elif "dataTypeIDRef" in var.extra:
        out.add(6, f"<q1:dataTypeIDRef uniqueIDRef={_attr(var.extra['dataTypeIDRef'])} />")
    if var.denotation is not None:
        out.add(6, f'<q1:denotation><label lang="en">{_text(var.denotation)}</label></q1:denotation>')
    for element, value, key in (
        ("actualValue", var.parameter_value, "ParameterValue"),
        ("defaultValue", var.default, "DefaultValue"),
    ):
        if value is not None:
            out.add(6, f"<q1:{element} value={_attr(_value(out, device, var, owner, value, key))} />")
        elif _kept_empty(var, key):
            out.add(6, f'<q1:{element} value="" />')
    _limits(out, device, var, owner)
    for key, text in var.extra.items():
        if key.startswith("parameter.") and text.startswith("<"):
            out.add(6, text)
    _properties(out, var)
    out.add(5, "</q1:parameter>")


def _kept_empty(var: Variable, key: str) -> bool:
    """Whether the source gave `key` with an empty value: kept as an empty attribute, as the EDS writer keeps
    `DefaultValue=` (peers read it as an empty string, not as absent)."""
    return var.origin is not None and var.origin.where(key) is not None and key not in var.extra


def _limits(out: _Out, device: Device, var: Variable, owner: Object) -> None:
    if var.low_limit is None and var.high_limit is None:
        return
    out.add(6, "<q1:allowedValues>")
    out.add(7, "<q1:range>")
    for element, value, key in (("minValue", var.low_limit, "LowLimit"), ("maxValue", var.high_limit, "HighLimit")):
        if value is not None:
            out.add(8, f"<{element} value={_attr(_value(out, device, var, owner, value, key))} />")
    out.add(7, "</q1:range>")
    out.add(6, "</q1:allowedValues>")


def _properties(out: _Out, var: Variable) -> None:
    info = var.canopennode
    if info is not None:  # most entries have none
        for name, field in PROPERTIES.items():
            value = getattr(info, field)
            if value is not None:
                text = _attr(value.value if hasattr(value, "value") else value)
                out.add(6, f'<q1:property name="{name}" value={text} />')
    for key, text in var.extra.items():
        if key.startswith("property."):
            out.add(6, f"<q1:property name={_attr(key[9:])} value={_attr(text)} />")
        elif _eds_only(key):
            out.add(6, f"<q1:property name={_attr(EDS_PROPERTY + key)} value={_attr(text)} />")


def _eds_only(key: str) -> bool:
    """An extra key from an EDS (no XML attribute or element of ours)."""
    if key in _HANDLED_EXTRA or key.startswith(("parameter", "property.", "<")):
        return False
    return not key[:1].islower()  # unknown XML attributes start in lower case, EDS keys do not


def pdo_mapping_text(var: Variable) -> str | None:
    if "PDOmapping" in var.extra and var.pdo_mapping is not None:
        return var.extra["PDOmapping"]
    return var.pdo_mapping_kind()


def _object_attributes(var: Variable, unique: str) -> list[tuple[str, object]]:
    pairs: list[tuple[str, object]] = [("name", var.name), ("objectType", None)]
    kind = var.object_type if hasattr(var, "object_type") else None
    pairs[1] = ("objectType", int(kind) if kind is not None else None)
    # an ARRAY/RECORD's parameter names its dataTypeList entry: its own DataType goes on the object
    grouped = isinstance(var, Object) and var.has_subs
    exact = var.data_type is not None and (grouped or var.data_type not in ELEMENT_OF_TYPE)
    pairs.append(("dataType", f"{var.data_type:04X}" if exact and var.data_type is not None else None))
    if var.obj_flags is not None:
        pairs.append(("objFlags", f"{var.obj_flags:04X}"))
    pairs.append(("PDOmapping", pdo_mapping_text(var)))
    pairs.append(("uniqueIDRef", unique))
    pairs += [(k, v) for k, v in var.extra.items() if k[:1].islower() and k not in _HANDLED_EXTRA and "." not in k]
    pairs = [(k, v) for k, v in pairs if not k.startswith(("parameter", "property", "<"))]
    return pairs


def _network_profile(out: _Out, device: Device, xdc: bool) -> None:
    out.add(1, "<ISO15745Profile>")
    _header(out, "CommunicationNetwork")
    attributes = f'xsi:type="q2:ProfileBody_CommunicationNetwork_CANopen"{_body_attributes(device)}'
    out.add(2, f'<ProfileBody xmlns:q2="{NS_1_1}" {attributes} xmlns="">')
    out.add(3, "<ApplicationLayers>")
    extra = device.device_info.extra
    list_attributes = [(k[18:], v) for k, v in extra.items() if k.startswith("CANopenObjectList.")]
    out.add(4, f"<q2:CANopenObjectList{_attrs(list_attributes)}>")
    for obj in device.objects.values():
        _object(out, obj)
    out.kept(5, "CommunicationNetwork.ApplicationLayers.CANopenObjectList")
    out.add(4, "</q2:CANopenObjectList>")
    if device.dummy_usage is not None:
        out.add(4, "<dummyUsage>")
        for index, enabled in sorted(device.dummy_usage.enabled.items()):
            out.add(5, f'<dummy entry="Dummy{index:04X}={int(enabled)}" />')
        out.kept(5, "CommunicationNetwork.ApplicationLayers.dummyUsage")
        out.add(4, "</dummyUsage>")
    out.kept(4, "CommunicationNetwork.ApplicationLayers")
    out.add(3, "</ApplicationLayers>")
    _transport(out, device)
    _management(out, device, xdc)
    out.kept(3, "CommunicationNetwork")
    out.add(2, "</ProfileBody>")
    out.add(1, "</ISO15745Profile>")


def _object(out: _Out, obj: Object) -> None:
    pairs = [("index", f"{obj.index:04X}"), *_object_attributes(obj, f"UID_OBJ_{obj.index:04X}")]
    if obj.sub_number is not None or obj.has_subs:
        pairs.append(("subNumber", obj.sub_number if obj.sub_number is not None else len(obj.subs)))
    children = [text for key, text in obj.extra.items() if key.startswith("<")]
    if not obj.subs and not children:
        out.add(5, f"<CANopenObject{_attrs(pairs)} />")
        return
    out.add(5, f"<CANopenObject{_attrs(pairs)}>")
    for subindex, sub in obj.subs.items():
        sub_pairs = [
            ("subIndex", f"{subindex:02X}"),
            *_object_attributes(sub, f"UID_SUB_{obj.index:04X}{subindex:02X}"),
        ]
        out.add(6, f"<CANopenSubObject{_attrs(sub_pairs)} />")
    for text in children:
        out.add(6, text)
    out.add(5, "</CANopenObject>")


def _transport(out: _Out, device: Device) -> None:
    info = device.device_info
    rates = [rate for rate, supported in sorted(info.baud_rates.items()) if supported]
    default = info.extra.get("baudRate.defaultValue")
    out.add(3, "<TransportLayers>")
    out.add(4, "<PhysicalLayer>")
    out.add(5, f"<baudRate{_attrs([('defaultValue', default)])}>")
    for rate in rates:
        out.add(6, f'<supportedBaudRate value="{rate} Kbps" />')
    if "supportedBaudRate.auto" in info.extra:
        out.add(6, f"<supportedBaudRate value={_attr(info.extra['supportedBaudRate.auto'])} />")
    out.kept(6, "CommunicationNetwork.TransportLayers.PhysicalLayer.baudRate")
    out.add(5, "</baudRate>")
    out.kept(5, "CommunicationNetwork.TransportLayers.PhysicalLayer")
    out.add(4, "</PhysicalLayer>")
    out.kept(4, "CommunicationNetwork.TransportLayers")
    out.add(3, "</TransportLayers>")


def _stated(value: object, default: object) -> object:
    return default if value is None else value


def _management(out: _Out, device: Device, xdc: bool) -> None:
    info = device.device_info
    extra = info.extra
    # CiA 311's defaults are written out: the text then reads back to the device it was written from.
    defaults = FEATURE_DEFAULTS["CANopenGeneralFeatures"]
    general = [(name, _stated(getattr(info, field), defaults.get(name))) for name, field in _GENERAL]
    general += [(k[23:], v) for k, v in extra.items() if k.startswith("CANopenGeneralFeatures.")]
    master: list[tuple[str, object]] = [("bootUpMaster", info.simple_boot_up_master)]
    master += [(k[22:], v) for k, v in extra.items() if k.startswith("CANopenMasterFeatures.")]
    out.add(3, "<NetworkManagement>")
    out.add(4, f"<CANopenGeneralFeatures{_attrs(general)} />")
    if any(value is not None for _, value in master):  # a device that states nothing of a master has none
        out.add(4, f"<CANopenMasterFeatures{_attrs(master)} />")
    commissioning = device.commissioning
    if xdc and commissioning is None and device.node_id is not None:
        commissioning = Commissioning(node_id=device.node_id)  # an XDC made for one node
    if commissioning is not None:  # an .xdd may state one too (CANopenEditor's do): it reads back as configured
        pairs = [(name, getattr(commissioning, field)) for name, field in _COMMISSIONING]
        pairs = [(k, f"{v} Kbps" if k == "actualBaudRate" and v is not None else v) for k, v in pairs]
        pairs += list(commissioning.extra.items())
        out.add(4, f"<deviceCommissioning{_attrs(pairs)} />")
    out.kept(4, "CommunicationNetwork.NetworkManagement")
    out.add(3, "</NetworkManagement>")
