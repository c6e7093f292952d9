"""PDOs (CiA 301 §7.2.2, §7.4.8, §7.5.2.35-38): where their records live, how a mapping entry is read,
and the one reading of a device's PDOs that the linter, the views, the generators and the importer share.

A PDO is its communication record (1400h/1800h + n - 1) and mapping record (1600h/1A00h + n - 1),
decoded from the configured values (ParameterValue, else DefaultValue). A mapping entry is an
UNSIGNED32: index (bits 31-16), sub-index (15-8) and the length in bits (7-0, the whole byte:
a length byte with its MSB set is read as the length it says, not as a flag). Sub0 counts the
entries 1..sub0; FEh and FFh mark multiplexed PDOs, which carry no fixed mapping.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from ..datatypes import BOOLEAN, UNSIGNED32, DataType, standard_type
from ..device import Device
from ..objects import Object, ObjectKind
from .cobid import PREDEFINED as PREDEFINED  # the COB-ID bases of PDOs 1-4 live with the others
from .cobid import Cob, cob_of
from .definitions import PDO_COMM_SUBS
from .objects import COMM_BASE as COMM_BASE  # the record ranges live in .objects (no imports): re-exported
from .objects import DATA_TYPE_AREA
from .objects import MAP_BASE as MAP_BASE
from .objects import MAX_ENTRIES as MAX_ENTRIES
from .objects import PDO_AREA as PDO_AREA
from .objects import PDO_SPAN as PDO_SPAN
from .objects import RX as RX
from .objects import TX as TX
from .slots import Slot, as_int

SAM_MPDO, DAM_MPDO = 0xFE, 0xFF
CLASSIC_CAN_BITS, CAN_FD_BITS = 64, 512

# The PDO_COMMUNICATION_PARAMETER record (0020h): sub-index -> (name, data type).
COMM_SUBS: dict[int, tuple[str, int]] = {
    sub: (entry.name, entry.data_type) for sub, entry in enumerate(PDO_COMM_SUBS) if sub and entry.data_type is not None
}
MAPPING_ENTRY_TYPE = UNSIGNED32.index
# The data types a device may map as dummy entries ([DummyUsage] Dummy0001-Dummy0007 of CiA 306).
DUMMY_TYPES = range(BOOLEAN.index, UNSIGNED32.index + 1)


# Sub-indices of the communication record that time a PDO (CiA 301 §7.5.2.35): the inhibit time counts
# 100 µs, the event timer 1 ms; the SYNC start value is a count of SYNC messages.
TRANSMISSION_SUB, INHIBIT_SUB, EVENT_TIMER_SUB, SYNC_START_SUB = 2, 3, 5, 6
INHIBIT_UNIT_US = 100


def transmission_meaning(value: int) -> str:
    """What a transmission type (communication sub-index 2) makes the PDO do, CiA 301 §7.5.2.35."""
    if value == 0:
        return "synchronous, acyclic"
    if value == 1:
        return "synchronous, every SYNC"
    if value <= 240:
        return f"synchronous, every {value}th SYNC"
    if value in (252, 253):
        return "RTR only"
    if value >= 254:
        return "event-driven"
    return "reserved"


def frame_bits(can_fd: bool) -> int:
    """The bits one PDO may carry: a classic CAN frame's 8 bytes, or CAN FD's 64."""
    return CAN_FD_BITS if can_fd else CLASSIC_CAN_BITS


def locate(index: int) -> tuple[str, str, int] | None:
    """("comm" or "map", direction, 1-based number) of a PDO record's index, else None."""
    for kind, bases in (("comm", COMM_BASE), ("map", MAP_BASE)):
        for direction, base in bases.items():
            if base <= index < base + PDO_SPAN:
                return kind, direction, index - base + 1
    return None


def is_comm(index: int, direction: str | None = None) -> bool:
    found = locate(index)
    return found is not None and found[0] == "comm" and direction in (None, found[1])


def is_mapping(index: int) -> bool:
    found = locate(index)
    return found is not None and found[0] == "map"


def partner(index: int) -> int | None:
    """The other record of the same PDO: the mapping record of a communication record, and back."""
    found = locate(index)
    if found is None:
        return None
    kind, direction, number = found
    return (MAP_BASE if kind == "comm" else COMM_BASE)[direction] + number - 1


def count_pdos(indices: Iterable[int], direction: str) -> int:
    """How many communication records of `direction` the indices hold (what NrOfRXPDO/NrOfTXPDO count)."""
    records = range(COMM_BASE[direction], COMM_BASE[direction] + PDO_SPAN)  # `is_comm(index, direction)`, at once
    return sum(1 for index in indices if index in records)


def is_mpdo_count(count: int | None) -> bool:
    """Sub0 FEh/FFh: a source- or destination-addressed multiplexed PDO (CiA 301 §7.2.3)."""
    return count in (SAM_MPDO, DAM_MPDO)


def count_invalid(count: int | None) -> bool:
    """Sub0 above 64 and not an MPDO: the mapping counts more entries than a PDO holds."""
    return count is not None and count > MAX_ENTRIES and not is_mpdo_count(count)


def decode_entry(raw: int) -> tuple[int, int, int]:
    """(index, sub-index, length in bits) of a mapping entry."""
    return (raw >> 16) & 0xFFFF, (raw >> 8) & 0xFF, raw & 0xFF


def is_dummy_index(index: int) -> bool:
    """A mapping entry naming a data type (below 1000h) is a dummy: the receiver skips its bits."""
    return index < DATA_TYPE_AREA.stop


@dataclass(frozen=True)
class MapEntry:
    """One mapping entry (sub-index `position` of a mapping record): index, sub-index, bit length."""

    slot: Slot
    position: int
    raw: int
    offset: int  # bit offset in the PDO, from the entries before it

    @property
    def index(self) -> int:
        return decode_entry(self.raw)[0]

    @property
    def subindex(self) -> int:
        return decode_entry(self.raw)[1]

    @property
    def flagged(self) -> bool:
        """The length byte has its MSB set: some vendors mean a private flag, CiA 301 a length above 127."""
        return bool(self.raw & 0x80)

    @property
    def bits(self) -> int:
        return decode_entry(self.raw)[2]

    @property
    def is_dummy(self) -> bool:
        return is_dummy_index(self.index)

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
        return is_mpdo_count(self.count)

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

    @property
    def bit_length(self) -> int:
        return sum(entry.bits for entry in self.mapped())

    def cob(self) -> Cob | None:
        return cob_of(self.comm_slot(1), self.name)


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


def dummy_shape_problem(dtype: DataType | None, index: int, subindex: int) -> str:
    """Why a dummy entry names no data type it may map, '' when it does.

    CiA 301 (7.4.7.1) lets the data-type entries be mapped into an RPDO to mark bits the device does
    not use; a data-type definition is one entry at sub-index 0 whose type has a fixed size, so a dummy
    names that index with sub-index 0 (0x00050008), never another sub-index (0x00050108)."""
    if dtype is None:
        return f"names {index:04X}h, not a fixed-size data type"
    if subindex != 0:
        return f"has sub-index {subindex}, expected 0"
    return ""


def dummy_length_fits(dtype: DataType, bits: int) -> bool:
    """The entry's length is the type's size (a BOOLEAN also as the byte CANopenNode stores it in)."""
    return bits == dtype.bits or (dtype.index == BOOLEAN.index and bits == 8)
