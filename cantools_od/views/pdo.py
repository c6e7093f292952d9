"""The PDO map: which object each PDO carries at which bits, from the configured values."""

from __future__ import annotations

from dataclasses import dataclass

from ..identifiers import Identifiers, assign
from ..model import DataType, Device, NodeIdExpr, standard_type

RPDO_COMM, RPDO_MAP, TPDO_COMM, TPDO_MAP = 0x1400, 0x1600, 0x1800, 0x1A00
PDO_SPAN = 0x200  # 512 PDOs per direction


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

    @property
    def is_dummy(self) -> bool:
        return self.index < 0x1000

    @property
    def data_type_name(self) -> str:
        return self.data_type.name if self.data_type is not None else "UNKNOWN"


@dataclass(frozen=True)
class Pdo:
    direction: str  # "rx" or "tx"
    number: int  # 1-based
    comm_index: int
    map_index: int
    cob_id: int | NodeIdExpr | None
    transmission_type: int | None
    entries: tuple[PdoEntry, ...]

    @property
    def name(self) -> str:
        return f"{'R' if self.direction == 'rx' else 'T'}PDO{self.number}"

    @property
    def bit_length(self) -> int:
        return sum(entry.bit_length for entry in self.entries)


def pdo_map(device: Device, node_id: int | None = None, identifiers: Identifiers | None = None) -> list[Pdo]:
    """Every PDO whose communication or mapping object the device has, RPDOs first."""
    ids = identifiers or assign(device)
    nid = node_id if node_id is not None else device.node_id
    pdos: list[Pdo] = []
    for direction, comm_base, map_base in (("rx", RPDO_COMM, RPDO_MAP), ("tx", TPDO_COMM, TPDO_MAP)):
        for offset in range(PDO_SPAN):
            comm, mapping = device.objects.get(comm_base + offset), device.objects.get(map_base + offset)
            if comm is None and mapping is None:
                continue
            cob_id = _int_or_expr(_value(device, comm_base + offset, 1, nid))
            transmission = _value(device, comm_base + offset, 2, nid)
            pdos.append(
                Pdo(
                    direction=direction,
                    number=offset + 1,
                    comm_index=comm_base + offset,
                    map_index=map_base + offset,
                    cob_id=cob_id,
                    transmission_type=transmission if isinstance(transmission, int) else None,
                    entries=tuple(_entries(device, map_base + offset, ids)),
                )
            )
    return pdos


def _value(device: Device, index: int, subindex: int, node_id: int | None) -> object:
    obj = device.objects.get(index)
    entry = obj.entry(subindex) if obj is not None else None
    return entry.value(node_id) if entry is not None else None


def _int_or_expr(value: object) -> int | NodeIdExpr | None:
    if isinstance(value, bool):
        return int(value)
    return value if isinstance(value, (int, NodeIdExpr)) else None


def _entries(device: Device, map_index: int, ids: Identifiers) -> list[PdoEntry]:
    count = _value(device, map_index, 0, None)
    if not isinstance(count, int) or isinstance(count, bool):
        return []
    entries: list[PdoEntry] = []
    offset = 0
    for subindex in range(1, min(count, 0x40) + 1):
        raw = _value(device, map_index, subindex, None)
        if not isinstance(raw, int) or isinstance(raw, bool) or raw == 0:
            continue
        index, sub, bits = (raw >> 16) & 0xFFFF, (raw >> 8) & 0xFF, raw & 0xFF
        entries.append(_entry(device, index, sub, offset, bits, ids))
        offset += bits
    return entries


def _entry(device: Device, index: int, subindex: int, offset: int, bits: int, ids: Identifiers) -> PdoEntry:
    if index < 0x1000:  # a dummy entry names a data type
        dtype = standard_type(index)
        name = dtype.name if dtype is not None else f"type 0x{index:04X}"
        return PdoEntry(index, subindex, offset, bits, name, dtype, None, dtype is not None)
    obj = device.objects.get(index)
    var = obj.entry(subindex) if obj is not None else None
    if obj is None or var is None:
        return PdoEntry(index, subindex, offset, bits, "", None, None, False)
    return PdoEntry(
        index, subindex, offset, bits, var.name, device.entry_type(var, obj), ids.flat(index, subindex), True
    )
