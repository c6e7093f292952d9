"""What CiA 301 says about the communication objects, to fill gaps the manuals leave.

Values taken from here are *inferred*: they are used only where no source says anything,
never conflict with a source, and are listed as inferred in the report and the EDS."""

from __future__ import annotations

from dataclasses import dataclass, field

from ..model import AccessType, ObjectKind
from .entries import Kind
from .facts import Fact, Source

U8, U16, U32 = 0x05, 0x06, 0x07
RO, RW, CONST = AccessType.RO, AccessType.RW, AccessType.CONST


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


def _var(name: str, data_type: int, access: AccessType | None) -> StdObject:
    return StdObject(name, ObjectKind.VAR, {0: StdEntry(name, data_type, access)})


_HIGHEST = StdEntry("Highest sub-index supported", U8, RO)

_PDO_COMM = {
    0: _HIGHEST,
    1: StdEntry("COB-ID used by PDO", U32, None),
    2: StdEntry("Transmission type", U8, None),
    3: StdEntry("Inhibit time", U16, None),
    4: StdEntry("Compatibility entry", U8, None),
    5: StdEntry("Event timer", U16, None),
    6: StdEntry("SYNC start value", U8, None),
}
_PDO_MAP_ELEMENT = StdEntry("Application object", U32, None)
_SDO = {
    0: _HIGHEST,
    1: StdEntry("COB-ID client to server", U32, None),
    2: StdEntry("COB-ID server to client", U32, None),
    3: StdEntry("Node-ID of the SDO client", U8, None),
}

STANDARD_OBJECTS: dict[int, StdObject] = {
    0x1000: _var("Device type", U32, RO),
    0x1001: _var("Error register", U8, RO),
    0x1002: _var("Manufacturer status register", U32, RO),
    0x1003: StdObject(
        "Pre-defined error field",
        ObjectKind.ARRAY,
        {0: StdEntry("Number of errors", U8, RW)},
        StdEntry("Standard error field", U32, RO),
    ),
    0x1005: _var("COB-ID SYNC", U32, None),
    0x1006: _var("Communication cycle period", U32, RW),
    0x1007: _var("Synchronous window length", U32, RW),
    0x1008: _var("Manufacturer device name", 0x09, None),
    0x1009: _var("Manufacturer hardware version", 0x09, None),
    0x100A: _var("Manufacturer software version", 0x09, None),
    0x100C: _var("Guard time", U16, RW),
    0x100D: _var("Life time factor", U8, RW),
    0x1010: StdObject("Store parameters", ObjectKind.ARRAY, {0: _HIGHEST}, StdEntry("Save", U32, RW)),
    0x1011: StdObject("Restore default parameters", ObjectKind.ARRAY, {0: _HIGHEST}, StdEntry("Restore", U32, RW)),
    0x1012: _var("COB-ID TIME", U32, None),
    0x1013: _var("High resolution time stamp", U32, RW),
    0x1014: _var("COB-ID EMCY", U32, None),
    0x1015: _var("Inhibit time EMCY", U16, RW),
    0x1016: StdObject(
        "Consumer heartbeat time", ObjectKind.ARRAY, {0: _HIGHEST}, StdEntry("Consumer heartbeat time", U32, RW)
    ),
    0x1017: _var("Producer heartbeat time", U16, RW),
    0x1018: StdObject(
        "Identity object",
        ObjectKind.RECORD,
        {
            0: _HIGHEST,
            1: StdEntry("Vendor-ID", U32, RO),
            2: StdEntry("Product code", U32, RO),
            3: StdEntry("Revision number", U32, RO),
            4: StdEntry("Serial number", U32, RO),
        },
    ),
    0x1019: _var("Synchronous counter overflow value", U8, RW),
    0x1029: StdObject("Error behavior", ObjectKind.ARRAY, {0: _HIGHEST}, StdEntry("Error class", U8, RW)),
}
for _n in range(0x80):
    STANDARD_OBJECTS[0x1200 + _n] = StdObject("SDO server parameter", ObjectKind.RECORD, _SDO)
for _n in range(0x200):
    STANDARD_OBJECTS[0x1400 + _n] = StdObject("RPDO communication parameter", ObjectKind.RECORD, _PDO_COMM)
    STANDARD_OBJECTS[0x1800 + _n] = StdObject("TPDO communication parameter", ObjectKind.RECORD, _PDO_COMM)
    STANDARD_OBJECTS[0x1600 + _n] = StdObject(
        "RPDO mapping parameter",
        ObjectKind.RECORD,
        {0: StdEntry("Number of mapped objects", U8, None)},
        _PDO_MAP_ELEMENT,
    )
    STANDARD_OBJECTS[0x1A00 + _n] = StdObject(
        "TPDO mapping parameter",
        ObjectKind.RECORD,
        {0: StdEntry("Number of mapped objects", U8, None)},
        _PDO_MAP_ELEMENT,
    )

_RECORDS: dict[int, dict[int, int]] = {
    0x20: {0: U8, 1: U32, 2: U8, 3: U16, 4: U8, 5: U16, 6: U8},
    0x21: {0: U8, **{n: U32 for n in range(1, 0x41)}},
    0x22: {0: U8, 1: U32, 2: U32, 3: U8},
    0x23: {0: U8, 1: U32, 2: U32, 3: U32, 4: U32},
}


def record_layout(type_index: int) -> dict[int, Fact] | None:
    """CiA 301's definition of a standard record type, as inferred facts."""
    layout = _RECORDS.get(type_index)
    if layout is None:
        return None
    source = Source("CiA 301", 0, f"record {type_index:04X}h", Kind.INFERRED)
    return {sub: Fact(type_index, sub, "data_type", str(t), t, source, ("", 0)) for sub, t in layout.items()}
