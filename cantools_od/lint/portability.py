"""Rule family: portability — what python-canopen, lely and CANopenNode read differently (dialects of peer tools).

These rules find nothing wrong by CiA 306; they point at content that a peer tool drops, misreads
or rejects, so that a file meant for those tools can be adjusted.
"""

from __future__ import annotations

import re
from collections import Counter
from collections.abc import Iterator
from weakref import WeakKeyDictionary

from ..canopennode.info import EDS_COMMENT_KEYS
from ..eds import keys
from ..eds.decode import decode_as
from ..model import (
    Dialect,
    NodeIdExpr,
    ObjectKind,
    Section,
    Severity,
    ValueKind,
    Variable,
)
from ..model.cia301.objects import DATA_TYPE_AREA
from ..model.cia301.pdo import DUMMY_TYPES
from ..model.datatypes import BASIC_TYPE_RANGE
from ..model.source import location
from .common import checked_vars, where
from .rules import Clause, Context, Finding, Placement, rule
from .syntax import EXTENSION_KEYS, RESERVED_DEVICE_INFO, spellings

E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

_EXTENSION_KEYS = {keys.normalize(key) for key in EXTENSION_KEYS}
_STRING_FIELDS = (("ParameterName", "name"), ("Denotation", "denotation"))
_EXTENSIONS = EDS_COMMENT_KEYS
_TEXT_FIELDS = (*_STRING_FIELDS, ("DefaultValue", "default"), ("ParameterValue", "parameter_value"))


@rule(
    "DIA001",
    E,
    "[DummyUsage] lacks one of Dummy0001..Dummy0007",
    """
python-canopen reads Dummy0001 to Dummy0007 from [DummyUsage] and raises an exception when one
is missing, although CiA 306 treats a missing key as "not supported" (sparse lely DCFs fail
this way). Error, though the file is right by CiA 306: python-canopen cannot load it at all
(NoOptionError). Write all seven keys, with 0 where a type is not usable as a dummy.""",
    "[DummyUsage]\nDummy0005=1\nDummy0006=1\nDummy0007=1",
    fixed="[DummyUsage]\nDummy0001=0\nDummy0002=0\nDummy0003=0\nDummy0004=0\nDummy0005=1\nDummy0006=1\nDummy0007=1",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen raises NoOptionError: No option 'Dummy0001'"),
)
def dummy_usage(ctx: Context) -> Iterator[Finding]:
    usage = ctx.device.dummy_usage
    if usage is None:
        return
    missing = [f"Dummy{index:04X}" for index in DUMMY_TYPES if index not in usage.enabled]
    if missing:
        message = f"[DummyUsage] lacks {', '.join(missing)}; python-canopen fails to load the file"
        yield ctx.report("DIA001", message, ctx.at(usage))


