"""Rule family: values — DefaultValue, ParameterValue and limits against their data type.

CiA 306 §4.6.3, §5.3.3.2; CiA 301 data types.
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Iterator

from ..model import (
    DataType,
    Location,
    NodeIdExpr,
    Object,
    ObjectKind,
    Severity,
    SubObject,
    TimeValue,
    Value,
    ValueKind,
    Variable,
)
from ..model.datatypes import TIME_OF_DAY
from . import examples as ex
from .rules import Clause, Context, Finding, Placement, rule

E, W = Severity.ERROR, Severity.WARNING

_COMPOUND = (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT)
_NODEID_TEXT = re.compile(r"\s*\$nodeid", re.IGNORECASE)
_TIME_OF_DAY_MS = 86_400_000
_ALL_NODE_IDS = tuple(range(1, 128))
_PLAIN = (int, float)  # the types of a value that is a number as it stands (bool is no limit's type)
_PLAIN_OR_NONE = (int, float, type(None))


class Entry:
    """One entry with values: `limits` is where its limits come from (the object, for CompactSubObj subs).

    Made once for the values family (`entries`) and held until its last rule, one for every entry of the device:
    a plain class with four slots, which keeps a large file's check within its memory bound. What the rules ask
    of it is derived when asked, and its label only for a message."""

    __slots__ = ("dtype", "owner", "subindex", "var")

    def __init__(self, owner: Object, subindex: int | None, var: Variable, dtype: DataType | None) -> None:
        self.owner = owner
        self.subindex = subindex  # None for the object itself
        self.var = var
        self.dtype = dtype

    @property
    def implicit(self) -> bool:
        """A CompactSubObj sub-object: only its [xxxxValue] value is its own, its limits are the object's."""
        return isinstance(self.var, SubObject) and self.var.implicit

    @property
    def limits(self) -> Variable:
        return self.owner if self.implicit else self.var

    @property
    def label(self) -> str:
        index = self.owner.index
        if self.subindex is None:
            return f"[{index:04X}]"
        return f"[{index:04X}Value] {self.subindex}" if self.implicit else f"[{index:04X}sub{self.subindex:X}]"

    def values(self) -> list[tuple[str, Value]]:
        """(key, value) of each value the entry states itself, in key order."""
        var = self.var
        own = not self.implicit
        found: list[tuple[str, Value]] = []
        if own and var.default is not None:
            found.append(("DefaultValue", var.default))
        if var.parameter_value is not None:
            found.append(("ParameterValue", var.parameter_value))
        if own and var.low_limit is not None:
            found.append(("LowLimit", var.low_limit))
        if own and var.high_limit is not None:
            found.append(("HighLimit", var.high_limit))
        return found


def entries(ctx: Context) -> list[Entry]:
    """Every entry whose values are its own, once: a CompactSubObj object stands for the subs it copies into.

    Walked once for the rules of this family that ask (`Context.forget` drops it after them)."""
    return ctx.once("value_entries", lambda: list(_walk(ctx)))


def _walk(ctx: Context) -> Iterator[Entry]:
    device = ctx.device
    entry_type = device.entry_type
    for obj in device.objects.values():
        if obj.implicit:
            continue  # CompactPDO: made up from the standard, not from the file
        compound = obj.kind in _COMPOUND
        if not compound or obj.compact_sub_obj:
            yield Entry(obj, None, obj, entry_type(obj, obj))
        if not compound:
            continue
        for subindex, sub in obj.subs.items():
            if not sub.implicit or subindex != 0:
                yield Entry(obj, subindex, sub, entry_type(sub, obj))


def _at(ctx: Context, entry: Entry, key: str) -> Location:
    return ctx.written_at(entry.owner, entry.var, key)


def node_ids(ctx: Context) -> tuple[int, ...]:
    """The node-IDs `$NODEID` may stand for: the given or commissioned one, else 1..127."""
    for candidate in (ctx.options.node_id, ctx.device.node_id):
        if candidate is not None and 1 <= candidate <= 127:
            return (candidate,)
    return _ALL_NODE_IDS


def number(value: Value | None, node_id: int) -> int | float | None:
    """A value as a number to compare, `$NODEID` resolved; None when it is no number (or no value)."""
    if isinstance(value, NodeIdExpr):
        return value.resolve(node_id)
    if isinstance(value, (int, float)):  # bool included: BOOLEAN is 0 or 1
        return value
    return None


def always(nids: tuple[int, ...], problem: Callable[[int], str | None]) -> str | None:
    """The problem for the first node-ID when there is one for every node-ID, else None.

    A `$NODEID` value that is wrong only for some node-IDs describes a device restricted to the
    others (a COB-ID limited to 0x181..0x18F serves node-IDs 1..15); that is not reported.
    """
    first = problem(nids[0])
    if first is None or any(problem(nid) is None for nid in nids[1:]):
        return None
    return first


