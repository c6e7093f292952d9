"""PDO comparison: each PDO as configured on both sides, compared by COB-ID, transmission type and bit layout."""

from __future__ import annotations

from collections.abc import Iterator

from ..model import Device, NodeIdExpr
from ..model.cia301.pdo import (
    EVENT_TIMER_SUB,
    INHIBIT_SUB,
    INHIBIT_UNIT_US,
    SYNC_START_SUB,
    TRANSMISSION_SUB,
    is_dummy_index,
    transmission_meaning,
)
from ..views.pdo import Pdo, PdoEntry, pdo_map
from . import describe
from .compare import Sides
from .records import Change, Impact, Kind, PdoDiff, PdoEntryView, PdoView, new_change
from .traffic import timing_effect, transmission_effect

COB_ID_SUB = 1
# The timing entries of a PDO communication record (CiA 301 §7.5.2.35/36), with their unit.
TIMING_SUBS = {
    INHIBIT_SUB: ("inhibit time", INHIBIT_UNIT_US, "µs"),
    EVENT_TIMER_SUB: ("event timer", 1, "ms"),
    SYNC_START_SUB: ("SYNC start value", 0, ""),
}
VALUE_KINDS = (Kind.DEFAULT, Kind.PARAMETER_VALUE, Kind.NODEID_FORM)


def pdo_diffs(sides: Sides) -> list[PdoDiff]:
    """The PDOs that were added, removed or changed, RPDOs first."""
    old = {(p.direction, p.number): p for p in _in_device(sides.old, pdo_map(sides.old, sides.old_node, sides.old_ids))}
    new = {(p.direction, p.number): p for p in _in_device(sides.new, pdo_map(sides.new, sides.new_node, sides.new_ids))}
    diffs = []
    for key in sorted(set(old) | set(new), key=lambda k: (k[0] != "rx", k[1])):
        before, after = old.get(key), new.get(key)
        changes = _changes(before, after, sides.new_node)
        if before is not None and after is not None:
            changes += list(_timing(sides, before, after))
        if changes:
            some = after or before
            assert some is not None
            diffs.append(
                PdoDiff.model_construct(
                    name=some.name,
                    direction=some.direction,
                    number=some.number,
                    comm_index=some.comm_index,
                    map_index=some.map_index,
                    before=PdoView.of(before, timing(sides.old, before, sides.old_node))
                    if before is not None
                    else None,
                    after=PdoView.of(after, timing(sides.new, after, sides.new_node)) if after is not None else None,
                    changes=changes,
                )
            )
    return diffs


def _in_device(device: Device, pdos: list[Pdo]) -> list[Pdo]:
    """The PDOs the device has: not those whose communication or mapping object is CO_disabled (left out of the
    OD CANopenNode generates)."""

    def disabled(index: int) -> bool:
        obj = device.objects.get(index)
        return obj is not None and obj.canopennode is not None and bool(obj.canopennode.disabled)

    return [pdo for pdo in pdos if not (disabled(pdo.comm_index) or disabled(pdo.map_index))]


def _layout(pdo: Pdo) -> tuple[tuple[int, int, int, int], ...]:
    return tuple((e.index, e.subindex, e.bit_offset, e.bit_length) for e in pdo.entries)


def _changes(before: Pdo | None, after: Pdo | None, node_id: int | None) -> list[Change]:
    if before is None and after is not None:
        return [
            new_change(kind=Kind.PDO_ADDED, impact=Impact.COMPATIBLE, index=after.comm_index, new_text=_summary(after))
        ]
    if after is None and before is not None:
        return [
            new_change(
                kind=Kind.PDO_REMOVED, impact=Impact.BREAKING, index=before.comm_index, old_text=_summary(before)
            )
        ]
    assert before is not None and after is not None
    changes = []
    cob = _cob_id(before, after, node_id)
    if cob is not None:
        changes.append(cob)
    if before.transmission_type != after.transmission_type:
        impact, note = transmission_effect(after.direction, before.transmission_type, after.transmission_type)
        changes.append(
            new_change(
                kind=Kind.PDO_TRANSMISSION_TYPE,
                impact=impact,
                note=note,
                index=before.comm_index,
                subindex=TRANSMISSION_SUB,
                field="transmission_type",
                old=before.transmission_type,
                new=after.transmission_type,
                old_text=transmission_text(before.transmission_type),
                new_text=transmission_text(after.transmission_type),
            )
        )
    if _layout(before) != _layout(after):
        changes.append(
            new_change(
                kind=Kind.PDO_LAYOUT,
                impact=Impact.BREAKING,
                index=before.map_index,
                field="mapping",
                old_text=layout_text(before),
                new_text=layout_text(after),
                note=layout_note(before, after),
            )
        )
    return changes


