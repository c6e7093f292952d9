"""Rule family: canopennode — what the CANopenNode v4 stack needs of an object dictionary.

These rules run only with `lint --profile canopennode` and whenever `gen -t canopennode` runs:
an error means the generated OD.h/OD.c would not compile, would trip one of CANopen.c's
`#error` checks, or would make `CO_CANopenInit` fail. None has an automatic fix: the right
change (a type, a count, an extra object) is a design decision. Settings an EDS cannot hold go
into `<stem>.canopennode.toml` beside it (see docs/canopennode.md).
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator

from ..canopennode.editor import editor_entry_type, editor_reads, pdo_bits_pair, sdo_directions
from ..canopennode.profile import (
    COMPANIONS,
    CONSECUTIVE,
    COUNT_LIMITS,
    HEARTBEAT_CONSUMERS,
    NODEID_AREAS,
    REQUIRED_COUNTS,
    SWITCHED_COMPANIONS,
    SWITCHED_COUNTS,
    StackConfig,
    StackSwitch,
    count_label_for,
    count_macro,
    pdo_attribute_text,
    standard_storage_group,
)
from ..model import DataType, Device, Location, NodeIdExpr, Object, ObjectKind, RawValue, Severity, ValueKind, Variable
from ..model.datatypes import DOMAIN, INDEX_BY_NAME, REAL32, UNSIGNED8
from . import examples as ex
from .rules import CANOPENNODE, Clause, Context, Finding, Placement, rule

E, W = Severity.ERROR, Severity.WARNING
PROFILE = CANOPENNODE
# Rule examples: an ARRAY of two INTEGER16 gains, its sub-index 0 and one gain.
_COUNT = ("Highest sub-index supported", UNSIGNED8.index, "ro", 2)
_GAIN = ("Gain", INDEX_BY_NAME["INTEGER16"], "rw", 0)


def _array() -> str:
    """The ARRAY 2000h of the examples below: two INTEGER16 gains."""
    return ex.record(0x2000, "Gains", {0: _COUNT, 1: _GAIN, 2: _GAIN}).replace("ObjectType=0x9", "ObjectType=0x8", 1)


_C_IDENTIFIER = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_SUPPORTED = (ObjectKind.VAR, ObjectKind.DOMAIN, ObjectKind.ARRAY, ObjectKind.RECORD)


def _objects(ctx: Context) -> Iterator[Object]:
    """The objects that go into the generated OD, when the profile is on."""
    if ctx.options.profile != PROFILE:
        return
    for _, obj in sorted(ctx.device.objects.items()):
        if obj.kind in _SUPPORTED and not obj.left_out:
            yield obj


def _entries(obj: Object) -> list[tuple[int, Variable]]:
    return sorted(obj.subs.items()) if obj.has_subs else [(0, obj)]


@rule(
    "CNO001",
    E,
    "Data type the stack cannot hold",
    """
Every entry of a CANopenNode object dictionary is stored in a C variable of its CiA 301 basic
type (BOOLEAN to UNSIGNED64, REAL32/64, the string types, TIME types, DOMAIN). An entry without
a DataType, with an unknown index or with a complex type (PDO_MAPPING, IDENTITY...) as its own
type cannot be laid out: the exporter has no C type for it. Fix: give the entry the basic type
it holds; there is no automatic fix.""",
    "[2000]\nParameterName=Mapping\nObjectType=0x7\nDataType=0x0021\nAccessType=rw",
    fixed="[2000]\nParameterName=Mapping\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "CANopenEditor's exporter has no C type for it"),
)
def unsupported_type(ctx: Context) -> Iterator[Finding]:
    for obj in _objects(ctx):
        for subindex, var in _entries(obj):
            dtype = editor_entry_type(ctx.device, var, obj)
            if dtype is None or dtype.kind is ValueKind.COMPLEX:
                what = f"DataType {var.data_type:#06x}" if var.data_type else "no DataType"
                what = f"type {dtype.name}" if dtype else what
                where = f"{obj.index:04X}h" + (f" sub{subindex:X}" if obj.has_subs else "")
                yield ctx.report("CNO001", f"{where} has {what}: CANopenNode has no C type for it",
                                 ctx.at(ctx.section_of(obj, var), "DataType"))  # fmt: skip


@rule(
    "CNO002",
    E,
    "Sub-index 0 of an ARRAY or RECORD is not UNSIGNED8",
    """
