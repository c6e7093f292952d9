"""Rule family: standard objects — the objects of CiA 301 (1000h-1FFFh), CiA 302 and, for a drive,
CiA 402, checked against their definitions in the standard (cantools_od/model/cia301/definitions.py).

A master reads such an object by the standard without looking at the EDS: a 1000h written as
INTEGER32 or a 1018h sub-index 3 as UNSIGNED16 makes a tool that trusts the file read other bytes
than the device sends. Vendors that deviate on purpose suppress the code (`--ignore STD003` or a
`; cantools-od: ignore[STD003]` comment).

The PDO records (1400h-1BFFh) are checked by the pdo and cobid families (PDO002, PDO012, PDO013,
PDO064), and sub-index 0 of every ARRAY and RECORD by EDS025; these rules leave them out.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from ..model import Device, Object, ObjectKind, Severity, SubObject, Variable, standard_type
from ..model.cia301 import cia402, definitions
from ..model.cia301.definitions import Definition, Entry, Mapping
from ..model.cia301.objects import COMMUNICATION_AREA, DEVICE_TYPE
from ..model.cia301.pdo import PDO_AREA
from ..model.cia301.slots import as_int
from . import examples as ex
from .common import kind_unknown
from .rules import Clause, Context, Finding, Fix, Placement, rule

E, W = Severity.ERROR, Severity.WARNING

_PDO_RECORDS = PDO_AREA


def _type_name(data_type: int | None) -> str:
    found = standard_type(data_type)
    return f"{found.name} (0x{data_type:04X})" if found is not None and data_type is not None else f"{data_type}"


def is_drive(device: Device) -> bool:
    """1000h names device profile 402 (the drive profile) in its low 16 bits."""
    return _profile(device, DEVICE_TYPE) == cia402.PROFILE


def _profile(device: Device, index: int) -> int | None:
    """The device profile number a device type object names, None without one."""
    obj = device.objects.get(index)
    value = as_int(device.resolve(obj.value())) if obj is not None else None
    return cia402.device_profile(value) if value is not None else None


def _drives(device: Device) -> set[int]:
    """The logical devices (0: the first) that are drives: the first by 1000h or 67FFh, a further one by its own
    device type object (6FFFh, 77FFh, ...)."""
    found = {0} if is_drive(device) else set()
    for logical in range(cia402.LOGICAL_DEVICES):
        if _profile(device, cia402.device_type_object(logical)) == cia402.PROFILE:
            found.add(logical)
    return found


def standard_objects(device: Device) -> Iterator[tuple[Object, Definition]]:
    """Every object the file writes that a standard defines, with its definition (a further logical drive's
    objects with the first one's definitions, 800h lower)."""
    drives = _drives(device)
    for index, obj in device.objects.items():
        if obj.implicit or index in _PDO_RECORDS or kind_unknown(obj):
            continue  # an unreadable ObjectType (EDS030) already explains the object
        if index in COMMUNICATION_AREA:
            found = definitions.definition(index)
        elif (logical := cia402.logical_device(index)) in drives and logical is not None:
            found = cia402.definition(index - logical * cia402.LOGICAL_DEVICE_SPAN)
        else:
            continue
        if found is not None:
            yield obj, found


def _standard(ctx: Context) -> list[tuple[Object, Definition]]:
    """`standard_objects` of the device under check, found once for all the rules that ask."""
    return ctx.once("standard_objects", lambda: list(standard_objects(ctx.device)))


def same_layout(obj: Object, found: Definition) -> bool:
    """The object has sub-indices where the standard's has them (ARRAY and RECORD alike), or none."""
    return found.accepts(obj.kind) or obj.has_subs == (found.kind in (ObjectKind.ARRAY, ObjectKind.RECORD))


def _entries(obj: Object, found: Definition) -> Iterator[tuple[int, Variable, Entry]]:
    """(sub-index, entry as written, entry as defined) after sub-index 0; a CompactSubObj array's elements once."""
    if not same_layout(obj, found):
        return  # STD001
    if not obj.has_subs:
        entry = found.entry(0)
        if entry is not None and not found.subs[1:] and found.rest is None:
            yield 0, obj, entry
        return
    compact_seen = False
    for subindex, sub in obj.subs.items():
        entry = found.entry(subindex)
        if entry is None or subindex == 0:
            continue
        if sub.implicit:  # written once, as the object's own keys
            if compact_seen:
                continue
            compact_seen = True
        yield subindex, sub, entry


def _label(obj: Object, subindex: int, var: Variable) -> str:
    if var is obj:
        return f"[{obj.index:04X}]"
    return f"[{obj.index:04X}sub{subindex:X}]"


def _what(obj: Object, found: Definition, subindex: int, var: Variable, entry: Entry) -> str:
    """The standard entry, named as the standard names it."""
    named = f"{obj.index:04X}h {found.name}"
    return named if var is obj else f"{named} sub-index {subindex} ({entry.name})"


def _keys_of(ctx: Context, obj: Object, var: Variable, key: str) -> tuple[Variable, str]:
    """The section whose `key` says it: the object's own for CompactSubObj elements."""
    return (obj, key) if isinstance(var, SubObject) and var.implicit else (var, key)


@rule(
    "STD001",
    E,
    "Standard object of another object type",
    """
CiA 301 §7.5.2 (and CiA 302, CiA 402-2) fix the object type of each standard object: 1000h is a
VAR, 1018h a RECORD, 1016h an ARRAY. A file that makes a VAR of an ARRAY (or the reverse) gives
another layout of sub-indices than the one a master addresses: it reads sub-index 0 where the
device has none, or misses the entries.

Error: the object cannot be read the way the standard says. An ARRAY written where the standard
has a RECORD (or the reverse) lays out the same entries: that is STD002.""",
    "[1018]\nParameterName=Identity\nObjectType=0x7\nDataType=0x0007\nAccessType=ro",
    fixed=lambda: ex.identity(),
    fix_safety="No automatic fix: the object must be described again.",
    placed=Placement(Clause.PEER_READS_OTHERWISE, "a master addresses another layout of sub-indices"),
)
def object_type(ctx: Context) -> Iterator[Finding]:
    for obj, found in _standard(ctx):
        if same_layout(obj, found):
            continue
        message = (
            f"[{obj.index:04X}] ObjectType {obj.kind.name}: {found.clause} defines {obj.index:04X}h "
            f"{found.name} as {found.kind.name}"
        )
        yield ctx.report("STD001", message, ctx.value_at(obj, "ObjectType"))


@rule(
    "STD002",
    W,
    "Standard ARRAY written as RECORD, or the reverse",
    """
The standard defines the object as an ARRAY (all elements of one data type, 1016h) or as a RECORD
(entries of their own types, 1018h), and the file writes the other. The sub-indices and their
types can still be the same, so a master reading the entries gets the right bytes; tools that
build their API from the object type (python-canopen's ODArray/ODRecord, CANopenNode's OD.h)
offer another interface than for the standard object.

Warning: nothing is read wrong; the description differs from the standard's.""",
    lambda: ex.identity().replace("ObjectType=0x9", "ObjectType=0x8", 1),
    fixed=lambda: ex.identity(),
    fix_safety="No automatic fix (changing ObjectType changes generated code).",
    placed=Placement(
        Clause.PORTABILITY, "the entries read alike; python-canopen and CANopenNode offer another interface"
    ),
)
def array_or_record(ctx: Context) -> Iterator[Finding]:
    for obj, found in _standard(ctx):
        wanted = (ObjectKind.ARRAY, ObjectKind.RECORD)
        if obj.kind is found.kind or obj.kind not in wanted or found.kind not in wanted:
            continue
        message = f"[{obj.index:04X}] is {obj.kind.name}; {found.clause} defines {found.name} as {found.kind.name}"
        yield ctx.report("STD002", message, ctx.value_at(obj, "ObjectType"))


@rule(
    "STD003",
    E,
    "Standard object entry of another data type",
    """
The data type of every sub-index of a standard object is fixed by its standard: 1000h is
UNSIGNED32, 1001h UNSIGNED8, 1017h UNSIGNED16, 1018h sub-indices 1-4 UNSIGNED32, 6041h (CiA 402)
UNSIGNED16. A master reads these objects by the standard: an entry declared INTEGER32 or
UNSIGNED16 makes tools that trust the file (python-canopen, lely, generated code) decode and
encode other bytes than the device uses, and an SDO write of the declared size is refused.

Error: the file and the standard give different bytes for the same entry. Where the standard's peers
agree on another type (1022h Store format: UNSIGNED16 in CANopenEditor, objdictgen and kacanopen;
CiA 301 says UNSIGNED8), a file that follows them is not reported.
Fix (unsafe, shown only): set DataType to the standard's; the values must then be checked by hand.""",
    "[1000]\nParameterName=Device type\nDataType=0x0004\nAccessType=ro",
    fixed="[1000]\nParameterName=Device type\nDataType=0x0007\nAccessType=ro",
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "python-canopen, lely and generated code decode other bytes than the device sends"
    ),
)
def data_type(ctx: Context) -> Iterator[Finding]:
    for obj, found in _standard(ctx):
        for subindex, var, entry in _entries(obj, found):
            written = ctx.device.entry_type(var, obj)
            if entry.data_type is None or var.data_type is None or written is None:
                continue  # open in the standard, or missing/undefined in the file (EDS020, EDS080)
            if written.index == entry.data_type or written.index in entry.peer_types:
                continue
            section, key = _keys_of(ctx, obj, var, "DataType")
            message = (
                f"{_label(obj, subindex, var)} DataType={_type_name(var.data_type)}: {found.clause} defines "
                f"{_what(obj, found, subindex, var, entry)} as {_type_name(entry.data_type)}"
            )
            fix = Fix(f"set DataType=0x{entry.data_type:04X}", False, _set_type(obj.index, subindex, entry.data_type))
            yield ctx.report("STD003", message, ctx.value_at(section, key), fix)
        yield from _vendor_entries(ctx, obj, found)


