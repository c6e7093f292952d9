"""COB-IDs (CiA 301 §7.2, §7.3): the bits of a COB-ID entry, the pre-defined connection set and the
restricted CAN-IDs, and a COB-ID entry read from its configured value."""

from __future__ import annotations

from collections.abc import Iterator
from typing import NamedTuple

from ..device import Device
from ..source import Location
from ..values import NodeIdExpr
from .objects import RX, TX
from .slots import Locator, Slot, as_int

VALID, RTR, EXTENDED = 1 << 31, 1 << 30, 1 << 29  # bit 31 set: invalid; 30: no RTR / produces; 29: 29-bit
BASE_11BIT, BASE_29BIT = 0x7FF, 0x1FFFFFFF
HIGH_BITS = BASE_29BIT & ~BASE_11BIT  # bits 28-11: 0 in an 11-bit COB-ID
ALL_NODE_IDS = range(1, 128)

# The pre-defined connection set: COB-ID = base + node-ID.
EMCY_BASE, SDO_RX_BASE, SDO_TX_BASE, HEARTBEAT_BASE = 0x080, 0x600, 0x580, 0x700
PREDEFINED = {RX: (0x200, 0x300, 0x400, 0x500), TX: (0x180, 0x280, 0x380, 0x480)}  # PDOs 1-4
SYNC_ID, TIME_ID = 0x080, 0x100
SERVICE_IDS = range(SYNC_ID, TIME_ID + 1)  # SYNC, EMCY of the pre-defined set, TIME
# CAN-IDs no PDO may use (CiA 301 v4.2, restricted CAN-IDs).
RESTRICTED = (
    (0x000, 0x000), (0x001, 0x07F), (0x101, 0x180), (0x581, 0x5FF), (0x601, 0x67F), (0x6E0, 0x6FF), (0x701, 0x77F),
    (0x780, 0x7FF),
)  # fmt: skip


def predefined_pdo(can_id: int) -> tuple[str, int, int] | None:
    """The PDO of the pre-defined connection set an 11-bit CAN-ID belongs to: (direction, PDO number 1-4,
    node-ID 1-127), else None. An RPDO on 190h consumes TPDO1 of node 16."""
    for direction, bases in PREDEFINED.items():
        for number, base in enumerate(bases, 1):
            if 1 <= can_id - base <= 127:
                return direction, number, can_id - base
    return None


def restricted(can_id: int) -> bool:
    """Whether an 11-bit CAN-ID is one a PDO must not use."""
    return any(low <= can_id <= high for low, high in RESTRICTED)


class Cob(NamedTuple):
    """A COB-ID entry: its slot (None for the implicit NMT error-control COB-ID) and its value."""

    slot: Slot | None
    value: int | NodeIdExpr
    role: str  # "TPDO1", "EMCY", "SDO server 1200h (tx)", "heartbeat", ...

    @property
    def symbolic(self) -> bool:
        return isinstance(self.value, NodeIdExpr)

    def at(self, node_id: int) -> int:
        value = self.value.resolve(node_id) if isinstance(self.value, NodeIdExpr) else self.value
        return value & 0xFFFFFFFF

    def can_id(self, node_id: int) -> tuple[bool, int]:
        """(29-bit frame, CAN-ID) for one node-ID."""
        value = self.at(node_id)
        extended = bool(value & EXTENDED)
        return extended, value & (BASE_29BIT if extended else BASE_11BIT)

    def valid(self, node_id: int) -> bool:
        return not self.at(node_id) & VALID

    @property
    def written(self) -> str:
        return self.value.canonical() if isinstance(self.value, NodeIdExpr) else f"0x{self.value:X}"

    def shown(self, node_id: int) -> str:
        """The COB-ID as written, with its value for `node_id` when it uses $NODEID."""
        suffix = f" (0x{self.at(node_id):X} for node-ID {node_id})" if self.symbolic else ""
        return self.written + suffix

    def describe(self, node_id: int) -> str:
        extended, can_id = self.can_id(node_id)
        return f"{can_id:08X}h (29-bit)" if extended else f"{can_id:03X}h"

    def location(self, at: Locator) -> Location:
        return self.slot.location(at) if self.slot is not None else at.at(None)


def cob_of(found: Slot | None, role: str) -> Cob | None:
    if found is None:
        return None
    value = found.value()
    if isinstance(value, NodeIdExpr):
        return Cob(found, value, role) if value.offset >= 0 else None
    number = as_int(value)
    return Cob(found, number, role) if number is not None and number >= 0 else None


def default_cob(found: Slot | None, role: str) -> Cob | None:
    """The COB-ID as the EDS defaults it (DefaultValue, not a DCF's ParameterValue)."""
    value = found.var.default if found is not None else None
    if found is None or not isinstance(value, (int, NodeIdExpr)) or isinstance(value, bool):
        return None
    return Cob(found, value, role) if (value.offset if isinstance(value, NodeIdExpr) else value) >= 0 else None


def known_node_id(device: Device, option: int | None) -> int | None:
    node_id = option if option is not None else device.node_id
    return node_id if node_id is not None and 1 <= node_id <= 127 else None


def collisions(cobs: list[Cob], ids: range | list[int]) -> Iterator[tuple[Cob, Cob, int]]:
    """Pairs of valid COB-IDs with one CAN-ID, each with the first node-ID where they meet.

    CAN-ID 0 (NMT) counts as not configured: several entries left at 0 are no collision.
    """
    if not any(cob.symbolic for cob in cobs):
        ids = ids[:1]
    met: set[tuple[int, int]] = set()
    for node_id in ids:
        seen: dict[tuple[bool, int], int] = {}
        for position, cob in enumerate(cobs):
            value = cob.at(node_id)  # what `valid` and `can_id` tell, from one resolution: 127 node-IDs per COB-ID
            extended = bool(value & EXTENDED)
            can_id = (extended, value & (BASE_29BIT if extended else BASE_11BIT))
            if value & VALID or not can_id[1]:
                continue
            earlier = seen.setdefault(can_id, position)
            if earlier != position and (earlier, position) not in met:
                met.add((earlier, position))
                yield cobs[earlier], cob, node_id