The stack keeps sub-index 0 of an ARRAY as `uint8_t` (`OD_obj_array_t.dataOrig0`) and reads it
as the number of entries; CiA 301 defines it as UNSIGNED8 too. Another type there makes the
generated data disagree with what the stack reads. Fix: DataType=0x0005 on sub-index 0.""",
    lambda: "; also: EDS025 (CiA 301 says the same)\n" + _array().replace("0x0005", "0x0007", 1),
    fixed=_array,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the stack reads sub-index 0 as uint8_t"),
)
def sub0_type(ctx: Context) -> Iterator[Finding]:
    for obj in _objects(ctx):
        sub0 = obj.subs.get(0)
        if obj.has_subs and sub0 is not None and sub0.data_type not in (None, UNSIGNED8.index):
            message = f"{obj.index:04X}h sub0 has DataType {sub0.data_type:#06x}, the stack needs UNSIGNED8"
            yield ctx.report("CNO002", message, ctx.at(ctx.section_of(obj, sub0), "DataType"))


@rule(
    "CNO003",
    E,
    "ARRAY elements differ in type or attribute",
    """
A CANopenNode ARRAY is one C array: one element type, one element size and one attribute
(`OD_obj_array_t.attribute`) for sub-indices 1 to n. Elements with another DataType than
sub-index 1, or an AccessType or PDOMapping that gives other ODA_* bits (`ro` and `const` give
the same), cannot be represented; the exporter would silently use sub-index 1's. Fix: make the
elements alike, or declare the object as a RECORD.""",
    lambda: _array().replace("AccessType=rw", "AccessType=ro", 2).replace("AccessType=ro", "AccessType=rw", 2),
    fixed=_array,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the exporter uses sub-index 1's type and attribute for every element"),
)
def array_elements(ctx: Context) -> Iterator[Finding]:
    for obj in _objects(ctx):
        if obj.kind is not ObjectKind.ARRAY or 1 not in obj.subs:
            continue
        first = obj.subs[1]
        for subindex, sub in sorted(obj.subs.items()):
            if subindex < 2:
                continue
            key = "DataType" if sub.data_type != first.data_type else None
            if key is None and _sdo(sub) != _sdo(first):
                key = "AccessType"
            elif key is None and pdo_bits_pair(sub)[0] != pdo_bits_pair(first)[0]:
                key = "PDOMapping"
            if key is not None:
                message = f"{obj.index:04X}h sub{subindex:X}: {key} differs from sub1's; an ARRAY has one"
                yield ctx.report("CNO003", message, ctx.at(ctx.section_of(obj, sub), key))


def _sdo(var: Variable) -> str:
    return sdo_directions(var.access.value if var.access else None)


@rule(
    "CNO004",
    E,
    "ARRAY sub-indices with gaps, or an ARRAY/RECORD without entries",
    """
The stack finds ARRAY element n at position n-1 of one C array and takes the number of
sub-entries from the OD list, so an ARRAY's sub-indices must run 0, 1, ... n without gaps. An
ARRAY with no element would be a zero-length C array, which C forbids, and a RECORD needs
sub-index 0 plus at least one member. Fix: add the missing sub-indices (or use a RECORD, whose
sub-indices may have gaps).""",
    lambda: ex.record(0x2000, "Gains", {0: (*_COUNT[:3], 3), 1: _GAIN, 3: _GAIN}).replace(
        "ObjectType=0x9", "ObjectType=0x8", 1
    ),
    fixed=_array,
    placed=Placement(Clause.PEER_CANNOT_LOAD, "C forbids a zero-length array; the stack finds element n at n-1"),
)
def array_shape(ctx: Context) -> Iterator[Finding]:
    for obj in _objects(ctx):
        if not obj.has_subs:
            continue
        subs = sorted(obj.subs)
        where = ctx.at(obj)
        if len(subs) < 2 or subs[0] != 0:
            missing = "sub-index 0" if 0 not in obj.subs else "sub-index above 0"
            yield ctx.report("CNO004", f"{obj.index:04X}h ({obj.kind.name}) has no {missing}", where)
        elif obj.kind is ObjectKind.ARRAY and subs != list(range(len(subs))):
            gap = next(n for n in range(len(subs)) if n not in obj.subs)
            yield ctx.report("CNO004", f"{obj.index:04X}h: ARRAY sub-index {gap:X}h is missing", where)


@rule(
    "CNO005",
    E,
    "Object the stack requires is missing",
    """
