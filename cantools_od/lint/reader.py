"""Codes the reader reports while it reads a file (see cantools_od/eds)."""

from __future__ import annotations

from collections.abc import Callable

from ..eds.keys import OBJECT_KEYS, Kind
from ..model import Device, Diagnostic, NodeIdExpr, Severity, Variable
from ..model.assemble import construct
from .rules import Clause, Context, Fix, Placement, declare

E, W = Severity.ERROR, Severity.WARNING

declare(
    "EDS000",
    E,
    "Not an EDS/DCF file",
    """
The file holds no device description: binary data (a NUL byte), nothing but blank space, text
without a single `[section]` header, INI text of another tool (`setup.cfg`, `.gitconfig`: no section
CiA 306 knows, neither a file's own such as `[FileInfo]` nor an object's such as `[1000]`), JSON that
is no model (`[]`, `{"name": ...}`), or XML (CiA 311 XDD/XDC files are not CiA 306 text). Every
command refuses such a file with this one line and exit code 2, and never writes to it: a
formatter that read it as an empty device would otherwise replace it with one. The line names what
the file's name promised: a binary `device.xdd` is "not an XDD/XDC (CiA 311) file". `lint` reports a
file it cannot read at all (missing, a folder, no permission) with this code too, "cannot read: REASON",
whatever is selected, and checks every other file before it exits 2.""",
    "; whole file: device.eds\nIndex,Name,Data type,Access\n0x1000,Device type,UNSIGNED32,ro",
    fixed="; file: device.eds\n[1000]\nParameterName=Device type\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\n"
    "DefaultValue=0\nPDOMapping=0",
    fix_safety="No automatic fix: nothing is written to a file that is no device description.",
    placed=Placement(Clause.NOT_DONE, "no peer reads it as a device description; every command refuses it (exit 2)"),
)
declare(
    "JSN001",
    E,
    "Not a cantools-od model",
    """
A file read as JSON (by its `.json` name or its leading `{`) is not a model that `dump --format json`
or `convert -o x.json` wrote: it does not parse, or its fields are not the model's. Every command
refuses it with this one line and exit code 2, and never writes to it.""",
    '; whole file: device.json\n{"objects": 5}',
    fixed="; file: device.eds\n; $ cantools-od convert device.eds -o device.json\n; $ cantools-od lint device.json",
    fix_safety="No automatic fix: write the JSON model with `convert` or `dump --format json`.",
    placed=Placement(Clause.NOT_DONE, "not a model dump: every command refuses it (exit 2)"),
)
declare(
    "EDS002",
    E,
    "Duplicate section or key",
    """
A section or key appears twice. CiA 306 files are INI files, where names are unique; tools
disagree on which copy counts. cantools-od merges repeated sections and keeps the last value
of a repeated key. Error: python-canopen and lely's dcfchk cannot load the file at all
(configparser's DuplicateOptionError, DuplicateSectionError). `fmt` and `convert` still write it,
once, as cantools-od read it: that is how to repair it, after checking that the kept copy is the
one meant.""",
    (
        "[2000]\nParameterName=Speed\nParameterName=Velocity\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fixed=("[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"),
    fix_safety="No automatic fix: delete the copy that is not meant (cantools-od keeps the last value).",
    placed=Placement(
        Clause.PEER_CANNOT_LOAD, "python-canopen and lely dcfchk raise DuplicateOptionError/DuplicateSectionError"
    ),
)
declare(
    "EDS030",
    E,
    "Value not valid for its data type",
    """
A value (DefaultValue, ParameterValue, LowLimit, HighLimit, or a number in an info section)
cannot be read as its data type: not a number, an invalid octal number, a formula other than
`$NODEID` plus constants, hex digits that are not byte pairs, a REAL out of range. The text is
kept as it is.

Error: tools read another value or none. Warning for `DefaultValue=0` on a DOMAIN: CANopenNode's
editors write it for an empty domain and CANopenNode reads it so; lely rejects it, python-canopen
reads the byte 00h.""",
    ("[2000]\nParameterName=Count\nObjectType=0x7\nDataType=0x0005\nAccessType=rw\nDefaultValue=twelve\nPDOMapping=0"),
    fixed=(
        "[2000]\nParameterName=Count\nObjectType=0x7\nDataType=0x0005\nAccessType=rw\nDefaultValue=12\nPDOMapping=0"
    ),
    fix_safety="No automatic fix: write the value in its type's form (DOMAIN: hex byte pairs).",
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "peers read another value or none (lely dcfchk: invalid DefaultValue)"
    ),
)
declare(
    "EDS032",
    W,
    "Value written in a non-portable form",
    """
CiA 306 does not define this form, and peer tools read it differently: octal numbers (python-
canopen drops them), C suffixes such as `LL`, two's-complement hex for negative limits (lely
rejects it), an inline comment after a value (CiA 306 has none), blank-separated hex bytes.""",
    (
        "[2000]\nParameterName=Homing\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\n"
        "DefaultValue=0x3ED ; prevent homing\nPDOMapping=0"
    ),
    fixed=(
        "; 0x3ED: prevent homing\n[2000]\nParameterName=Homing\nObjectType=0x7\nDataType=0x0006\n"
        "AccessType=rw\nDefaultValue=0x3ED\nPDOMapping=0"
    ),
    fix_safety="No automatic fix: write the value as CiA 306 does (decimal, or hex with 0x), a comment on its own "
    "line.",
    placed=Placement(
        Clause.PORTABILITY, "not CiA 306's form; python-canopen drops octal, lely rejects two's-complement limits"
    ),
)
declare(
    "EDS033",
    E,
    "Non-portable $NODEID formula",
    """
CiA 306 writes `$NODEID` first, in upper case, followed by `+` terms. `0x180+$NODEID` and
`$NODEID+0x100+0x80` are errors: lely's dcf-tools reject the value ("invalid value"), so dcfchk
fails and dcfgen refuses the file ("invalid DCF"); python-canopen reads the first and no value
for the second. Subtracting from
`$NODEID` is an error. Lower-case `$nodeid`, which the peers read, is a warning, and so is a
form only lely rejects when it stands in an XDD, which lely does not read. `fmt` writes
each formula as `$NODEID+n` (a subtraction as it was written).""",
    (
        "[2000]\nParameterName=Response COB-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
        "DefaultValue=0x580+$NODEID\nPDOMapping=0"
    ),
    fixed=(
        "[2000]\nParameterName=Response COB-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
        "DefaultValue=$NODEID+0x580\nPDOMapping=0"
    ),
    placed=Placement(
        Clause.PEER_CANNOT_LOAD, "lely's dcf-tools raise on `0x180+$NODEID`: dcfchk fails, dcfgen refuses the file"
    ),
)
declare(
    "EDS100",
    E,
    "File is not UTF-8",
    """
The file contains bytes that are not UTF-8; it was read as DOS code page 850 when a word says so (`Sch\\x94naich`
is Schönaich there, `Sch”naich` in Windows-1252), else as Windows-1252. Other tools may read those
characters differently. Save the file as ASCII or UTF-8. Error: python-canopen (which opens the
file in the locale's encoding) and lely's dcfchk raise UnicodeDecodeError in a UTF-8 locale, so
they cannot load it; `fmt` still formats it, in the code page it was read with.""",
    "; encoding: cp1252\n; Drehzahl für Achse 1\n[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\n"
    "AccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fixed="; Drehzahl für Achse 1\n[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\n"
    "AccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fix_safety="No automatic fix: which code page a file is in is a guess, so `fmt` writes it back in the one it "
    "was read with and no byte of its text changes; save it as UTF-8 yourself.",
    placed=Placement(
        Clause.PEER_CANNOT_LOAD, "python-canopen and lely dcfchk raise UnicodeDecodeError in a UTF-8 locale"
    ),
)
declare(
    "EDS101",
    E,
    "Line is not an entry",
    """
Inside a section every line is `key=value`, a `;` comment or blank. This line is none of them
(or stands before the first section) and is ignored.""",
    ("[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue 0\nPDOMapping=0"),
    fixed=("[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0"),
    fix_safety="No automatic fix: the line is ignored; write it as key=value, or as a `;` comment.",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen and lely dcfchk raise configparser's ParsingError"),
)
declare(
    "EDS102",
    E,
    "Section header without ']'",
    """
A line starting with `[` must end its section name with `]`.""",
    "[2000\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fixed="[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\nPDOMapping=0",
    fix_safety="No automatic fix: close the section name with `]`.",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen and lely dcfchk fail on the broken header"),
)
declare(
    "EDS103",
    E,
    "Sub-object section without its object",
    """
A `[<index>sub<n>]` section exists, but `[<index>]` does not (or the sub-index is above FEh).
The section is kept as text, but no tool can use it.""",
    "[2000sub1]\nParameterName=Orphan",
    fixed=(
        "[2000]\nParameterName=Parent\nObjectType=0x9\nSubNumber=2\n\n[2000sub0]\n"
        "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=1\nPDOMapping=0\n\n[2000sub1]\nParameterName=Child\nObjectType=0x7\nDataType=0x0005\n"
        "AccessType=rw\nDefaultValue=0\nPDOMapping=0"
    ),
    fix_safety="No automatic fix: add the object's section, or delete the sub-object.",
    placed=Placement(
        Clause.PEER_CANNOT_LOAD,
        "python-canopen raises KeyError on the orphaned sub-object; lely dcfchk: object not defined",
    ),
)
declare(
    "EDS104",
    E,
    "Bad [xxxxName]/[xxxxValue]/[xxxxDenotation]/[xxxxObjectLinks] section",
    """
Such a section needs its object, and the first three need CompactSubObj on it; keys are
decimal sub-indices 1..254 (ObjectLinks: 1..n), and NrOfEntries (ObjectLinks) counts them.""",
    "[2000Name]\nNrOfEntries=2\n1=First",
    fixed=(
        "[2000]\nParameterName=Inputs\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=2\n\n"
        "[2000Name]\nNrOfEntries=2\n1=First\n2=Second"
    ),
    fix_safety="Safe for a wrong ObjectLinks count (no peer reads it): `--fix` writes the number of entries. Unsafe "
    "for a wrong NrOfEntries: python-canopen reads that many names, so the count changes what it reads (applied "
    "by `--unsafe-fixes`). No automatic fix otherwise.",
    placed=Placement(Clause.PEER_CANNOT_LOAD, "python-canopen raises KeyError; lely dcfchk: object not defined"),
)


# Keys whose values are typed by the data type, so may hold `$NODEID`: canonical key → model field.
_VALUE_KEYS = {key: field for key, field, kind in OBJECT_KEYS.values() if kind is Kind.VALUE}


def reader_fix(ctx: Context, diagnostic: Diagnostic) -> Fix | None:
    """A fix for a finding the reader made: a wrong count (EDS104), a `$NODEID` spelling (EDS033)."""
    if diagnostic.code == "EDS104":
        key = next((k for k in ("NrOfEntries", "ObjectLinks") if f"{k}=" in diagnostic.message), None)
        # python-canopen reads as many names as NrOfEntries says: a new count changes what it reads.
        return Fix("write the number of entries", key == "ObjectLinks", _recount(key)) if key else None
    if diagnostic.code != "EDS033":
        return None
    for _, _, var in ctx.variables():
        if var.origin is None:
            continue
        for key, field in _VALUE_KEYS.items():
            where = var.origin.where(key)
            value = getattr(var, field)
            if where is None or where[0] != diagnostic.location.line or not isinstance(value, NodeIdExpr):
                continue
            if value.offset < 0:
                return None  # `$NODEID-n` has no portable spelling
            canonical = construct(NodeIdExpr, {"offset": value.offset})
            # Unsafe: a peer that did not read the old spelling reads a value from the new one.
            return Fix(f"write {canonical.canonical()}", safe=False, apply=_setter(var, field, canonical))
    return None


def _setter(var: Variable, field: str, value: NodeIdExpr) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        setattr(var, field, value)

    return apply


def _recount(key: str) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        device._recount.add(key)

    return apply
