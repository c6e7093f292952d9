"""Object-level comparison: objects and sub-objects added, removed, and each field that changed."""

from __future__ import annotations

import math
from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass
from operator import attrgetter

from ..canopennode.info import DISABLED_PROPERTY
from ..canopennode.info import STORAGE_LOCATION_PREFIX as STORAGE_PREFIX
from ..identifiers import Identifiers
from ..model import (
    CanopenNodeInfo,
    DataType,
    Device,
    NodeIdExpr,
    Object,
    ObjectKind,
    Section,
    SubObject,
    Value,
    Variable,
)
from . import describe, moves, written
from .impact import (
    access_impact,
    canopennode_impact,
    data_type_impact,
    flag_impact,
    limit_impact,
    pdo_direction_impact,
    value_impact,
)
from .records import Change, Impact, Kind, ObjectDiff, new_change, replaced


@dataclass(frozen=True)
class Sides:
    """Both devices with their identifiers, and the node-ID `$NODEID` stands for on each side (None: unknown)."""

    old: Device
    new: Device
    old_ids: Identifiers
    new_ids: Identifiers
    old_node: int | None
    new_node: int | None


def same_value(old: Value | None, new: Value | None) -> bool:
    """Equal typed values; NaN equals NaN, and text equals no bytes (a str is never bytes)."""
    if isinstance(old, float) and isinstance(new, float) and math.isnan(old) and math.isnan(new):
        return True
    if isinstance(old, (str, bytes)) or isinstance(new, (str, bytes)):
        return type(old) is type(new) and old == new
    return old == new


def object_diffs(sides: Sides) -> list[ObjectDiff]:
    """One record per object that changed, in index order."""
    diffs = []
    moved = _moves(sides)
    moved_away = set(moved.values())  # reported at the index each moved to
    for index in sorted(set(sides.old.objects) | set(sides.new.objects)):
        new = sides.new.objects.get(index)
        old = sides.old.objects.get(index) if index not in moved_away else None
        changes = [_moved(sides, moved[index], index, moved)] if index in moved else []
        new_here = None if index in moved else new  # a moved object is told by its move alone
        if old is None and new_here is not None:
            changes.append(_added(sides.new, new_here, None, Kind.OBJECT_ADDED))
        elif new_here is None and old is not None:
            changes.append(_removed(sides.old, old, None, Kind.OBJECT_REMOVED))
        elif old is not None and new_here is not None:
            changes += _outside(old, new_here, _object_changes(sides, old, new_here))
        if changes:
            named = [_named(change, old, new) for change in changes]
            diffs.append(ObjectDiff.model_construct(index=index, name=_entry_name(old, new, None), changes=named))
    return diffs


def _outside(old: Object, new: Object, changes: Iterable[Change]) -> list[Change]:
    """The changes of an object disabled on both sides, which the device has on neither: cosmetic."""
    if not (_disabled(old) and _disabled(new)):
        return list(changes)
    return [
        replaced(change, impact=Impact.COSMETIC, note=f"{_OUTSIDE}; {change.note}".rstrip("; ")) for change in changes
    ]


def _moves(sides: Sides) -> dict[int, int]:
    """Objects found at another index with the same name (unique on both sides), kind and content: new index →
    old index."""
    found = {}
    for index, before in moves.by_name(sides.old.objects, sides.new.objects).items():
        old, new = sides.old.objects[before], sides.new.objects[index]
        if old.kind == new.kind and not any(_shown(c) for c in _object_changes(sides, old, new)):
            found[index] = before
    return found


def _shown(change: Change) -> bool:
    """A change with something to show: its old and new text differ (identifiers follow the index when pinned)."""
    return change.old_text != change.new_text and change.kind is not Kind.IDENTIFIER


def _moved(sides: Sides, before: int, index: int, moved: dict[int, int]) -> Change:
    if moves.closed(moved):  # the same objects, each at an index another had
        where = f"{sides.new_ids.object(index)} now at 0x{index:04X}, was 0x{before:04X}"
        note = f"meaning swapped: {where}; code and masters built for the old file address another object there"
    elif (step := moves.step(moved)) is not None:
        note = f"one of {len(moved)} objects shifted by {step:+d}, same name and content; a master addresses it here"
    else:
        note = "same name and content; a master addresses it at the new index"
    return _move(Kind.OBJECT_MOVED, "index", (before, None), (index, None), note)


