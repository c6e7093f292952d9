"""All descriptions of one object merged; every disagreement a conflict with both sources.

A conflict is resolved by the overrides file, else by the policy (see docs/import-table.md):

* `detail` (default): the value from the kind of description that is most specific wins —
  per-object detail block > per-object table (default values, sub-tables) > record
  definition > block heading > summary table > value derived from another field;
* `summary`: a summary or list table wins over the detail blocks;
* `first` / `last`: the source that comes first / last (files in command-line order, then lines).

Ties go to the source that comes first. Values filled in from CiA 301 (`inferred`) never
conflict: they are used only where no source says anything.
"""

from __future__ import annotations

import dataclasses
import functools
import re
from collections import defaultdict
from dataclasses import dataclass
from typing import Literal

from ..model import AccessType, NodeIdExpr, ObjectKind, standard_type
from ..model.cia301.objects import DATA_TYPE_AREA
from ..model.cia301.pdo import COMM_BASE, MAP_BASE, PDO_SPAN
from ..model.datatypes import UNSIGNED8
from .cia import STANDARD_OBJECTS, StdEntry, record_layout
from .entries import Kind
from .facts import LATE_FIELDS, Fact, Norm, Source
from .notation import norm_name, parse_number, parse_value, type_name

Policy = Literal["detail", "summary", "first", "last"]
POLICIES: tuple[Policy, ...] = ("detail", "summary", "first", "last")
CONFLICT_FIELDS = ("object_code", "data_type", "access", "pdo_mapping", "default", "low", "high", "name")
RECORD_TYPES = range(0x20, 0x260)


@dataclass
class Candidate:
    value: Norm
    facts: list[Fact]

    @property
    def sources(self) -> list[Source]:
        seen: dict[tuple[str, int], Source] = {}
        for fact in self.facts:
            seen.setdefault((fact.source.file, fact.source.line), fact.source)
        return list(seen.values())

    @property
    def weight(self) -> int:
        return max(int(f.source.kind) for f in self.facts)


@dataclass
class Conflict:
    index: int
    sub: int | None
    field: str
    candidates: list[Candidate]
    chosen: int  # position in candidates
    resolution: str  # "override", "policy:detail", ...
    reason: str = ""
    also: list[tuple[int, int | None]] = dataclasses.field(default_factory=list)  # entries the same rows disagree on

    @property
    def rows(self) -> frozenset[tuple[str, int]]:
        return frozenset(f.row for c in self.candidates for f in c.facts)


@dataclass
class Resolved:
    value: Norm
    facts: list[Fact]
    inferred: bool = False
    conflict: Conflict | None = None
    note: str = ""

    @property
    def source(self) -> Source | None:
        real = [f.source for f in self.facts]
        return min(real, key=lambda s: (int(s.kind) * -1, s.line)) if real else None


@dataclass
class MergedEntry:
    sub: int
    fields: dict[str, Resolved] = dataclasses.field(default_factory=dict)
    notes: dict[str, str] = dataclasses.field(default_factory=dict)
    aliases: list[tuple[str, Source]] = dataclasses.field(default_factory=list)
    direction: str | None = None


@dataclass
class MergedObject:
    index: int
    kind: ObjectKind
    fields: dict[str, Resolved] = dataclasses.field(default_factory=dict)
    entries: dict[int, MergedEntry] = dataclasses.field(default_factory=dict)
    notes: dict[str, str] = dataclasses.field(default_factory=dict)
    aliases: list[tuple[str, Source]] = dataclasses.field(default_factory=list)
    sources: list[Source] = dataclasses.field(default_factory=list)


@dataclass
class Override:
    index: int
    sub: int | None
    field: str
    raw: str
    value: Norm | None
    reason: str
    source: Source


@dataclass
class MergeOptions:
    policy: Policy = "detail"
    object_policy: dict[int, Policy] = dataclasses.field(default_factory=dict)
    overrides: list[Override] = dataclasses.field(default_factory=list)
    exclude: dict[int, str] = dataclasses.field(default_factory=dict)
    exclude_entries: dict[tuple[int, int], str] = dataclasses.field(default_factory=dict)
    file_order: dict[str, int] = dataclasses.field(default_factory=dict)  # sources in the order given


