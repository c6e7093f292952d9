"""Rule family: object lists — [MandatoryObjects], [OptionalObjects], [ManufacturerObjects] (CiA 306, object lists)."""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterator

from ..eds import keys
from ..model import Device, Location, ObjectList, Severity
from ..model.cia301.objects import DATA_TYPE_AREA
from ..model.cia301.objects import MANDATORY as MANDATORY_INDICES
from ..model.device import OBJECT_LISTS, object_list_home
from ..model.source import location
from .common import file_start
from .rules import Clause, Context, Finding, Fix, Placement, rule

E, W = Severity.ERROR, Severity.WARNING

MANDATORY, OPTIONAL, MANUFACTURER = "MandatoryObjects", "OptionalObjects", "ManufacturerObjects"
LISTS = OBJECT_LISTS


def object_list(device: Device, name: str) -> ObjectList | None:
    found: ObjectList | None = getattr(device, LISTS[name])
    return found


home = object_list_home


def listings(device: Device) -> Iterator[tuple[str, ObjectList, int, int]]:
    """(list name, list, position, index) for every entry, in list and position order."""
    for name in LISTS:
        found = object_list(device, name)
        if found is not None:
            for position, index in sorted(found.entries.items()):
                yield name, found, position, index


def _listings(ctx: Context) -> list[tuple[str, ObjectList, int, int]]:
    """`listings` of the device under check, sorted once for all the rules that ask."""
    return ctx.once("listings", lambda: list(listings(ctx.device)))


def listed_indices(device: Device) -> set[int]:
    """Every listed index, also those a repeated position hides (EDS015 renumbers them)."""
    listed: set[int] = set()
    for name in LISTS:
        found = object_list(device, name)
        if found is not None:
            listed.update(found.entries.values())
            listed.update(index for entries in found.repeats.values() for _, _, index in entries)
    return listed


def _entry_at(ctx: Context, found: ObjectList, position: int) -> Location:
    return ctx.value_at(found, str(position))


def _renumber(found: ObjectList, drop: Collection[int] = ()) -> None:
    """Positions 1..n in the old order, without the dropped positions; the count follows when it was right."""
    was_right = found.supported_objects == len(found.entries)
    kept = [index for position, index in sorted(found.entries.items()) if position not in drop]
    found.entries = {position: index for position, index in enumerate(kept, 1)}
    if was_right:
        found.supported_objects = len(found.entries)


# ---- presence --------------------------------------------------------------------------------------------------


@rule(
    "EDS010",
    E,
    "Listed object has no section",
    """
Each entry of an object list names an object that the file describes in its own `[<index>]`
section. A listed object without one (e.g. 6505h in a real drive EDS) makes tools fail to load
the file or announce an object the device does not describe. A missing 1000h, 1001h or 1018h is
reported by EDS011.""",
    "[OptionalObjects]\nSupportedObjects=1\n1=0x6505\n; no [6505] section in the file",
    fixed=(
        "[OptionalObjects]\nSupportedObjects=1\n1=0x6505\n\n[6505]\n"
        "ParameterName=Http drive catalog address\nObjectType=0x7\nDataType=0x0009\nAccessType=ro\n"
        "DefaultValue=x\nPDOMapping=0"
    ),
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "the list announces an object the file does not describe (lely dcfchk: not found)"
    ),
)
def listed_absent(ctx: Context) -> Iterator[Finding]:
    for name, found, position, index in _listings(ctx):
        if index not in ctx.device.objects and index not in MANDATORY_INDICES:  # those: EDS011
            fix = Fix(f"remove 0x{index:04X} from [{name}]", False, _fix_unlist(name, index))
            message = f"[{name}] {position}=0x{index:04X}: no [{index:04X}] section"
            yield ctx.report("EDS010", message, _entry_at(ctx, found, position), fix)


def _fix_unlist(name: str, index: int) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        found = object_list(device, name)
        if found is not None:
            _renumber(found, {p for p, i in found.entries.items() if i == index})

    return apply