def _move(kind: Kind, field: str, was: tuple[int, int | None], now: tuple[int, int | None], note: str) -> Change:
    """A move between two addresses (index, sub-index); `old`/`new` hold the index of an object, the
    sub-index of a sub-object."""
    position = 0 if now[1] is None else 1
    return new_change(
        kind=kind,
        impact=Impact.BREAKING,
        index=now[0],
        subindex=now[1],
        field=field,
        old=was[position],
        new=now[position],
        old_text=describe.address(*was),
        new_text=describe.address(*now),
        note=note,
    )


def _entry_name(old: Object | None, new: Object | None, subindex: int | None) -> str:
    for obj in (new, old):
        var = obj if obj is None or subindex is None else obj.subs.get(subindex)
        if var is not None:
            return var.name
    return ""


def _named(change: Change, old: Object | None, new: Object | None) -> Change:
    if change.kind is Kind.SUB_REMOVED:  # what was there: another entry may stand at its sub-index now
        return replaced(change, name=_entry_name(None, old, change.subindex))
    return replaced(change, name=_entry_name(old, new, change.subindex))


def _summary(device: Device, var: Variable, owner: Object) -> str:
    disabled = (
        f", disabled ({DISABLED_PROPERTY}: not in the generated OD)"
        if var.canopennode and var.canopennode.disabled
        else ""
    )
    if var is owner and owner.has_subs:
        count = len(owner.subs)
        return f"{owner.kind.name}, {count} sub-object{'s' if count != 1 else ''}{disabled}"
    return _var_summary(device, var, owner) + disabled


def _var_summary(device: Device, var: Variable, owner: Object) -> str:
    dtype = device.entry_type(var, owner)
    parts = [dtype.name if dtype is not None else _type_index(var.data_type)]
    if var.access is not None:
        parts.append(var.access.value)
    if var.pdo_mapping:
        parts.append("PDO-mappable")
    if var.value() is not None:
        parts.append(f"default {describe.value_text(var.value(), dtype)}")
    return ", ".join(parts)


_OUTSIDE = "disabled: outside the device on both sides, the OD neither gains nor loses it"


def _disabled(obj: Object) -> bool:
    """CO_disabled: left out of the OD CANopenNode generates, so not in the device."""
    return bool(obj.canopennode and obj.canopennode.disabled)


def _added(device: Device, obj: Object, subindex: int | None, kind: Kind) -> Change:
    var = obj if subindex is None else obj.subs[subindex]
    shown = _summary(device, var, obj)
    impact, note = (Impact.COSMETIC, _OUTSIDE) if _disabled(obj) else (Impact.COMPATIBLE, "")
    return new_change(
        kind=kind, impact=impact, index=obj.index, subindex=subindex, new=var.name, new_text=shown, note=note
    )


def _removed(device: Device, obj: Object, subindex: int | None, kind: Kind) -> Change:
    """The other side of `_added`: what was there, now gone (breaking, unless it was never in the device)."""
    added = _added(device, obj, subindex, kind)
    impact = Impact.COSMETIC if _disabled(obj) else Impact.BREAKING
    return replaced(added, impact=impact, old=added.new, old_text=added.new_text, new=None, new_text="")