def _formula(value: Value, node_id: int, nids: tuple[int, ...]) -> str:
    if not isinstance(value, NodeIdExpr):
        return ""
    return f" for node-ID {node_id}" if len(nids) == 1 else " for every node-ID 1..127"


@rule(
    "EDS034",
    E,
    "Value outside its data type's range",
    """
A DefaultValue, ParameterValue or limit must fit its data type: UNSIGNED8 holds 0..255,
INTEGER16 -32768..32767, and so on; a TIME value's days fit 16 bits and its milliseconds 28
bits (a day for TIME_OF_DAY). `$NODEID` values are checked for every node-ID 1..127 (or the
node-ID given). Tools truncate such values or reject the file.""",
    "[2000]\nParameterName=Count\nDataType=0x0005\nAccessType=rw\nDefaultValue=300",
    fixed="[2000]\nParameterName=Count\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=300\nPDOMapping=0",
    per_object=True,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "lely dcfchk: overflow; tools truncate the value"),
)
def type_range(ctx: Context) -> Iterator[Finding]:
    bounds: dict[int, tuple[int, int] | None] = {}  # per data type index
    for entry in entries(ctx):
        dtype = entry.dtype
        if dtype is None:
            continue
        index = dtype.index
        if index not in bounds:
            bounds[index] = dtype.int_range() if dtype.is_integer else None
        fits = bounds[index]
        for key, value in entry.values():
            if fits is not None and type(value) is int and fits[0] <= value <= fits[1]:
                continue  # the common case, without a call
            problem = _range_problem(ctx, dtype, value)
            if problem:
                yield ctx.report("EDS034", f"{entry.label} {key}: {problem}", _at(ctx, entry, key))


def _range_problem(ctx: Context, dtype: DataType, value: Value) -> str | None:
    if isinstance(value, TimeValue) and dtype.kind is ValueKind.TIME:
        ms_limit = _TIME_OF_DAY_MS if dtype.index == TIME_OF_DAY.index else 1 << 28
        if not (0 <= value.days <= 0xFFFF and 0 <= value.ms < ms_limit):
            return f"{value.days} days {value.ms} ms is outside {dtype.name}"
        return None
    bounds = dtype.int_range() if dtype.is_integer else None
    if bounds is None or isinstance(value, bool):
        return None
    low, high = bounds
    if isinstance(value, int) and low <= value <= high:
        return None  # the common case, without a node-ID to try
    nids = relevant(ctx, value)

    def problem(nid: int) -> str | None:
        resolved = number(value, nid)
        if not isinstance(resolved, int) or low <= resolved <= high:
            return None
        shown = f"{resolved} (0x{resolved:X})" if resolved >= 0 else str(resolved)
        return f"{shown}{_formula(value, nid, nids)} is outside {dtype.name} ({low}..{high})"

    return always(nids, problem)


@rule(
    "EDS036",
    E,
    "Limits on a non-numeric data type",
    """
LowLimit and HighLimit bound numeric values (integers, BOOLEAN, REAL); strings, OCTET_STRING,
DOMAIN and the TIME types have no order a limit could use (CiA 306, LowLimit/HighLimit).""",
    "[2000]\nParameterName=Name\nDataType=0x0009\nAccessType=rw\nLowLimit=0",
    fixed="[2000]\nParameterName=Name\nObjectType=0x7\nDataType=0x0009\nAccessType=rw\nDefaultValue=x\nPDOMapping=0",
    per_object=True,
    placed=Placement(
        Clause.PEER_READS_OTHERWISE, "lely dcfchk: limit not supported for the type; no order a limit could use"
    ),
)
def non_numeric_limits(ctx: Context) -> Iterator[Finding]:
    for entry in entries(ctx):
        if entry.implicit or entry.dtype is None or entry.dtype.is_numeric or entry.owner.kind is ObjectKind.DOMAIN:
            continue  # limits on a DOMAIN object: EDS024
        for key, field in (("LowLimit", "low_limit"), ("HighLimit", "high_limit")):
            if getattr(entry.var, field) is not None:
                message = f"{entry.label} {key} on {entry.dtype.name}, which has no numeric order"
                yield ctx.report("EDS036", message, ctx.at(entry.var, key))


def relevant(ctx: Context, *values: Value | None) -> tuple[int, ...]:
    """The node-IDs worth trying: one stands for all when no value is a `$NODEID` formula."""
    return node_ids(ctx) if any(isinstance(v, NodeIdExpr) for v in values) else (1,)


