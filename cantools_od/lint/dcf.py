"""Rule family: dcf — DCF-only keys, Upload/DownloadFile, [DeviceComissioning] NodeID, modules (CiA 306 §5, §6)."""

from __future__ import annotations

import re
from collections.abc import Iterator

from ..eds.keys import is_decimal, plain_int
from ..model import AccessType, Device, Object, RawSection, Severity, Variable
from ..model.cia301.modules import has_module_section, object_section_name
from ..model.datatypes import DOMAIN
from . import examples as ex
from .common import checked_vars, file_start, given, invalid, where
from .rules import Clause, Context, Finding, Placement, rule

E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO


# ---- DCF -------------------------------------------------------------------------------------------------------

_DCF_KEYS = ("ParameterValue", "Denotation", "ParamRefd", "UploadFile", "DownloadFile")


@rule(
    "EDS050",
    W,
    "UploadFile/DownloadFile with a mismatching AccessType",
    """
UploadFile receives the content of a DOMAIN read from the device, so the object should be `ro`;
DownloadFile is written to the device, so the object should be `wo` (CiA 306 §5). lely forces
these access types and warns.""",
    (
        ex.NODE_5 + "[2F50]\nParameterName=Program\nObjectType=0x7\nDataType=0x000F\nAccessType=rw\nPDOMapping=0\n"
        "DownloadFile=firmware.bin"
    ),
    fixed=(
        ex.NODE_5 + "[2F50]\nParameterName=Program\nObjectType=0x7\nDataType=0x000F\nAccessType=wo\nPDOMapping=0\n"
        "DownloadFile=firmware.bin"
    ),
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "lely forces the access type and warns"),
)
def file_access(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var, domain in _with_files(ctx):
        if not domain:
            continue  # EDS051
        access = var.access.value if var.access is not None else "rw"
        for key, path, wanted in (("UploadFile", var.upload_file, "ro"), ("DownloadFile", var.download_file, "wo")):
            if path and access != wanted:
                message = f"{where(obj, subindex)}: {key} with AccessType {access}; expected {wanted}"
                yield ctx.report("EDS050", message, ctx.at(var, key))


def _with_files(ctx: Context) -> Iterator[tuple[Object, int | None, Variable, bool]]:
    """Each entry that names an UploadFile or DownloadFile, and whether it is a DOMAIN: the data type is looked up
    for these few entries only."""
    for obj, subindex, var in checked_vars(ctx):
        if var.upload_file or var.download_file:
            yield obj, subindex, var, _domain(ctx.device, obj, var)


def _domain(device: Device, obj: Object, var: Variable) -> bool:
    dtype = device.entry_type(var, obj)
    return dtype is not None and dtype.index == DOMAIN.index


@rule(
    "EDS051",
    E,
    "UploadFile/DownloadFile on an entry that is not a DOMAIN",
    """
UploadFile and DownloadFile name files that hold the content of a DOMAIN (ObjectType 0x2 or
DataType 0x000F); other entries have a value of their data type.""",
    (
        ex.NODE_5 + "[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=ro\nDefaultValue=0\n"
        "PDOMapping=0\nUploadFile=speed.bin"
    ),
    fixed=(
        ex.NODE_5 + "[2000]\nParameterName=Speed log\nObjectType=0x7\nDataType=0x000F\nAccessType=ro\nPDOMapping=0\n"
        "UploadFile=speed.bin"
    ),
    per_object=True,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "the file names a DOMAIN's content for an entry that has a value of its own type"
    ),
)
def file_domain(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var, domain in _with_files(ctx):
        if domain:
            continue
        for key, path in (("UploadFile", var.upload_file), ("DownloadFile", var.download_file)):
            if path:
                message = f"{where(obj, subindex)}: {key} on an entry that is not a DOMAIN"
                yield ctx.report("EDS051", message, ctx.at(var, key))


@rule(
    "EDS052",
    W,
    "DCF-only key in an EDS",
    """
ParameterValue, Denotation, ParamRefd, UploadFile and DownloadFile (and LastEDS in [FileInfo])
describe one configured node and belong in a DCF (CiA 306 §5). In an EDS, tools ignore them
or take them for the device's defaults.""",
    "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\nParameterValue=100",
    fixed="[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=100\nPDOMapping=0",
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "tools ignore the DCF-only key in an EDS, or take it for a default"),
)
def dcf_keys(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    if device.is_dcf:
        return
    if device.file_info.last_eds:
        yield ctx.report("EDS052", "LastEDS in an EDS", ctx.at(device.file_info, "LastEDS"))
    for obj, subindex, var in checked_vars(ctx):
        for key in _DCF_KEYS:
            if given(var, key):
                yield ctx.report("EDS052", f"{where(obj, subindex)}: {key} in an EDS", ctx.at(var, key))


@rule(
    "EDS060",
    E,
    "DCF without [DeviceComissioning] NodeID",
    """
A DCF describes one configured node: [DeviceComissioning] (spelled with one "m") gives its
NodeID, and `$NODEID` values are resolved with it. Without it the DCF's COB-IDs are unknown;
lely dcfchk fails with `$NODEID not defined` unless a node-ID is given on the command line.""",
    "[DeviceComissioning]\nNodeName=Drive\nBaudrate=500",
    fixed="[DeviceComissioning]\nNodeID=5\nNodeName=Drive\nBaudrate=500",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "lely dcfchk fails with `$NODEID not defined`; the COB-IDs are unknown"),
)
def dcf_node_id(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    if not device.is_dcf:
        return
    section = device.commissioning
    if section is None:
        yield ctx.report("EDS060", "DCF without [DeviceComissioning]", file_start(ctx))
    elif section.node_id is None and not invalid(section, "NodeID"):
        yield ctx.report("EDS060", "[DeviceComissioning] has no NodeID", ctx.at(section, "NodeID"))


@rule(
    "EDS064",
    E,
    "Constant entry with another ParameterValue",
    """
A `const` entry holds its DefaultValue for ever: no SDO writes it, and the device reports that
value whatever the DCF says. A ParameterValue that differs is not what the device holds: a tool
that configures from the DCF fails on the write (abort 0601 0002h), and one that reads the DCF
as the device's state reads a value the device never has.""",
    lambda: ex.NODE_5 + ex.var(0x2000, "Build", 0x0007, "const", 7, 0) + "ParameterValue=8\n",
    fixed=lambda: ex.NODE_5 + ex.var(0x2000, "Build", 0x0007, "const", 7, 0) + "ParameterValue=7\n",
    placed=Placement(
        Clause.DEVICE_MISBEHAVES,
        "a configuring master's write fails (abort 0601 0002h); the device holds another value",
    ),
)
def const_parameter_value(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var in checked_vars(ctx):
        if var.access is not AccessType.CONST or var.parameter_value is None or var.default is None:
            continue
        configured, held = ctx.device.resolve(var.parameter_value), ctx.device.resolve(var.default)
        if configured != held:
            message = f"{where(obj, subindex)} is const: ParameterValue={configured!r}, but it holds {held!r}"
            yield ctx.report("EDS064", message, ctx.value_at(var, "ParameterValue"))


@rule(
    "EDS062",
    E,
    "NodeID outside 1..127",
    """
CANopen node-IDs are 1..127. lely also writes 255 for "not configured", and CANopenEditor a
`<deviceCommissioning nodeID="0">` in a device description (.xdd): both are EDS063.""",
    "[DeviceComissioning]\nNodeID=128",
    fixed="[DeviceComissioning]\nNodeID=127",
    placed=Placement(Clause.DEVICE_MISBEHAVES, "no CANopen node can have this node-ID"),
)
def node_id_range(ctx: Context) -> Iterator[Finding]:
    section = ctx.device.commissioning
    node_id = section.node_id if section is not None else None
    if _placeholder(ctx):
        return  # EDS063
    if section is not None and node_id is not None and not 1 <= node_id <= 127 and node_id != 255:
        yield ctx.report("EDS062", f"NodeID={node_id} is not a node-ID (1..127)", ctx.value_at(section, "NodeID"))


@rule(
    "EDS063",
    INFO,
    "Node-ID not configured (NodeID 255, an XDD's nodeID 0)",
    """
lely writes `NodeID=255` (0xFF) for a node whose node-ID is assigned later (LSS), and
CANopenEditor `<deviceCommissioning nodeID="0">` into every XDD device description it saves.
`$NODEID` values stay unresolved.""",
    "[DeviceComissioning]\nNodeID=0xFF",
    fixed="[DeviceComissioning]\nNodeID=5",
    placed=Placement(Clause.DECISION, "the node-ID is assigned later (LSS)"),
)
def node_id_unset(ctx: Context) -> Iterator[Finding]:
    section = ctx.device.commissioning
    if section is not None and section.node_id == 255:
        yield ctx.report("EDS063", "NodeID=255: node-ID not configured", ctx.value_at(section, "NodeID"))
    elif section is not None and _placeholder(ctx):
        message = 'nodeID="0" in a device description: a placeholder (CANopenEditor writes it), node-ID not configured'
        yield ctx.report("EDS063", message, ctx.value_at(section, "NodeID"))


def _placeholder(ctx: Context) -> bool:
    """An XDD device description (not an .xdc) whose deviceCommissioning says nodeID="0": CANopenEditor writes
    one into every project file it saves; no node is configured by it."""
    section, device = ctx.device.commissioning, ctx.device
    description = device.file_format == "xdd" and not device.source.lower().endswith(".xdc")
    return description and section is not None and section.node_id == 0


# ---- module concept --------------------------------------------------------------------------------------------

_MODULE_NAME = re.compile(r"m([1-9][0-9]{0,8})(moduleinfo|fixedobjects|subextends|fixed|subext)(.*)\Z", re.IGNORECASE)


def _count(raw: RawSection, key: str) -> int | None:
    for written, text in raw.entries.items():
        if written.lower() == key.lower():
            return plain_int(text)
    return None


def _listed(raw: RawSection) -> dict[str, str]:
    return {k: v for k, v in raw.entries.items() if is_decimal(k)}


@rule(
    "EDS070",
    E,
    "Module sections inconsistent",
    """
In the module concept (CiA 306 §6) [SupportedModules] NrOfEntries counts the modules
M1..Mn, each with an [M<x>ModuleInfo]; [M<x>FixedObjects] and [M<x>SubExtends] count their
numbered entries in NrOfEntries, and each listed index has its [M<x>Fixed<index>] or
[M<x>SubExt<index>] section (the index in hex without leading zeros, as for `[M3SubExtA0]`;
one written with them is accepted); [ConnectedModules] lists module numbers 1..n.""",
    "; also: DIA012 (any module section)\n[SupportedModules]\nNrOfEntries=2\n\n[M1ModuleInfo]\n"
    "ProductName=Input module",
    fixed="; also: DIA012 (any module section)\n[SupportedModules]\nNrOfEntries=1\n\n[M1ModuleInfo]\n"
    "ProductName=Input module",
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "module sections that do not add up: CANopenEditor reads other modules"
    ),
)
def modules(ctx: Context) -> Iterator[Finding]:
    sections = {raw.name.lower(): raw for raw in ctx.device.module_sections}
    supported = sections.get("supportedmodules")
    total = _count(supported, "NrOfEntries") if supported is not None else None
    infos = set()
    for raw in ctx.device.module_sections:
        match = _MODULE_NAME.match(raw.name)
        if match is None:
            continue
        number, part = int(match.group(1)), match.group(2).lower()
        if part == "moduleinfo":
            infos.add(number)
        if total is not None and number > total:
            yield ctx.report("EDS070", f"[{raw.name}]: module {number} but NrOfEntries={total}", ctx.at(raw))
        if part in ("fixedobjects", "subextends") and not match.group(3):
            yield from _module_list(ctx, raw, number, "Fixed" if part == "fixedobjects" else "SubExt")
    if supported is not None and total is not None:
        for number in sorted(set(range(1, total + 1)) - infos):
            yield ctx.report("EDS070", f"module {number}: no [M{number}ModuleInfo]", ctx.at(supported))
    for name in ("supportedmodules", "connectedmodules"):
        listing = sections.get(name)
        if listing is not None:
            yield from _counted(ctx, listing)
    connected = sections.get("connectedmodules")
    if connected is not None and total is not None:
        for key, text in _listed(connected).items():
            if not (is_decimal(text.strip()) and 1 <= int(text) <= total):
                message = f"[{connected.name}] {key}={text}: not a module number 1..{total}"
                yield ctx.report("EDS070", message, ctx.at(connected, key))


def _counted(ctx: Context, raw: RawSection) -> Iterator[Finding]:
    count, entries = _count(raw, "NrOfEntries"), _listed(raw)
    if raw.name.lower() != "supportedmodules" and count != len(entries):
        message = f"[{raw.name}]: NrOfEntries={count} but {len(entries)} entries"
        yield ctx.report("EDS070", message, ctx.at(raw, "NrOfEntries"))


def _module_list(ctx: Context, raw: RawSection, number: int, prefix: str) -> Iterator[Finding]:
    yield from _counted(ctx, raw)
    for key, text in _listed(raw).items():
        try:
            index = int(text.strip(), 0)
        except ValueError:
            yield ctx.report("EDS070", f"[{raw.name}] {key}={text}: not an object index", ctx.at(raw, key))
            continue
        if not has_module_section(ctx.device, number, prefix, index):  # CiA 306 spells [M3SubExtA0]
            message = f"[{raw.name}] {key}=0x{index:04X}: no [{object_section_name(number, prefix, index)}] section"
            yield ctx.report("EDS070", message, ctx.at(raw, key))