def _object_changes(sides: Sides, old: Object, new: Object) -> Iterator[Change]:
    index = old.index
    unread_type = "objecttype" in written.unread(old, new)  # then told by `_entry_changes`, as written
    if old.kind != new.kind and not unread_type:
        yield new_change(
            kind=Kind.OBJECT_TYPE,
            impact=Impact.BREAKING,
            index=index,
            field="object_type",
            old=int(old.kind),
            new=int(new.kind),
            old_text=describe.object_type_text(old.kind),
            new_text=describe.object_type_text(new.kind),
            note="the generated structure changes",
        )
    yield from _entry_changes(sides, Entry(old, old, None), Entry(new, new, None))
    if old.links != new.links:
        yield _as_text(Kind.OBJECT_LINKS, Impact.COSMETIC, index, None, "links", _links(old.links), _links(new.links))
    # Sub-objects count only under an object type that has them (a VAR with [xxxxsubN] sections has none), or
    # whose type could not be read: they are compared as written.
    old_subs, new_subs = (obj.subs if obj.has_subs or unread_type else {} for obj in (old, new))
    pairs = moves.by_name(old_subs, new_subs)
    moved_away = set(pairs.values())
    for sub in sorted(set(old_subs) | set(new_subs)):
        if sub in pairs:
            yield from _sub_moved(sides, old, new, pairs, sub)
        was = sub in old_subs and sub not in moved_away
        if was and sub in new_subs and sub not in pairs:
            yield from _sub_changes(sides, Entry(old.subs[sub], old, sub), Entry(new.subs[sub], new, sub))
        elif was:
            yield _removed(sides.old, old, sub, Kind.SUB_REMOVED)
        elif sub in new_subs and sub not in pairs:
            yield _added(sides.new, new, sub, Kind.SUB_ADDED)


def _sub_moved(sides: Sides, old: Object, new: Object, pairs: dict[int, int], sub: int) -> Iterator[Change]:
    """A sub-object found at another sub-index: the move, then what else changed in it (its name has not)."""
    before = pairs[sub]
    symbol = _known(sides.new_ids.member, new.index, sub)
    where = f"{symbol} now at sub-index {sub}, was {before}"
    if moves.closed(pairs):  # the same symbols, each addressing another entry
        note = f"meaning swapped: {where}; code built for the old file reads another quantity there"
    else:
        note = f"{where}; code and masters built for the old file address another entry"
    yield _move(Kind.SUB_MOVED, "subindex", (old.index, before), (new.index, sub), note)
    compared = _sub_changes(sides, Entry(old.subs[before], old, sub), Entry(new.subs[sub], new, sub))
    yield from (change for change in compared if change.kind not in (Kind.NAME, Kind.IDENTIFIER))


def _links(links: list[int] | None) -> str:
    return "-" if links is None else " ".join(f"0x{index:04X}" for index in links)


@dataclass(frozen=True)
class Entry:
    """An object (subindex None) or one of its sub-objects, with the object it belongs to."""

    var: Variable
    owner: Object
    subindex: int | None


