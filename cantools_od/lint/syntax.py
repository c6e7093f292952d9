"""Rule family: syntax — lines, sections, keys, dates, EDSVersion and [Comments].

CiA 306 §4: file structure, [FileInfo], [DeviceInfo]; [Comments] §4.6.5.
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Iterator
from typing import NamedTuple

from ..canopennode.info import STORAGE_LOCATION
from ..eds import keys
from ..eds.peer_names import python_canopen_reads
from ..model import Device, Location, Section, Severity
from ..model.source import location
from .common import OBJECT_FIELDS, explicit_objects, explicit_vars, file_start, invalid, present, where
from .rules import Clause, Context, Finding, Fix, Placement, declare, rule

E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO

MAX_NAME = 241  # 255 - len("ParameterName=")
RESERVED_DEVICE_INFO = ("ProductVersion", "ProductRevision", "LMT_ManufacturerName", "LMT_ProductName",
                        "ExtendedBootUpMaster", "ExtendedBootUpSlave")  # fmt: skip
LATER_OBJECT_KEYS = ("SRDOMapping", "InvertedSRAD")
EXTENSION_KEYS = ("Factor", "Unit", "Description", STORAGE_LOCATION)  # python-canopen; see portability
_OBJECT_KEYS = (*OBJECT_FIELDS, *LATER_OBJECT_KEYS, *EXTENSION_KEYS)
_OBJECT_LIKE = re.compile(r"[0-9a-f]{1,4}(?:sub[0-9a-f]+|name|value|denotation|objectlinks)?\Z", re.IGNORECASE)
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


def _suggest(key: str, known: Iterable[str]) -> str:
    import difflib  # here, as the writers below: a lint run without such a finding does not load them

    by_lower = {k.lower(): k for k in known}
    close = difflib.get_close_matches(key.lower(), list(by_lower), n=2, cutoff=0.75)
    return f"; did you mean {' or '.join(by_lower[c] for c in close)}?" if close else ""


# ---- lines, sections, keys -------------------------------------------------------------------------------------


# The reader measures the lines (only it sees the text); the rule is documented with its family.
declare(
    "EDS001",
    W,
    "Line longer than 255 characters",
    """
CiA 306 limits every line to 255 characters; the length limits of the string keys (ParameterName
241, Description 243, ...) follow from it. Tools with fixed line buffers cut longer lines.
Warning: python-canopen and lely's dcfchk read the whole line; a reader with a buffer of CiA
306's size is a tool beyond them.""",
    "; "
    + "A comment that goes on " * 12
    + "\n"
    + "[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    family="syntax",
    fixed="; A comment that stays short\n"
    + "[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fix_safety="No automatic fix: shorten the line; a comment can go on several lines.",
    placed=Placement(
        Clause.BEYOND_THE_PEERS,
        "python-canopen and lely read the whole line; readers with fixed 255-character buffers cut it",
    ),
)


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
    fixed=("[DeviceInfo]\nBaudRate_125=1"),
    per_object=True,
    placed=Placement(Clause.STYLE, "CiA 306 allows unknown keys; often a typo that leaves the meant key missing"),
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
    fixed="[DeviceInfo]\nVendorName=Example\nBaudRate_500=1",
    placed=Placement(Clause.STYLE, "peers keep or drop it alike; often a typo of a known section"),
)
def unknown_sections(ctx: Context) -> Iterator[Finding]:
    for raw in ctx.device.other_sections:
        if _OBJECT_LIKE.match(raw.name) or keys.OTHER_SECTION.match(raw.name):
            continue  # object-like leftovers were reported by the reader (EDS103/EDS104)
        message = f"[{raw.name}]: not a CiA 306 section{_suggest(raw.name, _KNOWN_SECTIONS)}"
        yield ctx.report("EDS004", message, ctx.at(raw))
    for raw in ctx.device.module_sections:
        if not _MODULE.match(raw.name):
            yield ctx.report("EDS004", f"[{raw.name}]: not a module-concept section name (CiA 306 §6)", ctx.at(raw))