@dataclass
class MergeResult:
    objects: dict[int, MergedObject]
    conflicts: list[Conflict]
    inferred: list[tuple[int, int | None, str, str]]  # index, sub, field, what
    excluded: dict[int, str]
    excluded_entries: list[tuple[int, int, str]]
    unused_overrides: list[Override]


def _key(value: Norm, field: str) -> object:
    """What makes two values the same: names compare folded, numbers by value."""
    if field == "name" and isinstance(value, str):
        return norm_name(value)
    if isinstance(value, bool):
        return ("bool", value)
    if isinstance(value, float) and value.is_integer():
        return int(value)
    return value


def _choose(candidates: list[Candidate], policy: Policy, order_of: dict[str, int]) -> int:
    def _position(candidate: Candidate) -> int:
        return min(order_of.get(f.source.file, 0) * 1_000_000 + f.source.line for f in candidate.facts)

    order = list(range(len(candidates)))
    if policy == "detail":
        return max(order, key=lambda i: (candidates[i].weight, -_position(candidates[i])))
    if policy == "summary":

        def summary_weight(c: Candidate) -> int:
            kinds = {int(f.source.kind) for f in c.facts}
            best = 0
            for rank, kind in enumerate((Kind.DETAIL, Kind.TABLE, Kind.SUMMARY), start=1):
                if int(kind) in kinds:
                    best = max(best, rank)
            return best

        return max(order, key=lambda i: (summary_weight(candidates[i]), -_position(candidates[i])))
    if policy == "first":
        return min(order, key=lambda i: _position(candidates[i]))
    return max(order, key=lambda i: _position(candidates[i]))


def resolve(
    facts: list[Fact],
    field_name: str,
    index: int,
    sub: int | None,
    options: MergeOptions,
    conflicts: list[Conflict],
    type_index: int | None = None,
) -> Resolved | None:
    """One field's value from its facts, the override, and the policy."""
    override = next((o for o in options.overrides if o.index == index and o.sub == sub and o.field == field_name), None)
    if override is not None and field_name in LATE_FIELDS and isinstance(override.value, str):
        read = parse_default if field_name == "default" else _limit
        parsed = read(override.value, type_index)
        override.value = parsed[0] if parsed is not None else None
    real = [f for f in facts if f.value is not None and f.source.kind is not Kind.INFERRED]
    inferred = [f for f in facts if f.value is not None and f.source.kind is Kind.INFERRED]
    if override is not None and override.value is not None:
        fact = Fact(index, sub, field_name, override.raw, override.value, override.source, ("", 0), override.reason)
        candidates = _candidates(real, field_name)
        if len(candidates) > 1 or (
            candidates and _key(candidates[0].value, field_name) != _key(override.value, field_name)
        ):
            candidates.append(Candidate(override.value, [fact]))
            made = Conflict(index, sub, field_name, candidates, len(candidates) - 1, "override", override.reason)
            conflicts.append(made)
            options.overrides.remove(override)
            return Resolved(override.value, [fact], note=override.reason, conflict=made)
        options.overrides.remove(override)
        return Resolved(override.value, [fact], note=override.reason)
    if not real:
        if inferred:
            return Resolved(inferred[0].value if inferred[0].value is not None else "", inferred, inferred=True)
        return None
    candidates = _candidates(real, field_name)
    if len(candidates) == 1:
        return Resolved(candidates[0].value, candidates[0].facts)
    policy = options.object_policy.get(index, options.policy)
    chosen = _choose(candidates, policy, options.file_order)
    conflict = Conflict(index, sub, field_name, candidates, chosen, f"policy:{policy}")
    conflicts.append(conflict)
    return Resolved(candidates[chosen].value, candidates[chosen].facts, conflict=conflict)