def timing(device: Device, pdo: Pdo, node_id: int | None) -> dict[int, int]:
    """The PDO's timing entries as configured (sub-index → value), those that are numbers."""
    obj = device.objects.get(pdo.comm_index)
    found = {}
    for sub in TIMING_SUBS:
        var = obj.subs.get(sub) if obj is not None else None
        value = var.value(node_id) if var is not None else None
        if isinstance(value, int) and not isinstance(value, bool):
            found[sub] = value
    return found


def timing_text(sub: int, value: int | None) -> str:
    """`100 (10.0 ms)`, `1000 ms`, `0 (off)`."""
    if value is None:
        return "-"
    _, scale, unit = TIMING_SUBS[sub]
    if not unit:
        return str(value)
    if value == 0:
        return "0 (off)"
    return f"{value} ({value * scale / 1000:g} ms)" if scale != 1 else f"{value} ms"


def _timing(sides: Sides, before: Pdo, after: Pdo) -> Iterator[Change]:
    old, new = timing(sides.old, before, sides.old_node), timing(sides.new, after, sides.new_node)
    swapped = _swapped(old, new)
    for sub, (label, _, _) in TIMING_SUBS.items():
        if sub in old and sub in new and old[sub] != new[sub]:  # an entry on one side only is a sub-object change
            impact, note = timing_effect(after.direction, after.transmission_type, sub, old[sub], new[sub])
            yield new_change(
                kind=Kind.PDO_TIMING,
                impact=impact,
                note=f"{note}; inhibit time and event timer swapped" if swapped and sub in _SWAPPABLE else note,
                index=before.comm_index,
                subindex=sub,
                field=label.replace(" ", "_"),
                old=old.get(sub),
                new=new.get(sub),
                old_text=timing_text(sub, old.get(sub)),
                new_text=timing_text(sub, new.get(sub)),
            )


_SWAPPABLE = (INHIBIT_SUB, EVENT_TIMER_SUB)


def _swapped(old: dict[int, int], new: dict[int, int]) -> bool:
    """The inhibit time and the event timer traded values (an edit in the wrong column)."""
    if not all(sub in old and sub in new for sub in _SWAPPABLE):
        return False
    return old[INHIBIT_SUB] != old[EVENT_TIMER_SUB] and (old[INHIBIT_SUB], old[EVENT_TIMER_SUB]) == (
        new[EVENT_TIMER_SUB],
        new[INHIBIT_SUB],
    )


def entry_text(entry: PdoEntry | PdoEntryView) -> str:
    """`0x6064:00 position_actual_value`, `dummy INTEGER16`, `0x6064:00 (no such object)`."""
    if is_dummy_index(entry.index):
        name = entry.data_type if isinstance(entry, PdoEntryView) else entry.data_type_name
        return f"dummy {name}"
    where = describe.address(entry.index, entry.subindex)
    return f"{where} {entry.identifier}" if entry.identifier else f"{where} (no such object)"


def _bytes(pdo: Pdo) -> str:
    bits = pdo.bit_length
    return f"{bits // 8} bytes" if bits % 8 == 0 else f"{bits} bits"


def layout_note(before: Pdo, after: Pdo) -> str:
    """What happened to the layout, as a reviewer says it: appended, dropped, resized, reordered, source changed;
    then the length before and after."""
    old = [(e.index, e.subindex) for e in before.entries]
    new = [(e.index, e.subindex) for e in after.entries]
    notes = list(_layout_notes(before, after, old, new))
    if before.bit_length != after.bit_length:
        notes.append(f"length {_bytes(before)} → {_bytes(after)}")
    return "; ".join(notes) or "bit positions changed"


def _layout_notes(before: Pdo, after: Pdo, old: list[tuple[int, int]], new: list[tuple[int, int]]) -> Iterator[str]:
    def kept(shorter: Pdo, longer: Pdo) -> bool:
        """The shorter layout is the start of the longer one, entry for entry and bit for bit."""
        count = len(shorter.entries)
        return [(e.index, e.subindex, e.bit_length) for e in longer.entries[:count]] == [
            (e.index, e.subindex, e.bit_length) for e in shorter.entries
        ]

    if not old:
        yield "entries mapped (none before)"
    elif not new:
        yield "every entry unmapped"
    elif len(new) > len(old) and kept(before, after):
        yield "appended " + ", ".join(entry_text(e) for e in after.entries[len(old) :])
    elif len(new) < len(old) and kept(after, before):
        dropped = before.entries[len(new) :]
        yield f"trailing entr{'y' if len(dropped) == 1 else 'ies'} dropped: " + ", ".join(map(entry_text, dropped))
    elif sorted(old) == sorted(new) and old != new:
        moved = sum(a != b for a, b in zip(old, new, strict=True))
        yield f"reordered: {moved} of {len(new)} entries at other bits"
    else:
        yield from _entry_notes(before, after)


