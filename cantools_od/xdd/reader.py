"""XDD/XDC (CiA 311) bytes → Device. Never raises on content; problems become diagnostics.

Both CiA 311 namespaces (1.0, 1.1) and files without one are read by local
element names. What the model has no field for is kept: attributes of known
elements in the part's `extra` (as `Element.attribute`), whole elements as
`XDD.<path>` raw sections holding the element as one line of XML.
"""

from __future__ import annotations

from typing import Any

from ..eds.keys import MAX_DIGITS, is_decimal
from ..eds.report import Report
from ..model import Commissioning, Device, Dialect, DummyUsage, RawSection
from ..model.assemble import fresh
from . import RAW_PREFIX as RAW_PREFIX
from . import REFUSED_CODES as REFUSED_CODES
from . import compact_marks, file_comments  # where writers and tests have always found them
from . import refused as refused
from .context import ReadContext
from .fragments import fragment, one_line
from .objects import ObjectReader
from .safe import Element, XmlRefused, parse, utf8_form
from .vocabulary import KNOWN_ELEMENTS, NAMESPACES, XSI, standard_header

_FILE_ATTRIBUTES = {
    "fileName": ("file_name", "FileName"),
    "fileCreator": ("created_by", "CreatedBy"),
    "fileCreationDate": ("creation_date", "CreationDate"),
    "fileCreationTime": ("creation_time", "CreationTime"),
    "fileModifiedBy": ("modified_by", "ModifiedBy"),
    "fileModificationDate": ("modification_date", "ModificationDate"),
    "fileModificationTime": ("modification_time", "ModificationTime"),
}
_IDENTITY = {
    "vendorName": ("vendor_name", "VendorName", False),
    "vendorID": ("vendor_number", "VendorNumber", True),
    "productName": ("product_name", "ProductName", False),
    "productID": ("product_number", "ProductNumber", True),
    "orderNumber": ("order_code", "OrderCode", False),
    "revisionNumber": ("revision_number", "RevisionNumber", True),
}
_FEATURES = {
    "granularity": ("granularity", "Granularity", int),
    "nrOfRxPDO": ("nr_of_rx_pdo", "NrOfRXPDO", int),
    "nrOfTxPDO": ("nr_of_tx_pdo", "NrOfTXPDO", int),
    "layerSettingServiceSlave": ("lss_supported", "LSS_Supported", bool),
    "groupMessaging": ("group_messaging", "GroupMessaging", bool),
    "dynamicChannels": ("dynamic_channels_supported", "DynamicChannelsSupported", int),
    "bootUpSlave": ("simple_boot_up_slave", "SimpleBootUpSlave", bool),
    "bootUpMaster": ("simple_boot_up_master", "SimpleBootUpMaster", bool),
}
# CiA 311's defaults for the attributes of these elements, which hold when the element is present.
FEATURE_DEFAULTS: dict[str, dict[str, object]] = {
    "CANopenGeneralFeatures": {
        "groupMessaging": False,
        "dynamicChannels": 0,
        "bootUpSlave": False,
        "layerSettingServiceSlave": False,
        "nrOfRxPDO": 0,
        "nrOfTxPDO": 0,
    },
    "CANopenMasterFeatures": {"bootUpMaster": False},
}
_COMMISSIONING = {
    "nodeID": ("node_id", "NodeID", int),
    "nodeName": ("node_name", "NodeName", str),
    "actualBaudRate": ("baudrate", "Baudrate", "baud"),
    "networkNumber": ("net_number", "NetNumber", int),
    "networkName": ("network_name", "NetworkName", str),
    "CANopenManager": ("canopen_manager", "CANopenManager", bool),
}


def read_bytes(data: bytes, file: str = "", node_id: int | None = None, dcf: bool | None = None) -> Device:
    return read_with_context(data, file, node_id, dcf)[0]