def _candidates(facts: list[Fact], field_name: str) -> list[Candidate]:
    groups: dict[object, Candidate] = {}
    for fact in facts:
        assert fact.value is not None
        key = _key(fact.value, field_name)
        if key in groups:
            groups[key].facts.append(fact)
        else:
            groups[key] = Candidate(fact.value, [fact])
    return list(groups.values())


def merge(facts: list[Fact], options: MergeOptions, files: list[str]) -> MergeResult:
    """Objects from facts: kinds, names, types, access, mapping, defaults and limits."""
    options.file_order = {name: i for i, name in enumerate(files)}
    by_key: dict[tuple[int, int | None, str], list[Fact]] = defaultdict(list)
    indices: set[int] = set()
    for fact in facts:
        by_key[(fact.index, fact.sub, fact.field)].append(fact)
        indices.add(fact.index)
    records = _record_definitions(by_key)
    conflicts: list[Conflict] = []
    inferred: list[tuple[int, int | None, str, str]] = []
    objects: dict[int, MergedObject] = {}
    excluded: dict[int, str] = {}
    excluded_entries: list[tuple[int, int, str]] = []
    for index in sorted(indices):
        if index < DATA_TYPE_AREA.stop:
            continue  # data-type definitions, used through `records`
        if index in options.exclude:
            excluded[index] = options.exclude[index]
            continue
        obj = _merge_object(index, by_key, records, options, conflicts, inferred, excluded_entries)
        if obj is None:
            continue
        if obj.kind in (ObjectKind.ARRAY, ObjectKind.RECORD) and not obj.entries:
            excluded[index] = "no sub-index of this container is documented (not invented)"
            continue
        objects[index] = obj
    _from_siblings(objects, inferred)
    unused = list(options.overrides)
    return MergeResult(objects, _group(conflicts), inferred, excluded, excluded_entries, unused)


def _record_definitions(by_key: dict[tuple[int, int | None, str], list[Fact]]) -> dict[int, dict[int, Fact]]:
    """Record types the manual defines (0020h, 0021h, 0080h ...): sub-index → its data-type fact."""
    out: dict[int, dict[int, Fact]] = defaultdict(dict)
    for (index, sub, field_name), found in by_key.items():
        if index in RECORD_TYPES and sub is not None and field_name == "data_type":
            out[index][sub] = found[0]
    return out


def _subs_of(index: int, by_key: dict[tuple[int, int | None, str], list[Fact]]) -> set[int]:
    return {sub for (i, sub, _field) in by_key if i == index and sub is not None}


def _merge_object(
    index: int,
    by_key: dict[tuple[int, int | None, str], list[Fact]],
    records: dict[int, dict[int, Fact]],
    options: MergeOptions,
    conflicts: list[Conflict],
    inferred: list[tuple[int, int | None, str, str]],
    excluded_entries: list[tuple[int, int, str]],
) -> MergedObject | None:
    def facts(sub: int | None, field_name: str) -> list[Fact]:
        return list(by_key.get((index, sub, field_name), []))

    subs = _subs_of(index, by_key)
    obj_sources = sorted(
        {f.source for (i, _s, _f), fs in by_key.items() if i == index for f in fs}, key=lambda s: (s.file, s.line)
    )
    standard = STANDARD_OBJECTS.get(index)
    code_facts = facts(None, "object_code")
    if standard is not None:
        code_facts.append(_inferred_fact(index, None, "object_code", standard.kind))
    code = resolve(code_facts, "object_code", index, None, options, conflicts)
    kind = _object_kind(index, code, subs, by_key, conflicts)
    obj = MergedObject(index, kind, sources=obj_sources)
    if code is not None:
        obj.fields["object_code"] = code
    name_facts = facts(None, "name") + (facts(0, "name") if kind not in (ObjectKind.ARRAY, ObjectKind.RECORD) else [])
    name = resolve(name_facts, "name", index, None, options, conflicts)
    if name is None and standard is not None:
        name = Resolved(standard.name, [_inferred_fact(index, None, "name", standard.name)], inferred=True)
        inferred.append((index, None, "name", standard.name))
    if name is not None:
        obj.fields["name"] = name
    for note in ("category", "description", "unit", "note"):
        found = facts(None, note) + (facts(0, note) if kind is ObjectKind.VAR else [])
        if found:
            obj.notes[note] = str(found[0].value)
    # object-level type, access, mapping, default: go to the VAR or to the entries
    obj_type = resolve(facts(None, "data_type"), "data_type", index, None, options, conflicts)
    if obj_type is not None:
        obj.fields["data_type"] = obj_type
    if kind in (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT):
        record = None
        if obj_type is not None and isinstance(obj_type.value, int) and obj_type.value in RECORD_TYPES:
            record = records.get(obj_type.value) or record_layout(obj_type.value)
        for sub in _entry_subs(index, subs, options, inferred, excluded_entries):
            entry = _merge_entry(index, sub, kind, obj_type, record, by_key, options, conflicts, inferred)
            if entry is not None:
                obj.entries[sub] = entry
    else:
        entry = _merge_entry(index, 0, kind, obj_type, None, by_key, options, conflicts, inferred)
        if entry is not None:
            obj.entries[0] = entry
    if kind in (ObjectKind.ARRAY, ObjectKind.RECORD) and 0 in obj.entries:
        _fill_sub0(obj, inferred)
    return obj