def _inverted(ctx: Context, entry: Entry) -> bool:
    """LowLimit > HighLimit (for every node-ID, with `$NODEID` limits)."""
    limits = entry.limits
    low_value, high_value = limits.low_limit, limits.high_limit
    if low_value is None or high_value is None:
        return False
    if type(low_value) in _PLAIN and type(high_value) in _PLAIN:  # the common case, without a node-ID to try
        return low_value > high_value  # type: ignore[operator]

    def problem(nid: int) -> str | None:
        low, high = number(low_value, nid), number(high_value, nid)
        return "inverted" if low is not None and high is not None and low > high else None

    return always(relevant(ctx, low_value, high_value), problem) is not None


@rule(
    "EDS031",
    E,
    "LowLimit above HighLimit",
    """
No value can satisfy a LowLimit greater than its HighLimit; every write to the entry fails.
Signed limits are compared as the numbers they denote (two's-complement hex included).""",
    "[2000]\nParameterName=Offset\nDataType=0x0003\nAccessType=rw\nLowLimit=100\nHighLimit=-100",
    fixed=(
        "[2000]\nParameterName=Offset\nObjectType=0x7\nDataType=0x0003\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0\nLowLimit=-100\nHighLimit=100"
    ),
    per_object=True,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "every write to the entry fails"),
)
def limits_order(ctx: Context) -> Iterator[Finding]:
    for entry in entries(ctx):
        if entry.implicit or entry.var.low_limit is None or entry.var.high_limit is None or entry.dtype is None:
            continue
        if entry.dtype.is_numeric and _inverted(ctx, entry):
            low, high = entry.var.low_limit, entry.var.high_limit
            low_number = number(low, 1)
            hint = ""
            if entry.dtype.kind is ValueKind.SIGNED and isinstance(high, int) and high < 0 <= (low_number or 0):
                hint = " (a hex HighLimit such as 0xFF is two's complement for a signed type)"
            message = f"{entry.label} LowLimit {_shown(low)} > HighLimit {_shown(high)}{hint}"
            yield ctx.report("EDS031", message, ctx.value_at(entry.var, "LowLimit"))


def _shown(value: Value | None) -> str:
    if isinstance(value, NodeIdExpr):
        return value.canonical()
    return repr(value) if isinstance(value, str) else str(value)


def _beyond(key: str, value: float, low: float | None, high: float | None, formula: str) -> str | None:
    if low is not None and value < low:
        return f"{key} {value}{formula} is below LowLimit {low}"
    if high is not None and value > high:
        return f"{key} {value}{formula} is above HighLimit {high}"
    return None


def _outside(ctx: Context, entry: Entry, key: str, value: Value) -> str | None:
    limits = entry.limits
    low_value, high_value = limits.low_limit, limits.high_limit
    if low_value is None and high_value is None:
        return None
    if entry.dtype is None or not entry.dtype.is_numeric or _inverted(ctx, entry):
        return None
    if type(value) in _PLAIN and type(low_value) in _PLAIN_OR_NONE and type(high_value) in _PLAIN_OR_NONE:
        return _beyond(key, value, low_value, high_value, "")  # type: ignore[arg-type]  # no node-ID to try
    nids = relevant(ctx, value, low_value, high_value)

    def problem(nid: int) -> str | None:
        resolved = number(value, nid)
        if resolved is None:
            return None
        return _beyond(key, resolved, number(low_value, nid), number(high_value, nid), _formula(value, nid, nids))

    return always(nids, problem)


@rule(
    "EDS035",
    E,
    "DefaultValue outside the limits",
    """
The DefaultValue lies within LowLimit..HighLimit (CiA 306, LowLimit/HighLimit); a device cannot start with a
value it would refuse to be written. `$NODEID` defaults are checked for node-IDs 1..127.""",
    "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\nDefaultValue=5000\nHighLimit=3000",
    fixed=(
        "[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=3000\n"
        "PDOMapping=0\nHighLimit=3000"
    ),
    per_object=True,
    placed=Placement(
        Clause.DEVICE_MISBEHAVES, "the device starts with a value it refuses to be written (lely dcfchk: overflow)"
    ),
)
def default_in_limits(ctx: Context) -> Iterator[Finding]:
    for entry in entries(ctx):
        if (
            entry.implicit
            or entry.var.default is None
            or (entry.var.low_limit is None and entry.var.high_limit is None)
        ):
            continue
        problem = _outside(ctx, entry, "DefaultValue", entry.var.default)
        if problem:
            yield ctx.report("EDS035", f"{entry.label} {problem}", ctx.value_at(entry.var, "DefaultValue"))


