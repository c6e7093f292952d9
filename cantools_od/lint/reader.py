"""Codes the reader reports while it reads a file (see cantools_od/eds)."""

from __future__ import annotations

from collections.abc import Callable

from ..eds.keys import OBJECT_KEYS, Kind
from ..model import Device, Diagnostic, NodeIdExpr, Severity, Variable
from .rules import Context, Fix, declare

E, W = Severity.ERROR, Severity.WARNING

declare(
    "EDS000",
    E,
    "Not an EDS/DCF file",
    """
The file holds no device description: binary data (a NUL byte), nothing but blank space, text
without a single `[section]` header, or XML (CiA 311 XDD/XDC files are not CiA 306 text). Every
command refuses such a file with this one line and exit code 2, and never writes to it: a
formatter that read it as an empty device would otherwise replace it with one.""",
    "\x7fELF\x02\x01\x01\x00...",
)
declare(
    "EDS002",
    W,
    "Duplicate section or key",
    """
A section or key appears twice. CiA 306 files are INI files, where names are unique; tools
disagree on which copy counts. cantools-od merges repeated sections and keeps the last value
of a repeated key.""",
    "[1000]\nParameterName=Device type\nParameterName=Device kind",
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
reads the byte 00h. Fix: none offered; write the value in its type's form (DOMAIN: hex byte pairs).
Fixed: `DefaultValue=12`.""",
    "[2000]\nDataType=0x0005\nDefaultValue=twelve",
)
declare(
    "EDS032",
    W,
    "Value written in a non-portable form",
    """
CiA 306 does not define this form, and peer tools read it differently: octal numbers (python-
canopen drops them), C suffixes such as `LL`, two's-complement hex for negative limits (lely
rejects it), an inline comment after a value (CiA 306 has none), blank-separated hex bytes.""",
    "DefaultValue=0x3ED ; prevent homing",
)
declare(
    "EDS033",
    W,
    "Non-portable $NODEID formula",
    """
CiA 306 writes `$NODEID` first, in upper case, followed by `+` terms. `0x180+$NODEID` is
rejected by lely; `$NODEID+0x100+0x80` is read as one term by python-canopen and lely;
lower-case `$nodeid` is not accepted by every tool. Subtracting from `$NODEID` is an error.""",
    "DefaultValue=0x180+$NODEID",
)
declare(
    "EDS100",
    W,
    "File is not UTF-8",
    """
The file contains bytes that are not UTF-8; it was read as Windows-1252 (or Latin-1). Other
tools may read those characters differently. Save the file as ASCII or UTF-8.""",
)
declare(
    "EDS101",
    E,
    "Line is not an entry",
    """
Inside a section every line is `key=value`, a `;` comment or blank. This line is none of them
(or stands before the first section) and is ignored.""",
    "[1000]\nParameterName Device type",
)
declare(
    "EDS102",
    E,
    "Section header without ']'",
    """
A line starting with `[` must end its section name with `]`.""",
    "[1000\nParameterName=Device type",
)
declare(
    "EDS103",
    E,
    "Sub-object section without its object",
    """
A `[<index>sub<n>]` section exists, but `[<index>]` does not (or the sub-index is above FEh).
The section is kept as text, but no tool can use it.""",
    "[2000sub1]\nParameterName=Orphan",
)
declare(
    "EDS104",
    E,
    "Bad [xxxxName]/[xxxxValue]/[xxxxDenotation]/[xxxxObjectLinks] section",
    """
Such a section needs its object, and the first three need CompactSubObj on it; keys are
decimal sub-indices 1..254 (ObjectLinks: 1..n), and NrOfEntries (ObjectLinks) counts them.""",
    "[2000Name]\nNrOfEntries=2\n1=First",
)


# Keys whose values are typed by the data type, so may hold `$NODEID`: canonical key → model field.
_VALUE_KEYS = {key: field for key, field, kind in OBJECT_KEYS.values() if kind is Kind.VALUE}


def reader_fix(ctx: Context, diagnostic: Diagnostic) -> Fix | None:
    """A fix for a finding the reader made: a wrong count (EDS104), a `$NODEID` spelling (EDS033)."""
    if diagnostic.code == "EDS104" and ("NrOfEntries=" in diagnostic.message or "ObjectLinks=" in diagnostic.message):
        return Fix("write the number of entries", safe=True, apply=_recount)
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
            canonical = NodeIdExpr(offset=value.offset)
            return Fix(f"write {canonical.canonical()}", safe=True, apply=_setter(var, field, canonical))
    return None


def _setter(var: Variable, field: str, value: NodeIdExpr) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        setattr(var, field, value)

    return apply


def _recount(device: Device) -> None:
    device._recount = True