def _entry_subs(
    index: int,
    subs: set[int],
    options: MergeOptions,
    inferred: list[tuple[int, int | None, str, str]],
    excluded_entries: list[tuple[int, int, str]],
) -> list[int]:
    """The sub-indices of a container to merge: sub0 added when the manual omits it, exclusions left out."""
    entry_subs = sorted(subs)
    if entry_subs and 0 not in entry_subs:
        entry_subs.insert(0, 0)
        inferred.append((index, 0, "exists", "sub-index 0 (highest sub-index) added: the manual omits it"))
    kept = []
    for sub in entry_subs:
        if (index, sub) in options.exclude_entries:
            excluded_entries.append((index, sub, options.exclude_entries[(index, sub)]))
        else:
            kept.append(sub)
    return kept


def _structural(index: int, raw: str, kind: ObjectKind) -> Fact:
    """The object code the structure of the rows implies, as a derived fact."""
    return Fact(index, None, "object_code", raw, kind, Source("", 0, "structure", Kind.DERIVED), ("", 0))


def _object_kind(
    index: int,
    code: Resolved | None,
    subs: set[int],
    by_key: dict[tuple[int, int | None, str], list[Fact]],
    conflicts: list[Conflict],
) -> ObjectKind:
    """The object code: as stated, else from the rows; corrected where the rows contradict it."""
    has_entries = any(s > 0 for s in subs)
    kind: ObjectKind
    if code is not None and isinstance(code.value, ObjectKind):
        kind = code.value
    else:
        kind = ObjectKind.RECORD if has_entries else ObjectKind.VAR
    if kind in (ObjectKind.ARRAY, ObjectKind.RECORD) and not has_entries and code is not None:
        sub0 = [f for (i, s, _f), fs in by_key.items() if i == index and s == 0 for f in fs]
        if sub0 and (all(f.implicit_sub for f in sub0) or _one_value(sub0)):
            # A block stating RECORD but describing one value without sub-indices: a VAR in fact.
            structural = _structural(index, "one entry, no sub-index", ObjectKind.VAR)
            candidates = [Candidate(kind, code.facts), Candidate(ObjectKind.VAR, [structural])]
            reason = "stated as a container, but described as one value without sub-indices"
            conflicts.append(Conflict(index, None, "object_code", candidates, 1, "structure", reason))
            kind = ObjectKind.VAR
    if kind in (ObjectKind.VAR, ObjectKind.DOMAIN, ObjectKind.DEFTYPE) and has_entries:
        _var_with_entries(index, kind, code, by_key, conflicts)
        kind = ObjectKind.RECORD
    return kind


