"""Imports every rule family so that RULES is complete."""

from __future__ import annotations

import importlib
from functools import cache

FAMILIES = (
    "reader",
    "xdd",
    "syntax",
    "objects",
    "dcf",
    "objlists",
    "values",
    "identity",
    "pdo",
    "cobid",
    "portability",
    "canopennode",
)


@cache
def load() -> None:
    for family in FAMILIES:
        importlib.import_module(f"{__package__}.{family}")
