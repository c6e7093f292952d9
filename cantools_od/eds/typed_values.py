"""Gives DefaultValue, ParameterValue and the limits their data type's form."""

from __future__ import annotations

from ..model import Device, Dialect, Object, SubObject, ValueKind, Variable
from .dialect import unquote
from .ini import Entry
from .keys import OBJECT_KEYS, normalize
from .report import Report
from .sections import Collected
from .values import Parsed, parse_value


def type_entry(device: Device, var: Variable, owner: Object, field: str, entry: Entry, report: Report) -> None:
    dtype = device.entry_type(var, owner)
    kind = dtype.kind if dtype is not None else None
    text = entry.value
    if kind is ValueKind.STRING and device.dialect is Dialect.LELY:
        unquoted = unquote(text)
        if unquoted is not None:
            var.__dict__[field] = unquoted  # the reader's own instance: no validation to run
            return
    parsed = parse_value(text, kind, dtype.bits if dtype else None, dtype.name if dtype else "this type")
    store(var, field, entry, parsed, report)


def store(var: Variable, field: str, entry: Entry, parsed: Parsed, report: Report) -> None:
    """A typed value into the reader's own instance (no validation to run), with its notes reported."""
    var.__dict__[field] = parsed.value
    for note in parsed.notes:
        report.add(note.code, note.severity, f"{entry.key}: {note.message}", entry.line, entry.value_col)
    if parsed.comment is not None:
        key = OBJECT_KEYS[normalize(entry.key)][0]
        var.comments = {**var.comments, key: [*var.comments.get(key, []), parsed.comment]}


def type_values(device: Device, deferred: list[tuple[Object, SubObject | None, Collected]], report: Report) -> None:
    for owner, sub, collected in deferred:
        var: Variable = sub if sub is not None else owner
        for field, entry in collected.deferred.items():
            type_entry(device, var, owner, field, entry, report)
