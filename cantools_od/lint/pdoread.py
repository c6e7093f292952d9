"""The linter's view of the PDO and COB-ID reading of model/cia301: decoded once per lint run,
checked for every node-ID the device may have, reported with locations and fixes.

A COB-ID keeps `$NODEID` symbolic: `Cob.at(node_id)` gives its value for one node-ID, and the
checks try every node-ID the device may have (`node_ids`).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from weakref import WeakKeyDictionary

from ..model import Device, Object, Severity, Variable
from ..model.cia301.cobid import ALL_NODE_IDS, Cob, known_node_id
from ..model.cia301.pdo import MapEntry, Pdo, pdos
from ..model.cia301.slots import Slot, as_int
from .rules import Context, Finding, Fix

_CACHE: WeakKeyDictionary[Context, list[Pdo]] = WeakKeyDictionary()


def device_pdos(ctx: Context) -> list[Pdo]:
    """`pdos` of the context's device, decoded once per lint run."""
    found = _CACHE.get(ctx)
    if found is None:
        found = _CACHE[ctx] = pdos(ctx.device)
    return found


def node_ids(ctx: Context) -> range | list[int]:
    """The node-IDs `$NODEID` may stand for: the known one, else 1..127."""
    known = known_node_id(ctx.device, ctx.options.node_id)
    return [known] if known is not None else ALL_NODE_IDS


def first(cob: Cob, ids: range | list[int], failing: Callable[[Cob, int], bool]) -> int | None:
    """The first node-ID of `ids` for which `failing(cob, node_id)` holds (one try for a literal)."""
    for node_id in ids if cob.symbolic else ids[:1]:
        if failing(cob, node_id):
            return node_id
    return None


def int_value(found: Slot | None) -> int | None:
    return as_int(found.value()) if found is not None else None


def mapped_objects(ctx: Context) -> Iterator[tuple[Pdo, MapEntry, Object | None, Variable | None]]:
    """Mapped entries that are not dummies, with the object and variable they name (or None)."""
    for pdo in device_pdos(ctx):
        for entry in pdo.mapped():
            if not entry.is_dummy:
                obj = ctx.device.objects.get(entry.index)
                yield pdo, entry, obj, obj.entry(entry.subindex) if obj is not None else None


def dummies(ctx: Context) -> Iterator[tuple[Pdo, MapEntry]]:
    for pdo in device_pdos(ctx):
        for entry in pdo.mapped():
            if entry.is_dummy:
                yield pdo, entry


def named(entry: MapEntry, var: Variable | None) -> str:
    return f"{entry.target} ({var.name})" if var is not None and var.name else entry.target


def length_fix(entry: MapEntry, bits: int) -> Fix | None:
    """Rewrite the entry's length byte. Never safe: the frame's layout changes (every later entry moves), and
    every peer reads the new mapping value."""
    if entry.flagged:
        return None
    new = (entry.raw & ~0xFF) | bits
    index, position = entry.slot.owner.index, entry.position

    def apply(device: Device) -> None:
        obj = device.objects.get(index)
        var = obj.entry(position) if obj is not None else None
        if var is not None:
            var.hold(new)

    return Fix(f"write 0x{new:08X} (mapping entry length from the mapped type)", False, apply)


def with_severity(finding: Finding, severity: Severity) -> Finding:
    """A rule whose severity depends on the case reports its milder cases through this."""
    return finding._replace(severity=severity)
