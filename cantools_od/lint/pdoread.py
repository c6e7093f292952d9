"""Reading PDO records and COB-IDs for the pdo, cobid and network rule families.

The rules see a PDO as its communication record (1400h/1800h + n - 1) and mapping record
(1600h/1A00h + n - 1), decoded from the configured values (ParameterValue, else DefaultValue).
A COB-ID keeps `$NODEID` symbolic: `Cob.at(node_id)` gives its value for one node-ID, and the
checks try every node-ID the device may have (`node_ids`).
"""

from __future__ import annotations

import dataclasses
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from weakref import WeakKeyDictionary

from ..model import (
    DataType,
    Device,
    Location,
    NodeIdExpr,
    Object,
    ObjectKind,
    Severity,
    SubObject,
    Variable,
    standard_type,
)
from .rules import Context, Finding, Fix

RX, TX = "rx", "tx"
COMM_BASE = {RX: 0x1400, TX: 0x1800}
MAP_BASE = {RX: 0x1600, TX: 0x1A00}
PDO_SPAN = 0x200
MAX_ENTRIES = 0x40
VALID, RTR, EXTENDED = 1 << 31, 1 << 30, 1 << 29
PREDEFINED = {RX: (0x200, 0x300, 0x400, 0x500), TX: (0x180, 0x280, 0x380, 0x480)}
ALL_NODE_IDS = range(1, 128)


def as_int(value: object) -> int | None:
    """An integer value; None for bool, text, `$NODEID` formulas and unreadable values."""
    return value if isinstance(value, int) and not isinstance(value, bool) else None


@dataclass(frozen=True)
class Slot:
    """One value-carrying entry: an object's sub-index (or a VAR) and where its value is written."""

    owner: Object
    subindex: int
    var: Variable

    @property
    def key(self) -> str:
        return "ParameterValue" if self.var.parameter_value is not None else "DefaultValue"

    @property
    def name(self) -> str:
        return f"{self.owner.index:04X}" if self.var is self.owner else f"{self.owner.index:04X}sub{self.subindex:X}"

    @property
    def implicit(self) -> bool:
        """No section of its own (CompactSubObj, CompactPDO): findings go to the owner."""
        return isinstance(self.var, SubObject) and self.var.implicit

    def location(self, ctx: Context) -> Location:
        """Where the configured value is written: the [xxxxValue] entry of a CompactSubObj value,
        the owner when the entry is not written at all (CompactPDO, CompactSubObj default)."""
        return ctx.written_at(self.owner, self.var, self.key)

    def key_location(self, ctx: Context, key: str) -> Location:
        if self.implicit:
            return ctx.at(self.owner)
        return ctx.at(self.var, key)

    def value(self, node_id: int | None = None) -> object:
        return self.var.value(node_id)


def slot(device: Device, index: int, subindex: int) -> Slot | None:
    obj = device.objects.get(index)
    var = obj.entry(subindex) if obj is not None else None
    return Slot(obj, subindex, var) if obj is not None and var is not None else None


@dataclass(frozen=True)
class MapEntry:
    """One mapping entry (sub-index `position` of a mapping record): index, sub-index, bit length."""

    slot: Slot
    position: int
    raw: int
    offset: int  # bit offset in the PDO, from the entries before it

    @property
    def index(self) -> int:
        return (self.raw >> 16) & 0xFFFF

    @property
    def subindex(self) -> int:
        return (self.raw >> 8) & 0xFF

    @property
    def flagged(self) -> bool:
        """The length byte has its MSB set (a vendor flag, not a length)."""
        return bool(self.raw & 0x80)

    @property
    def bits(self) -> int:
        return self.raw & (0x7F if self.flagged else 0xFF)

    @property
    def is_dummy(self) -> bool:
        return self.index < 0x1000

    @property
    def target(self) -> str:
        return f"{self.index:04X}sub{self.subindex:X}"


