"""Rule family: structure — lines, sections, keys, the obligation matrix, sub-objects (cia306.md §1-§11)."""

from __future__ import annotations

import difflib
import re
from collections.abc import Callable, Iterable, Iterator

from ..eds import keys
from ..eds.decode import decode
from ..model import Device, Location, Object, ObjectKind, RawSection, Section, Severity, SubObject, Variable
from ..model.datatypes import STANDARD_TYPES
from .rules import Context, Finding, Fix, rule

E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

MAX_LINE = 255
MAX_NAME = 241  # 255 - len("ParameterName=")
RESERVED_DEVICE_INFO = ("ProductVersion", "ProductRevision", "LMT_ManufacturerName", "LMT_ProductName",
                        "ExtendedBootUpMaster", "ExtendedBootUpSlave")  # fmt: skip
LATER_OBJECT_KEYS = ("SRDOMapping", "InvertedSRAD")
EXTENSION_KEYS = ("Factor", "Unit", "Description", "StorageLocation")  # python-canopen; see portability
_FIELD = {spec[0]: spec[1] for spec in keys.OBJECT_KEYS.values()}
_OBJECT_KEYS = (*_FIELD, *LATER_OBJECT_KEYS, *EXTENSION_KEYS)
_COMPOUND = (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT)
_TYPE_KINDS = (ObjectKind.DEFTYPE, ObjectKind.DEFSTRUCT)
_EOL = re.compile(r"\r\n|\r|\n")
_OBJECT_LIKE = re.compile(r"[0-9a-f]{1,4}(?:sub[0-9a-f]+|name|value|denotation|objectlinks)?\Z", re.IGNORECASE)
_OTHER_KNOWN = re.compile(r"(?:tools|tool[1-9][0-9]*|dynamicchannels)\Z", re.IGNORECASE)
_MODULE = re.compile(
    r"(?:supportedmodules|connectedmodules|m[1-9][0-9]*(?:moduleinfo|comments|fixedobjects|subextends"
    r"|(?:fixed|subext)[0-9a-f]{1,4}(?:sub[0-9a-f]{1,2})?))\Z",
    re.IGNORECASE,
)
_KNOWN_SECTIONS = ("FileInfo", "DeviceInfo", "DummyUsage", "Comments", "MandatoryObjects", "OptionalObjects",
                   "ManufacturerObjects", "DeviceComissioning", "Tools", "DynamicChannels", "SupportedModules",
                   "ConnectedModules")  # fmt: skip
_DATE = re.compile(r"(0[1-9]|1[0-2])-(0[1-9]|[12][0-9]|3[01])-[0-9]{4}\Z")
_TIME = re.compile(r"(0[1-9]|1[0-2]):[0-5][0-9](AM|PM)\Z")


# ---- helpers ---------------------------------------------------------------------------------------------------


def file_start(ctx: Context) -> Location:
    """Line 1: where file-level findings (a missing section) are reported."""
    return Location(file=ctx.device.source, line=1, column=1)


def present(section: Section) -> bool:
    """Whether the file gave this section (a model from JSON: whether the section holds anything)."""
    return section.origin is not None or section != type(section)()


def invalid(section: Section, key: str) -> bool:
    """The key was written, but its value could not be read (it is in `extra`; the reader reported it)."""
    wanted = keys.normalize(key)
    return any(keys.normalize(written) == wanted for written in section.extra)


def given(var: Variable, key: str) -> bool:
    """The object key has a non-empty value (a missing and an empty entry are the same, §1)."""
    value = getattr(var, _FIELD[key])
    return (value is not None and value != "") or invalid(var, key)


def explicit_objects(device: Device) -> Iterator[Object]:
    """Objects with a section of their own (CompactPDO ones have none)."""
    return (obj for obj in device.objects.values() if not obj.implicit)


def explicit_vars(device: Device) -> Iterator[tuple[Object, int | None, Variable]]:
    """Every object and every sub-object with a section of its own; sub-index None for the object."""
    for obj in explicit_objects(device):
        yield obj, None, obj
        for subindex, sub in obj.subs.items():
            if not sub.implicit:
                yield obj, subindex, sub


