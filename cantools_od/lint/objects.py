"""Rule family: objects — obligation matrix, sub-objects, sub-index 0 and FFh, data types.

CiA 306 §4.6.3; CiA 301 data types and index areas.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from ..model import Device, Object, ObjectKind, Severity, SubObject, Variable
from ..model.cia301.objects import DATA_TYPE_AREA, ERROR_HISTORY
from ..model.cia301.pdo import PDO_AREA
from ..model.datatypes import STANDARD_TYPES, STATIC_TYPE_AREA, UNSIGNED8
from .common import checked_vars, explicit_objects, explicit_vars, given, kind_unknown, where
from .rules import Clause, Context, Finding, Fix, Placement, rule

E, W = Severity.ERROR, Severity.WARNING

_COMPOUND = (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT)
_TYPE_KINDS = (ObjectKind.DEFTYPE, ObjectKind.DEFSTRUCT)


def compact(obj: Object) -> bool:
    return bool(obj.compact_sub_obj)


# ---- object sections -------------------------------------------------------------------------------------------


def _mandatory(obj: Object, sub: bool) -> tuple[str, ...]:
    if sub or obj.kind in (ObjectKind.VAR, ObjectKind.DEFTYPE) or (obj.kind in _COMPOUND and compact(obj)):
        return ("ParameterName", "DataType", "AccessType")
    if obj.kind in _COMPOUND:
        return ("ParameterName", "SubNumber")
    return ("ParameterName",)


def _forbidden(obj: Object, sub: bool) -> tuple[str, ...]:
    if sub or obj.kind in (ObjectKind.VAR, ObjectKind.DEFTYPE):
        return ("SubNumber",)  # CompactSubObj: EDS022
    if obj.kind in _COMPOUND and not compact(obj):
        return ("DataType", "AccessType", "DefaultValue", "PDOMapping", "LowLimit", "HighLimit", "ParameterValue")
    if obj.kind is ObjectKind.DOMAIN:
        return ("PDOMapping", "SubNumber", "LowLimit", "HighLimit")
    return ()


# Sub-objects 0 and 1 of the RECORD "Pair" (2000h) that several examples below show.
_PAIR_SUBS = (
    "[2000sub0]\nParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
    "DefaultValue=1\nPDOMapping=0\n\n[2000sub1]\nParameterName=First\nObjectType=0x7\nDataType=0x0006\n"
    "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
)


@rule(
    "EDS020",
    E,
    "Mandatory key missing",
    """
The obligation matrix of CiA 306 (object descriptions, §4.6.3) makes ParameterName mandatory everywhere;
DataType and AccessType for VAR, DEFTYPE, sub-objects and CompactSubObj objects; SubNumber for
ARRAY, RECORD and DEFSTRUCT without CompactSubObj. A missing key equals an empty one. Tools
crash on these (lely: `KeyError: 'DataType'`) or drop the object.

An XDD's `access="noAccess"` (CiA 311: the entry exists, no SDO reaches it) is a warning: an EDS
has no AccessType that says it (`convert` writes `ro`), and CANopenEditor writes it for entries
whose access type it lost, which a master then cannot configure.""",
    "[2000]\nParameterName=Speed\nDataType=0x0006",
    fixed="[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    per_object=True,
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen raises NoOptionError, lely dcfchk KeyError: 'DataType'"),
)
def missing_keys(ctx: Context) -> Iterator[Finding]:
    xml = ctx.device.file_format != "eds"
    for obj, subindex, var in checked_vars(ctx):
        if kind_unknown(obj):
            continue  # which keys it needs depends on the ObjectType nobody could read (EDS030)
        for key in _mandatory(obj, subindex is not None):
            if xml and key == "ParameterName":
                continue  # an XDD's missing name attribute is XDD006
            if key == "AccessType" and var.no_access:
                yield _no_access(ctx, var, where(obj, subindex))
            elif not given(var, key):
                kind = "a sub-object" if subindex is not None else f"{obj.kind.name}"
                empty = var.origin is not None and var.origin.where(key) is not None
                message = f"{where(obj, subindex)}: {key} is empty" if empty else f"{where(obj, subindex)}: no {key}"
                yield ctx.report("EDS020", f"{message}; {kind} needs it", ctx.at(var, key))


def _no_access(ctx: Context, var: Variable, label: str) -> Finding:
    """An XDD's access="noAccess" is CiA 311: the device has the entry but no SDO reaches it."""
    message = (
        f'{label}: access="noAccess": no SDO reads or writes it, and an EDS has no AccessType for it '
        "(CANopenEditor writes noAccess where it does not know the access type)"
    )
    return ctx.report("EDS020", message, ctx.at(var, "AccessType"))._replace(severity=W)