def _swaps(before: Pdo, after: Pdo) -> list[tuple[PdoEntry, PdoEntry]]:
    """Positions where one entry took another's place at the same bits: the old one gone, the new one new."""
    old = {(e.index, e.subindex) for e in before.entries}
    new = {(e.index, e.subindex) for e in after.entries}
    return [
        (a, b)
        for a, b in zip(before.entries, after.entries, strict=False)
        if (a.bit_offset, a.bit_length) == (b.bit_offset, b.bit_length)
        and (b.index, b.subindex) not in old
        and (a.index, a.subindex) not in new
    ]


def _entry_notes(before: Pdo, after: Pdo) -> Iterator[str]:
    """Entry by entry: same bits with another source, resized, moved, or added and removed."""
    old = {(e.index, e.subindex): e for e in before.entries}
    new = {(e.index, e.subindex): e for e in after.entries}
    swaps = _swaps(before, after)
    for a, b in swaps:
        yield f"source at bits {a.bit_offset}-{a.bit_offset + a.bit_length - 1}: {entry_text(a)} → {entry_text(b)}"
    swapped_out = {(a.index, a.subindex) for a, _ in swaps}
    swapped_in = {(b.index, b.subindex) for _, b in swaps}
    for key, entry in new.items():
        if key in old and old[key].bit_length != entry.bit_length:
            yield f"resized {entry_text(entry)}: {old[key].bit_length} → {entry.bit_length} bits"
        elif key in old and old[key].bit_offset != entry.bit_offset:
            yield f"moved {entry_text(entry)}: bit {old[key].bit_offset} → {entry.bit_offset}"
    added = [entry_text(e) for key, e in new.items() if key not in old and key not in swapped_in]
    removed = [entry_text(e) for key, e in old.items() if key not in new and key not in swapped_out]
    if added:
        yield "added " + ", ".join(added)
    if removed:
        yield "removed " + ", ".join(removed)


def _cob_id(before: Pdo, after: Pdo, node_id: int | None) -> Change | None:
    if before.cob_id == after.cob_id:
        return None
    resolved = [
        cob.resolve(node_id) if isinstance(cob, NodeIdExpr) and node_id is not None else cob
        for cob in (before.cob_id, after.cob_id)
    ]
    same = resolved[0] == resolved[1] and not isinstance(resolved[0], NodeIdExpr)
    return new_change(
        kind=Kind.NODEID_FORM if same else Kind.PDO_COB_ID,
        impact=Impact.VALUE if same else Impact.BREAKING,
        index=before.comm_index,
        subindex=COB_ID_SUB,
        field="cob_id",
        old=before.cob_id,
        new=after.cob_id,
        old_text=describe.cob_id_text(before.cob_id),
        new_text=describe.cob_id_text(after.cob_id),
        note=f"the same for node-ID {node_id}" if same else "",
    )


def transmission_text(value: int | None) -> str:
    """A transmission type with what it means (CiA 301 §7.5.2.35)."""
    return "-" if value is None else f"{value} ({transmission_meaning(value)})"


def layout_text(pdo: Pdo) -> str:
    """`bits 0-15 0x6041:00 statusword, bits 16-31 0x6064:00 position_actual_value` (empty: `no entries`)."""
    if not pdo.entries:
        return "no entries"
    return ", ".join(f"bits {e.bit_offset}-{e.bit_offset + e.bit_length - 1} {entry_text(e)}" for e in pdo.entries)


def _summary(pdo: Pdo) -> str:
    return f"COB-ID {describe.cob_id_text(pdo.cob_id)}, {layout_text(pdo)}"


def absorbed(diffs: list[PdoDiff]) -> set[tuple[int, int | None]]:
    """Entries whose value changes the PDO records already show: COB-ID, transmission type, mapping."""
    shown: set[tuple[int, int | None]] = set()
    for diff in diffs:
        for change in diff.changes:
            if change.kind is Kind.PDO_LAYOUT:
                shown.add((diff.map_index, None))
            elif change.index is not None and change.subindex is not None:
                shown.add((change.index, change.subindex))
    return shown