@rule(
    "EDS012",
    E,
    "Object section not listed",
    """
Every object section (except data types below 1000h) is listed in exactly one of the object
lists: 1000h, 1001h and 1018h in [MandatoryObjects], 2000h-5FFFh in [ManufacturerObjects], all
others in [OptionalObjects]. Tools that follow the lists (lely, Vector CANeds) ignore or reject
unlisted objects; python-canopen imports every section, so the two disagree about the device.
Objects implied by CompactPDO need not be listed.""",
    "[ManufacturerObjects]\nSupportedObjects=0\n\n[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw",
    fixed=(
        "[ManufacturerObjects]\nSupportedObjects=1\n1=0x2000\n\n[2000]\nParameterName=Speed\n"
        "ObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "lely follows the lists and leaves it out; python-canopen imports every section"
    ),
)
def unlisted(ctx: Context) -> Iterator[Finding]:
    listed = listed_indices(ctx.device)
    for index, obj in ctx.device.objects.items():
        target = home(index)
        if obj.implicit or target is None or index in listed:
            continue
        found = object_list(ctx.device, target)
        count_line = (found.origin.where("SupportedObjects") or (0,))[0] if found and found.origin else 0
        fix = Fix(f"add 0x{index:04X} to [{target}]", True, _fix_list(index), (count_line,) if count_line else ())
        yield ctx.report("EDS012", f"[{index:04X}] is in no object list; it belongs in [{target}]", ctx.at(obj), fix)


def _fix_list(index: int) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        target = home(index)
        if target is None or index in listed_indices(device):
            return
        found = _ensure(device, target)
        was_right = found.supported_objects == len(found.entries)
        found.entries = {**found.entries, max(found.entries, default=0) + 1: index}
        if was_right:
            found.supported_objects = len(found.entries)

    return apply


def _ensure(device: Device, name: str) -> ObjectList:
    found = object_list(device, name)
    if found is None:
        found = ObjectList(supported_objects=0)
        setattr(device, LISTS[name], found)
    return found


@rule(
    "EDS019",
    E,
    "Object list section missing",
    """
An EDS has all three object lists, even when one is empty (`SupportedObjects=0`). Objects that
a missing list would hold are reported as unlisted (EDS012); this rule reports the missing
section itself. Error: lely's dcfchk cannot load such a file (`KeyError: 'ManufacturerObjects'`),
though python-canopen does.""",
    "; no [OptionalObjects], [ManufacturerObjects]\n"
    "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018",
    fixed="[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n\n[OptionalObjects]\n"
    "SupportedObjects=0\n\n[ManufacturerObjects]\nSupportedObjects=0",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "lely dcfchk raises KeyError on the missing list"),
)
def missing_list(ctx: Context) -> Iterator[Finding]:
    for name in LISTS:
        if object_list(ctx.device, name) is None:
            fix = Fix(f"add an empty [{name}]", True, _fix_missing(name))
            yield ctx.report("EDS019", f"[{name}] is missing", file_start(ctx), fix)


def _fix_missing(name: str) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        _ensure(device, name)

    return apply


# ---- placement -------------------------------------------------------------------------------------------------


@rule(
    "EDS013",
    E,
    "Mandatory and other object lists mixed up",
    """
[MandatoryObjects] lists exactly the objects every CANopen device has: 1000h (device type),
1001h (error register) and 1018h (identity). Other objects listed there, or one of these three
listed in another list, make tools misjudge which objects the device must implement.

Error when 1000h, 1001h or 1018h is missing from [MandatoryObjects]: a tool that checks the
mandatory list finds the device incomplete. Warning for another object listed there (often 1017h,
which CiA 301 makes mandatory only without node guarding): every tool still finds and reads it.
Fix (unsafe, shown only): move the entry; it renumbers both lists.""",
    (
        "[MandatoryObjects]\nSupportedObjects=4\n1=0x1000\n2=0x1001\n3=0x1018\n4=0x1017\n\n"
        "[OptionalObjects]\nSupportedObjects=0\n\n[1017]\nParameterName=Producer heartbeat time\n"
        "ObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n\n[OptionalObjects]\n"
        "SupportedObjects=1\n1=0x1017\n\n[1017]\nParameterName=Producer heartbeat time\nObjectType=0x7\n"
        "DataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "lely dcfchk: object is not mandatory; tools misjudge which objects must exist"
    ),
)
def mandatory_list(ctx: Context) -> Iterator[Finding]:
    for name, found, position, index in _listings(ctx):
        if (name == MANDATORY) != (index in MANDATORY_INDICES):
            target = home(index)
            if target is None:
                continue  # EDS018
            fix = Fix(f"move 0x{index:04X} to [{target}]", False, _fix_move(name, index, target))
            message = f"[{name}] {position}=0x{index:04X}: belongs in [{target}]"
            finding = ctx.report("EDS013", message, _entry_at(ctx, found, position), fix)
            yield finding._replace(severity=W) if name == MANDATORY else finding


