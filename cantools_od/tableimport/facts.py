"""Raw entries → facts: one normalised value of one field of one (index, sub-index), with its source.

Index ranges are expanded here onto the concrete indices the sources name (and, for PDOs,
their communication/mapping partners); a range no source makes concrete is expanded only
when it is short. Nothing is invented beyond that."""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Protocol

from ..model import AccessType, NodeIdExpr, ObjectKind, Severity
from .entries import Cell, Kind, RawEntry, ReadResult
from .notation import (
    IndexSpec,
    clean,
    is_blank,
    parse_access,
    parse_index,
    parse_mapping,
    parse_number,
    parse_object_code,
    parse_range,
    parse_sub,
    parse_type,
    split_per_index,
)

Norm = int | float | str | bytes | bool | NodeIdExpr | AccessType | ObjectKind

# Ranges longer than this are expanded only onto indices named elsewhere.
SHORT_RANGE = 16
# Value fields that are parsed once the entry's data type is known.
LATE_FIELDS = ("default", "low", "high")
NOTE_FIELDS = ("unit", "category", "description", "note", "sub_number", "scale", "entry_code", "direction")


@dataclass(frozen=True)
class Source:
    file: str
    line: int
    layout: str
    kind: Kind

    def short(self) -> str:
        name = self.file.rsplit("/", 1)[-1]
        return f"{name}:{self.line}"


@dataclass
class Fact:
    index: int
    sub: int | None  # None: the object itself
    field: str
    raw: str
    value: Norm | None  # None for late fields until the type is known
    source: Source
    row: tuple[str, int]  # the source row, so that a range reports one conflict
    note: str = ""
    implicit_sub: bool = False  # an entry that gave no sub-index (a VAR's block)


@dataclass
class _Pending:
    """A fact whose index is a range, waiting for the concrete indices."""

    spec: IndexSpec
    fact: Fact
    only: frozenset[int] | None = None  # per-index lists name their indices


def expand(results: Iterable[ReadResult]) -> tuple[list[Fact], list[ReadResult]]:
    """All facts of all sources; diagnostics are added to each result."""
    results = list(results)
    facts: list[Fact] = []
    pending: list[_Pending] = []
    letters: dict[str, int] = {}  # PDO letter (Nidec's RxPDO A..D) → PDO number
    for result in results:
        for entry in result.entries:
            _learn_letter(entry, letters)
    for result in results:
        for entry in result.entries:
            _entry_facts(entry, result, facts, pending, letters)
    known = {f.index for f in facts}
    partners = set()
    for index in known:
        if 0x1400 <= index <= 0x17FF or 0x1800 <= index <= 0x1BFF:
            partners.add(index ^ 0x0200 if (index & 0x0200) else index + 0x0200)
    concrete = known | partners
    by_file = {r.file: r for r in results}
    unexpanded: set[tuple[str, int, int, int]] = set()
    for item in pending:
        spec = item.spec
        targets = [i for i in spec.indices() if i in concrete]
        if not targets and spec.last - spec.first < SHORT_RANGE:
            targets = list(spec.indices())
        if item.only is not None:
            targets = [i for i in targets if i in item.only] or sorted(item.only)
        if not targets:
            key = (item.fact.source.file, item.fact.source.line, spec.first, spec.last)
            if key not in unexpanded:
                unexpanded.add(key)
                by_file[item.fact.source.file].warn(
                    "IMP013",
                    f"index range {spec.first:04X}h-{spec.last:04X}h names no concrete object; its entries are not "
                    "imported (objects are not invented)",
                    item.fact.source.line,
                    Severity.INFO,
                )
            continue
        for index in targets:
            fact = item.fact
            facts.append(
                Fact(
                    index,
                    fact.sub,
                    fact.field,
                    fact.raw,
                    fact.value,
                    fact.source,
                    fact.row,
                    fact.note,
                    fact.implicit_sub,
                )
            )
    return facts, results