CANopen.c stops the build with `#error` unless OD_CNT_NMT, OD_CNT_EM and OD_CNT_HB_PROD are 1:
every device needs 1000h (device type, NMT), 1001h (error register, EM) and 1017h (producer
heartbeat time, HB_PROD). Other objects are needed only when a function of the stack is built in
(301/CO_config.h): 1014h (COB-ID EMCY) with `CO_CONFIG_EM_PRODUCER` in `CO_CONFIG_EM`, 1003h
(error history) with `CO_CONFIG_EM_HISTORY`, 1016h (consumer heartbeat time, whose size
CANopen.c takes from OD_CNT_ARR_1016) with `CO_CONFIG_HB_CONS_ENABLE`, 1006h (communication cycle
period, read with 1005h) with `CO_CONFIG_SYNC_ENABLE`, 13FEh/13FFh with `CO_CONFIG_SRDO_ENABLE`.
These are errors when the project declares its configuration (a `[stack]` table in the
.canopennode.toml file, or `--stack-config` naming its `CO_driver_target.h`) and it turns the
function on; warnings naming the switch when it declares none; nothing when it turns it off.
Fix: add the object, or declare the configuration that leaves the function out; the count label
follows from the index (or set `count_label` in the .canopennode.toml file).""",
    "; no [1017]\n[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018",
    fixed=lambda: (
        "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n\n"
        + ex.var(0x1017, "Producer heartbeat time", 0x0006, mapping=0)
    ),
    placed=Placement(Clause.PEER_CANNOT_LOAD, "CANopen.c stops the build with #error"),
)
def required_counts(ctx: Context) -> Iterator[Finding]:
    counts = _counts(ctx)
    if ctx.options.profile != PROFILE:
        return
    stack = ctx.options.stack or StackConfig()
    for label, index in REQUIRED_COUNTS:
        if label not in counts:
            message = f"no object counts as {label} (usually {index:04X}h): CANopen.c needs {count_macro(label)}"
            where = ctx.at(ctx.device.mandatory_objects or ctx.device.file_info)
            yield from _switched(ctx, stack, SWITCHED_COUNTS.get(label), message, where)
    present = {obj.index for obj in _objects(ctx)}
    for label, needed in COMPANIONS:
        for index in needed if label in counts else ():
            if index not in present:
                message = f"{counts[label][0].index:04X}h counts as {label}, so CANopen.c also uses {index:04X}h"
                yield from _switched(ctx, stack, SWITCHED_COMPANIONS.get(label), message, ctx.at(counts[label][0]))


def _switched(
    ctx: Context, stack: StackConfig, need: StackSwitch | None, message: str, where: Location
) -> Iterator[Finding]:
    """CNO005 as the declared configuration has it: an error when it needs the object, a warning when unknown."""
    wanted = True if need is None else stack.needs(need)
    if wanted:
        declared = (
            f" (the configuration declared in {', '.join(stack.sources)} has {need.spelled()})"
            if (need and stack.sources)
            else ""
        )
        yield ctx.report("CNO005", message + declared, where)
    elif wanted is None and need is not None:
        note = f" when built with {need.spelled()} (the stack's default); declare the configuration to decide"
        yield Finding("CNO005", W, message + note, where)


def _counts(ctx: Context) -> dict[str, list[Object]]:
    counts: dict[str, list[Object]] = {}
    for obj in _objects(ctx):
        label = count_label_for(obj.index, obj.canopennode)
        if label is not None:
            counts.setdefault(label, []).append(obj)
    return counts


@rule(
    "CNO006",
    E,
    "Count label or array size outside the stack's limits",
    """