def _vendor_entries(ctx: Context, obj: Object, found: Definition) -> Iterator[Finding]:
    """Sub-indices a vendor added to a profile ARRAY beyond the ones the profile defines: the profile gives them
    no type, so the finding says only that (a warning), never a type."""
    if found.clause != cia402.CLAUSE or found.rest is None or not same_layout(obj, found):
        return
    for subindex, sub in obj.subs.items():
        if subindex == 0 or found.entry(subindex) is not None or sub.implicit:
            continue
        message = (
            f"{_label(obj, subindex, sub)}: sub-index {subindex} of {obj.index:04X}h {found.name} is not defined by "
            f"{found.clause} (a vendor's extension; its data type is the vendor's)"
        )
        yield ctx.report("STD003", message, ctx.at(sub))._replace(severity=W)


def _set_type(index: int, subindex: int, wanted: int) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        obj = device.objects.get(index)
        var = obj.entry(subindex) if obj is not None else None
        if var is not None:
            var.data_type = wanted

    return apply


@rule(
    "STD004",
    W,
    "Standard object entry with an access type the standard does not allow",
    """
CiA 301 §7.5.2 gives the access of each standard entry: 1000h and 1018h are read-only (ro or
const), 1024h is write-only, the heartbeat and COB-ID objects are rw or, where the device fixes
them, ro/const. A master that follows the file writes where the device refuses, or does not write
what the standard says it may (a consumer heartbeat time, an error history clear through 1003h sub 0).
For a drive (CiA 402-2, in each logical device whose device type names profile 402): what the drive
reports is read-only (6041h statusword, 6064h position actual value, 6077h torque actual value),
what the master commands is read-write (6040h controlword, 6060h modes of operation), and no
parameter is write-only.

Warning: communication works, but configuration steps fail or are skipped.""",
    "[1018]\nParameterName=Identity\nObjectType=0x9\nSubNumber=2\n[1018sub0]\nParameterName=Count\n"
    "DataType=0x0005\nAccessType=ro\nDefaultValue=1\n[1018sub1]\nParameterName=Vendor-ID\nDataType=0x0007\n"
    "AccessType=rw",
    fixed="[1018]\nParameterName=Identity\nObjectType=0x9\nSubNumber=2\n[1018sub0]\nParameterName=Count\n"
    "DataType=0x0005\nAccessType=ro\nDefaultValue=1\n[1018sub1]\nParameterName=Vendor-ID\nDataType=0x0007\n"
    "AccessType=ro",
    fix_safety="No automatic fix (the device's behaviour decides which side is wrong).",
    placed=Placement(Clause.PORTABILITY, "a master writes where the device refuses, or leaves out what it may write"),
)
def access_type(ctx: Context) -> Iterator[Finding]:
    for obj, found in _standard(ctx):
        for subindex, var, entry in _all_entries(obj, found):
            if entry.access is None or var.access is None or var.access in entry.access:
                continue
            allowed = "/".join(sorted(a.value for a in entry.access if a.value in ("ro", "wo", "rw", "const")))
            section, key = _keys_of(ctx, obj, var, "AccessType")
            message = (
                f"{_label(obj, subindex, var)} AccessType={var.access.value}: {found.clause} gives "
                f"{_what(obj, found, subindex, var, entry)} access {allowed}"
            )
            yield ctx.report("STD004", message, ctx.value_at(section, key))