def read_with_context(
    data: bytes, file: str = "", node_id: int | None = None, dcf: bool | None = None
) -> tuple[Device, ReadContext]:
    """The device, and where each of its parts is written (for the preserving writer)."""
    report = Report(file)
    device = Device.model_construct(source=file, file_format="xdd")  # validation would build the schema: slow
    device.diagnostics = report.diagnostics  # the report keeps adding to this list
    ctx = ReadContext(utf8_form(data), file, report)
    try:
        root = parse(ctx.data)
    except XmlRefused as refused:
        report.error(refused.code, str(refused), *ctx.positions.at(refused.offset))
        device._original = data  # so writing it back unchanged gives these bytes, never an empty device
        return device, ctx
    _Document(ctx, device).read(root)
    if any(var.canopennode for obj in device.objects.values() for var in (obj, *obj.subs.values())):
        device.dialect = Dialect.CANOPENNODE  # as in the EDS CANopenEditor exports from such a project
    if dcf is not None:
        device.is_dcf = dcf
    elif file.lower().endswith(".xdc") or device.commissioning is not None:
        device.is_dcf = True
    if node_id is not None:
        device.node_id = node_id
    device._original = data
    return device, ctx


def parse_number(text: str) -> int | None:
    """A decimal or `0x` hex number; None for anything else, a number longer than any type needs included."""
    text = text.strip()
    if len(text) > MAX_DIGITS:
        return None
    try:
        return int(text, 16) if text[:2].lower() == "0x" else int(text)
    except ValueError:
        return None


def _baud(text: str) -> int | None:
    head = text.strip().lower().removesuffix("kbps").strip()
    return parse_number(head)


