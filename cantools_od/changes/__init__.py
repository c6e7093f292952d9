"""What changed between two device descriptions, and what it breaks: `diff` and its change records.

The package is not called `diff` so that importing it never hides the `cantools_od.diff` function.
"""

from __future__ import annotations

import os
from collections.abc import Mapping

from ..identifiers import assign, load_pins
from ..model import Device
from . import formats, peers
from .compare import Sides, object_diffs
from .device import device_changes
from .pdos import VALUE_KINDS, absorbed, pdo_diffs
from .records import IMPACT_ORDER, Breaks, Change, DeviceDiff, Impact, Kind, ObjectDiff, PdoDiff, PdoEntryView, PdoView

__all__ = [
    "IMPACT_ORDER",
    "Breaks",
    "Change",
    "DeviceDiff",
    "Impact",
    "Kind",
    "ObjectDiff",
    "PdoDiff",
    "PdoEntryView",
    "PdoView",
    "compare",
    "diff",
]

Pins = Mapping[str, str] | str | os.PathLike[str] | None


def diff(
    old: Device | str | os.PathLike[str],
    new: Device | str | os.PathLike[str],
    node_id: int | None = None,
    old_pins: Pins = None,
    new_pins: Pins = None,
) -> DeviceDiff:
    """What changed from `old` to `new`: devices, or paths of files `cantools_od.load` reads.

    Pins are pin tables or pin files (`cantools-od ids`); see `compare`. Raises OSError for an
    unreadable path and ValueError for a JSON file that is not a model or a bad pin file.
    """
    from ..api import load

    before = old if isinstance(old, Device) else load(old)
    after = new if isinstance(new, Device) else load(new)
    return compare(before, after, node_id, _pins(old_pins), _pins(new_pins))


def _pins(pins: Pins) -> Mapping[str, str] | None:
    if pins is None or isinstance(pins, Mapping):
        return pins
    return load_pins(os.fspath(pins))


def compare(
    old: Device,
    new: Device,
    node_id: int | None = None,
    old_pins: Mapping[str, str] | None = None,
    new_pins: Mapping[str, str] | None = None,
) -> DeviceDiff:
    """The changes from `old` to `new`.

    `node_id` is what `$NODEID` stands for when comparing a formula with a number (default: the
    node-ID each device states, else the other's). Pins (see docs/identifiers.md) decide the identifiers of each side:
    a renamed entry whose identifier is pinned is a cosmetic change.
    """
    old_node, new_node = (node_id, node_id) if node_id is not None else (old.node_id, new.node_id)
    old_node = old_node if old_node is not None else new_node
    new_node = new_node if new_node is not None else old_node
    sides = Sides(old, new, assign(old, old_pins), assign(new, new_pins), old_node, new_node)
    pdos = pdo_diffs(sides)
    shown = absorbed(pdos)
    objects = []
    for obj in object_diffs(sides):
        kept = [
            change
            for change in obj.changes
            if _told(change)
            and not (
                change.kind in VALUE_KINDS
                and ((change.index, change.subindex) in shown or (change.index, None) in shown)
            )
        ]
        if kept:
            objects.append(obj.model_copy(update={"changes": kept}))
    spelled = list(peers.spelling_changes(old, new))
    objects = _with(objects, [change for change in spelled if change.index is not None])
    device = [change for change in device_changes(old, new) if _told(change)]
    device += [change for change in spelled if change.index is None]
    everything = device + [change for obj in objects for change in obj.changes]
    kept, not_comparable = formats.split(old.source, new.source, everything)
    if not_comparable:
        chosen = {id(change) for change in kept}
        device = [change for change in device if id(change) in chosen] + not_comparable
        objects = [
            obj.model_copy(update={"changes": [c for c in obj.changes if id(c) in chosen]})
            for obj in objects
            if any(id(c) in chosen for c in obj.changes)
        ]
    return DeviceDiff.model_construct(old=old.source, new=new.source, device=device, objects=objects, pdos=pdos)


def _with(objects: list[ObjectDiff], changes: list[Change]) -> list[ObjectDiff]:
    """The object records with these changes added, each to its object's record (made when missing)."""
    if not changes:
        return objects
    by_index = {obj.index: obj for obj in objects}
    for change in changes:
        assert change.index is not None
        found = by_index.get(change.index)
        if found is None:
            found = ObjectDiff.model_construct(index=change.index, name=change.name, changes=[])
        by_index[change.index] = found.model_copy(update={"changes": [*found.changes, change]})
    return [by_index[index] for index in sorted(by_index)]


_WHOLE = frozenset({Kind.OBJECT_ADDED, Kind.OBJECT_REMOVED, Kind.SUB_ADDED, Kind.SUB_REMOVED})


def _told(change: Change) -> bool:
    """A change a reader can see: nothing is reported whose old and new text are equal."""
    return change.kind in _WHOLE or change.old_text != change.new_text