def compact(obj: Object) -> bool:
    return bool(obj.compact_sub_obj)


def where(obj: Object, subindex: int | None) -> str:
    return f"[{obj.index:04X}]" if subindex is None else f"[{obj.index:04X}sub{subindex:X}]"


def _suggest(key: str, known: Iterable[str]) -> str:
    by_lower = {k.lower(): k for k in known}
    close = difflib.get_close_matches(key.lower(), list(by_lower), n=2, cutoff=0.75)
    return f"; did you mean {' or '.join(by_lower[c] for c in close)}?" if close else ""


# ---- lines, sections, keys -------------------------------------------------------------------------------------


@rule(
    "EDS001",
    E,
    "Line longer than 255 characters",
    """
CiA 306 limits every line to 255 characters; the length limits of the string keys (ParameterName
241, Description 243, ...) follow from it. Tools with fixed line buffers cut longer lines.""",
    "[2000]\nParameterName=<a name of 250 characters>",
)
def long_lines(ctx: Context) -> Iterator[Finding]:
    data = ctx.device._original
    if data is None:
        return
    text, _ = decode(data)
    for number, line in enumerate(_EOL.split(text), 1):
        if len(line) > MAX_LINE:
            location = Location(file=ctx.device.source, line=number, column=MAX_LINE + 1)
            yield ctx.report("EDS001", f"line has {len(line)} characters; CiA 306 allows {MAX_LINE}", location)


def _keyed_sections(device: Device) -> Iterator[tuple[str, Section, tuple[str, ...]]]:
    """Sections with a fixed key set: display name, section, known canonical keys."""
    yield "FileInfo", device.file_info, tuple(s[0] for s in keys.FILE_INFO_KEYS.values())
    yield "DeviceInfo", device.device_info, (*(s[0] for s in keys.DEVICE_INFO_KEYS.values()), *RESERVED_DEVICE_INFO)
    if device.commissioning is not None:
        yield "DeviceComissioning", device.commissioning, tuple(s[0] for s in keys.COMMISSIONING_KEYS.values())
    if device.dummy_usage is not None:
        yield "DummyUsage", device.dummy_usage, ()
    if device.comments is not None:
        yield "Comments", device.comments, ("Lines",)
    for obj, subindex, var in explicit_vars(device):
        if var.extra:
            yield where(obj, subindex)[1:-1], var, _OBJECT_KEYS


@rule(
    "EDS003",
    W,
    "Unknown key",
    """
The key is not a CiA 306 key of this section. CiA 306 allows unknown keys for future extensions,
but they are often typos (`Baudrate_100`, `ParamterName`) that leave the intended key missing.
Reserved compatibility keys of [DeviceInfo] (ProductVersion, ...) and the extension keys that
python-canopen reads (Factor, Unit, Description, StorageLocation) are not reported here.""",
    "[DeviceInfo]\nBaudrate_100=1",
)
def unknown_keys(ctx: Context) -> Iterator[Finding]:
    for name, section, known in _keyed_sections(ctx.device):
        if not section.extra:
            continue
        normalized = {keys.normalize(k) for k in known}
        for key in section.extra:
            if keys.normalize(key) in normalized or _numbered(name, key):
                continue
            message = f"[{name}] {key}: not a CiA 306 key of this section{_suggest(key, known)}"
            yield ctx.report("EDS003", message, ctx.at(section, key))


def _numbered(section: str, key: str) -> bool:
    """Keys that other rules judge: Dummy<xxxx> values, Line<n>, sub-object SubNumber/CompactSubObj."""
    lower = key.lower()
    if section == "DummyUsage":
        return lower.startswith("dummy")
    if section == "Comments":
        return lower.startswith("line")
    return key in ("SubNumber", "CompactSubObj") and "sub" in section