CANopen.c checks the OD_CNT_* counts with `#error` (NMT, EM, HB_PROD exactly 1; SYNC, TIME,
HB_CONS, GFC at most 1; SDO servers 1-128, clients up to 128; RPDO and TPDO up to 512; SRDO up
to 64) and, with the heartbeat consumer built in (`CO_CONFIG_HB_CONS_ENABLE`; a warning when the
project declares no configuration), needs 1016h to be an ARRAY of 1 to 127 heartbeat consumers.
Its init loops also walk the OD list by position: SDO server i is 1200h+i, RPDO i is 1400h+i
with mapping 1600h+i, TPDO i 1800h+i with 1A00h+i, SRDO i 1301h+i with 1381h+i, so these must be
consecutive and paired. Count labels and storage groups become C names, so they must be C
identifiers. Fix: correct the objects or the
`count_label` setting.""",
    lambda: ex.pdo("rx", "0x60400010") + ex.pdo("rx", "0x607A0020", number=3) + ex.CONTROLWORD + ex.TARGET_POSITION,
    fixed=lambda: (
        ex.pdo("rx", "0x60400010") + ex.pdo("rx", "0x607A0020", number=2) + ex.CONTROLWORD + ex.TARGET_POSITION
    ),
    placed=Placement(Clause.PEER_CANNOT_LOAD, "CANopen.c stops the build with #error"),
)
def count_limits(ctx: Context) -> Iterator[Finding]:
    counts = _counts(ctx)
    for label, objects in counts.items():
        where = ctx.at(objects[0])
        if not _C_IDENTIFIER.fullmatch(label):
            yield ctx.report("CNO006", f"{objects[0].index:04X}h: count label {label!r} is not a C identifier", where)
            continue
        least, most = COUNT_LIMITS.get(label, (0, 0xFFFF))
        if not least <= len(objects) <= most:
            limit = f"exactly {least}" if least == most else f"{least} to {most}"
            yield ctx.report("CNO006", f"{len(objects)} objects count as {label}; the stack allows {limit}", where)
        yield from _consecutive(ctx, label, objects)
    yield from _heartbeat_consumers(ctx, counts)
    for obj in _objects(ctx):
        group = (obj.canopennode.storage_group if obj.canopennode else None) or standard_storage_group(obj.index)
        if not _C_IDENTIFIER.fullmatch(group):
            yield ctx.report("CNO006", f"{obj.index:04X}h: storage group {group!r} is not a C identifier", ctx.at(obj))


def _heartbeat_consumers(ctx: Context, counts: dict[str, list[Object]]) -> Iterator[Finding]:
    """1016h as the heartbeat consumer (when built in) needs it: an ARRAY of 1 to 127 entries."""
    heartbeat = ctx.device.objects.get(0x1016)
    if HEARTBEAT_CONSUMERS not in counts or heartbeat is None:
        return
    message = ""
    if heartbeat.kind is not ObjectKind.ARRAY:
        message = f"1016h must be an ARRAY: the stack sizes its consumers by {count_macro('ARR_1016')}"
    elif not 1 <= len(heartbeat.subs) - 1 <= 127:
        message = f"1016h has {len(heartbeat.subs) - 1} consumers; the stack allows 1 to 127"
    if message:
        need = SWITCHED_COUNTS[HEARTBEAT_CONSUMERS]
        wanted = (ctx.options.stack or StackConfig()).needs(need)
        if wanted:
            yield ctx.report("CNO006", message, ctx.at(heartbeat))
        elif wanted is None:
            yield Finding("CNO006", W, f"{message}, when built with {need.spelled()} (the stack's default)",
                          ctx.at(heartbeat))  # fmt: skip


def _consecutive(ctx: Context, label: str, objects: list[Object]) -> Iterator[Finding]:
    if label not in CONSECUTIVE:
        return
    first, partner = CONSECUTIVE[label]
    indices = [o.index for o in objects]
    expected = list(range(first, first + len(objects)))
    if indices != expected:
        wrong = next(i for i, e in zip(indices, expected, strict=True) if i != e)
        message = f"{label} objects must be {first:04X}h, {first + 1:04X}h, ... without gaps; {wrong:04X}h is not"
        yield ctx.report("CNO006", message, ctx.at(ctx.device.objects[wrong]))
        return
    present = {o.index for o in _objects(ctx)}
    for index in indices:
        if partner is not None and index + partner not in present:
            message = f"{index:04X}h has no mapping object {index + partner:04X}h; the stack pairs them by position"
            yield ctx.report("CNO006", message, ctx.at(ctx.device.objects[index]))


@rule(
    "CNO007",
    E,
    "Default value the stack cannot store",
    """
