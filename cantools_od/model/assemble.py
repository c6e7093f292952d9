"""Builds model instances from values already of the right type, without validation.

Readers produce typed values themselves; pydantic's `model_construct` would
spend longer filling in defaults than the whole parse of a line takes.
"""

from __future__ import annotations

from copy import copy
from functools import cache
from typing import Any, TypeVar

from pydantic import BaseModel

M = TypeVar("M", bound=BaseModel)

_TEMPLATES: dict[tuple[type[BaseModel], int], tuple[dict[str, Any], dict[str, Any], set[str]]] = {}


def assemble(cls: type[M], values: dict[str, Any], defaults: dict[str, Any]) -> M:
    """An instance of `cls` from `defaults` overlaid with `values`.

    `defaults` must name every field (immutable values only, as they are shared). Every field
    counts as set (a reader gives each a value), and the instances of one class share that set:
    a set per instance would cost more memory than the instance's values in a large file.
    """
    found = _TEMPLATES.get((cls, id(defaults)))  # a reader calls this once per section: no further call
    if found is None or found[0] is not defaults:
        found = _template(cls, defaults)
    fields = found[1].copy()  # a copy of a key-sharing dict shares its keys too
    fields.update(values)
    obj = cls.__new__(cls)
    _set(obj, "__dict__", fields)
    _set(obj, "__pydantic_fields_set__", found[2])
    _set(obj, "__pydantic_extra__", None)
    _set(obj, "__pydantic_private__", None)
    return obj


_set = object.__setattr__


def _template(cls: type[BaseModel], defaults: dict[str, Any]) -> tuple[dict[str, Any], dict[str, Any], set[str]]:
    """`defaults` as the attribute dict of an instance of `cls`, made by setting the attributes one by
    one: CPython then shares the key table among the class's instances (PEP 412), which makes each
    copy about half the size of a plain dict of the same fields. Kept with `defaults` (so that its id
    stays its own) and the set of all field names."""
    instance = cls.__new__(cls)
    for name, value in defaults.items():
        _set(instance, name, value)
    found = _TEMPLATES[(cls, id(defaults))] = (defaults, instance.__dict__, _all_fields(cls))
    return found


@cache
def _all_fields(cls: type[BaseModel]) -> set[str]:
    # Shared: pydantic adds a field's name on assignment, which changes nothing here.
    return set(cls.model_fields)


def construct(cls: type[M], values: dict[str, Any]) -> M:
    """An instance of `cls` from `values` already of the right type, its other fields at their defaults (made
    fresh where a field has a default factory): `assemble` for classes with few instances, without validation
    (which would build the class's schema on first use: a cost at every start of the command line)."""
    defaults, factories = _class_defaults(cls)
    for name, factory in factories:
        if name not in values:
            values[name] = factory()
    return assemble(cls, values, defaults)


def fresh(cls: type[M], values: dict[str, Any]) -> M:
    """`construct`, with a new copy of each mutable default (a dict, list or set) the values do not give, as a
    validating constructor makes: for instances edited in place after they are made (the XDD reader's).
    Validation costs more than the rest of making an object of an XML element."""
    for name, default in _mutable_defaults(cls):
        if name not in values:
            values[name] = copy(default)
    return construct(cls, values)


@cache
def _mutable_defaults(cls: type[BaseModel]) -> tuple[tuple[str, Any], ...]:
    return tuple((name, value) for name, value in field_defaults(cls).items() if isinstance(value, dict | list | set))


@cache
def _class_defaults(cls: type[BaseModel]) -> tuple[dict[str, Any], tuple[tuple[str, Any], ...]]:
    factories = tuple((name, info.default_factory) for name, info in cls.model_fields.items() if info.default_factory)
    made = {name for name, _ in factories}  # these take the place of their factory's value, in field order
    defaults = {name: (None if name in made else value) for name, value in field_defaults(cls).items()}
    return defaults, factories


def field_defaults(cls: type[BaseModel]) -> dict[str, Any]:
    """The default of every field of `cls` (None where a field has none)."""
    return {name: (None if info.is_required() else info.default) for name, info in cls.model_fields.items()}