@rule(
    "EDS024",
    E,
    "Key not allowed for this object type",
    """
Per the obligation matrix of CiA 306 (§4.6.3) ARRAY, RECORD and DEFSTRUCT objects without
CompactSubObj describe their values in sub-objects and carry no DataType, AccessType,
DefaultValue, PDOMapping or limits; DOMAIN objects have no PDOMapping, SubNumber or limits; VAR
and sub-objects have no SubNumber. Tools disagree about what such keys mean.

Error, as a rule: a tool may take the key at its word (sub-objects on a VAR, a mappable DOMAIN).
Warning where the value says what the object type already says: `SubNumber=0` on a VAR or a
sub-object, `PDOMapping=0` on a DOMAIN (CANopenNode's editors write both); every tool reads them
as if they were absent. Warning too for a DataType, AccessType, value or limit on the header of an
ARRAY or RECORD whose sub-objects have their own sections: every peer reads the sub-objects and
passes over the header's keys.""",
    "[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=2\nAccessType=ro\n\n" + _PAIR_SUBS,
    fixed="[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=2\n\n" + _PAIR_SUBS,
    fix_safety="No automatic fix: delete the key.",
    per_object=True,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "lely dcfchk: the key is not supported there; a tool may take it at its word"
    ),
)
def forbidden_keys(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var in checked_vars(ctx):
        if kind_unknown(obj):
            continue  # EDS030: the ObjectType that decides which keys are allowed is unreadable
        for key in _forbidden(obj, subindex is not None):
            if _written(var, key, subindex is not None):
                kind = "a sub-object" if subindex is not None else f"an object of type {obj.kind.name}"
                message = f"{where(obj, subindex)}: {key} is not allowed on {kind}"
                finding = ctx.report("EDS024", message, ctx.at(var, key))
                mild = _says_absent(var, key, subindex is not None) or _header_key(obj, subindex)
                yield finding._replace(severity=W) if mild else finding


def _header_key(obj: Object, subindex: int | None) -> bool:
    """A key on the header of an ARRAY or RECORD whose sub-objects have sections: every peer reads the
    sub-objects and passes over the header's DataType, AccessType or value (python-canopen, lely)."""
    return subindex is None and obj.kind in (ObjectKind.ARRAY, ObjectKind.RECORD) and not obj.compact_sub_obj


def _says_absent(var: Variable, key: str, sub: bool) -> bool:
    """`SubNumber=0` or `PDOMapping=0`: the value every tool takes when the key is absent."""
    if key == "PDOMapping":
        return var.pdo_mapping is False
    if sub:  # a sub-object section keeps SubNumber as text
        return var.extra.get(key, "").strip().lower() in ("0", "0x0", "0x00")
    return key == "SubNumber" and isinstance(var, Object) and var.sub_number == 0


def _written(var: Variable, key: str, sub: bool) -> bool:
    if sub and key in ("SubNumber", "CompactSubObj"):  # a sub-object section keeps them in `extra`
        return bool(var.extra.get(key, "").strip())
    return given(var, key)


@rule(
    "EDS021",
    E,
    "SubNumber does not match the sub-object sections",
    """
SubNumber counts the sub-objects an ARRAY, RECORD or DEFSTRUCT implements, sub-index 0 included
(and FFh excluded); each needs a `[<index>sub<n>]` section. A wrong count makes tools allocate
the wrong number of entries or reject the file.""",
    "[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=3\n\n" + _PAIR_SUBS,
    fixed="[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=2\n\n" + _PAIR_SUBS,
    per_object=True,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "lely dcfchk: missing sub-objects; tools size the object otherwise"),
)
def sub_number(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        if obj.kind not in _COMPOUND or compact(obj) or obj.sub_number is None:
            continue
        count = _explicit_sub_count(obj)
        if obj.sub_number != count:
            message = f"[{obj.index:04X}]: SubNumber={obj.sub_number} but {count} sub-object sections"
            fix = Fix(f"set SubNumber={count}", True, _fix_sub_number(obj.index))
            yield ctx.report("EDS021", message, ctx.value_at(obj, "SubNumber"), fix)


def _explicit_sub_count(obj: Object) -> int:
    return sum(1 for subindex, sub in obj.subs.items() if not sub.implicit and subindex != 0xFF)


def _fix_sub_number(index: int) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        obj = device.objects.get(index)
        if obj is not None:
            obj.sub_number = _explicit_sub_count(obj)

    return apply


@rule(
    "EDS022",
    E,
    "CompactSubObj misused",
    """
CompactSubObj (CiA 306 §4.6.3.4.2) describes the sub-objects of an ARRAY (lely: also RECORD)
implicitly: sub0 plus subs 1..n copied from the object. It is not allowed on VAR, DOMAIN or
sub-objects, must be 1..254, and excludes both a non-zero SubNumber and `[<index>sub<n>]`
sections, which would describe the same sub-objects twice.""",
    "[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=4\nSubNumber=5",
    fixed="[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=4",
    per_object=True,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE,
        "lely dcfchk rejects SubNumber with CompactSubObj; the sub-objects are described twice",
    ),
)
def compact_misuse(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        name = f"[{obj.index:04X}]"
        for subindex, sub in obj.subs.items():
            if not sub.implicit and sub.extra.get("CompactSubObj", "").strip() not in ("", "0"):
                yield ctx.report("EDS022", f"{where(obj, subindex)}: CompactSubObj on a sub-object", ctx.at(sub))
        if not obj.compact_sub_obj:
            continue
        if obj.kind not in _COMPOUND:
            message = f"{name}: CompactSubObj on an object of type {obj.kind.name}"
            yield ctx.report("EDS022", message, ctx.at(obj, "CompactSubObj"))
            continue
        if not 1 <= obj.compact_sub_obj <= 0xFE:
            message = f"{name}: CompactSubObj={obj.compact_sub_obj} is not 1..254"
            yield ctx.report("EDS022", message, ctx.value_at(obj, "CompactSubObj"))
        if obj.sub_number:
            message = f"{name}: SubNumber={obj.sub_number} together with CompactSubObj (must be absent or 0)"
            yield ctx.report("EDS022", message, ctx.at(obj, "SubNumber"))
        for subindex, sub in obj.subs.items():
            if not sub.implicit:
                message = f"{where(obj, subindex)}: sub-object section of a CompactSubObj object"
                yield ctx.report("EDS022", message, ctx.at(sub))


@rule(
    "EDS023",
    E,
    "ObjFlags reserved bits set",
    """
ObjFlags (CiA 306 §4.6.3.3) defines bit 0 (refuse write on download) and bit 1 (refuse read on
scan); bits 2-31 are reserved and must be 0. lely ORs ObjFlags into its own flag word, where
reserved bits switch on lely-internal behaviour.""",
    "[2000]\nParameterName=Setpoint\nDataType=0x0006\nAccessType=rw\nObjFlags=0x4",
    fixed=(
        "[2000]\nParameterName=Setpoint\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0\nObjFlags=0x0"
    ),
    per_object=True,
    placed=Placement(
        Clause.DEVICE_MISBEHAVES,
        "lely ORs ObjFlags into its flag word: reserved bits switch on lely-internal behaviour",
    ),
)
def obj_flags(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var in checked_vars(ctx):
        if var.obj_flags is not None and var.obj_flags & ~0x3:
            message = f"{where(obj, subindex)}: ObjFlags=0x{var.obj_flags:X} sets reserved bits (only bits 0 and 1)"
            yield ctx.report("EDS023", message, ctx.value_at(var, "ObjFlags"))


def _has_subs(obj: Object) -> bool:
    return obj.kind in _COMPOUND and not compact(obj)


@rule(
    "EDS025",
    E,
    "Sub-index 0 missing or not UNSIGNED8",
    """
Every ARRAY, RECORD and DEFSTRUCT has a sub-index 0 of type UNSIGNED8 (0x0005) holding the
highest sub-index (or the number of entries). Tools read it to size the object; without it, or
with another type, they reject the object or read the wrong count.""",
    (
        "[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=2\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\n"
        "DefaultValue=1\nPDOMapping=0\n\n[2000sub1]\nParameterName=First\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed="[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=2\n\n" + _PAIR_SUBS,
    per_object=True,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "lely dcfchk: DataType should be UNSIGNED8; tools read the wrong count"
    ),
)
def sub0_type(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        if not _has_subs(obj):
            continue
        sub0 = obj.subs.get(0)
        if sub0 is None:
            yield ctx.report("EDS025", f"[{obj.index:04X}]: no sub-index 0 ({obj.kind.name})", ctx.at(obj))
        elif sub0.data_type is not None and ctx.device.entry_type(sub0, obj) is not UNSIGNED8:
            message = f"[{obj.index:04X}sub0]: DataType=0x{sub0.data_type:04X}; sub-index 0 is UNSIGNED8 (0x0005)"
            yield ctx.report("EDS025", message, ctx.value_at(sub0, "DataType"))


def _counts_entries(obj: Object, sub0: SubObject) -> bool:
    """Objects whose sub0 is a number of valid entries rather than the highest sub-index."""
    if obj.index == ERROR_HISTORY or obj.index in PDO_AREA:  # error history; PDOs (PDO010/PDO040)
        return True
    return sub0.access is not None and sub0.access.writable


@rule(
    "EDS026",
    E,
    "Sub-index 0 below the highest sub-index",
    """
Sub-index 0 of an ARRAY or RECORD holds the highest sub-index it implements; sub-indices need not
be consecutive (1010h may have sub0 and sub4 only, sub0=4). A smaller value hides the upper
sub-objects. The value judged is the one the device holds: a DCF's ParameterValue, else the
DefaultValue. Not checked: 1003h (sub0 counts the errors), PDO objects (see the PDO rules) and
objects whose sub0 is writable, where sub0 counts the valid entries.""",
    (
        "[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=3\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=1\nPDOMapping=0\n\n[2000sub1]\nParameterName=First\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n[2000sub2]\nParameterName=Second\nObjectType=0x7\n"
        "DataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=3\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=2\nPDOMapping=0\n\n[2000sub1]\nParameterName=First\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n[2000sub2]\nParameterName=Second\nObjectType=0x7\n"
        "DataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    per_object=True,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "the upper sub-objects are hidden from a master that reads sub-index 0"
    ),
)
def sub0_value(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        sub0 = obj.subs.get(0)
        if not _has_subs(obj) or sub0 is None or _counts_entries(obj, sub0):
            continue
        highest, held, key = _highest(obj), sub0.held, sub0.held_key
        if isinstance(held, int) and not isinstance(held, bool) and held < highest:
            message = f"[{obj.index:04X}sub0]: {key}={held} but sub-index {highest} exists"
            # Unsafe: the value every reader reads changes, and a vendor's sub0 may count entries.
            fix = Fix(f"set {key}={highest}", False, _fix_sub0(obj.index))
            yield ctx.report("EDS026", message, ctx.value_at(sub0, key), fix)


def _highest(obj: Object) -> int:
    return max((subindex for subindex in obj.subs if subindex != 0xFF), default=0)


def _fix_sub0(index: int) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        obj = device.objects.get(index)
        sub0 = obj.subs.get(0) if obj is not None else None
        if obj is None or sub0 is None or not isinstance(sub0.held, int):
            return
        sub0.hold(max(sub0.held, _highest(obj)))

    return apply


@rule(
    "EDS027",
    E,
    "Sub-index FFh described",
    """
Sub-index FFh is reserved: it holds the object's data type and object code, is not counted by
SubNumber and is never described in an EDS.""",
    (
        "[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=2\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=1\nPDOMapping=0\n\n[2000sub1]\nParameterName=First\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n[2000subFF]\nParameterName=Structure\n"
        "ObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed="[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=2\n\n" + _PAIR_SUBS,
    per_object=True,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "lely dcfchk: invalid sub-index; FFh is the object's structure, never a value"
    ),
)
def sub_ff(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        sub = obj.subs.get(0xFF)
        if sub is not None and not sub.implicit:
            yield ctx.report("EDS027", f"[{obj.index:04X}subFF]: sub-index FFh is reserved", ctx.at(sub))


@rule(
    "EDS028",
    E,
    "ARRAY elements of different data types",
    """
All elements (sub-index 1 and above) of an ARRAY share one data type; only a RECORD mixes types.
Tools and generated code store an ARRAY as one C array.""",
    (
        "[2000]\nParameterName=Gains\nObjectType=0x8\nSubNumber=3\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=2\nPDOMapping=0\n\n[2000sub1]\nParameterName=Gain 1\nObjectType=0x7\n"
        "DataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n[2000sub2]\nParameterName=Gain 2\n"
        "ObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[2000]\nParameterName=Gains\nObjectType=0x8\nSubNumber=3\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=2\nPDOMapping=0\n\n[2000sub1]\nParameterName=Gain 1\nObjectType=0x7\n"
        "DataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n[2000sub2]\nParameterName=Gain 2\n"
        "ObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    per_object=True,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "one C array in generated code: the elements' own types are lost"),
)
def array_types(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        if obj.kind is not ObjectKind.ARRAY or compact(obj):
            continue
        elements = [(i, s) for i, s in obj.subs.items() if 1 <= i <= 0xFE and s.data_type is not None]
        if not elements:
            continue
        first_index, first = elements[0]
        for subindex, sub in elements[1:]:
            if sub.data_type != first.data_type:
                message = (
                    f"[{obj.index:04X}sub{subindex:X}]: DataType=0x{sub.data_type:04X} but sub{first_index:X} "
                    f"has 0x{first.data_type:04X}; ARRAY elements share one type"
                )
                yield ctx.report("EDS028", message, ctx.value_at(sub, "DataType"))


# ---- data types ------------------------------------------------------------------------------------------------


def _typed_vars(device: Device) -> Iterator[tuple[Object, int | None, Variable]]:
    """Entries whose DataType means something (not ARRAY/RECORD/DEFSTRUCT objects without CompactSubObj)."""
    for obj, subindex, var in explicit_vars(device):
        if subindex is not None or not _has_subs(obj):
            yield obj, subindex, var


@rule(
    "EDS080",
    E,
    "DataType not defined",
    """
DataType names a CiA 301 data type (0001h-001Bh, 0020h-0023h) or a type the file defines with a
DEFTYPE or DEFSTRUCT object at that index. Reserved indices (000Eh, 0017h, 001Ch-001Fh) and
custom types without their definition cannot be read: python-canopen falls back to DOMAIN,
canmatrix and lely fail.""",
    "[2000]\nParameterName=Gain\nDataType=0x0040\nAccessType=rw",
    fixed="[2000]\nParameterName=Gain\nObjectType=0x7\nDataType=0x0008\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    per_object=True,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "python-canopen falls back to DOMAIN; lely and canmatrix fail"),
)
def undefined_types(ctx: Context) -> Iterator[Finding]:
    objects = ctx.device.objects
    for obj, subindex, var in _typed_vars(ctx.device):
        dtype = var.data_type
        if dtype is None or dtype in STANDARD_TYPES:
            continue
        definition = objects.get(dtype)
        if dtype in DATA_TYPE_AREA and definition is not None and definition.kind in _TYPE_KINDS:
            continue
        reason = "reserved data type index" if dtype in STATIC_TYPE_AREA else "no DEFTYPE/DEFSTRUCT object defines it"
        message = f"{where(obj, subindex)}: DataType=0x{dtype:04X}: {reason}"
        yield ctx.report("EDS080", message, ctx.value_at(var, "DataType"))


@rule(
    "EDS081",
    E,
    "Object type does not fit the data-type index area",
    """
Indices 0001h-0FFFh hold data types: DEFTYPE and DEFSTRUCT objects belong there and nowhere
else, and nothing else belongs there (CiA 301, object dictionary index areas). Index 0000h is not used.""",
    "; also: DIA005 (every DEFTYPE)\n[2000]\nParameterName=My type\nObjectType=0x5\nDataType=0x0007\nAccessType=ro",
    fixed="[2000]\nParameterName=Setting\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fix_safety="No automatic fix: move the definition below 1000h, or use the basic type itself as here.",
    per_object=True,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE,
        "the data-type area holds data types only: peers read the object as a type or drop it",
    ),
)
def type_area(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        in_area = obj.index in DATA_TYPE_AREA
        if obj.index == 0:
            yield ctx.report("EDS081", "[0000]: index 0000h is not used", ctx.at(obj))
        elif obj.kind in _TYPE_KINDS and not in_area:
            message = f"[{obj.index:04X}]: {obj.kind.name} outside the data-type area 0001h-0FFFh"
            yield ctx.report("EDS081", message, ctx.at(obj, "ObjectType"))
        elif obj.kind not in _TYPE_KINDS and in_area:
            message = f"[{obj.index:04X}]: {obj.kind.name} in the data-type area; only DEFTYPE/DEFSTRUCT belong there"
            yield ctx.report("EDS081", message, ctx.at(obj, "ObjectType"))