The generator writes every default into C initializers. A DefaultValue that could not be read
as the entry's type, or a REAL32 beyond the float range, has no C spelling. Read as CANopenEditor
reads them, and so not reported: a DOMAIN's default (ignored: the application streams a DOMAIN's
data), OCTET_STRING bytes of one or two hex digits between blanks (`0`, `1 2 A`) and REAL C
literals (`0.0f`). Fix: write the value in the entry's type.""",
    "; also: EDS030 (the value is not a REAL32)\n"
    + "[2000]\nParameterName=Gain\nObjectType=0x7\nDataType=0x0008\nAccessType=rw\nDefaultValue=1e40\nPDOMapping=0",
    fixed="[2000]\nParameterName=Gain\nObjectType=0x7\nDataType=0x0008\nAccessType=rw\nDefaultValue=1e30\nPDOMapping=0",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "no C spelling for the default"),
)
def unstorable_default(ctx: Context) -> Iterator[Finding]:
    for obj in _objects(ctx):
        for subindex, var in _entries(obj):
            value = var.held
            dtype = editor_entry_type(ctx.device, var, obj)
            bad = isinstance(value, RawValue) and not _editor_readable(dtype, value)
            if dtype is not None and dtype.index == REAL32.index and isinstance(value, (int, float)):
                bad = math.isfinite(value) and abs(value) > 3.4028234663852886e38
            if bad:
                where = f"{obj.index:04X}h" + (f" sub{subindex:X}" if obj.has_subs else "")
                shown = value.text if isinstance(value, RawValue) else value
                yield ctx.report("CNO007", f"{where}: default {shown!r} cannot be stored as its type",
                                 ctx.at(ctx.section_of(obj, var), var.held_key))  # fmt: skip


def _editor_readable(dtype: DataType | None, value: RawValue) -> bool:
    return dtype is not None and editor_reads(dtype, value.text)


@rule(
    "CNO008",
    W,
    "$NODEID where the stack does not add the node-ID",
    """
CANopenNode stores `$NODEID+n` as n: the stack adds the node-ID itself, but only to the
COB-IDs it manages (1014h EMCY, 1200h-12FFh SDO, 1400h-15FFh RPDO, 1800h-19FFh TPDO, when they
hold their pre-defined value). Elsewhere the device would see n alone. Fix: write the value the
device needs, or set it at run time in the application.""",
    "[2000]\nParameterName=Reply COB-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
    "DefaultValue=$NODEID+0x700\nPDOMapping=0",
    fixed="[2000]\nParameterName=Reply COB-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
    "DefaultValue=0x705\nPDOMapping=0",
    placed=Placement(
        Clause.PORTABILITY,
        "`$NODEID` is CiA 306, but the stack adds the node-ID only to its own COB-IDs: the device sees n alone",
    ),
)
def nodeid_elsewhere(ctx: Context) -> Iterator[Finding]:
    for obj in _objects(ctx):
        if any(low <= obj.index <= high for low, high in NODEID_AREAS):
            continue
        for subindex, var in _entries(obj):
            value = var.held
            if isinstance(value, NodeIdExpr):
                where = f"{obj.index:04X}h" + (f" sub{subindex:X}" if obj.has_subs else "")
                message = f"{where}: {value.canonical()} is stored as 0x{value.offset:X}; no node-ID is added here"
                yield ctx.report("CNO008", message, ctx.at(ctx.section_of(obj, var), var.held_key))