def _var_with_entries(
    index: int,
    kind: ObjectKind,
    code: Resolved | None,
    by_key: dict[tuple[int, int | None, str], list[Fact]],
    conflicts: list[Conflict],
) -> None:
    """A VAR with sub-indices above 0 documented is a RECORD: say so, and move its own row to the object."""
    stated = code.facts if code is not None else []
    if stated:
        structural = _structural(index, "sub-indices > 0 documented", ObjectKind.RECORD)
        conflicts.append(
            Conflict(
                index,
                None,
                "object_code",
                [Candidate(kind, stated), Candidate(ObjectKind.RECORD, [structural])],
                1,
                "structure",
                "the object is stated to be a VAR but sub-indices above 0 are documented",
            )
        )
    # what the VAR's own row said (type, access) speaks for the elements, not for sub-index 0
    for key in [k for k in by_key if k[0] == index and k[1] == 0]:
        moved = [f for f in by_key[key] if f.implicit_sub and f.field in ("data_type", "access", "pdo_mapping")]
        if moved:
            by_key[key] = [f for f in by_key[key] if f not in moved]
            by_key[(index, None, key[2])] = by_key.get((index, None, key[2]), []) + moved


_COUNT_NAME = re.compile(r"number|largest|highest|max(?:imum)?\s*sub|entries|sub-?index", re.IGNORECASE)


def _one_value(sub0: list[Fact]) -> bool:
    """Sub-index 0 alone, named like a value (`Password`) rather than a count, and not UNSIGNED8."""
    names = [str(f.value) for f in sub0 if f.field == "name"]
    types = {f.value for f in sub0 if f.field == "data_type"}
    return bool(names) and not any(_COUNT_NAME.search(n) for n in names) and types != {UNSIGNED8.index}


PDO_FAMILIES = tuple((base, base + PDO_SPAN - 1) for bases in (COMM_BASE, MAP_BASE) for base in bases.values())


def _from_siblings(objects: dict[int, MergedObject], inferred: list[tuple[int, int | None, str, str]]) -> None:
    """PDO parameter objects of one family share their entries' type and access: an entry the
    manual leaves silent takes them from the first sibling that states them (marked inferred)."""
    for low, high in PDO_FAMILIES:
        family = [objects[i] for i in sorted(objects) if low <= i <= high]
        for obj in family:
            for sub, entry in obj.entries.items():
                for field_name in ("data_type", "access"):
                    current = entry.fields.get(field_name)
                    if current is not None and not current.inferred:
                        continue
                    for sibling in family:
                        other = sibling.entries.get(sub)
                        found = other.fields.get(field_name) if other is not None and sibling is not obj else None
                        if found is not None and not found.inferred:
                            fact = Fact(
                                obj.index,
                                sub,
                                field_name,
                                str(found.value),
                                found.value,
                                Source("", 0, f"as {sibling.index:04X}h", Kind.INFERRED),
                                ("", 0),
                            )
                            entry.fields[field_name] = Resolved(found.value, [fact], inferred=True)
                            inferred.append(
                                (
                                    obj.index,
                                    sub,
                                    field_name,
                                    f"{display(found.value, field_name)} (as sibling {sibling.index:04X}h)",
                                )
                            )
                            break


def _inferred_fact(index: int, sub: int | None, field_name: str, value: Norm) -> Fact:
    return Fact(index, sub, field_name, str(value), value, Source("CiA 301", 0, "inferred", Kind.INFERRED), ("", 0))


def _entry_field_facts(
    by_key: dict[tuple[int, int | None, str], list[Fact]], index: int, sub: int, container: bool, field_name: str
) -> list[Fact]:
    """The facts of one field of an entry, with what the object's own row says for it."""
    found = list(by_key.get((index, sub, field_name), []))
    # Object-level values speak for the VAR; for a container, access speaks for every entry
    # and PDO mapping for the elements (sub-index 0 is never mapped).
    speaks = not container or field_name == "access" or (field_name == "pdo_mapping" and sub > 0)
    if speaks and field_name in ("access", "pdo_mapping", "default", "low", "high"):
        found += by_key.get((index, None, field_name), [])
    return found