class _Document:
    def __init__(self, ctx: ReadContext, device: Device) -> None:
        self.ctx = ctx
        self.device = device
        self.parameters: dict[str, Element] = {}
        self.objects = ObjectReader(ctx, device, self.parameters)
        self.raw_parameters: list[Element] = []

    def read(self, root: Element) -> None:
        ctx = self.ctx
        if root.local != "ISO15745ProfileContainer":
            ctx.error("XDD004", f"root element is <{root.local}>, not a CiA 311 <ISO15745ProfileContainer>", root)
        if root.ns not in NAMESPACES:
            why = "no namespace" if not root.ns else f"namespace {root.ns!r}"
            ctx.warning("XDD005", f"<{root.local}> has {why}; CiA 311 uses {NAMESPACES[1]!r}", root)
        for element in root.walk():
            if element.local == "parameter" and "uniqueID" in element.attrs:
                unique = element.attrs["uniqueID"]
                if unique in self.parameters:
                    ctx.error("XDD008", f"parameter uniqueID {unique!r} given again; the first is used", element)
                    continue
                self.parameters[unique] = element
        bodies = [e for e in root.walk() if e.local == "ProfileBody"]
        for profile in root.all("ISO15745Profile"):
            self._profile(profile)
        for element in root.children:
            if element.local != "ISO15745Profile":
                self._raw(element, "")
        self.objects.type_values()
        if bodies:
            self._file_info(bodies)
        self._unused_parameters()
        marked = [(offset, text) for offset, text in root.prologue if file_comments.marked(text)]
        if marked:
            line = ctx.positions.at(marked[0][0])[0]
            self.device.comments = file_comments.read_comment_block(marked[0][1], line, ctx.report)
        compact = [text for _, text in root.prologue if compact_marks.marked(text)]
        if compact:  # the compact forms of the EDS this was written from (see compact_marks)
            compact_marks.restore_compact(self.device, compact[0])
        if self.device.commissioning is not None:
            self.device.node_id = self.device.commissioning.node_id

    def _kind(self, profile: Element) -> str:
        body = profile.child("ProfileBody")
        kind = body.attrs.get("xsi:type", "") if body is not None else ""
        for key, value in body.attrs.items() if body is not None else ():
            if key.endswith(":type") and key != "xsi:type" and value:
                kind = value
        if "CommunicationNetwork" in kind or (body is not None and body.child("ApplicationLayers") is not None):
            return "CommunicationNetwork"
        return "Device"

    def _profile(self, profile: Element) -> None:
        kind = self._kind(profile)
        for element in profile.children:
            if element.local == "ProfileBody":
                self._body(element, kind)
            else:
                self._raw(element, kind)

    def _body(self, body: Element, kind: str) -> None:
        handlers = {
            "DeviceIdentity": self._identity,
            "ApplicationProcess": self._application_process,
            "ApplicationLayers": self._application_layers,
            "TransportLayers": self._transport_layers,
            "NetworkManagement": self._network_management,
        }
        for element in body.children:
            handle = handlers.get(element.local)
            if handle is None:
                self._raw(element, f"{kind}")
            else:
                handle(element, f"{kind}.{element.local}")

    def _raw(self, element: Element, path: str) -> None:
        if element.local not in KNOWN_ELEMENTS:
            self.ctx.warning("XDD010", f"unknown element <{element.local}>; kept", element)
        text = fragment(element)
        if element.local == "ProfileHeader" and text == standard_header(path):
            return  # the header every CANopen profile has: the writers write it again
        name = f"{RAW_PREFIX}{path}.{element.local}" if path else f"{RAW_PREFIX}{element.local}"
        section = fresh(RawSection, {"name": name, "entries": {"xml": text}, "origin": self.ctx.origin(element)})
        self.device.other_sections.append(section)

    def _file_info(self, bodies: list[Element]) -> None:
        body = next((b for b in bodies if b.child("DeviceIdentity") is not None), bodies[0])
        info = self.device.file_info
        origin = self.ctx.origin(body)
        fields: dict[str, Any] = {}
        for attr, text in body.attrs.items():
            if attr in _FILE_ATTRIBUTES:
                field, key = _FILE_ATTRIBUTES[attr]
                fields[field] = text
                self.ctx.mark(origin, key, body, attr)
            elif attr == "fileVersion" and is_decimal(text):
                fields["file_version"] = int(text)
                self.ctx.mark(origin, "FileVersion", body, attr)
            elif not attr.startswith("xmlns") and attr != "xsi:type":
                info.extra[f"ProfileBody.{attr}"] = text
        for key, value in fields.items():
            setattr(info, key, value)
        info.origin = origin

    def _identity(self, identity: Element, path: str) -> None:
        info = self.device.device_info
        origin = info.origin = self.ctx.origin(identity)
        for element in identity.children:
            spec = _IDENTITY.get(element.local)
            if spec is not None and not element.children:
                field, key, numeric = spec
                text = element.text.strip()
                value: Any = parse_number(text) if numeric else element.text
                if numeric and value is None and text:
                    self.ctx.warning("XDD007", f"<{element.local}>{text}</{element.local}> is not a number", element)
                    info.extra[f"DeviceIdentity.{element.local}"] = text
                    continue
                setattr(info, field, value)
                self.ctx.mark(origin, key, element)
            elif element.local == "productText" and element.child("description") is not None:
                description = element.child("description")
                assert description is not None
                self.device.file_info.description = one_line(description.text)
                if len(element.children) > 1:
                    self._raw(element, path)
            else:
                self._raw(element, path)

    def _application_process(self, process: Element, path: str) -> None:
        for element in process.children:
            if element.local == "parameterList":
                self.raw_parameters.extend(element.all("parameter"))
                for child in element.children:
                    if child.local != "parameter":
                        self._raw(child, f"{path}.parameterList")
            elif element.local != "dataTypeList":
                self._raw(element, path)
            else:
                self._data_types(element, path)

    def _data_types(self, types: Element, path: str) -> None:
        """Array and struct types are rebuilt from the objects; other types are kept."""
        for element in types.children:
            if element.local not in ("array", "struct"):
                self._raw(element, f"{path}.dataTypeList")

    def _unused_parameters(self) -> None:
        for element in self.raw_parameters:
            if element.attrs.get("uniqueID") not in self.objects.used:
                self._raw(element, "Device.ApplicationProcess.parameterList")

    def _application_layers(self, layers: Element, path: str) -> None:
        for element in layers.children:
            if element.local == "CANopenObjectList":
                for attr, text in element.attrs.items():
                    if not attr.startswith("xmlns"):
                        self.device.device_info.extra[f"CANopenObjectList.{attr}"] = text
                for other in self.objects.read_list(element):
                    self._raw(other, f"{path}.CANopenObjectList")
            elif element.local == "dummyUsage":
                self._dummy_usage(element, path)
            else:
                self._raw(element, path)

    def _dummy_usage(self, usage: Element, path: str) -> None:
        section = self.device.dummy_usage or fresh(DummyUsage, {"origin": self.ctx.origin(usage)})
        self.device.dummy_usage = section
        assert section.origin is not None
        for element in usage.children:
            entry = element.attrs.get("entry", "") if element.local == "dummy" else ""
            key, _, flag = entry.partition("=")
            if key.lower().startswith("dummy") and flag.strip() in ("0", "1") and _hex(key[5:]) is not None:
                index = _hex(key[5:])
                assert index is not None
                section.enabled[index] = flag.strip() == "1"
                self.ctx.mark(section.origin, f"Dummy{index:04X}", element, "entry")
            else:
                if element.local == "dummy":
                    self.ctx.warning("XDD007", f"dummy entry={entry!r} is not DummyXXXX=0|1; kept", element, "entry")
                self._raw(element, f"{path}.dummyUsage")

    def _transport_layers(self, layers: Element, path: str) -> None:
        info = self.device.device_info
        for physical in layers.children:
            if physical.local != "PhysicalLayer":
                self._raw(physical, path)
                continue
            for element in physical.children:
                if element.local != "baudRate":
                    self._raw(element, f"{path}.PhysicalLayer")
                    continue
                if "defaultValue" in element.attrs:
                    info.extra["baudRate.defaultValue"] = element.attrs["defaultValue"]
                for rate in element.children:
                    self._baud_rate(rate, f"{path}.PhysicalLayer.baudRate")

    def _baud_rate(self, element: Element, path: str) -> None:
        info = self.device.device_info
        value = element.attrs.get("value", "") if element.local == "supportedBaudRate" else ""
        kbits = _baud(value)
        if kbits is None:
            if value.replace("-", "").lower() == "autobaudrate":
                info.extra["supportedBaudRate.auto"] = value
                return
            self._raw(element, path)
            return
        info.baud_rates[kbits] = True
        if info.origin is not None:
            self.ctx.mark(info.origin, f"BaudRate_{kbits}", element, "value")

    def _network_management(self, management: Element, path: str) -> None:
        for element in management.children:
            if element.local in ("CANopenGeneralFeatures", "CANopenMasterFeatures"):
                self._features(element)
            elif element.local == "deviceCommissioning":
                self._commissioning(element)
            else:
                self._raw(element, path)

    def _features(self, element: Element) -> None:
        info = self.device.device_info
        if info.origin is None:
            info.origin = self.ctx.origin(element)
        for attr, text in element.attrs.items():
            spec = _FEATURES.get(attr)
            value = _typed(text, spec[2]) if spec is not None else None
            if spec is None or value is None:
                if spec is not None:
                    self.ctx.warning("XDD007", f"{attr}={text!r} cannot be read; kept as text", element, attr)
                info.extra[f"{element.local}.{attr}"] = text
                continue
            setattr(info, spec[0], value)
            self.ctx.mark(info.origin, spec[1], element, attr)
        for attr, value in FEATURE_DEFAULTS.get(element.local, {}).items():
            if attr not in element.attrs:
                setattr(info, _FEATURES[attr][0], value)  # the schema's default for an absent attribute

    def _commissioning(self, element: Element) -> None:
        origin = self.ctx.origin(element)
        fields: dict[str, Any] = {}
        extra: dict[str, str] = {}
        for attr, text in element.attrs.items():
            spec = _COMMISSIONING.get(attr)
            value = _typed(text, spec[2]) if spec is not None else None
            if spec is None or value is None:
                extra[attr] = text
                continue
            fields[spec[0]] = value
            self.ctx.mark(origin, spec[1], element, attr)
        self.device.commissioning = fresh(Commissioning, {**fields, "extra": extra, "origin": origin})


def _typed(text: str, kind: object) -> Any:
    if kind is bool:
        return {"true": True, "false": False, "1": True, "0": False}.get(text.strip())
    if kind is int:
        return parse_number(text)
    if kind == "baud":
        return _baud(text)
    return text


def _hex(text: str) -> int | None:
    try:
        return int(text, 16) if len(text) == 4 else None
    except ValueError:
        return None


__all__ = ["XSI", "read_bytes"]
