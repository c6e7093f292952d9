"""Models as plain data, for comparisons, without pydantic's serializer.

`model_dump` needs the class's core schema: the first call in a process builds it and loads pydantic's plugins
(about 30 ms), a cost a writer would pay at every start of `fmt` or `convert`. The model excludes no field, and
its one serializer, the typed values' JSON form (`model.values.Value`), is used for JSON only: its Python dump
(`model_dump()`, not `model_dump(mode="json")`) is its fields, walked.
"""

from __future__ import annotations

from collections.abc import Collection

from pydantic import BaseModel

_ATOMS = frozenset({int, str, float, bool, type(None)})


def plain(value: object, exclude: Collection[str] = ()) -> object:
    """`value` as `model_dump()` (Python mode) gives it (`exclude`: fields of the top model left out): each model
    a dict of its fields (its `__dict__`: pydantic keeps private attributes elsewhere), lists, tuples and dicts
    walked, every other value as it is."""
    if type(value) in _ATOMS:  # most values: one look-up rather than the checks below
        return value
    if isinstance(value, BaseModel):
        return {name: plain(item) for name, item in value.__dict__.items() if name not in exclude}
    if isinstance(value, dict):
        return {key: plain(item) for key, item in value.items()}
    if isinstance(value, list):
        return [plain(item) for item in value]
    if isinstance(value, tuple):
        return tuple(plain(item) for item in value)
    return value