def _learn_letter(entry: RawEntry, letters: dict[str, int]) -> None:
    letter = entry.fields.get("letter")
    if not letter:
        return
    match = _LETTER.match(clean(letter[0].text))
    spec = parse_index(entry.index.text)
    if match is None or spec is None:
        return
    if match.group(2):
        letters[match.group(1).upper()] = int(match.group(2))
    elif not spec.is_range and 0x1400 <= spec.first <= 0x1BFF:
        letters.setdefault(match.group(1).upper(), (spec.first & 0x1FF) + 1)


def _entry_facts(
    entry: RawEntry, result: ReadResult, facts: list[Fact], pending: list[_Pending], letters: dict[str, int]
) -> None:
    specs = _index_specs(entry, result, letters)
    if not specs:
        return
    subs: list[int | None]
    name_from_sub = ""
    implicit = False
    if entry.sub is not None and not entry.object_level:
        sub_spec = parse_sub(entry.sub.text, entry.hex_singles)
        if sub_spec is None:
            result.warn("IMP012", f"sub-index {entry.sub.text!r} not understood; row skipped", entry.sub.line)
            return
        subs = list(sub_spec.subs)
        name_from_sub = sub_spec.name
    elif specs[0].sub is not None:
        subs = [specs[0].sub]
    elif entry.object_level:
        subs = [None]
    else:
        subs = [0]
        implicit = True
    row = (entry.file, entry.expanded_from or entry.line)

    def emit(
        field: str,
        raw: str,
        value: Norm | None,
        line: int,
        kind: Kind | None = None,
        note: str = "",
        only: frozenset[int] | None = None,
        sub_list: list[int | None] | None = None,
    ) -> None:
        source = Source(entry.file, line, entry.layout, kind or entry.kind)
        for spec in specs:
            for sub in subs if sub_list is None else sub_list:
                fact = Fact(spec.first, sub, field, raw, value, source, row, note, implicit and sub == 0)
                if spec.is_range:
                    pending.append(_Pending(spec, fact, only))
                elif only is None or spec.first in only:
                    facts.append(fact)

    if name_from_sub:
        assert entry.sub is not None
        emit("name", name_from_sub, name_from_sub, entry.sub.line)
    for field, cells in entry.fields.items():
        for cell in cells:
            _field_facts(entry, result, field, cell, subs, emit)
    if not entry.fields and not name_from_sub and entry.sub is not None:
        emit("exists", entry.sub.text, True, entry.sub.line)


class _Emit(Protocol):  # the signature of `emit` above, for mypy
    def __call__(
        self,
        field: str,
        raw: str,
        value: Norm | None,
        line: int,
        kind: Kind | None = None,
        note: str = "",
        only: frozenset[int] | None = None,
        sub_list: list[int | None] | None = None,
    ) -> None: ...


