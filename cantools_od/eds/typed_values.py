"""Gives DefaultValue, ParameterValue and the limits their data type's form."""

from __future__ import annotations

from ..model import DataType, Device, Dialect, Object, SubObject, ValueKind, Variable
from .dialect import unquote
from .ini import Entry
from .keys import OBJECT_KEYS, normalize
from .report import Report
from .sections import Collected
from .values import parse_value


def type_entry(
    device: Device,
    var: Variable,
    owner: Object,
    field: str,
    entry: Entry,
    report: Report,
    dtype: DataType | None = None,
) -> None:
    """Types one value; `dtype`, when given, is the entry's type (a CiA 301 type the reader already looked up)."""
    if dtype is None:
        dtype = device.entry_type(var, owner)
    kind = dtype.kind if dtype is not None else None
    text = entry.value
    if kind is ValueKind.STRING and device.dialect is Dialect.LELY:
        unquoted = unquote(text)
        if unquoted is not None:
            var.__dict__[field] = unquoted  # the reader's own instance: no validation to run
            return
    parsed = parse_value(text, kind, dtype.bits if dtype else None, dtype.name if dtype else "this type")
    var.__dict__[field] = parsed.value
    for code, severity, message in parsed.notes:
        report.add(code, severity, f"{entry.key}: {message}", entry.line, entry.value_col)
    if parsed.comment is not None:
        key = OBJECT_KEYS[normalize(entry.key)][0]
        var.comments = {**var.comments, key: [*var.comments.get(key, []), parsed.comment]}


def type_values(device: Device, deferred: list[tuple[Object, SubObject | None, Collected]], report: Report) -> None:
    for owner, sub, collected in deferred:
        var: Variable = sub if sub is not None else owner
        for field, entry in collected.deferred.items():
            type_entry(device, var, owner, field, entry, report)