@rule(
    "EDS005",
    W,
    "Name longer than 241 characters",
    """
A ParameterName holds at most 241 characters. Names in a section are caught by the line
limit (EDS001); this rule checks the names that [xxxxName] gives to CompactSubObj sub-objects,
whose shorter keys let a too long name fit on one line. Warning: python-canopen and lely read
the whole name; only a reader that holds CiA 306's limit cuts it.""",
    "[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=1\n\n"
    "[2000Name]\nNrOfEntries=1\n1=" + "Input " * 41,
    fixed="[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=1\n\n"
    "[2000Name]\nNrOfEntries=1\n1=Input 1",
    per_object=True,
    placed=Placement(
        Clause.BEYOND_THE_PEERS, "python-canopen and lely read the whole name; CiA 306 limits it to 241 characters"
    ),
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
Every EDS and DCF has [FileInfo], [DeviceInfo] and [DummyUsage] (CiA 306 §4). Tools read the
vendor and product identity, supported baud rates and PDO counts from [DeviceInfo]; lely's dcfchk
refuses a file without it. A missing [FileInfo] or [DummyUsage] is a warning: python-canopen and
dcfchk load the file and read no file information and no dummy entries, as lely's own DCFs mean.
The object lists are checked by EDS019.""",
    "; no [DeviceInfo]",
    fixed="[DeviceInfo]\nVendorName=Example\nProductName=Example",
    placed=Placement(
        Clause.PEER_CANNOT_LOAD,
        "lely dcfchk refuses a file without [DeviceInfo] (without [FileInfo], [DummyUsage]: warning)",
    ),
)
def missing_sections(ctx: Context) -> Iterator[Finding]:
    device = ctx.device
    for name, there in (
        ("FileInfo", present(device.file_info)),
        ("DeviceInfo", present(device.device_info)),
        ("DummyUsage", device.dummy_usage is not None),
    ):
        if not there:
            finding = ctx.report("EDS009", f"[{name}] is missing", file_start(ctx))
            # Every peer loads a file without [FileInfo] or [DummyUsage] and reads none: not CiA 306's form only.
            yield finding if name == "DeviceInfo" else finding._replace(severity=W)


@rule(
    "EDS006",
    W,
    "Date or time not in CiA 306 form",
    """
CreationDate and ModificationDate are written `mm-dd-yyyy`, CreationTime and ModificationTime
`hh:mm` followed by AM or PM. Editors often write ISO dates (2024-02-27) or 24-hour times
(17:24:43), which other tools misread or reject.""",
    ("[FileInfo]\nFileName=example.eds\nEDSVersion=4.0\nCreationDate=2024-02-27\nCreationTime=17:24"),
    fixed=("[FileInfo]\nFileName=example.eds\nEDSVersion=4.0\nCreationDate=02-27-2024\nCreationTime=05:24PM"),
    placed=Placement(Clause.PORTABILITY, "not CiA 306's date/time form; tools that parse dates misread it"),
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
    fixed="[FileInfo]\nFileName=device.eds\nFileVersion=1\nEDSVersion=4.0",
    placed=Placement(Clause.DECISION, "counts as CiA 306 v3.0; nothing is read otherwise"),
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
    fixed="[FileInfo]\nEDSVersion=4.0",
    placed=Placement(Clause.STYLE, "names no version of CiA 306; peers read the file alike"),
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
    fixed="[Comments]\nLines=2\nLine1=First\nLine2=Second",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen raises NoOptionError on the missing Line<n>"),
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


# ---- spellings -------------------------------------------------------------------------------------------------


class Spelling(NamedTuple):
    """A known key or section name written otherwise than CiA 306 spells it."""

    written: str
    canonical: str
    where: Location  # the first character of the name as written
    header: bool

    @property
    def found_by_peers(self) -> bool:
        """Only the case differs: lely finds it (case-insensitive); python-canopen, case-sensitive, does not."""
        return self.written.lower() == self.canonical.lower()

    def fix(self) -> Fix:
        """Safe only for a name python-canopen does not look up: respelling one it does makes it read what it
        did not read before (a [DeviceInfo] count, a NodeID, an object's default), so that fix is unsafe."""
        what = "section" if self.header else "key"
        return Fix(f"write the {what} as {self.canonical}", not python_canopen_reads(self.canonical), self._respell)

    def _respell(self, device: Device) -> None:
        from ..eds.preserve import respell

        respell(device, self.where.line, self.where.column, self.written, self.canonical)


def spellings(ctx: Context) -> Iterator[Spelling]:
    """Every known key and section name written otherwise than CiA 306 spells it, in model order."""
    for section in ctx.device.sections():
        origin = section.origin
        if origin is None:
            continue
        for canonical, written in origin.spelled.items():
            if canonical == "":  # the section's own name; its text starts after the "["
                from ..eds.preserve import canonical_section_name

                header = origin.header()
                where = location(header.file, header.line, header.column + 1)
                yield Spelling(written, canonical_section_name(written), where, True)
            else:
                yield Spelling(written, canonical, origin.key(canonical), False)


@rule(
    "EDS091",
    E,
    "Key or section name that peers do not find",
    """
CiA 306 matches key and section names without regard to case, but not with blanks inside or
letters changed: `Supported Objects=` is not SupportedObjects (CiA 306 §4.5.2), and the DCF
section is spelled `[DeviceComissioning]` (one m, CiA 306 §5.3.1) even though the English word has
two. cantools-od reads such a name as meant, but lely's dcfchk rejects it and python-canopen does
not find it: a DCF's NodeID and baud rate, or an object list's count, are silently lost there.

Error: a peer reading the file by the standard loses the entry. Case alone is DIA018.
Fix: the name is written as CiA 306 spells it; the rest of the line stays. Safe for a name
python-canopen does not look up (an object list's count); unsafe (`--unsafe-fixes`) for one it
does, since it then reads a value it did not read before.""",
    "[MandatoryObjects]\nSupported Objects=3\n1=0x1000\n2=0x1001\n3=0x1018",
    fixed="[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018",
    per_object=True,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "lely dcfchk rejects the name and python-canopen does not find it"),
)
def unfound_spelling(ctx: Context) -> Iterator[Finding]:
    for spelling in spellings(ctx):
        if not spelling.found_by_peers:
            what = "section" if spelling.header else "key"
            message = (
                f"{spelling.written}: CiA 306 spells this {what} {spelling.canonical}; lely and python-canopen miss it"
            )
            yield ctx.report("EDS091", message, spelling.where, spelling.fix())