def _field_facts(
    entry: RawEntry, result: ReadResult, field: str, cell: Cell, subs: list[int | None], emit: _Emit
) -> None:
    raw = cell.text
    text = clean(raw)
    line = cell.line
    if field == "name":
        if not text or is_blank(text):
            return
        if (
            len(text) > 100
            or re.search(r"\. [A-Z]", text)
            or text.lower().startswith(("will return", "returns", "are used"))
        ):
            emit("description", raw, text, line)
            return
        emit("name", raw, text, line)
    elif field == "object_code":
        if is_blank(text):
            return
        code = parse_object_code(text)
        if code is None:
            result.warn("IMP010", f"object code {text!r} not understood", line)
            return
        if subs != [None]:
            emit("entry_code", raw, code, line)
        else:
            emit("object_code", raw, code, line)
    elif field == "data_type":
        if is_blank(text) or text.lower() == "size":
            return
        spec = parse_type(text)
        if spec is None:
            result.warn("IMP010", f"data type {text!r} not understood; left unknown", line)
            emit("unknown_type", raw, text, line)
            return
        if spec.container is not None:
            emit("object_code", raw, spec.container, line, sub_list=[None])
            return
        if spec.index is not None:
            emit("data_type", raw, spec.index, line, note=spec.note)
    elif field == "access":
        spec_a = parse_access(text)
        if spec_a is None:
            if not is_blank(text):
                result.warn("IMP010", f"access {text!r} not understood; left unknown", line)
            return
        if spec_a.per_index:
            for index, access in spec_a.per_index.items():
                emit("access", raw, access, line, note=spec_a.note, only=frozenset([index]))
        elif spec_a.access is not None:
            emit("access", raw, spec_a.access, line, note=spec_a.note)
    elif field == "pdo_mapping":
        spec_m = parse_mapping(text)
        if spec_m is None or spec_m.mappable is None:
            if text and not is_blank(text):
                result.warn("IMP010", f"PDO mapping {text!r} not understood; left unknown", line)
            return
        emit("pdo_mapping", raw, spec_m.mappable, line)
        if spec_m.direction in ("rx", "tx"):
            emit("direction", raw, spec_m.direction, line)
    elif field == "default":
        per_index = split_per_index(text)
        if per_index:
            for index, value in per_index.items():
                emit("default", value, None, line, only=frozenset([index]))
            return
        if is_blank(text):
            return
        emit("default", raw, None, line)
    elif field == "range":
        spec_r = parse_range(text)
        if spec_r is None:
            return
        if spec_r.type_index is not None:
            emit("data_type", raw, spec_r.type_index, line, kind=Kind.DERIVED, note="type name given as value range")
        if spec_r.low is not None and spec_r.high is not None:
            emit("low", str(spec_r.low), None, line, note="from value range")
            emit("high", str(spec_r.high), None, line, note="from value range")
    elif field in ("low", "high"):
        if is_blank(text):
            return
        scale = entry.fields.get("scale")
        number = parse_number(text)
        if number is None:
            return
        if scale and "." in text:
            factor = parse_number(scale[0].text)
            if isinstance(factor, float) and factor > 0:
                emit(field, str(round(number / factor)), None, line, note=f"{text} / 1LSB {scale[0].text}")
                return
        emit(field, text, None, line)
    elif field == "description":
        constant = re.search(r"(?:constant|default)\s+value\s*(?:=|is)\s*(0x[0-9A-Fa-f]+|\d+)", text, re.IGNORECASE)
        if constant:
            emit("default", constant.group(1), None, line, note="stated in the description")
        emit("description", raw, text, line)
    elif field in NOTE_FIELDS and text and not is_blank(text):
        emit(field, raw, text, line)


_LETTER = re.compile(r"^\s*([A-D])\s*(?:\(\s*default\s*=\s*(\d+)\s*\))?", re.IGNORECASE)


def _index_specs(entry: RawEntry, result: ReadResult, letters: dict[str, int]) -> list[IndexSpec]:
    text = entry.index.text
    parts = [p for p in re.split(r",|\band\b", clean(text)) if p.strip()]
    specs = []
    for i, part in enumerate(parts):
        part = part.strip()
        if i > 0 and re.fullmatch(r"[0-9A-Fa-f]{4}h?", part):
            part = part if part.endswith("h") else part + "h"
        spec = parse_index(part, bare=entry.bare_index)
        if spec is None:
            if i == 0:
                result.warn("IMP011", f"index {text!r} not understood; row skipped", entry.index.line)
                return []
            continue
        specs.append(spec)
    letter = entry.fields.get("letter")
    if letter and specs and specs[0].is_range:
        match = _LETTER.match(clean(letter[0].text))
        if match and match.group(2):
            letters[match.group(1).upper()] = int(match.group(2))
            number = int(match.group(2))
            index = specs[0].first + number - 1
            if index <= specs[0].last:
                specs = [IndexSpec(index, index, specs[0].sub)]
    if letter and specs and specs[0].is_range:
        match = _LETTER.match(clean(letter[0].text))
        known = letters.get(match.group(1).upper()) if match else None
        if known is not None and specs[0].first + known - 1 <= specs[0].last:
            index = specs[0].first + known - 1
            specs = [IndexSpec(index, index, specs[0].sub)]
    return specs
