"""What CiA 301 says about the communication objects, to fill gaps the manuals leave.

Values taken from here are *inferred*: they are used only where no source says anything,
never conflict with a source, and are listed as inferred in the report and the EDS. The
objects themselves are the standard's (model/cia301/definitions); this module only picks the
ones manuals list and says what the importer takes from them: the name EDS files use, the data
type, and the access type devices all but always give.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..model import AccessType, ObjectKind
from ..model.cia301.definitions import Definition, Entry, definition, record_type_layout
from ..model.cia301.objects import DEVICE_TYPE, ERROR_BEHAVIOR, PDO_AREA, SDO_SERVERS, SYNC_COUNTER_OVERFLOW
from .entries import Kind
from .facts import Fact, Source


@dataclass(frozen=True)
class StdEntry:
    name: str
    data_type: int | None
    access: AccessType | None


@dataclass(frozen=True)
class StdObject:
    name: str
    kind: ObjectKind
    entries: dict[int, StdEntry] = field(default_factory=dict)
    element: StdEntry | None = None  # every sub-index above 0 of an ARRAY

    def entry(self, sub: int) -> StdEntry | None:
        if sub in self.entries:
            return self.entries[sub]
        return self.element if sub > 0 else None


# The objects the importer completes from the standard: those vendor manuals list.
_FILLED = (
    range(DEVICE_TYPE, SYNC_COUNTER_OVERFLOW + 1),
    range(ERROR_BEHAVIOR, ERROR_BEHAVIOR + 1),
    SDO_SERVERS,
    PDO_AREA,
)


def _std_entry(entry: Entry) -> StdEntry:
    return StdEntry(entry.eds_name or entry.name, entry.data_type, entry.usual)


def _std_object(found: Definition) -> StdObject:
    element = _std_entry(found.rest) if found.rest is not None else None
    entries = {sub: _std_entry(entry) for sub, entry in enumerate(found.subs)}
    return StdObject(found.eds_name or found.name, found.kind, entries, element)


STANDARD_OBJECTS: dict[int, StdObject] = {
    index: _std_object(found) for area in _FILLED for index in area if (found := definition(index)) is not None
}


def record_layout(type_index: int) -> dict[int, Fact] | None:
    """CiA 301's definition of a standard record type, as inferred facts."""
    layout = record_type_layout(type_index)
    if layout is None:
        return None
    source = Source("CiA 301", 0, f"record {type_index:04X}h", Kind.INFERRED)
    return {sub: Fact(type_index, sub, "data_type", str(t), t, source, ("", 0)) for sub, t in layout.items()}