@rule(
    "CNO009",
    W,
    "Writable string without memory",
    """
A VISIBLE_STRING, UNICODE_STRING or OCTET_STRING gets as many bytes as its default, or
`string_length_min` when larger. A writable string with an empty default and no minimum gets
none: SDO writes to it fail until the application provides memory through OD_extension_init.
CANopenEditor keeps the capacity as CO_stringLengthMin in its project; an EDS cannot say it.""",
    "[2000]\nParameterName=Name\nDataType=0x0009\nAccessType=rw\nDefaultValue=",
    fixed="[2000]\nParameterName=Name\nObjectType=0x7\nDataType=0x0009\nAccessType=rw\nDefaultValue=drive\n"
    "PDOMapping=0",
    fix_safety="No automatic fix: set `string_length_min` for the entry in `<stem>.canopennode.toml`.",
    placed=Placement(
        Clause.PORTABILITY, "an EDS cannot say the capacity; SDO writes fail until the application gives memory"
    ),
)
def string_without_memory(ctx: Context) -> Iterator[Finding]:
    for obj in _objects(ctx):
        for subindex, var in _entries(obj):
            dtype = editor_entry_type(ctx.device, var, obj)
            if dtype is None or dtype.kind not in (ValueKind.STRING, ValueKind.UNICODE, ValueKind.OCTETS):
                continue
            if dtype.index == DOMAIN.index or var.access is None or not var.access.writable:
                continue
            value = var.held
            minimum = var.canopennode.string_length_min if var.canopennode else None
            if not value and not minimum:
                where = f"{obj.index:04X}h" + (f" sub{subindex:X}" if obj.has_subs else "")
                message = f"{where}: writable {dtype.name} with no default and no string_length_min: no memory"
                yield ctx.report("CNO009", message, ctx.at(ctx.section_of(obj, var), var.held_key))


@rule(
    "CNO010",
    Severity.INFO,
    "PDO attribute differs from CANopenEditor's on purpose",
    """
An EDS says only whether an entry may be mapped (PDOMapping=1), not into which PDOs. CANopenEditor
reads PDOMapping=1 as CiA 311's `optional` and gives the entry ODA_TRPDO whatever its access, so
an RPDO could write a read-only entry. CiA 301 maps read-only entries into TPDOs and write-only
ones into RPDOs only, and CANopenEditor's own EDS export writes `AccessType=ro` with PDOMapping=1
for its TPDO-only entries; the generator keeps the direction the access allows (ODA_TPDO, ODA_RPDO).
This note names each such entry. Firmware that maps one of them the other way needs CANopenEditor's
bits: `pdo_attributes = "canopeneditor"` in the `[stack]` table of the .canopennode.toml file.""",
    "[2000]\nParameterName=Status\nObjectType=0x7\nDataType=0x0006\nAccessType=ro\nDefaultValue=0\nPDOMapping=1",
    fixed="[2000]\nParameterName=Status\nObjectType=0x7\nDataType=0x0006\nAccessType=rwr\nDefaultValue=0\nPDOMapping=1",
    fix_safety="No automatic fix: the access type is a design decision; the setting keeps CANopenEditor's bits.",
    placed=Placement(Clause.DECISION, "CiA 301's PDO attribute, not CANopenEditor's"),
)
def pdo_bits_differ(ctx: Context) -> Iterator[Finding]:
    for obj in _objects(ctx):
        for subindex, var in _entries(obj):
            ours, its = pdo_bits_pair(var)
            if ours != its:
                where = f"{obj.index:04X}h" + (f" sub{subindex:X}" if obj.has_subs else "")
                keep = '([stack] pdo_attributes = "canopeneditor" keeps its bits)'
                message = (f"{where}: {pdo_attribute_text(ours)} for {var.access} with PDOMapping=1; CANopenEditor "
                           f"writes {pdo_attribute_text(its)} {keep}")  # fmt: skip
                yield ctx.report("CNO010", message, ctx.at(ctx.section_of(obj, var), "PDOMapping"))


def profile_findings(
    device: Device, node_id: int | None = None, ignore: tuple[str, ...] = (), stack: StackConfig | None = None
) -> list[Finding]:
    """Only the canopennode rules, for gen -t canopennode; `ignore` as in [tool.cantools-od]."""
    from .config import Selection
    from .rules import LintOptions
    from .runner import lint

    return lint(
        device, LintOptions(node_id=node_id, profile=PROFILE, stack=stack), Selection(select=("CNO",), ignore=ignore)
    )
