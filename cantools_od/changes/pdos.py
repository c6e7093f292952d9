"""PDO comparison: each PDO as configured on both sides, compared by COB-ID, transmission type and bit layout."""

from __future__ import annotations

from ..model import NodeIdExpr
from ..views.pdo import Pdo, pdo_map
from . import describe
from .compare import Sides
from .records import Change, Impact, Kind, PdoDiff, PdoView

COB_ID_SUB, TRANSMISSION_SUB = 1, 2
VALUE_KINDS = (Kind.DEFAULT, Kind.PARAMETER_VALUE, Kind.NODEID_FORM)


def pdo_diffs(sides: Sides) -> list[PdoDiff]:
    """The PDOs that were added, removed or changed, RPDOs first."""
    old = {(p.direction, p.number): p for p in pdo_map(sides.old, sides.old_node, sides.old_ids)}
    new = {(p.direction, p.number): p for p in pdo_map(sides.new, sides.new_node, sides.new_ids)}
    diffs = []
    for key in sorted(set(old) | set(new), key=lambda k: (k[0] != "rx", k[1])):
        before, after = old.get(key), new.get(key)
        changes = _changes(before, after, sides.new_node)
        if changes:
            some = after or before
            assert some is not None
            diffs.append(
                PdoDiff(
                    name=some.name,
                    direction=some.direction,
                    number=some.number,
                    comm_index=some.comm_index,
                    map_index=some.map_index,
                    before=PdoView.of(before) if before is not None else None,
                    after=PdoView.of(after) if after is not None else None,
                    changes=changes,
                )
            )
    return diffs


def _layout(pdo: Pdo) -> tuple[tuple[int, int, int, int], ...]:
    return tuple((e.index, e.subindex, e.bit_offset, e.bit_length) for e in pdo.entries)


def _changes(before: Pdo | None, after: Pdo | None, node_id: int | None) -> list[Change]:
    if before is None and after is not None:
        return [Change(kind=Kind.PDO_ADDED, impact=Impact.COMPATIBLE, index=after.comm_index, new_text=_summary(after))]
    if after is None and before is not None:
        return [
            Change(kind=Kind.PDO_REMOVED, impact=Impact.BREAKING, index=before.comm_index, old_text=_summary(before))
        ]
    assert before is not None and after is not None
    changes = []
    cob = _cob_id(before, after, node_id)
    if cob is not None:
        changes.append(cob)
    if before.transmission_type != after.transmission_type:
        changes.append(
            Change(
                kind=Kind.PDO_TRANSMISSION_TYPE,
                impact=Impact.VALUE,
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
            Change(
                kind=Kind.PDO_LAYOUT,
                impact=Impact.BREAKING,
                index=before.map_index,
                field="mapping",
                old_text=layout_text(before),
                new_text=layout_text(after),
                note="fields moved, resized, added or removed",
            )
        )
    return changes


def _cob_id(before: Pdo, after: Pdo, node_id: int | None) -> Change | None:
    if before.cob_id == after.cob_id:
        return None
    resolved = [
        cob.resolve(node_id) if isinstance(cob, NodeIdExpr) and node_id is not None else cob
        for cob in (before.cob_id, after.cob_id)
    ]
    same = resolved[0] == resolved[1] and not isinstance(resolved[0], NodeIdExpr)
    return Change(
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
    if value is None:
        return "-"
    if value == 0:
        meaning = "synchronous, acyclic"
    elif value <= 240:
        meaning = "synchronous, every SYNC" if value == 1 else f"synchronous, every {value}th SYNC"
    elif value in (252, 253):
        meaning = "RTR only"
    elif value >= 254:
        meaning = "event-driven"
    else:
        meaning = "reserved"
    return f"{value} ({meaning})"


def layout_text(pdo: Pdo) -> str:
    """`bits 0-15 statusword, bits 16-31 position_actual_value` (empty: `no entries`)."""
    if not pdo.entries:
        return "no entries"
    return ", ".join(
        f"bits {e.bit_offset}-{e.bit_offset + e.bit_length - 1} {e.identifier or f'dummy {e.data_type_name}'}"
        for e in pdo.entries
    )


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
