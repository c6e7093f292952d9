"""Models as plain data, for comparisons, without pydantic's serializer.

`model_dump` needs the class's core schema: the first call in a process builds it and loads pydantic's plugins
(about 30 ms), a cost a writer would pay at every start of `fmt` or `convert`. The model has no serializers and
excludes no field, so its dump is its fields, walked.
"""

from __future__ import annotations

from collections.abc import Collection

from pydantic import BaseModel


def plain(value: object, exclude: Collection[str] = ()) -> object:
    """`value` as `model_dump()` gives it (`exclude`: fields of the top model left out): each model a dict of its
    fields, lists, tuples and dicts walked, every other value as it is."""
    if isinstance(value, BaseModel):
        return {name: plain(getattr(value, name)) for name in type(value).model_fields if name not in exclude}
    if isinstance(value, dict):
        return {key: plain(item) for key, item in value.items()}
    if isinstance(value, list):
        return [plain(item) for item in value]
    if isinstance(value, tuple):
        return tuple(plain(item) for item in value)
    return value
