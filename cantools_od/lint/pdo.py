"""Rule family: pdo. PDO records and mappings (CiA 301 §7.4.8, §7.5.2.35-38; CiA 306 §4.6.3.4.1)."""

from __future__ import annotations

from collections.abc import Iterable, Iterator

from ..model import AccessType, ObjectKind, Severity
from ..model.cia301.modules import connected_modules, module_objects, supports_modules
from ..model.cia301.pdo import MAPPING_ENTRY_TYPE, MAX_ENTRIES, RX, TX, MapEntry, Pdo, dummy_shape_problem, dummy_type
from ..model.cia301.slots import Slot
from ..model.datatypes import BOOLEAN
from . import examples as ex
from .pdoread import device_pdos, dummies, length_fix, mapped_objects, named, with_severity
from .rules import Clause, Context, Finding, Placement, rule

E, W = Severity.ERROR, Severity.WARNING


# --- records ---------------------------------------------------------------------------------


@rule(
    "PDO001",
    E,
    "PDO communication record without its mapping record, or the reverse",
    """
A PDO is described by a pair: the communication record (1400h/1800h + n - 1) says whether and
when it is sent, the mapping record (1600h/1A00h + n - 1) what it carries. One without the other
leaves the PDO unusable; configuration tools cannot set it up.""",
    lambda: ex.pdo("rx", "0x60400010", parts="comm") + ex.CONTROLWORD,
    fixed=lambda: ex.pdo("rx", "0x60400010") + ex.CONTROLWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "a configuration tool cannot set up half a PDO"),
)
def check_pairs(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        if pdo.comm is not None and pdo.mapping is None:
            yield ctx.report(
                "PDO001",
                f"{pdo.name}: {pdo.comm_index:04X}h has no mapping record {pdo.map_index:04X}h",
                ctx.at(pdo.comm),
            )
        elif pdo.mapping is not None and pdo.comm is None:
            yield ctx.report(
                "PDO001",
                f"{pdo.name}: {pdo.map_index:04X}h has no communication record {pdo.comm_index:04X}h",
                ctx.at(pdo.mapping),
            )


@rule(
    "PDO002",
    W,
    "PDO record is not a RECORD",
    """
CiA 301 defines the communication parameter as a RECORD of type PDO_COMMUNICATION_PARAMETER
(0020h) and the mapping parameter as a RECORD of type PDO_MAPPING (0021h). An ARRAY is tolerated
for the mapping, whose entries all share one type; anything else is not a PDO record.""",
    lambda: (
        "; also: EDS028 (an ARRAY's elements share one type)\n"
        + ex.pdo("tx", "0x60410010").replace("ObjectType=0x9", "ObjectType=0x8", 1)
        + ex.STATUSWORD
    ),
    fixed=lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD,
    placed=Placement(Clause.PORTABILITY, "the entries read alike; the object type is not CiA 301's"),
)
def check_record_kind(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        for obj, allowed in ((pdo.comm, (ObjectKind.RECORD,)), (pdo.mapping, (ObjectKind.RECORD, ObjectKind.ARRAY))):
            if obj is not None and obj.kind not in allowed:
                yield ctx.report(
                    "PDO002",
                    f"{pdo.name}: {obj.index:04X}h is {obj.kind.name}, expected {' or '.join(k.name for k in allowed)}",
                    ctx.at(obj, "ObjectType"),
                )


@rule(
    "PDO060",
    E,
    "PDO record lacks a mandatory sub-object",
    """
The COB-ID (sub1) and transmission type (sub2) of a communication record and the number of
mapped objects (sub0) of a mapping record are mandatory in CiA 301. CiA 306 adds that a PDO
described explicitly must describe all its sub-objects: CompactPDO fills in only the PDOs the
file leaves out entirely, never a part of one.""",
    lambda: (
        ex.record(
            0x1400,
            "RPDO1 communication parameter",
            {0: ("Highest sub-index supported", 0x0005, "ro", 1), 1: ("COB-ID", 0x0007, "rw", "$NODEID+0x200")},
        )
        + ex.pdo("rx", parts="map")
    ),
    fixed=lambda: ex.pdo("rx"),
    placed=Placement(Clause.PEER_READS_OTHERWISE, "a PDO described in part: CompactPDO does not fill the rest"),
)
def check_mandatory_subs(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        for obj, needed in ((pdo.comm, (0, 1, 2)), (pdo.mapping, (0,))):
            if obj is None or not obj.has_subs or obj.implicit:
                continue
            missing = [f"sub{s}" for s in needed if s not in obj.subs]
            if missing:
                yield ctx.report("PDO060", f"{pdo.name}: {obj.index:04X}h has no {', '.join(missing)}", ctx.at(obj))


# --- mapping record ---------------------------------------------------------------------------


@rule(
    "PDO064",
    W,
    "Mapping record sub-object of the wrong type or access",
    """
In a PDO_MAPPING record sub0 (number of mapped objects) is UNSIGNED8 and read-only (static
mapping) or writable (dynamic mapping); every entry is an UNSIGNED32 holding index, sub-index
and bit length. Another type cannot hold an entry; a write-only sub0 cannot be read back.""",
    lambda: (
        ex.pdo("tx", parts="comm")
        + ex.record(0x1A00, "TPDO1 mapping parameter", {0: ("Number of mapped objects", 0x0005, "wo", 0)})
    ),
    fixed=lambda: (
        ex.pdo("tx", parts="comm")
        + ex.record(0x1A00, "TPDO1 mapping parameter", {0: ("Number of mapped objects", 0x0005, "rw", 0)})
    ),
    placed=Placement(Clause.STYLE, "another type cannot hold an entry; tools read the type as written"),
)
def check_mapping_types(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        if pdo.mapping is None or not pdo.mapping.has_subs:
            continue
        for subindex, sub in pdo.mapping.subs.items():
            found = Slot(pdo.mapping, subindex, sub)
            dtype = ctx.device.entry_type(found.var, found.owner)
            if (
                subindex > 0 and dtype is not None and dtype.index != MAPPING_ENTRY_TYPE
            ):  # sub0: EDS025 checks every record's
                yield ctx.report(
                    "PDO064",
                    f"{pdo.name}: {found.name} is {dtype.name}, expected UNSIGNED32",
                    found.key_location(ctx, "DataType"),
                )
            if subindex == 0 and sub.access is AccessType.WO:
                yield ctx.report(
                    "PDO064", f"{pdo.name}: {found.name} is write-only", found.key_location(ctx, "AccessType")
                )


@rule(
    "PDO040",
    E,
    "Mapping count above 64 or above the entries described",
    """
Sub0 of a mapping record is the number of valid entries, sub1..sub<n>. A PDO holds at most 64
entries (40h), and every counted entry must exist in the record, else the device and the tools
disagree about what the PDO carries. FEh and FFh mark multiplexed PDOs (SAM-/DAM-MPDO) and are
not counts.""",
    lambda: ex.pdo("rx", "0x60400010", count=2) + ex.CONTROLWORD,
    fixed=lambda: ex.pdo("rx", "0x60400010") + ex.CONTROLWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device and the tools disagree about what the PDO carries"),
)
def check_count(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        count, found = pdo.count, pdo.count_slot()
        if pdo.mapping is None or found is None or count is None or pdo.is_mpdo:
            continue
        if count > MAX_ENTRIES:
            yield ctx.report("PDO040", f"{pdo.name}: {count} mapped objects, at most 64", found.location(ctx))
            continue
        missing = [s for s in range(1, count + 1) if s not in pdo.mapping.subs]
        if missing:
            yield ctx.report(
                "PDO040",
                f"{pdo.name}: {pdo.map_index:04X}sub0 counts {count} entries, but sub{missing[0]:X} is not described",
                found.location(ctx),
            )


@rule(
    "PDO041",
    E,
    "Hole in the mapping: a counted entry is 0",
    """
Entries 1..sub0 of a mapping record are all mapped; an entry of 0 inside that range maps
nothing, and devices reject it ("hole in mapping"). Lower sub0 or fill the entry. Reported
once per PDO: at sub0 when every counted entry is 0, else at the first empty entry.""",
    lambda: ex.pdo("tx", "0x00000000", "0x60410010") + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "devices reject a hole in the mapping"),
)
def check_holes(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        entries = list(pdo.entries())
        empty = [entry for entry in entries if entry.raw == 0]
        found = pdo.count_slot()
        if not empty or found is None:
            continue
        if len(empty) == len(entries):
            what, where = "all of them are 0", found
        else:
            positions = ", ".join(str(entry.position) for entry in empty)
            what, where = (
                f"entr{'ies' if len(empty) > 1 else 'y'} {positions} {'are' if len(empty) > 1 else 'is'} 0",
                empty[0].slot,
            )
        yield ctx.report("PDO041", f"{pdo.name}: sub0 counts {pdo.count} entries, but {what}", where.location(ctx))


@rule(
    "PDO042",
    E,
    "Mapped object does not exist",
    """
A mapping entry names an index and sub-index of the object dictionary. When the device has no
such object, downloading the mapping fails (abort 0602 0000h) and the PDO cannot be built.

A modular device (CiA 306 section 6, [SupportedModules]) is the exception: its default mappings
may name objects that only its modules create ([M<x>FixedObjects], [M<x>SubExtends]), which is
no error. In a DCF that lists its [ConnectedModules], a mapping is valid up to the first object
neither the device nor a connected module creates: that entry is a warning (the device shortens
the mapping there), the entries after it are not checked.""",
    lambda: ex.pdo("rx", "0x21000010"),
    fixed=lambda: ex.pdo("rx", "0x21000010") + ex.var(0x2100, "Setpoint", 0x0006, "rw"),
    placed=Placement(Clause.DEVICE_MISBEHAVES, "downloading the mapping fails (abort 0602 0000h)"),
)
def check_exists(ctx: Context) -> Iterator[Finding]:
    modular = supports_modules(ctx.device)
    created = module_objects(ctx.device) if modular else {}
    shortened = modular and connected_modules(ctx.device) is not None
    cut: set[int] = set()  # the PDOs (by mapping index) a configuration shortens at a missing object
    for pdo, entry, obj, var in mapped_objects(ctx):
        module = created.get(entry.index)
        if var is not None or (obj is not None and not obj.has_subs) or (module and module.has(entry.subindex)):
            continue  # present, a VAR with sub-index > 0 (PDO052), or made by a module
        if pdo.map_index in cut:
            continue
        message = f"{pdo.name}: maps {entry.target}, which does not exist"
        if not shortened:
            yield ctx.report("PDO042", message, entry.slot.location(ctx))
            continue
        cut.add(pdo.map_index)
        message += ", nor does a connected module create it: the mapping is valid up to here"
        yield with_severity(ctx.report("PDO042", message, entry.slot.location(ctx)), W)


@rule(
    "PDO052",
    E,
    "Mapped VAR with a sub-index other than 0",
    """
A VAR object has only sub-index 0; a mapping entry that gives it another sub-index names
nothing. Usually the entry should end in 00 before the length byte (0x60400010).""",
    lambda: ex.pdo("rx", "0x60400110") + ex.CONTROLWORD,
    fixed=lambda: ex.pdo("rx", "0x60400010") + ex.CONTROLWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the entry names nothing: the mapping fails on the device"),
)
def check_var_subindex(ctx: Context) -> Iterator[Finding]:
    for pdo, entry, obj, _ in mapped_objects(ctx):
        if obj is not None and not obj.has_subs and entry.subindex != 0:
            yield ctx.report(
                "PDO052",
                f"{pdo.name}: maps {entry.target}, but {entry.index:04X}h is a {obj.kind.name} (sub-index 0 only)",
                entry.slot.location(ctx),
            )


@rule(
    "PDO043",
    E,
    "Mapped object is not PDO-mappable",
    """
Only objects with PDOMapping=1 may be mapped (a missing key means 0). A device refuses any other
(abort 0604 0041h), so the default mapping cannot be restored.""",
    lambda: ex.pdo("tx", "0x60410010") + ex.var(0x6041, "Statusword", 0x0006, "ro", mapping=0),
    fixed=lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device refuses the mapping (abort 0604 0041h)"),
)
def check_mappable(ctx: Context) -> Iterator[Finding]:
    for pdo, entry, _, var in mapped_objects(ctx):
        if var is not None and not var.pdo_mapping:
            yield ctx.report(
                "PDO043", f"{pdo.name}: maps {named(entry, var)}, which is not PDO-mappable", entry.slot.location(ctx)
            )


@rule(
    "PDO044",
    E,
    "Mapped object's access does not fit the PDO direction",
    """
An RPDO writes the objects it maps, a TPDO reads them. A read-only or constant object in an
RPDO, or a write-only object in a TPDO, is an error. rwr ("read on process input") marks an
object for TPDOs and rww ("write on process output") one for RPDOs: rwr in an RPDO or rww in a
TPDO is reported as a warning. CANopenEditor v4.0 wrote XDD access words inverted
(`readWriteInput` beside `PDOmapping="RPDO"`); the OD.c it generated, which the stack follows,
maps such an entry by its PDOmapping, and the finding says so.""",
    lambda: ex.pdo("rx", "0x60410010") + ex.STATUSWORD,
    fixed=lambda: ex.pdo("rx", "0x60400010") + ex.CONTROLWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "an RPDO writes a read-only object: the device refuses the mapping"),
)
def check_direction(ctx: Context) -> Iterator[Finding]:
    for pdo, entry, _, var in mapped_objects(ctx):
        access = var.access if var is not None else None
        if access is None:
            continue
        if pdo.direction == RX:
            wrong, restricted = not access.writable, access is AccessType.RWR
        else:
            wrong, restricted = not access.readable, access is AccessType.RWW
        if wrong or restricted:
            verb = "writes" if pdo.direction == RX else "reads"
            message = f"{pdo.name} {verb} {named(entry, var)}, whose access is {access.value}"
            stated = var.stated_pdo_mapping if var is not None else None
            if restricted and stated == ("RPDO" if pdo.direction == RX else "TPDO"):
                message += (
                    f" beside PDOmapping={stated}: CANopenNode follows PDOmapping (CANopenEditor v4.0 wrote the "
                    f"access inverted; its OD.c maps the entry into {stated}s), tools that read the access do not"
                )
            finding = ctx.report("PDO044", message, entry.slot.location(ctx))
            yield finding if wrong else with_severity(finding, W)


@rule(
    "PDO045",
    E,
    "Mapping entry length differs from the mapped type's size",
    """
The low byte of a mapping entry is the length in bits, and CiA 301 requires it to equal the
size of the mapped object's data type (UNSIGNED16: 10h, INTEGER32: 20h). Devices check it
(abort 0604 0041h/0604 0042h), and a receiver that trusts the entry reads the wrong bits. The
fix rewrites the length byte from the type; it is unsafe (`--unsafe-fixes`): it moves every later
entry in the frame, and which side is wrong (the entry or the DataType) only the device tells. A
BOOLEAN mapped as 8 bits, as CANopenNode stores it, is only a warning: such a device expects the
byte.""",
    lambda: ex.pdo("tx", "0x60410008") + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE,
        "a receiver that trusts the entry reads the wrong bits (abort 0604 0041h on the device)",
    ),
)
def check_length(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        for entry in pdo.mapped():
            if entry.is_dummy:
                dtype, what = dummy_type(ctx.device, entry.index), "dummy entry"
            else:
                obj = ctx.device.objects.get(entry.index)
                var = obj.entry(entry.subindex) if obj is not None else None
                if obj is None or var is None:
                    continue
                dtype, what = ctx.device.entry_type(var, obj), named(entry, var)
            if dtype is None or dtype.bits is None or entry.bits == dtype.bits:
                continue
            message = f"{pdo.name}: entry 0x{entry.raw:08X} maps {entry.bits} bits, but {what} is {dtype.name}"
            if dtype.index == BOOLEAN.index and entry.bits == 8:  # CANopenNode's byte-sized BOOLEAN
                message += " (1 bit; CANopenNode devices expect the byte they store it in)"
                yield with_severity(ctx.report("PDO045", message, entry.slot.location(ctx), length_fix(entry, 1)), W)
            else:
                message += f" ({dtype.bits} bits)"
                yield ctx.report("PDO045", message, entry.slot.location(ctx), length_fix(entry, dtype.bits))


@rule(
    "PDO046",
    E,
    "PDO longer than the frame",
    """
The mapped entries of a PDO travel in one CAN frame: at most 64 bits on classic CAN, 512 bits
with CAN FD (`--can-fd`). A device refuses a longer mapping (abort 0604 0042h).""",
    lambda: ex.pdo("tx", "0x60640020", "0x606C0020", "0x60410010") + ex.POSITION + ex.VELOCITY + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60640020", "0x606C0020") + ex.POSITION + ex.VELOCITY,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device refuses a longer mapping (abort 0604 0042h)"),
)
def check_total(ctx: Context) -> Iterator[Finding]:
    limit = ctx.options.max_pdo_bits
    for pdo in device_pdos(ctx):
        total = sum(entry.bits for entry in pdo.mapped())
        found = pdo.count_slot()
        if total > limit and found is not None:
            yield ctx.report(
                "PDO046", f"{pdo.name}: the mapping is {total} bits, more than {limit}", found.location(ctx)
            )


@rule(
    "PDO048",
    W,
    "Mapping entry not aligned to the device's Granularity",
    """
`[DeviceInfo]Granularity` is the mapping granularity in bits: with 8, the device maps whole
bytes only, so every entry's length and bit offset must be a multiple of 8 (1 allows bit-wise
mapping). An entry off that grid cannot be configured on the device. Reported once, at
Granularity, naming the first entry off the grid: either the key or the mapping is wrong.""",
    (lambda: "[DeviceInfo]\nGranularity=8\n\n" + ex.pdo("tx", "0x20000001") + ex.var(8192, "Ready", 1, "ro")),
    fixed=(lambda: "[DeviceInfo]\nGranularity=1\n\n" + ex.pdo("tx", "0x20000001") + ex.var(8192, "Ready", 1, "ro")),
    placed=Placement(Clause.STYLE, "either Granularity or the mapping is wrong; the file does not say which"),
)
def check_granularity(ctx: Context) -> Iterator[Finding]:
    grain = ctx.device.device_info.granularity
    if grain is None or not 1 < grain <= 64:
        return
    off = [(pdo, e) for pdo in device_pdos(ctx) for e in pdo.mapped() if e.bits % grain or e.offset % grain]
    if off:
        pdo, entry = off[0]
        more = f" (and {len(off) - 1} more entries)" if len(off) > 1 else ""
        yield ctx.report(
            "PDO048",
            f"Granularity={grain}, but {pdo.name} maps {entry.target} at bit {entry.offset}, {entry.bits} bits{more}",
            ctx.at(ctx.device.device_info, "Granularity"),
        )


@rule(
    "PDO049",
    W,
    "Same object mapped twice in one PDO",
    """
Mapping one object twice in a PDO sends (or writes) the same value twice; devices report it as
a "duplicate map". It is usually a copy-and-paste slip in the default mapping.""",
    lambda: ex.pdo("tx", "0x60410010", "0x60410010") + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD,
    placed=Placement(Clause.STYLE, "usually a copy-and-paste slip; the same value is sent twice"),
)
def check_duplicates(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        seen: dict[tuple[int, int], int] = {}
        for entry in pdo.mapped():
            key = (entry.index, entry.subindex)
            if entry.is_dummy:
                continue
            if key in seen:
                yield ctx.report(
                    "PDO049",
                    f"{pdo.name}: {entry.target} is mapped again (first as entry {seen[key]})",
                    entry.slot.location(ctx),
                )
            else:
                seen[key] = entry.position


@rule(
    "PDO054",
    W,
    "Same object written by several RPDOs",
    """
When two valid RPDOs of a configured node map the same object, whichever arrives last wins and
the value races between two producers. Checked in DCFs only: an EDS's default mappings are a
menu, and CiA 402 itself puts the controlword into each of its pre-defined RPDOs. Invalid PDOs
are ignored.""",
    (
        lambda: (
            ex.NODE_5
            + ex.pdo("rx", "0x60400010", cob="0x205")
            + ex.pdo("rx", "0x60400010", number=2, cob="0x305")
            + ex.CONTROLWORD
        )
    ),
    fixed=(
        lambda: (
            ex.NODE_5
            + ex.pdo("rx", "0x60400010", cob="0x205")
            + ex.pdo("rx", "0x607A0020", number=2, cob="0x305")
            + ex.CONTROLWORD
            + ex.TARGET_POSITION
        )
    ),
    placed=Placement(
        Clause.STYLE, "in a DCF the value races between two RPDOs; nothing is read otherwise, and sometimes it is meant"
    ),
)
def check_shared_rpdo_objects(ctx: Context) -> Iterator[Finding]:
    if not ctx.device.is_dcf:
        return
    first: dict[tuple[int, int], Pdo] = {}
    for pdo in device_pdos(ctx):
        cob = pdo.cob()
        if pdo.direction != RX or cob is None or not cob.valid(1):
            continue
        own: dict[tuple[int, int], MapEntry] = {}
        for entry in pdo.mapped():
            if not entry.is_dummy:
                own.setdefault((entry.index, entry.subindex), entry)
        for key, entry in own.items():
            if key in first:
                yield ctx.report(
                    "PDO054",
                    f"{pdo.name}: {entry.target} is also written by {first[key].name}",
                    entry.slot.location(ctx),
                )
            else:
                first[key] = pdo


# --- dummy entries ----------------------------------------------------------------------------


@rule(
    "PDO050",
    E,
    "Dummy entry that names no fixed-size data type",
    """
An entry with an index below 1000h is a dummy: it names a data type (0001h-001Bh, or a DEFTYPE)
whose bits the receiver skips. CiA 301 (7.4.7.1) lets the data-type entries be mapped for this,
and a data-type entry is a single value at sub-index 0: a dummy names sub-index 0 (0x00050008,
never 0x00050108) and a type of fixed size; strings, DOMAIN, record types and undefined indices
cannot be dummies. `gen` refuses the same entries (GEN001), so a mapping lint rejects is never
turned into code.""",
    lambda: ex.pdo("rx", "0x00090008"),
    fixed=lambda: ex.pdo("rx", "0x00050008"),
    placed=Placement(Clause.DEVICE_MISBEHAVES, "a receiver cannot skip bits of a type without fixed size"),
)
def check_dummy_shape(ctx: Context) -> Iterator[Finding]:
    for pdo, entry in dummies(ctx):
        problem = dummy_shape_problem(dummy_type(ctx.device, entry.index), entry.index, entry.subindex)
        if problem:
            yield ctx.report("PDO050", f"{pdo.name}: dummy entry 0x{entry.raw:08X} {problem}", entry.slot.location(ctx))


@rule(
    "PDO062",
    E,
    "Dummy entry of a type [DummyUsage] does not enable",
    """
A device supports dummy entries only for the data types its `[DummyUsage]` section enables
(`Dummy0005=1`); a missing key or section means not supported. A default mapping with another
dummy cannot be downloaded.""",
    lambda: (
        ex.section(
            "DummyUsage", Dummy0001=0, Dummy0002=1, Dummy0003=1, Dummy0004=1, Dummy0005=0, Dummy0006=1, Dummy0007=1
        )
        + ex.pdo("rx", "0x00050008")
    ),
    fixed=lambda: (
        ex.section(
            "DummyUsage", Dummy0001=0, Dummy0002=1, Dummy0003=1, Dummy0004=1, Dummy0005=1, Dummy0006=1, Dummy0007=1
        )
        + ex.pdo("rx", "0x00050008")
    ),
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device refuses a dummy its [DummyUsage] does not enable"),
)
def check_dummy_usage(ctx: Context) -> Iterator[Finding]:
    usage = ctx.device.dummy_usage
    enabled = usage.enabled if usage is not None else {}
    for pdo, entry in dummies(ctx):
        if dummy_type(ctx.device, entry.index) is not None and not enabled.get(entry.index):
            yield ctx.report(
                "PDO062",
                f"{pdo.name}: dummy entry 0x{entry.raw:08X} needs Dummy{entry.index:04X}=1 in [DummyUsage]",
                entry.slot.location(ctx),
            )


@rule(
    "PDO051",
    E,
    "Dummy entry in a TPDO",
    """
A dummy entry tells a receiver which bits to skip; CiA 301 provides no dummy mapping for a
TPDO, which would have to invent the data. Some devices send zeros, but portable files do not
rely on it. The CANopenNode stack is one of them (CO_PDO.c maps the dummy to a zero byte): on a
device built with it (the canopennode profile, or a file CANopenEditor wrote) the finding is a
warning.""",
    lambda: ex.pdo("tx", "0x00050008", "0x60410010") + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "CiA 301 gives a TPDO no dummy: the device would invent the data"),
)
def check_dummy_in_tpdo(ctx: Context) -> Iterator[Finding]:
    for pdo, entry in dummies(ctx):
        if pdo.direction != TX:
            continue
        message = f"{pdo.name}: dummy entry 0x{entry.raw:08X} in a TPDO"
        if not ctx.for_canopennode:
            yield ctx.report("PDO051", message, entry.slot.location(ctx))
            continue
        message += "; the CANopenNode stack sends zeros for it, other stacks may refuse the mapping"
        yield with_severity(ctx.report("PDO051", message, entry.slot.location(ctx)), W)


@rule(
    "PDO053",
    W,
    "Mapping length byte with its MSB set",
    """
The length byte of a mapping entry is at most 40h (64 bits). Some vendors set its MSB as a
private flag (0x60410090), but CiA 301 reads the whole byte as the length: 144 bits. lint, pdo
and gen all read it that way (PDO045, PDO046 and GEN001 follow); clearing the flag is left to
the author.""",
    lambda: "; also: PDO045, PDO046 (the length it reads)\n" + ex.pdo("tx", "0x60410090") + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD,
    placed=Placement(Clause.PORTABILITY, "a vendor's private flag; every peer reads the whole byte as the length"),
)
def check_length_flag(ctx: Context) -> Iterable[Finding]:
    for pdo in device_pdos(ctx):
        for entry in pdo.mapped():
            if entry.flagged:
                yield ctx.report(
                    "PDO053",
                    f"{pdo.name}: entry 0x{entry.raw:08X} has the length byte's MSB set ({entry.raw & 0xFF:#04x})",
                    entry.slot.location(ctx),
                )