def _all_entries(obj: Object, found: Definition) -> Iterator[tuple[int, Variable, Entry]]:
    """Like _entries, with sub-index 0 of an ARRAY or RECORD."""
    count = obj.subs.get(0)
    if obj.has_subs and count is not None and not count.implicit and same_layout(obj, found):
        yield 0, count, found.subs[0]
    yield from _entries(obj, found)


@rule(
    "STD005",
    W,
    "Standard object entry PDO-mappable against the standard",
    """
CiA 301 §7.5.2 says which standard entries may be mapped into a PDO: 1001h, 1002h, 1013h and the
OS prompt 1026h may; 1000h, 1018h, the heartbeat, COB-ID and SDO objects may not. An entry marked
`PDOMapping=1` against the standard invites a master to map it, and a standard device refuses that
mapping (SDO abort 0604 0041h).

Warning: nothing is read wrong; a configuration step can fail.""",
    "[1017]\nParameterName=Producer heartbeat time\nDataType=0x0006\nAccessType=rw\nPDOMapping=1",
    fixed="[1017]\nParameterName=Producer heartbeat time\nDataType=0x0006\nAccessType=rw\nPDOMapping=0",
    fix_safety="No automatic fix.",
    placed=Placement(Clause.STYLE, "the device refuses the mapping; nothing is read wrong"),
)
def mapping(ctx: Context) -> Iterator[Finding]:
    for obj, found in _standard(ctx):
        for subindex, var, entry in _all_entries(obj, found):
            if entry.mapping is Mapping.NO and var.pdo_mapping:
                section, key = _keys_of(ctx, obj, var, "PDOMapping")
                message = (
                    f"{_label(obj, subindex, var)} PDOMapping=1: {found.clause} does not let "
                    f"{_what(obj, found, subindex, var, entry)} be mapped"
                )
                yield ctx.report("STD005", message, ctx.value_at(section, key))