@rule(
    "DIA002",
    W,
    "Quoted string outside a lely file",
    """
lely writes VISIBLE_STRING values in double quotes and strips them when reading; CiA 306 and the
other tools take the quotes as part of the text. In a file that is not otherwise lely's, a quoted
value is read with its quotes everywhere but in lely.""",
    '[1008]\nParameterName=Device name\nDataType=0x0009\nAccessType=const\nDefaultValue="Drive"',
    fixed=(
        "[1008]\nParameterName=Device name\nObjectType=0x7\nDataType=0x0009\nAccessType=const\n"
        "DefaultValue=Drive\nPDOMapping=0"
    ),
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "lely strips the quotes, the others keep them"),
)
def quoted_strings(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    if device.dialect is Dialect.LELY:
        return
    for obj, subindex, var in checked_vars(ctx):
        dtype = device.entry_type(var, obj)
        if dtype is None or dtype.kind is not ValueKind.STRING:
            continue
        for key, value in (("DefaultValue", var.default), ("ParameterValue", var.parameter_value)):
            if isinstance(value, str) and len(value) >= 2 and value[0] == value[-1] == '"':
                message = f"{where(obj, subindex)} {key}={value}: lely strips the quotes, other tools keep them"
                yield ctx.report("DIA002", message, ctx.value_at(var, key))


@rule(
    "DIA003",
    W,
    "REAL values as lely bit patterns",
    """
CiA 306 does not say how REAL32/REAL64 values are written. lely writes IEEE bit patterns
(`0x40490FDB`), which python-canopen drops without a word and CANopenNode copies into C as
integers. Decimals, the form the other tools read, are rejected by lely, so a lely file keeps
its REAL values only for lely. Reported once per file with the lely dialect, at the first REAL
value.""",
    "[DeviceInfo]\nVendorName=Lely Industries N.V.\n[2000]\nParameterName=Gain\nDataType=0x0008\nAccessType=rw\n"
    "DefaultValue=0x3FC00000",
    fixed="[2000]\nParameterName=Gain\nObjectType=0x7\nDataType=0x0008\nAccessType=rw\nDefaultValue=1.5\nPDOMapping=0",
    placed=Placement(Clause.PORTABILITY, "lely's form: python-canopen drops it, CANopenNode copies it as an integer"),
)
def real_values(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    if device.dialect is not Dialect.LELY:
        return  # decimals: what python-canopen and CANopenNode read
    found: list[tuple[Variable, str]] = []
    for obj, _, var in checked_vars(ctx):
        dtype = device.entry_type(var, obj)
        if dtype is not None and dtype.kind is ValueKind.REAL:
            found.extend((var, key) for key, field in _VALUE_KEYS if isinstance(getattr(var, field), float))
    if found:
        count = f"{len(found)} REAL value{'s' if len(found) != 1 else ''}"
        message = f"{count} in lely's bit-pattern form; python-canopen drops them, CANopenNode misreads them"
        yield ctx.report("DIA003", message, ctx.value_at(found[0][0], found[0][1]))


_VALUE_KEYS = (("DefaultValue", "default"), ("ParameterValue", "parameter_value"),
               ("LowLimit", "low_limit"), ("HighLimit", "high_limit"))  # fmt: skip


@rule(
    "DIA004",
    W,
    "CompactSubObj on a RECORD",
    """
CiA 306 defines CompactSubObj for ARRAY objects; lely also writes it on RECORDs (all its PDO
mapping objects). python-canopen turns such a RECORD into an empty record and ignores its
[xxxxValue] section, so PDO mappings are lost; CANopenEditor expands it.""",
    "[2000]\nParameterName=Pair\nObjectType=0x9\nDataType=0x0007\nAccessType=rw\nCompactSubObj=2",
    fixed="[2000]\nParameterName=Pair\nObjectType=0x8\nDataType=0x0007\nAccessType=rw\nCompactSubObj=2",
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "lely's form: python-canopen reads an empty record"),
)
def compact_record(ctx: Context) -> Iterator[Finding]:
    for obj in ctx.device.objects.values():
        if not obj.implicit and obj.kind is ObjectKind.RECORD and obj.compact_sub_obj:
            message = f"[{obj.index:04X}]: CompactSubObj on a RECORD; python-canopen reads an empty record"
            yield ctx.report("DIA004", message, ctx.at(obj, "CompactSubObj"))


@rule(
    "DIA005",
    W,
    "DEFTYPE or DEFSTRUCT object",
    """
Data-type definitions (ObjectType 0x5/0x6) are valid CiA 306, but lely dcfchk rejects them ("not
supported") and python-canopen skips them, failing with a KeyError on their sub-objects. Entries
typed by them become unreadable there.""",
    "[0040]\nParameterName=Unsigned32 alias\nObjectType=0x5\nDataType=0x0007\nAccessType=ro\n\n"
    "[2000]\nParameterName=Setting\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fixed="[2000]\nParameterName=Setting\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fix_safety="No automatic fix: type the entries by the basic types and delete the definition.",
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "CiA 306, but lely dcfchk rejects it and python-canopen skips it"),
)
def type_definitions(ctx: Context) -> Iterator[Finding]:
    for obj in ctx.device.objects.values():
        if not obj.implicit and obj.kind in (ObjectKind.DEFTYPE, ObjectKind.DEFSTRUCT):
            message = f"[{obj.index:04X}]: {obj.kind.name}; lely rejects it and python-canopen skips it"
            yield ctx.report("DIA005", message, ctx.at(obj))


