"""Helpers shared by the syntax, objects and dcf rule families: file start, given keys, explicit entries."""

from __future__ import annotations

from collections.abc import Iterator
from functools import cache

from ..eds import keys
from ..model import Device, Location, Object, Section, Variable
from ..model.assemble import construct
from ..model.source import location
from .rules import Context

OBJECT_FIELDS = {spec[0]: spec[1] for spec in keys.OBJECT_KEYS.values()}  # object key -> model field


def file_start(ctx: Context) -> Location:
    """Line 1: where file-level findings (a missing section) are reported."""
    return location(ctx.device.source, 1, 1)


def present(section: Section) -> bool:
    """Whether the file gave this section (a model from JSON: whether the section holds anything)."""
    return section.origin is not None or section != _empty(type(section))


@cache
def _empty(kind: type[Section]) -> Section:
    """The section with nothing in it, made without validation: the first validation in a process builds the
    class's schema and loads pydantic's plugins (about 30 ms), for every file without a [FileInfo]."""
    return construct(kind, {})


def invalid(section: Section, key: str) -> bool:
    """The key was written, but its value could not be read (it is in `extra`; the reader reported it)."""
    if not section.extra:
        return False
    wanted = keys.normalize(key)
    return any(keys.normalize(written) == wanted for written in section.extra)


def given(var: Variable, key: str) -> bool:
    """The object key has a non-empty value (a missing and an empty entry are the same, §1)."""
    value = getattr(var, OBJECT_FIELDS[key])
    if value is not None and value != "":
        return True
    return bool(var.extra) and invalid(var, key)  # `extra` is empty in nearly every section: no call


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


def checked_vars(ctx: Context) -> list[tuple[Object, int | None, Variable]]:
    """`explicit_vars` of the device under check, walked once for all the rules that ask."""
    return ctx.once("explicit_vars", lambda: list(explicit_vars(ctx.device)))


def where(obj: Object, subindex: int | None) -> str:
    return f"[{obj.index:04X}]" if subindex is None else f"[{obj.index:04X}sub{subindex:X}]"


def kind_unknown(obj: Object) -> bool:
    """The object's ObjectType was written but could not be read (EDS030): its kind in the model is a guess, so
    rules that judge what its kind requires say nothing (one root cause, one error)."""
    return invalid(obj, "ObjectType")