@rule(
    "EDS004",
    W,
    "Unknown section",
    """
The section is not defined by CiA 306 (nor is it a module-concept, [Tools] or [DynamicChannels]
section). It is kept as it is, but no other tool gives it a meaning; a typo in a known section's
name leaves that section missing.""",
    "[DeviceInfos]\nVendorName=Example",
)
def unknown_sections(ctx: Context) -> Iterator[Finding]:
    for raw in ctx.device.other_sections:
        if _OBJECT_LIKE.match(raw.name) or _OTHER_KNOWN.match(raw.name):
            continue  # object-like leftovers were reported by the reader (EDS103/EDS104)
        message = f"[{raw.name}]: not a CiA 306 section{_suggest(raw.name, _KNOWN_SECTIONS)}"
        yield ctx.report("EDS004", message, ctx.at(raw))
    for raw in ctx.device.module_sections:
        if not _MODULE.match(raw.name):
            yield ctx.report("EDS004", f"[{raw.name}]: not a module-concept section name (cia306.md §11)", ctx.at(raw))


@rule(
    "EDS005",
    E,
    "Name longer than 241 characters",
    """
A ParameterName holds at most 241 characters. Names in a section are caught by the line
limit (EDS001); this rule checks the names that [xxxxName] gives to CompactSubObj sub-objects,
whose shorter keys let a too long name fit on one line.""",
    "[2000Name]\nNrOfEntries=1\n1=<a name of 250 characters>",
)
def long_names(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        for subindex, sub in obj.subs.items():
            if sub.implicit and len(sub.name) > MAX_NAME and sub.name != f"{obj.name}{subindex}":
                message = f"[{obj.index:04X}Name] {subindex}: name has {len(sub.name)} characters; at most {MAX_NAME}"
                yield ctx.report("EDS005", message, ctx.at(obj))


@rule(
    "EDS009",
    E,
    "Mandatory section missing",
    """
Every EDS and DCF has [FileInfo], [DeviceInfo] and [DummyUsage] (cia306.md §2). Tools read the
vendor and product identity, supported baud rates and PDO counts from [DeviceInfo]. The object
lists are checked by EDS019.""",
    "; no [DeviceInfo] section in the file\n[FileInfo]\nFileName=device.eds",
)
def missing_sections(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    for name, there in (
        ("FileInfo", present(device.file_info)),
        ("DeviceInfo", present(device.device_info)),
        ("DummyUsage", device.dummy_usage is not None),
    ):
        if not there:
            yield ctx.report("EDS009", f"[{name}] is missing", file_start(ctx))


@rule(
    "EDS006",
    W,
    "Date or time not in CiA 306 form",
    """
CreationDate and ModificationDate are written `mm-dd-yyyy`, CreationTime and ModificationTime
`hh:mm` followed by AM or PM. Editors often write ISO dates (2024-02-27) or 24-hour times
(17:24:43), which other tools misread or reject.""",
    "[FileInfo]\nCreationDate=2024-02-27\nCreationTime=17:24",
)
def date_time(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.file_info
    for key, value, pattern, form in (
        ("CreationDate", info.creation_date, _DATE, "mm-dd-yyyy"),
        ("ModificationDate", info.modification_date, _DATE, "mm-dd-yyyy"),
        ("CreationTime", info.creation_time, _TIME, "hh:mm followed by AM or PM, e.g. 09:05PM"),
        ("ModificationTime", info.modification_time, _TIME, "hh:mm followed by AM or PM, e.g. 09:05PM"),
    ):
        if value and not pattern.match(value):
            yield ctx.report("EDS006", f"{key}={value}: CiA 306 writes {form}", ctx.value_at(info, key))


@rule(
    "EDS007",
    INFO,
    "EDSVersion missing",
    """
Without EDSVersion a file counts as CiA 306 version 3.0. Files following the current
specification write `EDSVersion=4.0`.""",
    "[FileInfo]\nFileName=device.eds\nFileVersion=1",
)
def eds_version_missing(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.file_info
    if present(info) and not info.eds_version:
        yield ctx.report("EDS007", "no EDSVersion: the file counts as EDS version 3.0", ctx.at(info, "EDSVersion"))


@rule(
    "EDS008",
    W,
    "EDSVersion is not 4.0",
    """
Files written to CiA 306 v1.3 state `EDSVersion=4.0`. Other values seen in the wild (`4.2`, the
python-canopen default, or `402`) name no version of the specification.""",
    "[FileInfo]\nEDSVersion=4.2",
)
def eds_version(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.file_info
    if info.eds_version and info.eds_version.strip() != "4.0":
        message = f"EDSVersion={info.eds_version}: files per CiA 306 v1.3 write 4.0"
        yield ctx.report("EDS008", message, ctx.value_at(info, "EDSVersion"))


@rule(
    "EDS090",
    E,
    "[Comments] Lines does not match its Line<n> entries",
    """
[Comments] counts its lines in `Lines` and numbers them Line1 ... Line<Lines> without gaps.
python-canopen reads exactly `Lines` lines and fails on a missing one.""",
    "[Comments]\nLines=3\nLine1=First\nLine2=Second",
)
def comment_lines(ctx: Context) -> Iterator[Finding]:
    comments = ctx.device.comments
    if comments is None or invalid(comments, "Lines"):
        return
    numbers = sorted(comments.lines)
    contiguous = numbers == list(range(1, len(numbers) + 1))
    odd = [k for k in comments.extra if k.lower().startswith("line") and keys.normalize(k) != "lines"]
    if not contiguous or odd:
        gaps = sorted(set(range(1, max(numbers, default=0) + 1)) - set(numbers))
        detail = ", ".join([*(f"Line{n} missing" for n in gaps), *(f"{k} is not Line<n>" for k in odd)])
        yield ctx.report("EDS090", f"[Comments]: lines not numbered 1..n ({detail})", ctx.at(comments))
    if comments.line_count != len(numbers):
        fix = Fix(f"set Lines={len(numbers)}", contiguous and not odd, _fix_comment_count)
        message = f"[Comments] Lines={comments.line_count} but {len(numbers)} Line<n> entries"
        yield ctx.report("EDS090", message, ctx.value_at(comments, "Lines"), fix)


def _fix_comment_count(device: Device) -> None:
    if device.comments is not None:
        device.comments.line_count = len(device.comments.lines)


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


@rule(
    "EDS020",
    E,
    "Mandatory key missing",
    """
The obligation matrix of CiA 306 (cia306.md §7.3) makes ParameterName mandatory everywhere;
DataType and AccessType for VAR, DEFTYPE, sub-objects and CompactSubObj objects; SubNumber for
ARRAY, RECORD and DEFSTRUCT without CompactSubObj. A missing key equals an empty one. Tools
crash on these (lely: `KeyError: 'DataType'`) or drop the object.""",
    "[2000]\nParameterName=Speed\nDataType=0x0006",
)
def missing_keys(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var in explicit_vars(ctx.device):
        for key in _mandatory(obj, subindex is not None):
            if not given(var, key):
                kind = "a sub-object" if subindex is not None else f"{obj.kind.name}"
                empty = var.origin is not None and key in var.origin.keys
                message = f"{where(obj, subindex)}: {key} is empty" if empty else f"{where(obj, subindex)}: no {key}"
                yield ctx.report("EDS020", f"{message}; {kind} needs it", ctx.at(var, key))


@rule(
    "EDS024",
    E,
    "Key not allowed for this object type",
    """
Per the obligation matrix (cia306.md §7.3) ARRAY, RECORD and DEFSTRUCT objects without
CompactSubObj describe their values in sub-objects and carry no DataType, AccessType,
DefaultValue, PDOMapping or limits; DOMAIN objects have no PDOMapping, SubNumber or limits; VAR
and sub-objects have no SubNumber. Tools disagree about what such keys mean.""",
    "[1018]\nParameterName=Identity\nObjectType=0x9\nSubNumber=5\nAccessType=ro",
)
def forbidden_keys(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var in explicit_vars(ctx.device):
        for key in _forbidden(obj, subindex is not None):
            if _written(var, key, subindex is not None):
                kind = "a sub-object" if subindex is not None else f"an object of type {obj.kind.name}"
                yield ctx.report("EDS024", f"{where(obj, subindex)}: {key} is not allowed on {kind}", ctx.at(var, key))


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
    "[1018]\nParameterName=Identity\nObjectType=0x9\nSubNumber=4\n[1018sub0]\n...\n[1018sub1]\n...",
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
CompactSubObj (cia306.md §8.1) describes the sub-objects of an ARRAY (lely: also RECORD)
implicitly: sub0 plus subs 1..n copied from the object. It is not allowed on VAR, DOMAIN or
sub-objects, must be 1..254, and excludes both a non-zero SubNumber and `[<index>sub<n>]`
sections, which would describe the same sub-objects twice.""",
    "[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=4\nSubNumber=5",
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
ObjFlags (cia306.md §7.5) defines bit 0 (refuse write on download) and bit 1 (refuse read on
scan); bits 2-31 are reserved and must be 0. lely ORs ObjFlags into its own flag word, where
reserved bits switch on lely-internal behaviour.""",
    "[2000]\nParameterName=Setpoint\nDataType=0x0006\nAccessType=rw\nObjFlags=0x4",
)
def obj_flags(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var in explicit_vars(ctx.device):
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
    "[1018]\nParameterName=Identity\nObjectType=0x9\nSubNumber=1\n[1018sub0]\nParameterName=Count\nDataType=0x0007",
)
def sub0_type(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        if not _has_subs(obj):
            continue
        sub0 = obj.subs.get(0)
        if sub0 is None:
            yield ctx.report("EDS025", f"[{obj.index:04X}]: no sub-index 0 ({obj.kind.name})", ctx.at(obj))
        elif sub0.data_type is not None and ctx.device.entry_type(sub0, obj) is not STANDARD_TYPES[0x0005]:
            message = f"[{obj.index:04X}sub0]: DataType=0x{sub0.data_type:04X}; sub-index 0 is UNSIGNED8 (0x0005)"
            yield ctx.report("EDS025", message, ctx.value_at(sub0, "DataType"))


def _counts_entries(obj: Object, sub0: SubObject) -> bool:
    """Objects whose sub0 is a number of valid entries rather than the highest sub-index."""
    if obj.index == 0x1003 or 0x1400 <= obj.index <= 0x1BFF:  # error history; PDOs (PDO010/PDO040)
        return True
    return sub0.access is not None and sub0.access.writable


@rule(
    "EDS026",
    E,
    "Sub-index 0 below the highest sub-index",
    """
Sub-index 0 of an ARRAY or RECORD holds the highest sub-index it implements; sub-indices need not
be consecutive (1010h may have sub0 and sub4 only, sub0=4). A smaller value hides the upper
sub-objects. Not checked: 1003h (sub0 counts the errors), PDO objects (see the PDO rules) and
objects whose sub0 is writable, where sub0 counts the valid entries.""",
    "[1018]\n...\n[1018sub0]\nParameterName=Highest sub-index\nDataType=0x0005\nAccessType=ro\nDefaultValue=2\n"
    "[1018sub1]\n...\n[1018sub2]\n...\n[1018sub3]\n...",
)
def sub0_value(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        sub0 = obj.subs.get(0)
        if not _has_subs(obj) or sub0 is None or _counts_entries(obj, sub0):
            continue
        highest = _highest(obj)
        if isinstance(sub0.default, int) and not isinstance(sub0.default, bool) and sub0.default < highest:
            message = f"[{obj.index:04X}sub0]: DefaultValue={sub0.default} but sub-index {highest} exists"
            fix = Fix(f"set DefaultValue={highest}", True, _fix_sub0(obj.index))
            yield ctx.report("EDS026", message, ctx.value_at(sub0, "DefaultValue"), fix)


def _highest(obj: Object) -> int:
    return max((subindex for subindex in obj.subs if subindex != 0xFF), default=0)


def _fix_sub0(index: int) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        obj = device.objects.get(index)
        sub0 = obj.subs.get(0) if obj is not None else None
        if obj is not None and sub0 is not None and isinstance(sub0.default, int):
            sub0.default = max(sub0.default, _highest(obj))

    return apply


@rule(
    "EDS027",
    E,
    "Sub-index FFh described",
    """
Sub-index FFh is reserved: it holds the object's data type and object code, is not counted by
SubNumber and is never described in an EDS.""",
    "[2000subFF]\nParameterName=Structure\nDataType=0x0007\nAccessType=ro",
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
    "[2000sub1]\nDataType=0x0006\n...\n[2000sub2]\nDataType=0x0007",
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
)
def undefined_types(ctx: Context) -> Iterator[Finding]:
    objects = ctx.device.objects
    for obj, subindex, var in _typed_vars(ctx.device):
        dtype = var.data_type
        if dtype is None or dtype in STANDARD_TYPES:
            continue
        definition = objects.get(dtype)
        if 0 < dtype < 0x1000 and definition is not None and definition.kind in _TYPE_KINDS:
            continue
        reason = "reserved data type index" if 0 < dtype < 0x0020 else "no DEFTYPE/DEFSTRUCT object defines it"
        message = f"{where(obj, subindex)}: DataType=0x{dtype:04X}: {reason}"
        yield ctx.report("EDS080", message, ctx.value_at(var, "DataType"))


@rule(
    "EDS081",
    E,
    "Object type does not fit the data-type index area",
    """
Indices 0001h-0FFFh hold data types: DEFTYPE and DEFSTRUCT objects belong there and nowhere
else, and nothing else belongs there (cia306.md §13). Index 0000h is not used.""",
    "[2000]\nParameterName=My type\nObjectType=0x5\nDataType=0x0007\nAccessType=ro",
)
def type_area(ctx: Context) -> Iterator[Finding]:
    for obj in explicit_objects(ctx.device):
        in_area = 0 < obj.index < 0x1000
        if obj.index == 0:
            yield ctx.report("EDS081", "[0000]: index 0000h is not used", ctx.at(obj))
        elif obj.kind in _TYPE_KINDS and not in_area:
            message = f"[{obj.index:04X}]: {obj.kind.name} outside the data-type area 0001h-0FFFh"
            yield ctx.report("EDS081", message, ctx.at(obj, "ObjectType"))
        elif obj.kind not in _TYPE_KINDS and in_area:
            message = f"[{obj.index:04X}]: {obj.kind.name} in the data-type area; only DEFTYPE/DEFSTRUCT belong there"
            yield ctx.report("EDS081", message, ctx.at(obj, "ObjectType"))


# ---- DCF -------------------------------------------------------------------------------------------------------

_DCF_KEYS = ("ParameterValue", "Denotation", "ParamRefd", "UploadFile", "DownloadFile")


@rule(
    "EDS050",
    W,
    "UploadFile/DownloadFile with a mismatching AccessType",
    """
UploadFile receives the content of a DOMAIN read from the device, so the object should be `ro`;
DownloadFile is written to the device, so the object should be `wo` (cia306.md §10). lely forces
these access types and warns.""",
    "[1F50]\nParameterName=Program\nObjectType=0x2\nAccessType=rw\nDownloadFile=firmware.bin",
)
def file_access(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var in explicit_vars(ctx.device):
        if not _domain(ctx.device, obj, var):
            continue  # EDS051
        access = var.access.value if var.access is not None else "rw"
        for key, path, wanted in (("UploadFile", var.upload_file, "ro"), ("DownloadFile", var.download_file, "wo")):
            if path and access != wanted:
                message = f"{where(obj, subindex)}: {key} with AccessType {access}; expected {wanted}"
                yield ctx.report("EDS050", message, ctx.at(var, key))


def _domain(device: Device, obj: Object, var: Variable) -> bool:
    dtype = device.entry_type(var, obj)
    return dtype is not None and dtype.index == 0x000F


@rule(
    "EDS051",
    E,
    "UploadFile/DownloadFile on an entry that is not a DOMAIN",
    """
UploadFile and DownloadFile name files that hold the content of a DOMAIN (ObjectType 0x2 or
DataType 0x000F); other entries have a value of their data type.""",
    "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=ro\nUploadFile=speed.bin",
)
def file_domain(ctx: Context) -> Iterator[Finding]:
    for obj, subindex, var in explicit_vars(ctx.device):
        if _domain(ctx.device, obj, var):
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
describe one configured node and belong in a DCF (cia306.md §10). In an EDS, tools ignore them
or take them for the device's defaults.""",
    "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\nParameterValue=100",
)
def dcf_keys(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    if device.is_dcf:
        return
    if device.file_info.last_eds:
        yield ctx.report("EDS052", "LastEDS in an EDS", ctx.at(device.file_info, "LastEDS"))
    for obj, subindex, var in explicit_vars(device):
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
    "EDS062",
    E,
    "NodeID outside 1..127",
    """
CANopen node-IDs are 1..127. lely also writes 255 for "not configured" (EDS063).""",
    "[DeviceComissioning]\nNodeID=128",
)
def node_id_range(ctx: Context) -> Iterator[Finding]:
    section = ctx.device.commissioning
    node_id = section.node_id if section is not None else None
    if section is not None and node_id is not None and not 1 <= node_id <= 127 and node_id != 255:
        yield ctx.report("EDS062", f"NodeID={node_id} is not a node-ID (1..127)", ctx.value_at(section, "NodeID"))


@rule(
    "EDS063",
    INFO,
    "NodeID 255: node-ID not configured",
    """
lely writes `NodeID=255` (0xFF) for a node whose node-ID is assigned later (LSS). `$NODEID`
values stay unresolved.""",
    "[DeviceComissioning]\nNodeID=0xFF",
)
def node_id_unset(ctx: Context) -> Iterator[Finding]:
    section = ctx.device.commissioning
    if section is not None and section.node_id == 255:
        yield ctx.report("EDS063", "NodeID=255: node-ID not configured", ctx.value_at(section, "NodeID"))


# ---- module concept --------------------------------------------------------------------------------------------

_MODULE_NAME = re.compile(r"m([1-9][0-9]*)(moduleinfo|fixedobjects|subextends|fixed|subext)(.*)\Z", re.IGNORECASE)


def _count(raw: RawSection, key: str) -> int | None:
    for written, text in raw.entries.items():
        if written.lower() == key.lower():
            try:
                return int(text.strip(), 0)
            except ValueError:
                return None
    return None


def _listed(raw: RawSection) -> dict[str, str]:
    return {k: v for k, v in raw.entries.items() if k.isdigit()}


@rule(
    "EDS070",
    E,
    "Module sections inconsistent",
    """
In the module concept (cia306.md §11) [SupportedModules] NrOfEntries counts the modules
M1..Mn, each with an [M<x>ModuleInfo]; [M<x>FixedObjects] and [M<x>SubExtends] count their
numbered entries in NrOfEntries, and each listed index has its [M<x>Fixed<index>] or
[M<x>SubExt<index>] section; [ConnectedModules] lists module numbers 1..n.""",
    "[SupportedModules]\nNrOfEntries=2\n[M1ModuleInfo]\nProductName=Input module",
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
            yield from _module_list(ctx, raw, number, "Fixed" if part == "fixedobjects" else "SubExt", sections)
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
            if not (text.strip().isdigit() and 1 <= int(text) <= total):
                message = f"[{connected.name}] {key}={text}: not a module number 1..{total}"
                yield ctx.report("EDS070", message, ctx.at(connected, key))


def _counted(ctx: Context, raw: RawSection) -> Iterator[Finding]:
    count, entries = _count(raw, "NrOfEntries"), _listed(raw)
    if raw.name.lower() != "supportedmodules" and count != len(entries):
        message = f"[{raw.name}]: NrOfEntries={count} but {len(entries)} entries"
        yield ctx.report("EDS070", message, ctx.at(raw, "NrOfEntries"))


def _module_list(
    ctx: Context, raw: RawSection, number: int, prefix: str, sections: dict[str, RawSection]
) -> Iterator[Finding]:
    yield from _counted(ctx, raw)
    for key, text in _listed(raw).items():
        try:
            index = int(text.strip(), 0)
        except ValueError:
            yield ctx.report("EDS070", f"[{raw.name}] {key}={text}: not an object index", ctx.at(raw, key))
            continue
        if f"m{number}{prefix}{index:04x}".lower() not in sections:
            message = f"[{raw.name}] {key}=0x{index:04X}: no [M{number}{prefix}{index:04X}] section"
            yield ctx.report("EDS070", message, ctx.at(raw, key))