@rule(
    "DIA006",
    INFO,
    "CANopenNode extension comments",
    """
CANopenEditor and eds-utils keep CANopenNode settings as comment lines (`;StorageLocation=RAM`,
`;TPDODetectCos=1`). Other tools ignore them, so the storage groups they define exist only for
CANopenNode's code generators. Reported once per file.""",
    (
        "[2000]\nParameterName=Counter\n;StorageLocation=PERSIST_COMM\nObjectType=0x7\nDataType=0x0007\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[2000]\nParameterName=Counter\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(Clause.DECISION, "only CANopenNode's generators read these comments"),
)
def extension_comments(ctx: Context) -> Iterator[Finding]:
    found: list[Section] = []
    for _, _, var in checked_vars(ctx):
        if var.comments and any(line.startswith(_EXTENSIONS) for block in var.comments.values() for line in block):
            found.append(var)
    if found:
        message = f"{len(found)} section{'s' if len(found) != 1 else ''} with {'/'.join(_EXTENSIONS)} comments"
        yield ctx.report("DIA006", message + "; only CANopenNode tools read them", ctx.at(found[0]))


@rule(
    "DIA007",
    W,
    "Text outside ASCII",
    """
CiA 306 files are ASCII. Names, denotations and [FileInfo]/[DeviceInfo] texts with other
characters (`µ`, `°C`, `‰`) depend on the file's encoding, which tools guess differently
(python-canopen uses the locale; non-UTF-8 fails). Generated code and documentation then carry
mangled names. VISIBLE_STRING values are checked by EDS038.""",
    (
        "[2000]\nParameterName=Motor rated current µA\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
        "DefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[2000]\nParameterName=Motor rated current uA\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
        "DefaultValue=0\nPDOMapping=0"
    ),
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "tools guess the encoding differently"),
)
def non_ascii(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    for owner, subindex, var in checked_vars(ctx):
        for key, field in _STRING_FIELDS:  # VISIBLE_STRING values: EDS038
            value = getattr(var, field)
            if isinstance(value, str) and not value.isascii():
                yield ctx.report(
                    "DIA007", f"{where(owner, subindex)} {key}: {value!r} is not ASCII", ctx.value_at(var, key)
                )
    tables: tuple[tuple[str, Section, dict[str, keys.KeySpec]], ...] = (
        ("FileInfo", device.file_info, keys.FILE_INFO_KEYS),
        ("DeviceInfo", device.device_info, keys.DEVICE_INFO_KEYS),
    )
    for name, section, table in tables:
        for spelling, field, kind in table.values():
            value = getattr(section, field, None) if kind is keys.Kind.STR else None
            if isinstance(value, str) and not value.isascii():
                message = f"[{name}] {spelling}: {value!r} is not ASCII"
                yield ctx.report("DIA007", message, ctx.value_at(section, spelling))


@rule(
    "DIA008",
    W,
    "Custom data type on an entry",
    """
An entry typed by a DEFTYPE/DEFSTRUCT data type (DataType above 001Bh and defined in the file)
is valid CiA 306, but python-canopen falls back to DOMAIN for it, canmatrix fails and lely does
not support it. Undefined custom types are reported by EDS080.""",
    "; also: DIA005 (the definition the type needs)\n"
    "[0040]\nParameterName=Unsigned32 alias\nObjectType=0x5\nDataType=0x0007\nAccessType=ro\n\n"
    "[2000]\nParameterName=Setting\nObjectType=0x7\nDataType=0x0040\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fixed="[2000]\nParameterName=Setting\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fix_safety="No automatic fix: type the entry by the basic type the definition stands for.",
    per_object=True,
    placed=Placement(
        Clause.PORTABILITY, "CiA 306, but python-canopen falls back to DOMAIN and lely does not support it"
    ),
)
def custom_types(ctx: Context) -> Iterator[Finding]:
    objects = ctx.device.objects
    for owner, subindex, var in checked_vars(ctx):
        dtype = var.data_type
        # (`None in range(...)` would compare None with every number of the range)
        custom = dtype is not None and dtype in DATA_TYPE_AREA and dtype not in BASIC_TYPE_RANGE
        definition = objects.get(dtype) if dtype is not None and custom else None
        if definition is not None and definition.kind in (ObjectKind.DEFTYPE, ObjectKind.DEFSTRUCT):
            message = (
                f"{where(owner, subindex)} DataType=0x{dtype:04X} (a custom type); python-canopen reads it as DOMAIN"
            )
            yield ctx.report("DIA008", message, ctx.value_at(var, "DataType"))


@rule(
    "DIA009",
    INFO,
    "RECORD sub-objects with the same name",
    """
CANopenNode's generator names the members of a RECORD's C structure after its sub-objects'
ParameterNames; two sub-objects with the same name produce colliding members, and other code
generators (and CANopenEditor, #55) drop one of them.""",
    (
        "[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=3\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=2\nPDOMapping=0\n\n[2000sub1]\nParameterName=Value\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n[2000sub2]\nParameterName=Value\nObjectType=0x7\n"
        "DataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed=(
        "[2000]\nParameterName=Pair\nObjectType=0x9\nSubNumber=3\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=2\nPDOMapping=0\n\n[2000sub1]\nParameterName=Value 1\nObjectType=0x7\n"
        "DataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0\n\n[2000sub2]\n"
        "ParameterName=Value 2\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0"
    ),
    per_object=True,
    placed=Placement(Clause.DECISION, "generated structures and CANopenEditor drop one of the members"),
)
def duplicate_names(ctx: Context) -> Iterator[Finding]:
    for obj in ctx.device.objects.values():
        if obj.implicit or obj.kind is not ObjectKind.RECORD:
            continue
        counts = Counter(sub.name for sub in obj.subs.values() if sub.name)
        seen: set[str] = set()
        for subindex, sub in obj.subs.items():
            if counts[sub.name] > 1 and sub.name in seen:
                message = f"[{obj.index:04X}sub{subindex:X}]: name {sub.name!r} repeats an earlier sub-object's"
                where = ctx.at(obj) if sub.implicit else ctx.at(sub, "ParameterName")
                yield ctx.report("DIA009", message, where)
            seen.add(sub.name)


@rule(
    "DIA010",
    W,
    "python-canopen extension key",
    """
python-canopen reads the keys Factor, Unit, Description and StorageLocation in object sections;
they are not CiA 306 keys, and lely dcfchk rejects them as invalid entries.""",
    "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\nUnit=rpm",
    fixed=(
        "[2000]\nParameterName=Speed (rpm)\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\n"
        "DefaultValue=0\nPDOMapping=0"
    ),
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "python-canopen's key: lely dcfchk rejects it as an invalid entry"),
)
def extension_keys(ctx: Context) -> Iterator[Finding]:
    for owner, subindex, var in checked_vars(ctx):
        for key in var.extra:
            if keys.normalize(key) in _EXTENSION_KEYS:
                message = f"{where(owner, subindex)} {key}: read by python-canopen only; lely rejects it"
                yield ctx.report("DIA010", message, ctx.at(var, key))