@dataclass(frozen=True)
class Pdo:
    direction: str
    number: int  # 1-based
    comm: Object | None
    mapping: Object | None

    @property
    def name(self) -> str:
        return f"{'R' if self.direction == RX else 'T'}PDO{self.number}"

    @property
    def comm_index(self) -> int:
        return COMM_BASE[self.direction] + self.number - 1

    @property
    def map_index(self) -> int:
        return MAP_BASE[self.direction] + self.number - 1

    def comm_slot(self, subindex: int) -> Slot | None:
        var = self.comm.entry(subindex) if self.comm is not None and self.comm.has_subs else None
        return Slot(self.comm, subindex, var) if self.comm is not None and var is not None else None

    def comm_int(self, subindex: int) -> int | None:
        found = self.comm_slot(subindex)
        return as_int(found.value()) if found is not None else None

    def count_slot(self) -> Slot | None:
        var = self.mapping.entry(0) if self.mapping is not None and self.mapping.has_subs else None
        return Slot(self.mapping, 0, var) if self.mapping is not None and var is not None else None

    @property
    def count(self) -> int | None:
        found = self.count_slot()
        return as_int(found.value()) if found is not None else None

    @property
    def is_mpdo(self) -> bool:
        """Sub0 FEh/FFh: a source- or destination-addressed multiplexed PDO (CiA 301 §7.2.3)."""
        return self.count in (0xFE, 0xFF)

    def entries(self) -> Iterator[MapEntry]:
        """The entries 1..sub0 that are described and hold a number, zero entries included.

        Nothing for a count above 64: an MPDO (FEh, FFh) or an invalid count (PDO040).
        """
        count, mapping = self.count, self.mapping
        if count is None or count > MAX_ENTRIES or mapping is None or not mapping.has_subs:
            return
        offset = 0
        for position in range(1, count + 1):
            var = mapping.subs.get(position)
            raw = as_int(var.value()) if var is not None else None
            if var is None or raw is None:
                continue
            entry = MapEntry(Slot(mapping, position, var), position, raw & 0xFFFFFFFF, offset)
            if raw:
                offset += entry.bits
            yield entry

    def mapped(self) -> list[MapEntry]:
        return [entry for entry in self.entries() if entry.raw]

    def cob(self) -> Cob | None:
        found = self.comm_slot(1)
        return cob_of(found, self.name)


_CACHE: WeakKeyDictionary[Context, list[Pdo]] = WeakKeyDictionary()


def device_pdos(ctx: Context) -> list[Pdo]:
    """`pdos` of the context's device, decoded once per lint run."""
    found = _CACHE.get(ctx)
    if found is None:
        found = _CACHE[ctx] = pdos(ctx.device)
    return found


def pdos(device: Device) -> list[Pdo]:
    """Every PDO whose communication or mapping object exists, RPDOs first."""
    found: list[Pdo] = []
    for direction in (RX, TX):
        for number in range(PDO_SPAN):
            comm = device.objects.get(COMM_BASE[direction] + number)
            mapping = device.objects.get(MAP_BASE[direction] + number)
            if comm is not None or mapping is not None:
                found.append(Pdo(direction, number + 1, comm, mapping))
    return found


def dummy_type(device: Device, index: int) -> DataType | None:
    """The fixed-size data type a dummy entry names: a CiA 301 type or a DEFTYPE alias."""
    dtype = standard_type(index)
    if dtype is None:
        alias = device.objects.get(index)
        if alias is not None and alias.kind is ObjectKind.DEFTYPE:
            dtype = standard_type(alias.data_type)
    return dtype if dtype is not None and dtype.bits is not None else None


@dataclass(frozen=True)
class Cob:
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
        return extended, value & (0x1FFFFFFF if extended else 0x7FF)

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

    def location(self, ctx: Context) -> Location:
        return self.slot.location(ctx) if self.slot is not None else ctx.at(None)


def cob_of(found: Slot | None, role: str) -> Cob | None:
    if found is None:
        return None
    value = found.value()
    if isinstance(value, NodeIdExpr):
        return Cob(found, value, role) if value.offset >= 0 else None
    number = as_int(value)
    return Cob(found, number, role) if number is not None and number >= 0 else None


def node_ids(ctx: Context) -> range | list[int]:
    """The node-IDs `$NODEID` may stand for: the known one, else 1..127."""
    known = known_node_id(ctx.device, ctx.options.node_id)
    return [known] if known is not None else ALL_NODE_IDS


def known_node_id(device: Device, option: int | None) -> int | None:
    node_id = option if option is not None else device.node_id
    return node_id if node_id is not None and 1 <= node_id <= 127 else None


def first(cob: Cob, ids: range | list[int], failing: Callable[[Cob, int], bool]) -> int | None:
    """The first node-ID of `ids` for which `failing(cob, node_id)` holds (one try for a literal)."""
    for node_id in ids if cob.symbolic else ids[:1]:
        if failing(cob, node_id):
            return node_id
    return None