@rule(
    "EDS017",
    W,
    "Object listed outside its index area",
    """
[ManufacturerObjects] holds the manufacturer-specific area 2000h-5FFFh and [OptionalObjects] the
communication and device-profile areas (CiA 301, object dictionary index areas); C000h-FFFFh is reserved. Real devices
put manufacturer objects into the profile area (e.g. 7001h), so this is a warning: check whether
the object is misplaced or its index is.""",
    (
        "[OptionalObjects]\nSupportedObjects=1\n1=0x2000\n\n[ManufacturerObjects]\nSupportedObjects=0\n\n"
        "[2000]\nParameterName=Vendor value\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\n"
        "DefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[OptionalObjects]\nSupportedObjects=0\n\n[ManufacturerObjects]\nSupportedObjects=1\n1=0x2000\n\n"
        "[2000]\nParameterName=Vendor value\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\n"
        "DefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(
        Clause.PORTABILITY, "lely dcfchk warns; real devices place manufacturer objects in the profile area"
    ),
)
def area(ctx: Context) -> Iterator[Finding]:
    entries = _listings(ctx)
    for name, found, position, index in entries:
        target = home(index)
        if name == MANDATORY or target is None or target == MANDATORY:
            continue  # EDS013, EDS018
        if name != target and any(other == target and listed == index for other, _, _, listed in entries):
            continue  # also in its own list: EDS016
        if index >= 0xC000:
            message = f"[{name}] {position}=0x{index:04X}: index in the reserved area C000h-FFFFh"
            yield ctx.report("EDS017", message, _entry_at(ctx, found, position))
        elif name != target:
            fix = Fix(f"move 0x{index:04X} to [{target}]", False, _fix_move(name, index, target))
            message = f"[{name}] {position}=0x{index:04X}: the index area belongs to [{target}]"
            yield ctx.report("EDS017", message, _entry_at(ctx, found, position), fix)


def _fix_move(source: str, index: int, target: str) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        _fix_unlist(source, index)(device)
        _fix_list(index)(device)

    return apply


@rule(
    "EDS018",
    W,
    "Data type listed",
    """
Data types (indices below 1000h, described by DEFTYPE/DEFSTRUCT objects) are not listed in the
object lists. lely dcfchk rejects them there ("data type objects are not supported").""",
    "; also: DIA005 (every DEFTYPE)\n[0040]\nParameterName=Unsigned32 alias\nObjectType=0x5\nDataType=0x0007\n"
    "AccessType=ro\n\n[OptionalObjects]\nSupportedObjects=1\n1=0x0040",
    fixed="; also: DIA005 (every DEFTYPE)\n[0040]\nParameterName=Unsigned32 alias\nObjectType=0x5\nDataType=0x0007\n"
    "AccessType=ro\n\n[OptionalObjects]\nSupportedObjects=0",
    placed=Placement(Clause.PORTABILITY, "lely dcfchk: data type objects are not supported in the lists"),
)
def data_type_listed(ctx: Context) -> Iterator[Finding]:
    for name, found, position, index in _listings(ctx):
        if index < DATA_TYPE_AREA.stop:
            message = f"[{name}] {position}=0x{index:04X}: data types are not listed"
            yield ctx.report("EDS018", message, _entry_at(ctx, found, position))