def _sub_changes(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    assert isinstance(old.var, SubObject) and isinstance(new.var, SubObject)
    before, after = old.var.object_type or ObjectKind.VAR, new.var.object_type or ObjectKind.VAR
    if before != after and "objecttype" not in written.unread(old.var, new.var):
        yield new_change(
            kind=Kind.OBJECT_TYPE,
            impact=Impact.BREAKING,
            index=old.owner.index,
            subindex=old.subindex,
            field="object_type",
            old=int(before),
            new=int(after),
            old_text=describe.object_type_text(before),
            new_text=describe.object_type_text(after),
        )
    yield from _entry_changes(sides, old, new)


def _entry_changes(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    if _compared(old.var) == _compared(new.var) and old.var.stated_pdo_mapping == new.var.stated_pdo_mapping:
        # Most entries of two revisions are alike; only the identifier, which other entries decide, can differ.
        yield from _name(sides, old, new)
        return
    unread = written.unread(old.var, new.var)
    if not unread:
        for compare in _FIELD_COMPARISONS:
            yield from compare(sides, old, new)
        return
    # Keys one side wrote unreadably: compared as written, in place of their fields and `extra` keys.
    yield from written.changes(old.var, new.var, unread, old.owner.index, old.subindex)
    told = written.fields(unread) | {
        f"extra.{key}" for key in (*old.var.extra, *new.var.extra) if key.lower() in unread
    }
    for compare in _FIELD_COMPARISONS:
        yield from (change for change in compare(sides, old, new) if change.field not in told)


def _plain(
    kind: Kind,
    impact: Impact,
    index: int | None,
    subindex: int | None,
    field: str,
    old: object,
    new: object,
    note: str = "",
) -> Change:
    return new_change(
        kind=kind,
        impact=impact,
        index=index,
        subindex=subindex,
        field=field,
        old=_storable(old),
        new=_storable(new),
        old_text=describe.text(old),
        new_text=describe.text(new),
        note=note,
    )


def _storable(value: object) -> Value | None:
    if value is None or isinstance(value, (bool, int, float, str, bytes)):
        return value
    return str(value)


def _identifier(ids: Identifiers, entry: Entry) -> str:
    if entry.subindex is None:
        return ids.object(entry.owner.index)
    return _known(ids.member, entry.owner.index, entry.subindex)


def _known(lookup: Callable[[int, int], str], index: int, subindex: int) -> str:
    """An identifier, or `(none)` when the entry has none: sub-objects of an object whose type could not be
    read (a VAR to code generators) have none."""
    try:
        return lookup(index, subindex)
    except KeyError:
        return "(none)"


def _name(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    index, sub = old.owner.index, old.subindex
    before, after = _identifier(sides.old_ids, old), _identifier(sides.new_ids, new)
    moved = before != after
    note = f"identifier {before} → {after}" if moved else f"identifier {after} stays"
    if old.var.name != new.var.name:
        impact = Impact.BREAKING if moved else Impact.COSMETIC
        yield _plain(Kind.NAME, impact, index, sub, "name", old.var.name, new.var.name, note)
    elif moved:
        note = "the name stays, but the generated identifier changes (a pin, or another entry took it)"
        yield _as_text(Kind.IDENTIFIER, Impact.BREAKING, index, sub, "identifier", before, after, note)
    new_index = new.owner.index  # another index when the object moved
    if sub is not None and not moved and sides.old_ids.object(index) == sides.new_ids.object(new_index):
        flat_before, flat_after = _known(sides.old_ids.flat, index, sub), _known(sides.new_ids.flat, new_index, sub)
        if flat_before != flat_after:
            note = "the flat identifier (PDO fields, Python) changes"
            yield _as_text(
                Kind.IDENTIFIER, Impact.BREAKING, index, sub, "flat_identifier", flat_before, flat_after, note
            )


def _as_text(
    kind: Kind, impact: Impact, index: int, subindex: int | None, field: str, old: str, new: str, note: str = ""
) -> Change:
    """A change of a field whose values are shown as they are (identifiers, access types, link lists)."""
    return new_change(
        kind=kind,
        impact=impact,
        index=index,
        subindex=subindex,
        field=field,
        old=old,
        new=new,
        old_text=old,
        new_text=new,
        note=note,
    )


def _type_index(index: int | None) -> str:
    return "-" if index is None else f"0x{index:04X}"


def _type_text(dtype: DataType | None, index: int | None) -> str:
    if dtype is None:
        return _type_index(index)
    return dtype.name if dtype.index == index else f"{_type_index(index)} ({dtype.name})"


def _data_type(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    if old.var.data_type == new.var.data_type:
        return
    before = sides.old.entry_type(old.var, old.owner)
    after = sides.new.entry_type(new.var, new.owner)
    impact, note = data_type_impact(before, after)
    yield new_change(
        kind=Kind.DATA_TYPE,
        impact=impact,
        index=old.owner.index,
        subindex=old.subindex,
        field="data_type",
        old=old.var.data_type,
        new=new.var.data_type,
        old_text=_type_text(before, old.var.data_type),
        new_text=_type_text(after, new.var.data_type),
        note=note,
    )


_NO_ACCESS = "noAccess"  # an XDD's access of an entry no SDO reaches; the model keeps it as the key `access`


def _access_text(var: Variable) -> str:
    if var.access is not None:
        return var.access.value
    return _NO_ACCESS if _no_access(var) else "-"


def _no_access(var: Variable) -> bool:
    return var.access is None and var.extra.get("access") == _NO_ACCESS


def _access(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    before, after = _access_text(old.var), _access_text(new.var)
    if before == after:
        return
    impact, note = access_impact(old.var.access, new.var.access, _no_access(old.var), _no_access(new.var))
    yield _as_text(Kind.ACCESS, impact, old.owner.index, old.subindex, "access", before, after, note)


def _pdo_mapping(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    if bool(old.var.pdo_mapping) == bool(new.var.pdo_mapping):
        yield from _pdo_direction(old, new)
        return  # an absent PDOMapping key reads as 0
    impact, note = flag_impact(old.var.pdo_mapping, new.var.pdo_mapping, "PDO-mappable")
    index, sub = old.owner.index, old.subindex
    yield _plain(
        Kind.PDO_MAPPING, impact, index, sub, "pdo_mapping", bool(old.var.pdo_mapping), bool(new.var.pdo_mapping), note
    )


def _pdo_direction(old: Entry, new: Entry) -> Iterator[Change]:
    """An XDD's PDOmapping word on both sides (TPDO, RPDO, optional, default): the PDOs it may be mapped into."""
    before, after = old.var.stated_pdo_mapping, new.var.stated_pdo_mapping
    if before is None or after is None or before == after or not old.var.pdo_mapping:
        return
    impact, note = pdo_direction_impact(before, after, old.var.access, new.var.access)
    index, sub = old.owner.index, old.subindex
    yield _as_text(Kind.PDO_MAPPING, impact, index, sub, "pdo_mapping", before, after, note)


def _limits(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    for low, field, kind in ((True, "low_limit", Kind.LOW_LIMIT), (False, "high_limit", Kind.HIGH_LIMIT)):
        before, after = getattr(old.var, field), getattr(new.var, field)
        if same_value(before, after) or written.same_as_written(before, after):
            continue
        dtype = sides.new.entry_type(new.var, new.owner)
        impact, note = limit_impact(before, after, low, dtype, sides.new_node, new.var.access or old.var.access)
        yield _value_change(kind, impact, old, field, before, after, dtype, note)


def _value_change(
    kind: Kind,
    impact: Impact,
    old: Entry,
    field: str,
    before: Value | None,
    after: Value | None,
    dtype: DataType | None,
    note: str = "",
) -> Change:
    return new_change(
        kind=kind,
        impact=impact,
        index=old.owner.index,
        subindex=old.subindex,
        field=field,
        old=before,
        new=after,
        old_text=describe.entry_value_text(old.owner.index, old.subindex, before, dtype),
        new_text=describe.entry_value_text(old.owner.index, old.subindex, after, dtype),
        note=note,
    )


def _values(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    for field, kind in (("default", Kind.DEFAULT), ("parameter_value", Kind.PARAMETER_VALUE)):
        before, after = getattr(old.var, field), getattr(new.var, field)
        if (
            same_value(before, after)
            or written.same_as_written(before, after)
            or (field == "parameter_value" and _same_configured(old.var, new.var, sides))
        ):
            continue
        dtype = sides.new.entry_type(new.var, new.owner) or sides.old.entry_type(old.var, old.owner)
        if _same_when_resolved(before, after, sides):
            yield _value_change(
                Kind.NODEID_FORM,
                Impact.VALUE,
                old,
                field,
                before,
                after,
                dtype,
                f"the same for node-ID {sides.new_node}, but no longer follows the node-ID"
                if isinstance(before, NodeIdExpr)
                else f"the same for node-ID {sides.new_node}, now follows the node-ID",
            )
        else:
            impact, note = value_impact(old.owner.index, old.subindex, before, after)
            yield _value_change(kind, impact, old, field, before, after, dtype, note)


def _same_configured(old: Variable, new: Variable, sides: Sides) -> bool:
    """A ParameterValue on one side only that states the default (as a DCF made from an EDS does)."""
    if (old.parameter_value is None) == (new.parameter_value is None):
        return False
    return same_value(old.value(sides.old_node), new.value(sides.new_node))


def _same_when_resolved(old: Value | None, new: Value | None, sides: Sides) -> bool:
    """A formula on one side and a number on the other that mean the same for the node-IDs known."""
    if isinstance(old, NodeIdExpr) == isinstance(new, NodeIdExpr):
        return False
    if isinstance(old, NodeIdExpr):
        return sides.old_node is not None and old.resolve(sides.old_node) == new
    assert isinstance(new, NodeIdExpr)
    return sides.new_node is not None and new.resolve(sides.new_node) == old


# Entry keys compared as plain fields: (attribute, kind, impact).
_PLAIN_FIELDS = (
    ("obj_flags", Kind.OBJ_FLAGS, Impact.VALUE),
    ("denotation", Kind.DENOTATION, Impact.COSMETIC),
    ("param_refd", Kind.DCF_ENTRY, Impact.VALUE),
    ("upload_file", Kind.DCF_ENTRY, Impact.VALUE),
    ("download_file", Kind.DCF_ENTRY, Impact.VALUE),
)


def _plain_fields(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    for field, kind, impact in _PLAIN_FIELDS:
        before, after = getattr(old.var, field), getattr(new.var, field)
        if before != after:
            yield _plain(kind, impact, old.owner.index, old.subindex, field, before, after)


def _canopennode(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    if old.var.canopennode is None and new.var.canopennode is None:
        return  # most entries of most files: nothing to compare
    empty = CanopenNodeInfo.model_construct()  # all None; no schema built at validation
    before = old.var.canopennode or empty
    after = new.var.canopennode or empty
    for field in CanopenNodeInfo.model_fields:
        was, now = getattr(before, field), getattr(after, field)
        if was == now:
            continue
        impact, note = canopennode_impact(field, was, now)
        yield _plain(
            Kind.CANOPENNODE,
            impact,
            old.owner.index,
            old.subindex,
            f"canopennode.{field}",
            _storable(was),
            _storable(now),
            note,
        )


def _section_extras(sides: Sides, old: Entry, new: Entry) -> Iterator[Change]:
    for change in section_changes(old.var, new.var, old.owner.index, old.subindex):
        if change.field != "extra.access":  # noAccess: told as the access change
            yield change


# Keys that are fields of the model when readable: kept in `extra` only when their value could not be read.
_VALUE_KEYS = {
    "defaultvalue",
    "parametervalue",
    "lowlimit",
    "highlimit",
    "datatype",
    "accesstype",
    "pdomapping",
    "objecttype",
    "objflags",
    "subnumber",
    "compactsubobj",
}


def section_changes(
    old: Section, new: Section, index: int | None, subindex: int | None, where: str = ""
) -> Iterator[Change]:
    """Keys of no known meaning (`extra`) and comment lines that changed in one section.

    `where` prefixes the field for device-level sections (`device_info.`).
    """
    for key in sorted(set(old.extra) | set(new.extra), key=str.lower):
        before, after = old.extra.get(key), new.extra.get(key)
        if before != after:
            impact = Impact.VALUE if key.lower() in _VALUE_KEYS else Impact.COSMETIC
            yield _plain(Kind.EXTRA_KEY, impact, index, subindex, f"{where}extra.{key}", before, after)
    before_text, after_text = _comment_text(old.comments), _comment_text(new.comments)
    if before_text != after_text:
        yield _plain(Kind.COMMENT, Impact.COSMETIC, index, subindex, f"{where}comments", before_text, after_text)


def _comment_text(comments: dict[str, list[str]]) -> str:
    """The comment lines on one line, without those that state a property compared on its own (the storage
    group of `;StorageLocation=`): one fact, one change."""
    return " / ".join(
        line.strip() for lines in comments.values() for line in lines if not line.startswith(STORAGE_PREFIX)
    )


# An entry's fields but its name (`_name`'s, with the identifiers) and origin (where it is written, never a
# change): equal in all, no comparison after `_name` reports one. A field added to Variable is in it unless named
# here, so that a comparison of it is never skipped.
_compared = attrgetter(*(field for field in Variable.model_fields if field not in ("name", "origin")))

_FIELD_COMPARISONS: tuple[Callable[[Sides, Entry, Entry], Iterator[Change]], ...] = (
    _name,
    _data_type,
    _access,
    _pdo_mapping,
    _limits,
    _values,
    _plain_fields,
    _canopennode,
    _section_extras,
)