@rule(
    "DIA011",
    INFO,
    "Reserved [DeviceInfo] compatibility key",
    """
CiA 306 reserves ProductVersion, ProductRevision, LMT_ManufacturerName, LMT_ProductName,
ExtendedBootUpMaster and ExtendedBootUpSlave in [DeviceInfo] for compatibility; they are
valid, but lely dcfchk wrongly rejects them as unknown keys.""",
    "[DeviceInfo]\nProductVersion=1",
    fixed=("[DeviceInfo]\nVendorName=Example"),
    placed=Placement(Clause.DECISION, "CiA 306's compatibility keys; lely dcfchk wrongly rejects them"),
)
def reserved_keys(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.device_info
    reserved = {keys.normalize(k) for k in RESERVED_DEVICE_INFO}
    for key in info.extra:
        if keys.normalize(key) in reserved:
            yield ctx.report("DIA011", f"[DeviceInfo] {key}: lely dcfchk rejects this reserved key", ctx.at(info, key))


@rule(
    "DIA012",
    INFO,
    "Module-concept sections",
    """
The module concept ([SupportedModules], [M<x>...], [ConnectedModules]) is CiA 306, but only
CANopenEditor reads it, partially: lely dcfchk fails on the sections and python-canopen ignores
them, so the objects of the modules are missing there. Reported once per file.""",
    "[SupportedModules]\nNrOfEntries=1\n[M1ModuleInfo]\nProductName=Input module",
    fixed="; the module's objects described as the device's own\n[2000]\nParameterName=Input module inputs\n"
    "ObjectType=0x7\nDataType=0x0005\nAccessType=ro\nDefaultValue=0\nPDOMapping=1",
    placed=Placement(Clause.DECISION, "CiA 306, read only by CANopenEditor"),
)
def module_sections(ctx: Context) -> Iterator[Finding]:
    sections = ctx.device.module_sections
    if sections:
        message = f"{len(sections)} module-concept sections; only CANopenEditor reads them"
        yield ctx.report("DIA012", message, ctx.at(sections[0]))


@rule(
    "DIA013",
    W,
    "TIME value",
    """
CiA 306 does not specify how TIME_OF_DAY and TIME_DIFFERENCE values are written. lely writes
`days ms`; python-canopen concatenates the two numbers into one integer (`365 43200000` becomes
36543200000) and CANopenNode expects a byte array.""",
    "[2000]\nParameterName=Start\nDataType=0x000C\nAccessType=rw\nDefaultValue=365 43200000",
    fixed="[2000]\nParameterName=Start\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "CiA 306 has no form: python-canopen concatenates lely's `days ms`"),
)
def time_values(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    for obj, subindex, var in checked_vars(ctx):
        dtype = device.entry_type(var, obj)
        if dtype is None or dtype.kind is not ValueKind.TIME:
            continue
        for key, field in _VALUE_KEYS:
            if getattr(var, field) is not None:
                message = f"{where(obj, subindex)} {key} of {dtype.name}: no portable text form"
                yield ctx.report("DIA013", message, ctx.value_at(var, key))


@rule(
    "DIA014",
    W,
    "$NODEID in a limit",
    """
CiA 306 allows `$NODEID` in LowLimit and HighLimit, but only lely reads it there; python-canopen
and CANopenNode drop or reject such limits.""",
    (
        "[2000]\nParameterName=Response COB-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
        "DefaultValue=$NODEID+0x580\nPDOMapping=0\nLowLimit=$NODEID+0x580"
    ),
    fixed=(
        "[2000]\nParameterName=Response COB-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
        "DefaultValue=$NODEID+0x580\nPDOMapping=0\nLowLimit=0x581"
    ),
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "CiA 306 allows it; python-canopen and CANopenNode drop such limits"),
)
def nodeid_limits(ctx: Context) -> Iterator[Finding]:
    for owner, subindex, var in checked_vars(ctx):
        for key, value in (("LowLimit", var.low_limit), ("HighLimit", var.high_limit)):
            if isinstance(value, NodeIdExpr):
                message = f"{where(owner, subindex)} {key}={value.canonical()}: only lely reads $NODEID in limits"
                yield ctx.report("DIA014", message, ctx.value_at(var, key))


@rule(
    "DIA015",
    E,
    "Empty PDOMapping",
    """
`PDOMapping=` without a value means 0 in CiA 306 (an empty entry equals a missing one), but
python-canopen fails on it (`int('')`, canopen #385). Error, though the file is right by CiA 306:
python-canopen cannot load it at all. Write 0 or leave the key out.""",
    "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\nPDOMapping=",
    fixed="[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    per_object=True,
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen raises ValueError on int('')"),
)
def empty_pdo_mapping(ctx: Context) -> Iterator[Finding]:
    for owner, subindex, var in checked_vars(ctx):
        written = var.origin is not None and var.origin.where("PDOMapping") is not None
        invalid = any(keys.normalize(k) == "pdomapping" for k in var.extra)  # the reader reported it
        if written and var.pdo_mapping is None and not invalid:
            message = f"{where(owner, subindex)} PDOMapping is empty; python-canopen fails on it"
            yield ctx.report("DIA015", message, ctx.at(var, "PDOMapping"))


@rule(
    "DIA016",
    INFO,
    "ObjFlags set",
    """
ObjFlags bit 0 (refuse write on download) and bit 1 (refuse read on scan) are CiA 306, but lely
ORs the value into its own flag word with bits 0 and 1 swapped, python-canopen keeps it as an
unknown option and the lely code generator drops it. Reported once per file.""",
    "[2000]\nParameterName=Serial number\nDataType=0x0007\nAccessType=ro\nObjFlags=0x2",
    fixed=(
        "[2000]\nParameterName=Serial number\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\n"
        "DefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(Clause.DECISION, "lely swaps bits 0 and 1, python-canopen keeps it as an option"),
)
def obj_flags(ctx: Context) -> Iterator[Finding]:
    found = [
        (where(obj, subindex), var)
        for obj, subindex, var in checked_vars(ctx)
        if var.obj_flags and not var.obj_flags & ~0x3
    ]
    if found:
        label, var = found[0]
        message = f"{_count(found, 'entry', 'entries')} with ObjFlags (first {label}); lely swaps bits 0 and 1"
        yield ctx.report("DIA016", message + ", python-canopen ignores them", ctx.value_at(var, "ObjFlags"))


def _count(items: list[tuple[str, Variable]] | list[tuple[str, Variable, str]], one: str, many: str) -> str:
    return f"{len(items)} {one if len(items) == 1 else many}"


@rule(
    "DIA017",
    W,
    "';' or '#' in a text value",
    """
CiA 306 has no inline comments: `Motor #1; left` is a legal name. lely's C parser ends the value
at the first `#` or `;`, lely's Python tools and python-canopen at a `;` (lely: also `#`) after
a blank, so those tools read a truncated name or string. Reported once per file.""",
    "[2000]\nParameterName=Motor #1 speed\nDataType=0x0006\nAccessType=rw",
    fixed=(
        "[2000]\nParameterName=Motor 1 speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\n"
        "DefaultValue=0\nPDOMapping=0"
    ),
    placed=Placement(
        Clause.PORTABILITY, "right by CiA 306; lely and python-canopen cut the text at the comment character"
    ),
)
def comment_characters(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    found: list[tuple[str, Variable, str]] = []
    for obj, subindex, var in checked_vars(ctx):
        for text in (var.name, var.denotation, var.default, var.parameter_value):
            if isinstance(text, str) and ("#" in text or ";" in text):
                break
        else:
            continue  # the common case, decided at once
        for key, field in _TEXT_FIELDS:
            value = getattr(var, field)
            if not isinstance(value, str) or ("#" not in value and ";" not in value):
                continue
            if field not in ("name", "denotation"):  # a value: text only when the entry is a string
                dtype = device.entry_type(var, obj)
                if dtype is None or dtype.kind is not ValueKind.STRING:
                    continue
            found.append((f"{where(obj, subindex)} {key}", var, key))
    if found:
        first = ", ".join(item[0] for item in found[:3]) + (", ..." if len(found) > 3 else "")
        message = f"{_count(found, 'text value', 'text values')} with '#' or ';' ({first}); lely cuts them there"
        yield ctx.report("DIA017", message, ctx.value_at(found[0][1], found[0][2]))


@rule(
    "DIA018",
    W,
    "Key or section name in another case than CiA 306",
    """
CiA 306 key and section names are case-insensitive, but python-canopen looks them up
case-sensitively: a key written `NrOfRxPDO` or `Baudrate_500`, or a section `[deviceinfo]`, is not
found there, and the tool silently takes a default (no PDOs, no baud rate). lely finds them.

Warning: the file is right by CiA 306; one peer misreads it. Names that no peer finds (blanks,
other letters) are EDS091.
Fix: the name is written as CiA 306 spells it; the rest of the line stays. Safe for a name
python-canopen does not look up; unsafe (`--unsafe-fixes`) for one it does (it then reads a value
it did not read before).""",
    ("[DeviceInfo]\nNrOfRxPDO=0"),
    fixed=("[DeviceInfo]\nNrOfRXPDO=0"),
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "right by CiA 306; python-canopen looks names up case-sensitively"),
)
def key_spelling(ctx: Context) -> Iterator[Finding]:
    for spelling in spellings(ctx):
        if spelling.found_by_peers:
            what = "section names" if spelling.header else "keys"
            message = f"{spelling.written}: CiA 306 spells it {spelling.canonical}; "
            message += f"python-canopen reads {what} case-sensitively"
            yield ctx.report("DIA018", message, spelling.where, spelling.fix())


# ---- what python-canopen cannot read at all in [DeviceInfo] and [Comments] --------------------------------------

# The [DeviceInfo] keys python-canopen reads with `int(text, 0)` (a number, or 0/1 for a flag): an empty value or
# one that form rejects stops it loading the file. BaudRate_<n> are read the same way.
_INT_DEVICE_INFO = ("VendorNumber", "ProductNumber", "RevisionNumber", "NrOfRXPDO", "NrOfTXPDO", "SimpleBootUpMaster",
                    "SimpleBootUpSlave", "Granularity", "DynamicChannelsSupported", "GroupMessaging", "LSS_Supported",
                    *(f"BaudRate_{rate}" for rate in (10, 20, 50, 125, 250, 500, 800, 1000)))  # fmt: skip
_OCTAL = re.compile(r"[+-]?0[0-9]*[1-9][0-9]*\Z")  # all zeros is 0 for every reader
_COMMENT_KEY = re.compile(r"(?:lines|line[0-9]+)\Z", re.IGNORECASE)
_COMMENT_SPELLING = re.compile(r"(?:Lines|Line[0-9]+)\Z")
_TEXT: WeakKeyDictionary[Context, str | bytes] = WeakKeyDictionary()
# Where str.splitlines breaks lines (what these rules number lines by); in ASCII bytes, the first of them.
_BREAK = re.compile("\r\n|[\n\r\v\f\x1c\x1d\x1e\x85\u2028\u2029]")
_BREAK_BYTES = re.compile(b"\r\n|[\n\r\v\f\x1c\x1d\x1e]")


def _lines_from(ctx: Context, first: int) -> Iterator[tuple[int, str]]:
    """The file's lines from line `first` (counted from 1) on, with their numbers, found as they are asked for:
    the rules on a few keys' spelling need only a few lines, and a list of all would cost a large file several
    times its size. An ASCII file is read as its bytes, any other once decoded."""
    if ctx not in _TEXT:
        original = ctx.device._original or b""
        _TEXT[ctx] = original if original.isascii() else decode_as(original)[0]
    text = _TEXT[ctx]
    breaks = _BREAK_BYTES.finditer(text) if isinstance(text, bytes) else _BREAK.finditer(text)
    start, number = 0, 1
    for found in breaks:
        if number >= first:
            yield number, _as_text(text[start : found.start()])
        start, number = found.end(), number + 1
    if start < len(text) and number >= first:
        yield number, _as_text(text[start:])


def _as_text(line: str | bytes) -> str:
    return line.decode("ascii") if isinstance(line, bytes) else line


def _written(ctx: Context, section: Section, key: str) -> str | None:
    """The value of `key` as the file writes it, None when the key is absent."""
    where = section.origin.where(key) if section.origin is not None else None
    if where is None or where[0] <= 0:
        return None
    number, line = next(_lines_from(ctx, where[0]), (0, ""))
    return line[where[2] - 1 :].strip() if number == where[0] else None


@rule(
    "DIA019",
    E,
    "Empty number in [DeviceInfo]",
    """
An empty `VendorNumber=` or `ProductNumber=` equals a missing key in CiA 306, but python-canopen
reads every number and flag of [DeviceInfo] (the identity, the PDO counts, the boot-up and LSS
flags, `BaudRate_<n>`) with `int()`, and an empty value stops it loading the file at all.

Error, though the file is right by CiA 306: python-canopen cannot load it at all. Write the number,
or delete the key.""",
    "[DeviceInfo]\nVendorName=Acme\nVendorNumber=\nProductName=Widget",
    fixed="[DeviceInfo]\nVendorName=Acme\nProductName=Widget",
    fix_safety="No automatic fix: only the vendor knows the number; deleting the key loses nothing.",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen raises ValueError on int('')"),
)
def empty_device_info_number(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.device_info
    for key in _INT_DEVICE_INFO:
        if _written(ctx, info, key) == "":
            yield ctx.report("DIA019", f"[DeviceInfo] {key} is empty; python-canopen fails to load the file",
                             ctx.at(info, key))  # fmt: skip


@rule(
    "DIA020",
    E,
    "Octal number in [DeviceInfo]",
    """
CiA 306 reads an integer with a leading 0 as octal: `ProductNumber=014101` is 6209, though a
vendor who wrote a catalogue number with a leading zero most likely meant 14101. python-canopen
(`int(text, 0)`) and lely's tools reject the form and fail on the file, and every reader that does
take it may take another number than its author meant.

Error: python-canopen and lely cannot load the file, and which number is meant only the author
knows; write it in decimal or as 0x hex.""",
    "[DeviceInfo]\nVendorName=Acme\nProductNumber=02",
    fixed="[DeviceInfo]\nVendorName=Acme\nProductNumber=2",
    fix_safety="No automatic fix: CiA 306 says 6209, the author probably meant 14101.",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen and lely dcfchk raise on the octal form"),
)
def octal_device_info_number(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.device_info
    for key in _INT_DEVICE_INFO:
        text = _written(ctx, info, key)
        if text is not None and _OCTAL.match(text):
            message = (
                f"[DeviceInfo] {key}={text}: octal by CiA 306 ({int(text, 8)}); python-canopen and lely fail on it"
            )
            yield ctx.report("DIA020", message, ctx.value_at(info, key))


@rule(
    "DIA021",
    E,
    "[Comments] key in another case than Lines/Line<n>",
    """
CiA 306 key names are case-insensitive, but python-canopen looks up `Lines` and then `Line1` ...
`Line<Lines>` exactly as spelled here: a `line5=` (or `LINES=`) makes it fail with NoOptionError and
load nothing at all.

Error, though the file is right by CiA 306: python-canopen cannot load it at all.""",
    "[Comments]\nLines=2\nLine1=First\nline2=Second",
    fixed="[Comments]\nLines=2\nLine1=First\nLine2=Second",
    fix_safety="No automatic fix: write the key as `Lines` or `Line<n>`.",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen raises NoOptionError"),
)
def comments_key_case(ctx: Context) -> Iterator[Finding]:
    comments = ctx.device.comments
    if comments is None or comments.origin is None:
        return
    for number, line in _lines_from(ctx, comments.origin.line + 1):
        if line.lstrip().startswith("["):
            return
        key = line.split("=", 1)[0].strip() if "=" in line else ""
        if _COMMENT_KEY.match(key) and not _COMMENT_SPELLING.match(key):
            message = f"[Comments] {key}: python-canopen looks it up as {key[:4].title()}{key[4:].lower()} and fails"
            yield ctx.report("DIA021", message, location(ctx.device.source, number, 1))