@rule(
    "EDS061",
    E,
    "ParameterValue outside the limits",
    """
A DCF's ParameterValue (and each `[xxxxValue]` entry of a CompactSubObj object, checked against
the object's limits) is configured into the device, which refuses values outside
LowLimit..HighLimit (SDO abort 0609 0031h/0032h); the configuration fails at boot-up. Not checked
on read-only (ro, const) entries: nothing configures them, their ParameterValue is what a tool read
back from the device.""",
    (
        ex.NODE_5 + "[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0\nHighLimit=3000\nParameterValue=5000"
    ),
    fixed=(
        ex.NODE_5 + "[2000]\nParameterName=Speed\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\n"
        "PDOMapping=0\nHighLimit=3000\nParameterValue=3000"
    ),
    per_object=True,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device refuses the configured value (abort 0609 0031h/0032h)"),
)
def parameter_in_limits(ctx: Context) -> Iterator[Finding]:
    for entry in entries(ctx):
        value, access = entry.var.parameter_value, entry.var.access
        if value is None or (access is not None and not access.writable):
            continue  # a read-only entry's ParameterValue is uploaded from the device, never configured into it
        problem = _outside(ctx, entry, "ParameterValue", value)
        if problem:
            yield ctx.report("EDS061", f"{entry.label} {problem}", _at(ctx, entry, "ParameterValue"))


@rule(
    "EDS037",
    W,
    "$NODEID in a value that is not an integer",
    """
`$NODEID` formulas are defined for integer entries only (CiA 306 §4.3). In a VISIBLE_STRING
the text stays as it is, which is rarely what was meant: usually the DataType is wrong.""",
    "[2000]\nParameterName=COB-ID\nDataType=0x0009\nAccessType=ro\nDefaultValue=$NODEID+0x180",
    fixed=(
        "[2000]\nParameterName=COB-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\n"
        "DefaultValue=$NODEID+0x180\nPDOMapping=0"
    ),
    per_object=True,
    placed=Placement(Clause.STYLE, "a string keeps `$NODEID` as text; usually the DataType is wrong"),
)
def nodeid_text(ctx: Context) -> Iterator[Finding]:
    for entry in entries(ctx):
        for key, value in entry.values():
            if isinstance(value, str) and _NODEID_TEXT.match(value) and entry.dtype is not None:
                message = f"{entry.label} {key}={value}: $NODEID on {entry.dtype.name} is kept as text"
                yield ctx.report("EDS037", message, _at(ctx, entry, key))


@rule(
    "EDS038",
    W,
    "VISIBLE_STRING with characters outside printable ASCII",
    """
VISIBLE_STRING holds the visible ISO 646 characters 20h-7Eh. Other characters (umlauts, µ, °,
control characters) have no defined encoding on the bus; devices and tools show them
differently. Use UNICODE_STRING or OCTET_STRING for other text.""",
    "[1008]\nParameterName=Device name\nDataType=0x0009\nAccessType=const\nDefaultValue=Motor 5°",
    fixed=(
        "[1008]\nParameterName=Device name\nObjectType=0x7\nDataType=0x0009\nAccessType=const\n"
        "DefaultValue=Motor 5 deg\nPDOMapping=0"
    ),
    per_object=True,
    placed=Placement(Clause.PORTABILITY, "no defined encoding on the bus; devices and tools show it differently"),
)
def visible_string(ctx: Context) -> Iterator[Finding]:
    for entry in entries(ctx):
        if entry.dtype is None or entry.dtype.kind is not ValueKind.STRING:
            continue
        for key, value in entry.values():
            odd = sorted({c for c in value if not " " <= c <= "~"}) if isinstance(value, str) else []
            if odd:
                shown = ", ".join(f"U+{ord(c):04X}" for c in odd[:5])
                message = f"{entry.label} {key}: characters outside printable ASCII ({shown})"
                yield ctx.report("EDS038", message, _at(ctx, entry, key))


@rule(
    "EDS039",
    W,
    "REAL value not finite",
    """
A REAL DefaultValue, ParameterValue or limit that is NaN or infinite cannot be compared or range
checked; as a limit it disables the check, as a default it is rarely intended. Peer tools read
`nan`/`inf` text differently or not at all.""",
    "[2000]\nParameterName=Gain\nDataType=0x0008\nAccessType=rw\nDefaultValue=nan",
    fixed="[2000]\nParameterName=Gain\nObjectType=0x7\nDataType=0x0008\nAccessType=rw\nDefaultValue=1.5\nPDOMapping=0",
    per_object=True,
    placed=Placement(Clause.BEYOND_THE_PEERS, "tools read `nan`/`inf` text differently; comparisons fail"),
)
def real_finite(ctx: Context) -> Iterator[Finding]:
    for entry in entries(ctx):
        if entry.dtype is None or entry.dtype.kind is not ValueKind.REAL:
            continue
        for key, value in entry.values():
            if isinstance(value, float) and not math.isfinite(value):
                yield ctx.report("EDS039", f"{entry.label} {key}={value}: not a finite number", _at(ctx, entry, key))