def _merge_entry(
    index: int,
    sub: int,
    kind: ObjectKind,
    obj_type: Resolved | None,
    record: dict[int, Fact] | None,
    by_key: dict[tuple[int, int | None, str], list[Fact]],
    options: MergeOptions,
    conflicts: list[Conflict],
    inferred: list[tuple[int, int | None, str, str]],
) -> MergedEntry | None:
    container = kind in (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT)
    facts = functools.partial(_entry_field_facts, by_key, index, sub, container)
    entry = MergedEntry(sub)
    standard = STANDARD_OBJECTS.get(index)
    std_entry = standard.entry(sub) if standard is not None else None
    type_facts = _type_facts(index, sub, container, obj_type, record, std_entry, facts("data_type"))
    dtype = resolve(type_facts, "data_type", index, sub, options, conflicts)
    if dtype is not None:
        entry.fields["data_type"] = dtype
        if dtype.inferred:
            inferred.append((index, sub, "data_type", display(dtype.value, "data_type")))
    type_index = int(dtype.value) if dtype is not None and isinstance(dtype.value, int) else None
    name = _entry_name(index, sub, std_entry, facts("name"), options, conflicts, inferred) if container else None
    if name is not None:  # names of entries of containers
        entry.fields["name"] = name
    access_facts = facts("access")
    if std_entry is not None and std_entry.access is not None:
        access_facts.append(_inferred_fact(index, sub, "access", std_entry.access))
    elif container and sub == 0:
        access_facts.append(_inferred_fact(index, sub, "access", AccessType.RO))
    access = resolve(access_facts, "access", index, sub, options, conflicts)
    if access is not None:
        entry.fields["access"] = access
        if access.inferred:
            inferred.append((index, sub, "access", str(access.value)))
    mapping = resolve(facts("pdo_mapping"), "pdo_mapping", index, sub, options, conflicts)
    if mapping is not None:
        entry.fields["pdo_mapping"] = mapping
    directions = {str(f.value) for f in facts("direction")}
    entry.direction = directions.pop() if len(directions) == 1 else None
    for field_name in LATE_FIELDS:  # values, read with the type now known
        parsed = _late_facts(facts(field_name), field_name, type_index)
        resolved = resolve(parsed, field_name, index, sub, options, conflicts, type_index)
        if resolved is not None:
            entry.fields[field_name] = resolved
    for note in ("unit", "category", "description", "note", "scale"):
        found = facts(note)
        if found:
            entry.notes[note] = str(found[0].value)
    entry.aliases = [(str(f.value), f.source) for f in facts("name")]
    present = any(
        by_key.get((index, sub, f))
        for f in ("exists", "name", "access", "data_type", "default", "pdo_mapping", "description")
    )
    return entry if present or sub == 0 else None


def _entry_name(
    index: int,
    sub: int,
    std_entry: StdEntry | None,
    stated: list[Fact],
    options: MergeOptions,
    conflicts: list[Conflict],
    inferred: list[tuple[int, int | None, str, str]],
) -> Resolved | None:
    """The name of a container's entry: stated, else CiA 301's (marked inferred)."""
    name = resolve(stated, "name", index, sub, options, conflicts)
    if name is None:
        fallback = std_entry.name if std_entry is not None else ("Highest sub-index supported" if sub == 0 else "")
        if fallback:
            name = Resolved(fallback, [_inferred_fact(index, sub, "name", fallback)], inferred=True)
            inferred.append((index, sub, "name", fallback))
    return name