def _direction(entry: Entry) -> str:
    """The PDOs a profile's predefined mapping puts the entry in: TPDOs for what the device reports (read-only),
    RPDOs for what the master writes."""
    return "TPDO" if entry.access is not None and entry.access <= definitions.RO else "RPDO"


@rule(
    "STD007",
    W,
    "Standard object entry a profile maps by default, not mappable that way",
    """
CiA 402-3 maps the controlword 6040h into the first RPDO and the statusword 6041h into the first
TPDO of a drive (in each logical device whose device type names profile 402): a master drives the
state machine through them, and a standard master sets up its PDOs that way. A file that marks one
of them `PDOMapping=0`, or makes the controlword TPDO-only (`AccessType=rwr`) or the statusword
RPDO-only (an XDD's `PDOmapping="RPDO"`), announces a drive that cannot be run by PDOs: the
configuration fails with SDO abort 0604 0041h, or the master polls by SDO.

The other objects of the profile may be mappable or not: drives with a static mapping make the
actual values unmappable, others map option codes too, and the profile allows both.

Warning: the drive may still be run by SDO; a standard PDO set-up fails.""",
    ex.DEVICE_TYPE_402 + ex.STATUSWORD.replace("PDOMapping=1", "PDOMapping=0"),
    fixed=ex.DEVICE_TYPE_402 + ex.STATUSWORD,
    fix_safety="No automatic fix: making an entry mappable changes what a master may map.",
    placed=Placement(Clause.STYLE, "a standard master sets up its PDOs otherwise than the file allows"),
)
def default_mapping(ctx: Context) -> Iterator[Finding]:
    for obj, found in _standard(ctx):
        for subindex, var, entry in _entries(obj, found):
            kind = var.pdo_mapping_kind()
            wanted = _direction(entry)
            if entry.mapping is not Mapping.DEFAULT or kind is None or kind in (wanted, "optional", "default"):
                continue
            section, key = _keys_of(ctx, obj, var, "PDOMapping" if kind == "no" else "AccessType")
            said = "not mappable" if kind == "no" else f"{kind} only"
            message = (
                f"{_label(obj, subindex, var)} {said}: {found.clause} maps {_what(obj, found, subindex, var, entry)} "
                f"into {wanted}s by default"
            )
            yield ctx.report("STD007", message, ctx.value_at(section, key))


