"""A PDO as a bit-field picture, in cells: which bits of which byte each mapped entry covers.

The picture follows the datasheet convention: bytes left to right in the order they are sent (byte 0
first), and within a byte its bits from 7 down to 0, as CANopen maps data least significant byte first.
A row holds eight bytes (one classic CAN frame); a CAN FD PDO takes more rows. An entry that is not
aligned to bytes can fall in two places of a row (bits 4-11: the low half of byte 0 and the high half of
byte 1), so each entry is drawn as one or more segments, each a run of adjacent cells in one row.

Everything here is counted in cells and bits; render/svg.py turns it into pixels.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from enum import Enum

from ..model import NodeIdExpr
from ..model.cia301.cobid import VALID
from ..model.cia301.pdo import INHIBIT_UNIT_US, transmission_meaning
from .pdo import Pdo, PdoEntry

BYTES_PER_ROW = 8
CELLS_PER_ROW = BYTES_PER_ROW * 8


class FieldKind(Enum):
    OBJECT = "object"  # an object of the dictionary
    DUMMY = "dummy"  # a dummy entry: bits the receiver skips
    MISSING = "missing"  # mapped, but the file does not describe the object
    UNUSED = "unused"  # the bits after the last entry, up to the end of the last byte


@dataclass(frozen=True)
class Segment:
    row: int
    first_cell: int  # within the row, from the left
    cells: int
    low_bit: int  # the lowest and highest PDO bit the segment covers
    high_bit: int


@dataclass(frozen=True)
class Field:
    number: int  # 1-based, as the legend lists it; 0 for unused bits
    kind: FieldKind
    bit_offset: int
    bit_length: int
    label: str  # the identifier, a dummy's type, or what is missing
    where: str  # `6041:00`, the mapped object and sub-index
    type_name: str
    name: str  # the object's name in the file
    segments: tuple[Segment, ...]

    @property
    def bits_text(self) -> str:
        last = self.bit_offset + self.bit_length - 1
        return f"bit {last}" if self.bit_length == 1 else f"bits {self.bit_offset}-{last}"


@dataclass(frozen=True)
class Diagram:
    anchor: str  # `tpdo1`
    title: str
    timing: str
    byte_count: int
    fields: tuple[Field, ...]

    @property
    def rows(self) -> int:
        return max(1, -(-self.byte_count // BYTES_PER_ROW))

    @property
    def row_bytes(self) -> int:
        """Bytes drawn in one row: all of them when they fit, else a whole row."""
        return max(1, min(self.byte_count, BYTES_PER_ROW))


def cell_of(bit: int) -> tuple[int, int]:
    """(row, cell within the row) of a PDO bit."""
    byte, within = divmod(bit, 8)
    row, column = divmod(byte, BYTES_PER_ROW)
    return row, column * 8 + 7 - within


def segments(bit_offset: int, bit_length: int) -> tuple[Segment, ...]:
    """The runs of adjacent cells that bits `bit_offset`.. cover, in the order of their cells."""
    runs: list[list[int]] = []  # [row, first cell, last cell, low bit, high bit]
    places = sorted((cell_of(bit), bit) for bit in range(bit_offset, bit_offset + bit_length))
    for (row, cell), bit in places:
        last = runs[-1] if runs else None
        if last is not None and last[0] == row and last[2] == cell - 1:
            last[2], last[3], last[4] = cell, min(last[3], bit), max(last[4], bit)
        else:
            runs.append([row, cell, cell, bit, bit])
    return tuple(Segment(row, first, last - first + 1, low, high) for row, first, last, low, high in runs)


def diagram(pdo: Pdo, node_id: int | None = None) -> Diagram:
    """The picture of one PDO as the file configures it."""
    byte_count = max(1, -(-pdo.bit_length // 8))
    fields = [_field(number, entry) for number, entry in enumerate(pdo.entries, 1)]
    spare = byte_count * 8 - pdo.bit_length
    if spare and pdo.entries:
        unused = segments(pdo.bit_length, spare)
        fields.append(Field(0, FieldKind.UNUSED, pdo.bit_length, spare, "unused", "", "", "", unused))
    return Diagram(pdo.name.lower(), _title(pdo, byte_count, node_id), timing(pdo), byte_count, tuple(fields))


def _field(number: int, entry: PdoEntry) -> Field:
    where = f"{entry.index:04X}:{entry.subindex:02X}"
    if entry.is_dummy:
        kind = FieldKind.DUMMY
    elif entry.exists or entry.module is not None:
        kind = FieldKind.OBJECT
    else:
        kind = FieldKind.MISSING
    return Field(
        number,
        kind,
        entry.bit_offset,
        entry.bit_length,
        entry.label,
        where,
        entry.data_type_name,
        entry.name,
        segments(entry.bit_offset, entry.bit_length),
    )


def cob_id_text(cob: int | NodeIdExpr | None, node_id: int | None, code: Callable[[str], str] = str) -> str:
    """`0x185`, `$NODEID+0x180 (0x185)`, `$NODEID+0x180`, or `no COB-ID`; `(not valid)` after one with bit 31.
    `code` marks the COB-ID as written (the Markdown page sets it in backticks)."""
    if cob is None:
        return "no COB-ID"
    if isinstance(cob, NodeIdExpr):
        text = code(cob.canonical()) + (f" (0x{cob.resolve(node_id):X})" if node_id is not None else "")
        value = cob.offset
    else:
        text, value = code(f"0x{cob:X}"), cob
    return text + (" (not valid)" if value & VALID else "")


def _title(pdo: Pdo, byte_count: int, node_id: int | None) -> str:
    size = f"{byte_count} byte" + ("" if byte_count == 1 else "s")
    if not pdo.entries:
        size = "no entries mapped"
    return f"{pdo.name} (mapping {pdo.map_index:04X}h) · COB-ID {cob_id_text(pdo.cob_id, node_id)} · {size}"


def timing(pdo: Pdo) -> str:
    """When the PDO is sent or taken: transmission type, inhibit time, event timer, SYNC start value."""
    parts = []
    kind = pdo.transmission_type
    parts.append(
        "transmission type not given" if kind is None else f"transmission type {kind} ({transmission_meaning(kind)})"
    )
    if pdo.inhibit_time:
        parts.append(f"inhibit time {pdo.inhibit_time * INHIBIT_UNIT_US / 1000:g} ms")
    if pdo.event_timer:
        parts.append(f"event timer {pdo.event_timer} ms")
    if pdo.sync_start:
        parts.append(f"SYNC start value {pdo.sync_start}")
    return " · ".join(parts)