def _type_facts(
    index: int,
    sub: int,
    container: bool,
    obj_type: Resolved | None,
    record: dict[int, Fact] | None,
    std_entry: StdEntry | None,
    stated: list[Fact],
) -> list[Fact]:
    """Every fact about an entry's data type: stated, the object's, the record definition's, CiA 301's."""
    type_facts = list(stated)
    element = obj_type is not None and isinstance(obj_type.value, int) and obj_type.value not in RECORD_TYPES
    if obj_type is not None and (not container or (sub > 0 and element)):
        type_facts += obj_type.facts
    if container and record is not None and sub in record:
        ref = record[sub]
        ref_kind = Kind.INFERRED if ref.source.kind is Kind.INFERRED else Kind.RECORD_DEF
        ref_source = Source(ref.source.file, ref.source.line, f"record definition {ref.index:04X}h", ref_kind)
        type_facts.append(Fact(index, sub, "data_type", ref.raw, ref.value, ref_source, ref.row))
    if std_entry is not None and std_entry.data_type is not None:
        type_facts.append(_inferred_fact(index, sub, "data_type", std_entry.data_type))
    elif container and sub == 0:
        type_facts.append(_inferred_fact(index, sub, "data_type", UNSIGNED8.index))
    return type_facts


def _late_facts(facts: list[Fact], field_name: str, type_index: int | None) -> list[Fact]:
    """Default and limit facts with their values read for the entry's data type; unreadable ones dropped."""
    parsed: list[Fact] = []
    for fact in facts:
        spec = parse_default(fact.raw, type_index) if field_name == "default" else _limit(fact.raw, type_index)
        if spec is None:
            continue
        value, note = spec
        joined = "; ".join(n for n in (fact.note, note) if n)
        parsed.append(Fact(fact.index, fact.sub, fact.field, fact.raw, value, fact.source, fact.row, joined))
    return parsed


def _limit(raw: str, type_index: int | None) -> tuple[Norm, str] | None:
    value = parse_number(raw)
    if value is None:
        return None
    dtype = standard_type(type_index)
    if dtype is not None and dtype.is_integer and isinstance(value, float):
        if not value.is_integer():
            return None
        value = int(value)
    return value, ""


def parse_default(raw: str, type_index: int | None) -> tuple[Norm, str] | None:
    spec = parse_value(raw, type_index)
    return None if spec is None else (spec.value, spec.note)


def _fill_sub0(obj: MergedObject, inferred: list[tuple[int, int | None, str, str]]) -> None:
    """Sub-index 0 of an ARRAY/RECORD: its default is the highest sub-index when the manual gives none."""
    entry = obj.entries[0]
    highest = max(obj.entries)
    if "default" not in entry.fields:
        fact = _inferred_fact(obj.index, 0, "default", highest)
        entry.fields["default"] = Resolved(highest, [fact], inferred=True)
        inferred.append((obj.index, 0, "default", str(highest)))


def _group(conflicts: list[Conflict]) -> list[Conflict]:
    """One conflict for the entries one source row speaks for (index or sub-index ranges,
    a summary row applied to every entry): the first stands for the rest, listed in `also`."""
    groups: dict[tuple[object, ...], Conflict] = {}
    out: list[Conflict] = []
    for conflict in conflicts:
        values = tuple(sorted(str(_key(c.value, conflict.field)) for c in conflict.candidates))
        detail_rows = frozenset(f.row for c in conflict.candidates for f in c.facts if f.sub is not None)
        object_rows = frozenset(f.row for c in conflict.candidates for f in c.facts if f.sub is None)
        key = (conflict.field, values, detail_rows or object_rows)
        first = groups.get(key)
        if first is None:
            key2 = (conflict.field, values, conflict.index, object_rows) if object_rows else None
            first = groups.get(key2) if key2 is not None else None
            if key2 is not None and first is None:
                groups[key2] = conflict
        if first is not None:
            first.also.append((conflict.index, conflict.sub))
            continue
        groups[key] = conflict
        out.append(conflict)
    return out


def display(value: Norm | None, field_name: str = "") -> str:
    """A value as the report shows it."""
    if value is None:
        return "—"
    if field_name == "data_type" and isinstance(value, int):
        return type_name(value)
    if isinstance(value, ObjectKind):
        return value.name
    if isinstance(value, AccessType):
        return value.value
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, NodeIdExpr):
        return value.canonical()
    if isinstance(value, int) and field_name in ("default", "low", "high") and value > 9:
        return f"0x{value:X}"
    if isinstance(value, bytes):
        return value.hex().upper()
    return str(value)
