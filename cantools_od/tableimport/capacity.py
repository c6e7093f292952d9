"""Capacities a manual states in prose: "Up to 8 objects can be mapped to a single RPDO",
"Sub-indices 1 to 4 define ...", "only four mapping parameters per PDO".

A manual often lists only the first entries of an object (sub-index 0 and 1 of a mapping record)
and says in a sentence how many there are. Each such sentence is read here, tied to the objects
it is about (all receive or transmit mapping records for a PDO sentence, else the objects
described just above it), and the missing entries are created with the type and access of the
last listed one, marked inferred with the sentence quoted.
"""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass
from pathlib import Path

from ..model import ObjectKind
from ..model.cia301.pdo import MAP_BASE, PDO_SPAN, RX, TX
from ..model.datatypes import standard_type
from .entries import Kind
from .facts import Fact, Norm, Source
from .merge import MergedEntry, MergedObject, MergeResult, Resolved

_WORDS = {
    "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8,
    "nine": 9, "ten": 10, "twelve": 12, "sixteen": 16, "thirty-two": 32, "sixty-four": 64,
}  # fmt: skip
_NUMBER = r"(\d+|" + "|".join(_WORDS) + r")"
_PDO_SENTENCE = re.compile(
    rf"\bup to {_NUMBER} (?:application )?(?:objects|entries) can be mapped"
    r" (?:to|in|into) (?:a single|one|each) ([RT])PDO",
    re.IGNORECASE,
)
_PER_PDO = re.compile(rf"\bonly {_NUMBER} mapping (?:parameters|entries|objects) per PDO", re.IGNORECASE)
_SUB_RANGE = re.compile(
    rf"\bsub-?ind(?:ex|ices|exes)\s*1\s*(?:to|\.\.\.|\.\.|\u2026|-|\u2013)\s*{_NUMBER}\b(?!\s*[.,]\d)", re.IGNORECASE
)
PROSE_CAPACITY = "prose capacity"  # the layout named in the sources of what a capacity sentence creates
# A sentence about sub-indices ties to the object described at most this many lines above it.
_NEAR = 120
MAX_SUB = 254


@dataclass(frozen=True)
class Capacity:
    """One sentence: in `file` at `line`, entries 1..`count` of the objects it names (`scope`)."""

    file: str
    line: int
    sentence: str
    count: int
    scope: str  # "rx", "tx", "pdo" (both) or "near" (the objects described above)

    def quote(self) -> str:
        return f'"{self.sentence}" ({Path(self.file).name}:{self.line})'


def _count(text: str) -> int:
    return int(text) if text.isdigit() else _WORDS[text.lower()]


def _sentence(line: str, start: int, end: int) -> str:
    """The sentence of `line` that holds the match at start..end."""
    head = max(line.rfind(". ", 0, start), -1) + 1
    tail = line.find(". ", end)
    text = line[head : tail + 1 if tail >= 0 else len(line)]
    return re.sub(r"\s+", " ", text.strip(" -*\t"))


def read_capacities(file: str, text: str) -> list[Capacity]:
    """Every capacity sentence of a manual's text, in line order."""
    found: list[Capacity] = []
    for number, line in enumerate(text.splitlines(), 1):
        for pattern in (_PDO_SENTENCE, _PER_PDO, _SUB_RANGE):
            for match in pattern.finditer(line):
                count = _count(match.group(1))
                if not 1 < count <= MAX_SUB:
                    continue
                if pattern is _PDO_SENTENCE:
                    scope = RX if match.group(2).upper() == "R" else TX
                else:
                    scope = "pdo" if pattern is _PER_PDO else "near"
                found.append(Capacity(file, number, _sentence(line, *match.span()), count, scope))
    return found


def _mapping_objects(merged: MergeResult, scope: str) -> list[MergedObject]:
    directions = (RX, TX) if scope == "pdo" else (scope,)
    ranges = [range(MAP_BASE[d], MAP_BASE[d] + PDO_SPAN) for d in directions]
    return [obj for index, obj in sorted(merged.objects.items()) if any(index in r for r in ranges)]


def _near_objects(merged: MergeResult, capacity: Capacity) -> list[MergedObject]:
    """The objects whose description ends closest above the sentence (a range of objects shares it)."""
    best, chosen = -1, []
    for obj in merged.objects.values():
        lines = [s.line for s in obj.sources if s.file == capacity.file and s.line <= capacity.line]
        last = max(lines, default=-1)
        if last < 0 or capacity.line - last > _NEAR:
            continue
        if last > best:
            best, chosen = last, [obj]
        elif last == best:
            chosen.append(obj)
    return chosen


def _copied(template: Resolved, obj: MergedObject, sub: int, field: str, value: Norm, source: Source) -> Resolved:
    fact = Fact(obj.index, sub, field, str(value), value, source, (source.file, source.line))
    return dataclasses.replace(template, value=value, facts=[fact], inferred=True, conflict=None, note="")


def _extend(obj: MergedObject, capacity: Capacity, inferred: list[tuple[int, int | None, str, str]]) -> None:
    listed = [sub for sub in obj.entries if sub >= 1]
    if not listed or obj.kind not in (ObjectKind.ARRAY, ObjectKind.RECORD) or max(listed) >= capacity.count:
        return
    last = max(listed)
    template = obj.entries[last]
    source = Source(capacity.file, capacity.line, PROSE_CAPACITY, Kind.INFERRED)
    name = template.fields.get("name")
    dtype = template.fields.get("data_type")
    numeric = dtype is not None and isinstance(dtype.value, int) and _is_integer(dtype.value)
    for sub in range(last + 1, capacity.count + 1):
        entry = MergedEntry(sub)
        for field in ("data_type", "access", "pdo_mapping"):
            found = template.fields.get(field)
            if found is not None:
                entry.fields[field] = _copied(found, obj, sub, field, found.value, source)
        if name is not None:
            entry.fields["name"] = _copied(name, obj, sub, "name", f"{name.value!s} ({sub})", source)
        if numeric and dtype is not None:
            entry.fields["default"] = _copied(dtype, obj, sub, "default", 0, source)
        obj.entries[sub] = entry
        inferred.append((obj.index, sub, "exists", f"entry created as sub {last}: {capacity.quote()}"))
    obj.entries = dict(sorted(obj.entries.items()))


def _is_integer(index: int) -> bool:
    dtype = standard_type(index)
    return dtype is not None and dtype.is_integer


def apply_capacities(merged: MergeResult, capacities: list[Capacity]) -> None:
    """Create the entries each capacity sentence states and the manual's lists leave out."""
    for capacity in capacities:
        if capacity.scope == "near":
            targets = _near_objects(merged, capacity)
        else:
            targets = _mapping_objects(merged, capacity.scope)
        for obj in targets:
            _extend(obj, capacity, merged.inferred)
