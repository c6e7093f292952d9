"""Entries that moved: a name found at another index or sub-index than before, where the entry that was there
had another name. A permutation (names traded places) keeps the symbol set of generated code but changes what
each symbol addresses; a shifted block moves each of its entries by the same step. Both are moves, never
renames: a rename says the firmware may not build, a move that it builds and reads another quantity.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Mapping
from typing import Protocol


class Named(Protocol):
    @property
    def name(self) -> str: ...


def _unique(entries: Mapping[int, Named]) -> dict[str, int]:
    counts = Counter(entry.name for entry in entries.values())
    return {entry.name: key for key, entry in entries.items() if entry.name and counts[entry.name] == 1}


def by_name(old: Mapping[int, Named], new: Mapping[int, Named]) -> dict[int, int]:
    """New key → old key of each entry whose name, unique on both sides, now stands at another key."""
    before, after = _unique(old), _unique(new)
    return {key: before[name] for name, key in after.items() if name in before and before[name] != key}


def closed(pairs: Mapping[int, int]) -> bool:
    """The moves only trade places among themselves (a permutation): every key left is taken again."""
    return bool(pairs) and set(pairs) == set(pairs.values())


def step(pairs: Mapping[int, int]) -> int | None:
    """The one distance every move shares (a shifted block), else None."""
    steps = {new - old for new, old in pairs.items()}
    return steps.pop() if len(steps) == 1 and len(pairs) > 1 else None