@rule(
    "STD006",
    W,
    "Standard object entry with a value the standard does not allow",
    """
Some standard entries allow only some values: 1018h sub-index 0 is 1-4, 1010h/1011h/1016h
sub-index 0 at least 1, 1019h (SYNC counter overflow) 0 or 2-240, a mapping count 0-64. A device
description with another default announces a device that a standard master cannot handle.

Warning: the value is one the standard rules out; which side is wrong depends on the device.""",
    "[1019]\nParameterName=Synchronous counter overflow value\nDataType=0x0005\nAccessType=rw\nDefaultValue=1",
    fixed="[1019]\nParameterName=Synchronous counter overflow value\nDataType=0x0005\nAccessType=rw\nDefaultValue=0",
    fix_safety="No automatic fix.",
    placed=Placement(Clause.STYLE, "which side is wrong depends on the device"),
)
def value_range(ctx: Context) -> Iterator[Finding]:
    for obj, found in _standard(ctx):
        for subindex, var, entry in _all_entries(obj, found):
            if entry.values is None or (isinstance(var, SubObject) and var.implicit):
                continue
            key = var.held_key
            value = as_int(ctx.device.resolve(var.value()))
            if value is None or any(low <= value <= high for low, high in entry.values):
                continue
            if subindex == 0 and obj.has_subs and value == max(obj.subs):
                continue  # sub-index 0 counts what the file has; entries the standard lacks are another matter
            allowed = ", ".join(f"{low}" if low == high else f"{low}-{high}" for low, high in entry.values)
            message = (
                f"{_label(obj, subindex, var)} {key}={value}: {found.clause} allows {allowed} for "
                f"{_what(obj, found, subindex, var, entry)}"
            )
            yield ctx.report("STD006", message, ctx.value_at(var, key))
