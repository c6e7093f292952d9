"""Builds model instances from values already of the right type, without validation.

Readers produce typed values themselves; pydantic's `model_construct` would
spend longer filling in defaults than the whole parse of a line takes.
"""

from __future__ import annotations

from functools import cache
from typing import Any, TypeVar

from pydantic import BaseModel

M = TypeVar("M", bound=BaseModel)


def assemble(cls: type[M], values: dict[str, Any], defaults: dict[str, Any]) -> M:
    """An instance of `cls` from `defaults` overlaid with `values`.

    `defaults` must name every field (immutable values only, as they are shared). Every field
    counts as set (a reader gives each a value), and the instances of one class share that set:
    a set per instance would cost more memory than the instance's values in a large file.
    """
    obj = cls.__new__(cls)
    object.__setattr__(obj, "__dict__", {**defaults, **values})
    object.__setattr__(obj, "__pydantic_fields_set__", _all_fields(cls))
    object.__setattr__(obj, "__pydantic_extra__", None)
    object.__setattr__(obj, "__pydantic_private__", None)
    return obj


@cache
def _all_fields(cls: type[BaseModel]) -> set[str]:
    # Shared: pydantic adds a field's name on assignment, which changes nothing here.
    return set(cls.model_fields)


def field_defaults(cls: type[BaseModel]) -> dict[str, Any]:
    """The default of every field of `cls` (None where a field has none)."""
    return {name: (None if info.is_required() else info.default) for name, info in cls.model_fields.items()}