def int_value(found: Slot | None) -> int | None:
    return as_int(found.value()) if found is not None else None


def default_cob(found: Slot | None, role: str) -> Cob | None:
    """The COB-ID as the EDS defaults it (DefaultValue, not a DCF's ParameterValue)."""
    value = found.var.default if found is not None else None
    if found is None or not isinstance(value, (int, NodeIdExpr)) or isinstance(value, bool):
        return None
    return Cob(found, value, role) if (value.offset if isinstance(value, NodeIdExpr) else value) >= 0 else None


def cob_entries(device: Device, pdo_list: list[Pdo]) -> Iterator[Cob]:
    """Every COB-ID entry as configured: PDOs, SYNC, TIME, EMCY, SDO server and client."""
    for pdo in pdo_list:
        cob = pdo.cob()
        if cob is not None:
            yield cob
    for index, role in ((0x1005, "SYNC"), (0x1012, "TIME"), (0x1014, "EMCY")):
        cob = cob_of(slot(device, index, 0), role)
        if cob is not None:
            yield cob
    for cob, _ in sdo_cobs(device):
        yield cob


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
            can_id = cob.can_id(node_id)
            if not cob.valid(node_id) or not can_id[1]:
                continue
            earlier = seen.setdefault(can_id, position)
            if earlier != position and (earlier, position) not in met:
                met.add((earlier, position))
                yield cobs[earlier], cob, node_id


def sdo_cobs(device: Device) -> Iterator[tuple[Cob, bool]]:
    """SDO COB-IDs with whether this device produces frames with them."""
    for index in range(0x1200, 0x1300):
        if index not in device.objects:
            continue
        server = index < 0x1280
        kind = "server" if server else "client"
        for subindex, direction in ((1, "rx" if server else "tx"), (2, "tx" if server else "rx")):
            cob = cob_of(slot(device, index, subindex), f"SDO {kind} {index:04X}h ({direction})")
            if cob is not None:
                yield cob, direction == "tx"


def producers(device: Device, pdo_list: list[Pdo] | None = None) -> list[Cob]:
    """Every COB-ID this device sends frames with (validity is left to the caller)."""
    found: list[Cob] = []
    for pdo in pdo_list if pdo_list is not None else pdos(device):
        cob = pdo.cob() if pdo.direction == TX else None
        if cob is not None:
            found.append(cob)
    emcy = cob_of(slot(device, 0x1014, 0), "EMCY")
    if emcy is not None:
        found.append(emcy)
    found.extend(cob for cob, produced in sdo_cobs(device) if produced)
    for index, role in ((0x1005, "SYNC"), (0x1012, "TIME")):
        cob = cob_of(slot(device, index, 0), role)
        if cob is not None and isinstance(cob.value, int) and cob.value & RTR:  # bit 30: produces
            found.append(Cob(cob.slot, cob.value & ~(VALID | RTR), role))
    found.append(Cob(None, NodeIdExpr(offset=0x700, text="$NODEID+0x700"), "NMT error control (heartbeat)"))
    return found


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


def length_fix(entry: MapEntry, bits: int, trusted: bool = True) -> Fix | None:
    """Rewrite the entry's length byte.

    Safe when the mapped type is `trusted` and the value is the entry's own (not the CompactSubObj
    default that every implicit entry shares).
    """
    if entry.flagged:
        return None
    new = (entry.raw & ~0xFF) | bits
    index, position = entry.slot.owner.index, entry.position
    field = "parameter_value" if entry.slot.var.parameter_value is not None else "default"
    shared = entry.slot.implicit and field == "default"
    safe = trusted and not shared

    def apply(device: Device) -> None:
        obj = device.objects.get(index)
        var = obj.entry(position) if obj is not None else None
        if var is not None:
            setattr(var, field, new)

    return Fix(f"write 0x{new:08X} (mapping entry length from the mapped type)", safe, apply)


def with_severity(finding: Finding, severity: Severity) -> Finding:
    """A rule whose severity depends on the case reports its milder cases through this."""
    return dataclasses.replace(finding, severity=severity)


def limits_fit(var: Variable, dtype: DataType) -> bool:
    """Whether the variable's integer limits lie within its data type: else the DataType itself is suspect."""
    bounds = dtype.int_range()
    if bounds is None:
        return True
    for limit in (var.low_limit, var.high_limit):
        if isinstance(limit, int) and not isinstance(limit, bool) and not bounds[0] <= limit <= bounds[1]:
            return False
    return True