@rule(
    "EDS016",
    W,
    "Object listed more than once",
    """
Each object appears once across the three object lists. A second entry inflates
SupportedObjects and leaves tools unsure which list is meant. Warning: python-canopen and lely's
dcfchk read the same objects either way.""",
    (
        "[OptionalObjects]\nSupportedObjects=2\n1=0x1017\n2=0x1017\n\n[1017]\n"
        "ParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\n"
        "DefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[OptionalObjects]\nSupportedObjects=1\n1=0x1017\n\n[1017]\nParameterName=Producer heartbeat time\n"
        "ObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(Clause.STYLE, "python-canopen and lely dcfchk read the same objects; the count is inflated"),
)
def listed_twice(ctx: Context) -> Iterator[Finding]:
    seen: dict[int, tuple[str, int]] = {}
    for name, found, position, index in sorted(_listings(ctx), key=lambda e: e[1] is not _home_list(ctx, e)):
        first = seen.setdefault(index, (name, position))
        if first != (name, position):
            fix = Fix(f"remove this entry of 0x{index:04X}", True, _fix_duplicate(index))
            message = f"[{name}] {position}=0x{index:04X}: already listed in [{first[0]}] as {first[1]}"
            yield ctx.report("EDS016", message, _entry_at(ctx, found, position), fix)


def _home_list(ctx: Context, entry: tuple[str, ObjectList, int, int]) -> ObjectList | None:
    target = home(entry[3])
    return object_list(ctx.device, target) if target is not None else None


def _fix_duplicate(index: int) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        target = home(index)
        keep: tuple[str, int] | None = None
        for name, _, position, listed in listings(device):
            if listed == index and (keep is None or (name == target and keep[0] != target)):
                keep = (name, position)
        for name in LISTS:
            found = object_list(device, name)
            if found is not None:
                drop = {p for p, i in found.entries.items() if i == index and (name, p) != keep}
                if drop:
                    _renumber(found, drop)

    return apply


# ---- counting --------------------------------------------------------------------------------------------------


@rule(
    "EDS014",
    E,
    "SupportedObjects does not match the list",
    """
SupportedObjects gives the number of entries of an object list (CiA 306, object lists); tools read
exactly that many entries, so a wrong count drops objects or fails on a missing entry.""",
    (
        "[OptionalObjects]\nSupportedObjects=1\n1=0x1006\n2=0x1017\n\n[1006]\n"
        "ParameterName=Communication cycle period\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0\n[1017]\nParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[OptionalObjects]\nSupportedObjects=2\n1=0x1006\n2=0x1017\n\n[1006]\n"
        "ParameterName=Communication cycle period\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0\n[1017]\nParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "lely dcfchk: too many entries; tools read exactly SupportedObjects entries"
    ),
)
def supported_count(ctx: Context) -> Iterator[Finding]:
    for name in LISTS:
        found = object_list(ctx.device, name)
        if found is None or _invalid_count(found) or found.supported_objects == written_entries(found):
            continue
        count = written_entries(found)
        fix = Fix(f"set SupportedObjects={count}", True, _fix_count(name))
        if found.supported_objects is None:
            message = f"[{name}]: no SupportedObjects (the list has {count} entries)"
            yield ctx.report("EDS014", message, ctx.at(found, "SupportedObjects"), fix)
        else:
            message = (
                f"[{name}]: SupportedObjects={found.supported_objects} but {count} entr{'y' if count == 1 else 'ies'}"
            )
            yield ctx.report("EDS014", message, ctx.value_at(found, "SupportedObjects"), fix)


def _invalid_count(found: ObjectList) -> bool:
    return any(keys.normalize(key) == "supportedobjects" for key in found.extra)  # the reader reported it


def written_entries(found: ObjectList) -> int:
    """The entries the list writes: a position written twice counts twice (EDS015 renumbers it)."""
    return len(found.entries) + sum(len(entries) - 1 for entries in found.repeats.values())


def _fix_count(name: str) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        found = object_list(device, name)
        if found is not None:
            found.supported_objects = written_entries(found)

    return apply


@rule(
    "EDS015",
    E,
    "Object list not numbered 1..n",
    """
The entries of an object list are keyed 1, 2, ... n in decimal, without gaps, repeats, leading
zeros or other keys (CiA 306 §4.5.2). Tools read keys 1..SupportedObjects and miss the others;
python-canopen and lely's dcfchk refuse a file with a number written twice.

Fix (safe): a number written twice keeps its first entry, and each later one moves to the next
free number (the first gap, else after the last): one line changes per repeat, nothing else.
Gaps without repeats are closed by renumbering the entries after the gap, in order.

For example, `12=0x3078`, `12=0x3079` with no 13 becomes `12=0x3078`, `13=0x3079`.""",
    (
        "[OptionalObjects]\nSupportedObjects=2\n1=0x1017\n3=0x1006\n\n[1006]\n"
        "ParameterName=Communication cycle period\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0\n[1017]\nParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[OptionalObjects]\nSupportedObjects=2\n1=0x1017\n2=0x1006\n\n[1006]\n"
        "ParameterName=Communication cycle period\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0\n[1017]\nParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "lely dcfchk: entry missing; tools read keys 1..SupportedObjects only"
    ),
)
def numbering(ctx: Context) -> Iterator[Finding]:
    for name in LISTS:
        found = object_list(ctx.device, name)
        if found is None:
            continue
        yield from _repeats(ctx, name, found)
        positions = sorted(found.entries)
        gaps = list(_missing(positions))
        gaps = gaps[sum(len(entries) - 1 for entries in found.repeats.values()) :]  # filled by the repeats
        if gaps:
            moved = tuple(_entry_line(found, p) for p in positions if p > gaps[0])
            fix = Fix(f"renumber [{name}] 1..{len(positions)}", True, _fix_renumber(name), moved)
            missing = ", ".join(str(g) for g in gaps)
            yield ctx.report("EDS015", f"[{name}]: no entry {missing}", ctx.at(found), fix)
        for key in found.extra:
            if keys.normalize(key) != "supportedobjects" and not _reported(key):
                message = f"[{name}] {key}: not a list position (1, 2, ... in decimal)"
                yield ctx.report("EDS015", message, ctx.at(found, key))


def _missing(positions: list[int]) -> Iterator[int]:
    """The numbers from 1 to the last of `positions` (sorted, distinct) that are not in it, in order; without a set
    of every number, which for a long list would be the largest thing a check of the file holds."""
    last = 0
    for position in positions:
        yield from range(last + 1, position)
        last = position


def _entry_line(found: ObjectList, position: int) -> int:
    return (found.origin.where(str(position)) or (0,))[0] if found.origin is not None else 0


def _repeats(ctx: Context, name: str, found: ObjectList) -> Iterator[Finding]:
    if not found.repeats:
        return
    lines = tuple(line for entries in found.repeats.values() for line, _, _ in entries[1:])
    fix = Fix(f"renumber the repeated entries of [{name}] into free numbers", True, _fix_repeats(name), lines)
    for position, entries in sorted(found.repeats.items()):
        first = entries[0][0]
        for line, column, index in entries[1:]:
            message = f"[{name}] {position}=0x{index:04X}: number {position} already given on line {first}"
            yield ctx.report("EDS015", message, location(ctx.device.source, line, column), fix)


def _free_numbers(found: ObjectList) -> Iterator[int]:
    taken = set(found.entries)
    number = 1
    while True:
        if number not in taken:
            yield number
        number += 1


def _fix_repeats(name: str) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        from ..eds.preserve import respell  # the writers load only when a fix is applied

        found = object_list(device, name)
        if found is None or not found.repeats:
            return  # applied already
        free = _free_numbers(found)
        for position, entries in sorted(found.repeats.items()):
            found.entries[position] = entries[0][2]
            for line, column, index in entries[1:]:
                number = next(free)
                found.entries[number] = index
                respell(device, line, column, str(position), str(number))
        found.entries = dict(sorted(found.entries.items()))
        found.repeats.clear()

    return apply


def _reported(key: str) -> bool:
    """Positions whose value was not an index: the reader reported them (EDS030)."""
    return keys.list_number(key) is not None


def _fix_renumber(name: str) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        found = object_list(device, name)
        if found is not None:
            _renumber(found)

    return apply
