"""The PDO map: which object each PDO carries at which bits, from the configured values."""

from __future__ import annotations

from dataclasses import dataclass

from ..identifiers import Identifiers, assign
from ..model import DataType, Device, NodeIdExpr
from ..model.cia301.modules import ModuleObject, module_objects
from ..model.cia301.pdo import (
    EVENT_TIMER_SUB,
    INHIBIT_SUB,
    SYNC_START_SUB,
    MapEntry,
    count_invalid,
    dummy_type,
    is_dummy_index,
    pdos,
)


@dataclass(frozen=True)
class PdoEntry:
    index: int
    subindex: int
    bit_offset: int
    bit_length: int
    name: str
    data_type: DataType | None
    identifier: str | None  # the flat identifier; None for a dummy entry
    exists: bool  # the mapped object (or dummy type) is known
    module: int | None = None  # the module that creates the mapped object (CiA 306 section 6), if one does

    @property
    def is_dummy(self) -> bool:
        return is_dummy_index(self.index)

    @property
    def data_type_name(self) -> str:
        return self.data_type.name if self.data_type is not None else "UNKNOWN"

    @property
    def label(self) -> str:
        """What the entry carries, in words: its identifier, a dummy's type, a module's object, or none."""
        if self.identifier:
            return self.identifier
        if self.is_dummy:
            return f"dummy {self.data_type_name}"
        if self.module is not None:
            return f"{self.name or 'object'} (module {self.module})"
        return "missing object"


@dataclass(frozen=True)
class Pdo:
    direction: str  # "rx" or "tx"
    number: int  # 1-based
    comm_index: int
    map_index: int
    cob_id: int | NodeIdExpr | None
    transmission_type: int | None
    entries: tuple[PdoEntry, ...]
    count: int | None = None  # sub0 of the mapping record as configured
    inhibit_time: int | None = None  # sub 3, in 100 µs
    event_timer: int | None = None  # sub 5, in ms
    sync_start: int | None = None  # sub 6, a count of SYNC messages

    @property
    def count_invalid(self) -> bool:
        """Sub0 counts more than 64 entries and is not an MPDO's FEh/FFh: no mapping can be read."""
        return count_invalid(self.count)

    @property
    def name(self) -> str:
        return f"{'R' if self.direction == 'rx' else 'T'}PDO{self.number}"

    @property
    def bit_length(self) -> int:
        return sum(entry.bit_length for entry in self.entries)


def pdo_map(device: Device, node_id: int | None = None, identifiers: Identifiers | None = None) -> list[Pdo]:
    """Every PDO whose communication or mapping object the device has, RPDOs first (the cia301 reading)."""
    ids = identifiers or assign(device)
    nid = node_id if node_id is not None else device.node_id
    found: list[Pdo] = []
    made = module_objects(device)
    for pdo in pdos(device):
        cob, transmission = pdo.comm_slot(1), pdo.comm_slot(2)
        transmission_type = transmission.value(nid) if transmission is not None else None
        found.append(
            Pdo(
                direction=pdo.direction,
                number=pdo.number,
                comm_index=pdo.comm_index,
                map_index=pdo.map_index,
                cob_id=_int_or_expr(cob.value(nid) if cob is not None else None),
                transmission_type=transmission_type if isinstance(transmission_type, int) else None,
                entries=tuple(_entry(device, entry, ids, made) for entry in pdo.mapped()),
                count=pdo.count,
                inhibit_time=pdo.comm_int(INHIBIT_SUB),
                event_timer=pdo.comm_int(EVENT_TIMER_SUB),
                sync_start=pdo.comm_int(SYNC_START_SUB),
            )
        )
    return found


def _int_or_expr(value: object) -> int | NodeIdExpr | None:
    if isinstance(value, bool):
        return int(value)
    return value if isinstance(value, (int, NodeIdExpr)) else None


def _entry(device: Device, mapped: MapEntry, ids: Identifiers, made: dict[int, ModuleObject]) -> PdoEntry:
    index, subindex, offset, bits = mapped.index, mapped.subindex, mapped.offset, mapped.bits
    if mapped.is_dummy:  # a dummy entry names a data type
        dtype = dummy_type(device, index)
        name = dtype.name if dtype is not None else f"type 0x{index:04X}"
        return PdoEntry(index, subindex, offset, bits, name, dtype, None, dtype is not None)
    obj = device.objects.get(index)
    var = obj.entry(subindex) if obj is not None else None
    if (obj is None or var is None) and index in made and made[index].has(subindex):  # CiA 306 section 6
        module = made[index]
        return PdoEntry(index, subindex, offset, bits, module.name, module.data_type, None, False, module.module)
    if obj is None or var is None:
        return PdoEntry(index, subindex, offset, bits, "", None, None, False)
    return PdoEntry(
        index, subindex, offset, bits, var.name, device.entry_type(var, obj), ids.flat(index, subindex), True
    )
