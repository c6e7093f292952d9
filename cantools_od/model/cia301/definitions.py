"""The standard objects as CiA 301 defines them in 1000h-1FFFh, and the CiA 302 objects real files carry.

For every object: its object type, and for each sub-index the data type, the access types the
standard allows, whether it may be mapped into a PDO, and the values it allows. Where the standard
leaves a choice (1017h is rw or ro, a COB-ID may be fixed), every choice is accepted; where it says
nothing, the entry says nothing (None).

Sources: CiA 301 v4.2 §7.5.2 (communication profile objects), CiA 302-2 (network management,
1F80h-1F89h), CiA 302-3 (configuration and program download, 1F22h, 1F25h, 1F50h-1F57h).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import Enum
from typing import NamedTuple

from ..datatypes import INDEX_BY_NAME, standard_type
from ..objects import AccessType, ObjectKind
from .objects import (
    COMM_BASE,
    DEVICE_TYPE,
    ERROR_REGISTER,
    FIRST_SDO_SERVER,
    IDENTITY,
    MAP_BASE,
    MAX_ENTRIES,
    PDO_SPAN,
    RX,
    SDO_CLIENTS,
    SDO_SERVERS,
    TX,
)

_A = AccessType
RO = frozenset({_A.RO, _A.CONST})
"""Read-only: `const` says the same and more (the value never changes)."""
RW = frozenset({_A.RW, _A.RWR, _A.RWW})
"""Read and write: rwr/rww only add a PDO direction."""
WO = frozenset({_A.WO})
RW_OR_RO = RW | RO
"""The standard lets the device choose (a fixed COB-ID, a fixed heartbeat time)."""
WRITABLE = RW | WO

_TYPE = INDEX_BY_NAME
BOOLEAN, INTEGER8, INTEGER16, INTEGER32 = _TYPE["BOOLEAN"], _TYPE["INTEGER8"], _TYPE["INTEGER16"], _TYPE["INTEGER32"]
UNSIGNED8, UNSIGNED16, UNSIGNED32 = _TYPE["UNSIGNED8"], _TYPE["UNSIGNED16"], _TYPE["UNSIGNED32"]
UNSIGNED64, VISIBLE_STRING, OCTET_STRING, DOMAIN = (
    _TYPE["UNSIGNED64"],
    _TYPE["VISIBLE_STRING"],
    _TYPE["OCTET_STRING"],
    _TYPE["DOMAIN"],
)


class Mapping(Enum):
    """What the standard says of mapping the entry into a PDO."""

    NO = "no"
    OPTIONAL = "optional"
    DEFAULT = "default"
    """A profile's predefined PDOs map it (CiA 402: 6040h into the first RPDO, 6041h into the first TPDO): the entry
    must be mappable, into RPDOs when the master writes it, into TPDOs when the device reports it."""


class Entry(NamedTuple):
    """One sub-index (sub-index 0 of a VAR) as the standard defines it."""

    name: str
    data_type: int | None
    access: frozenset[AccessType] | None = None
    mapping: Mapping = Mapping.NO
    values: tuple[tuple[int, int], ...] | None = None
    """The allowed values as inclusive ranges; None: any value of the data type."""
    usual: AccessType | None = None
    """The access type devices all but always give it (what the table importer assumes when a manual is
    silent); None where devices differ (COB-IDs, strings, PDO entries)."""
    eds_name: str | None = None
    """The ParameterName EDS files commonly give it, where that differs from the standard's name."""
    peer_types: frozenset[int] = frozenset()
    """Data types the peer tools give the entry instead of the standard's, which a file may follow: the
    standard and its peers disagree, so a file agreeing with the peers is not at fault."""


@dataclass(frozen=True)
class Definition:
    """An object, or a range of objects of one kind (SDO servers, PDOs), as its standard defines it."""

    index: int
    name: str
    kind: ObjectKind
    clause: str
    """Where the standard defines it, for messages: "CiA 301 §7.5.2"."""
    subs: tuple[Entry, ...]
    """Sub-index 0, 1, ... as far as the standard names them; a VAR or DOMAIN has its one entry here."""
    rest: Entry | None = None
    """The entry every further sub-index up to `rest_until` has (the elements of an ARRAY)."""
    last: int = -1
    """The last index of a range of like objects; -1: `index` alone."""
    kinds: frozenset[ObjectKind] = field(default_factory=frozenset)
    """Object types the standard accepts besides `kind` (a VAR of DataType DOMAIN for a DOMAIN)."""
    rest_until: int = 0xFE
    eds_name: str | None = None
    """The ParameterName EDS files commonly give it, where that differs from the standard's name."""

    @property
    def indices(self) -> range:
        return range(self.index, max(self.index, self.last) + 1)

    def accepts(self, kind: ObjectKind) -> bool:
        return kind is self.kind or kind in self.kinds

    def entry(self, subindex: int) -> Entry | None:
        if subindex < len(self.subs):
            return self.subs[subindex]
        return self.rest if subindex <= self.rest_until else None


CIA301 = "CiA 301 §7.5.2"
CIA302_2 = "CiA 302-2"
CIA302_3 = "CiA 302-3"


def count_entry(
    name: str = "Highest sub-index supported", access: frozenset[AccessType] = RO, *values: int,
    usual: AccessType | None = AccessType.RO,
) -> Entry:  # fmt: skip
    ranges = ((values[0], values[1]),) if values else None
    return Entry(name, UNSIGNED8, access, values=ranges, usual=usual)


def var(
    index: int, name: str, data_type: int, access: frozenset[AccessType], mapping: Mapping = Mapping.NO,
    clause: str = CIA301, values: tuple[tuple[int, int], ...] | None = None, usual: AccessType | None = None,
    eds_name: str | None = None, peer_types: frozenset[int] = frozenset(),
) -> Definition:  # fmt: skip
    entry = Entry(name, data_type, access, mapping, values, usual, eds_name, peer_types)
    return Definition(index, name, ObjectKind.VAR, clause, (entry,), eds_name=eds_name)


def array(
    index: int, name: str, element: Entry, count: Entry | None = None, clause: str = CIA301, last: int = -1,
    named: tuple[Entry, ...] = (), eds_name: str | None = None, until: int = 0xFE,
) -> Definition:  # fmt: skip
    """An ARRAY: sub-index 0 counts the elements, which all have one data type (the first may be named); the
    standard defines the elements up to sub-index `until`."""
    subs = (count or count_entry(), *named)
    return Definition(index, name, ObjectKind.ARRAY, clause, subs, element, last, rest_until=until, eds_name=eds_name)


def record(
    index: int, name: str, *subs: Entry, clause: str = CIA301, last: int = -1, rest: Entry | None = None,
    rest_until: int = 0xFE,
) -> Definition:  # fmt: skip
    """A RECORD: sub-index 0 counts its entries, each of its own data type."""
    return Definition(index, name, ObjectKind.RECORD, clause, subs, rest, last, rest_until=rest_until)


PDO_COMM_SUBS = (
    count_entry("Highest sub-index supported", RO, 2, 6),
    Entry("COB-ID", UNSIGNED32, RW_OR_RO, eds_name="COB-ID used by PDO"),
    Entry("Transmission type", UNSIGNED8, RW_OR_RO),
    Entry("Inhibit time", UNSIGNED16, RW_OR_RO),
    Entry("Compatibility entry", UNSIGNED8, RW_OR_RO),
    Entry("Event timer", UNSIGNED16, RW_OR_RO),
    Entry("SYNC start value", UNSIGNED8, RW_OR_RO),
)


def _last(base: int) -> int:
    return base + PDO_SPAN - 1


_PDO_MAP_COUNT = Entry("Number of mapped objects", UNSIGNED8, RW_OR_RO, values=((0, MAX_ENTRIES),))
_PDO_MAP_ENTRY = Entry("Mapped object", UNSIGNED32, RW_OR_RO, eds_name="Application object")
_SDO = (  # mappable, so that an SDO manager can set up connections (CiA 302-5)
    Entry("COB-ID client to server", UNSIGNED32, RW_OR_RO, Mapping.OPTIONAL),
    Entry("COB-ID server to client", UNSIGNED32, RW_OR_RO, Mapping.OPTIONAL),
)
_OS = (
    count_entry("Highest sub-index supported", RO),
    Entry("Command", OCTET_STRING, WRITABLE),
    Entry("Status", UNSIGNED8, RO),
    Entry("Reply", OCTET_STRING, RO),
)
_O = Mapping.OPTIONAL

DEFINITIONS: tuple[Definition, ...] = (
    var(DEVICE_TYPE, "Device type", UNSIGNED32, RO, usual=_A.RO),
    var(ERROR_REGISTER, "Error register", UNSIGNED8, RO, _O, usual=_A.RO),
    var(0x1002, "Manufacturer status register", UNSIGNED32, RO, _O, usual=_A.RO),
    array(0x1003, "Pre-defined error field", Entry("Standard error field", UNSIGNED32, RO, usual=_A.RO),
          count_entry("Number of errors", RW, 0, 0xFE, usual=_A.RW)),
    var(0x1005, "COB-ID SYNC message", UNSIGNED32, RW_OR_RO, eds_name="COB-ID SYNC"),
    var(0x1006, "Communication cycle period", UNSIGNED32, RW_OR_RO, usual=_A.RW),
    var(0x1007, "Synchronous window length", UNSIGNED32, RW_OR_RO, usual=_A.RW),
    var(0x1008, "Manufacturer device name", VISIBLE_STRING, RO),
    var(0x1009, "Manufacturer hardware version", VISIBLE_STRING, RO),
    var(0x100A, "Manufacturer software version", VISIBLE_STRING, RO),
    var(0x100C, "Guard time", UNSIGNED16, RW_OR_RO, usual=_A.RW),
    var(0x100D, "Life time factor", UNSIGNED8, RW_OR_RO, usual=_A.RW),
    array(0x1010, "Store parameters", Entry("Save parameters", UNSIGNED32, RW_OR_RO, usual=_A.RW, eds_name="Save"),
          count_entry("Highest sub-index supported", RO, 1, 0x7F)),
    array(0x1011, "Restore default parameters",
          Entry("Restore parameters", UNSIGNED32, RW_OR_RO, usual=_A.RW, eds_name="Restore"),
          count_entry("Highest sub-index supported", RO, 1, 0x7F)),
    var(0x1012, "COB-ID time stamp object", UNSIGNED32, RW_OR_RO, eds_name="COB-ID TIME"),
    var(0x1013, "High resolution time stamp", UNSIGNED32, RW_OR_RO, _O, usual=_A.RW),
    var(0x1014, "COB-ID EMCY", UNSIGNED32, RW_OR_RO),
    var(0x1015, "Inhibit time EMCY", UNSIGNED16, RW_OR_RO, usual=_A.RW),
    array(0x1016, "Consumer heartbeat time", Entry("Consumer heartbeat time", UNSIGNED32, RW_OR_RO, usual=_A.RW),
          count_entry("Highest sub-index supported", RO, 1, 0x7F)),
    var(0x1017, "Producer heartbeat time", UNSIGNED16, RW_OR_RO, usual=_A.RW),
    record(IDENTITY, "Identity object", count_entry("Highest sub-index supported", RO, 1, 4),
           Entry("Vendor-ID", UNSIGNED32, RO, usual=_A.RO), Entry("Product code", UNSIGNED32, RO, usual=_A.RO),
           Entry("Revision number", UNSIGNED32, RO, usual=_A.RO), Entry("Serial number", UNSIGNED32, RO, usual=_A.RO)),
    var(0x1019, "Synchronous counter overflow value", UNSIGNED8, RW_OR_RO, values=((0, 0), (2, 240)), usual=_A.RW),
    array(0x1020, "Verify configuration", Entry("Configuration", UNSIGNED32, RW_OR_RO),
          count_entry("Highest sub-index supported", RO, 2, 2),
          named=(Entry("Configuration date", UNSIGNED32, RW_OR_RO), Entry("Configuration time", UNSIGNED32, RW_OR_RO))),
    Definition(0x1021, "Store EDS", ObjectKind.DOMAIN, CIA301, (Entry("Store EDS", DOMAIN, RW_OR_RO),),
               kinds=frozenset({ObjectKind.VAR})),
    # CiA 301 gives UNSIGNED8; CANopenEditor's profile (every CANopenNode project), objdictgen and kacanopen
    # define UNSIGNED16.
    var(0x1022, "Store format", UNSIGNED8, RW_OR_RO, peer_types=frozenset({UNSIGNED16})),
    record(0x1023, "OS command", *_OS),
    var(0x1024, "OS command mode", UNSIGNED8, WO),
    record(0x1025, "OS debugger interface", *_OS),
    array(0x1026, "OS prompt", Entry("OS prompt", UNSIGNED8, None, _O),
          count_entry("Highest sub-index supported", RO, 3, 3),
          named=(Entry("StdIn", UNSIGNED8, WRITABLE, _O), Entry("StdOut", UNSIGNED8, RO, _O),
                 Entry("StdErr", UNSIGNED8, RO, _O))),
    array(0x1027, "Module list", Entry("Module", UNSIGNED16, RO), count_entry("Number of connected modules", RO)),
    array(0x1028, "Emergency consumer object", Entry("Emergency consumer", UNSIGNED32, RW_OR_RO)),
    array(0x1029, "Error behavior object", Entry("Error class", UNSIGNED8, RW_OR_RO, usual=_A.RW),
          eds_name="Error behavior"),
    var(0x102A, "NMT inhibit time", UNSIGNED16, RW_OR_RO),
    record(SDO_SERVERS[0], "SDO server parameter", count_entry("Highest sub-index supported", RO, 2, 3), *_SDO,
           Entry("Node-ID of the SDO client", UNSIGNED8, RW_OR_RO, Mapping.OPTIONAL), last=SDO_SERVERS[-1]),
    record(SDO_CLIENTS[0], "SDO client parameter", count_entry("Highest sub-index supported", RO, 2, 3), *_SDO,
           Entry("Node-ID of the SDO server", UNSIGNED8, RW_OR_RO, Mapping.OPTIONAL), last=SDO_CLIENTS[-1]),
    record(COMM_BASE[RX], "RPDO communication parameter", *PDO_COMM_SUBS, last=_last(COMM_BASE[RX])),
    record(MAP_BASE[RX], "RPDO mapping parameter", _PDO_MAP_COUNT, last=_last(MAP_BASE[RX]), rest=_PDO_MAP_ENTRY,
           rest_until=MAX_ENTRIES),
    record(COMM_BASE[TX], "TPDO communication parameter", *PDO_COMM_SUBS, last=_last(COMM_BASE[TX])),
    record(MAP_BASE[TX], "TPDO mapping parameter", _PDO_MAP_COUNT, last=_last(MAP_BASE[TX]), rest=_PDO_MAP_ENTRY,
           rest_until=MAX_ENTRIES),
    array(0x1F22, "Concise DCF", Entry("Concise DCF", DOMAIN, RW_OR_RO), clause=CIA302_3),
    array(0x1F25, "Configure slave", Entry("Configure slave", None, WRITABLE), clause=CIA302_3),
    array(0x1F50, "Program data", Entry("Program", DOMAIN, WRITABLE), clause=CIA302_3),
    array(0x1F51, "Program control", Entry("Program control", UNSIGNED8, RW_OR_RO), clause=CIA302_3),
    array(0x1F55, "Expected software identification", Entry("Software identification", UNSIGNED32, RW_OR_RO),
          clause=CIA302_3),
    array(0x1F56, "Program software identification", Entry("Software identification", UNSIGNED32, RO),
          clause=CIA302_3),
    array(0x1F57, "Flash status identification", Entry("Flash status", UNSIGNED32, RO), clause=CIA302_3),
    var(0x1F80, "NMT startup", UNSIGNED32, RW_OR_RO, clause=CIA302_2),
    array(0x1F81, "NMT slave assignment", Entry("Slave assignment", UNSIGNED32, RW_OR_RO), clause=CIA302_2),
    array(0x1F82, "Request NMT", Entry("Request NMT", UNSIGNED8, RW_OR_RO), clause=CIA302_2),
    array(0x1F84, "Device type identification", Entry("Device type", UNSIGNED32, RW_OR_RO), clause=CIA302_2),
    array(0x1F85, "Vendor identification", Entry("Vendor-ID", UNSIGNED32, RW_OR_RO), clause=CIA302_2),
    array(0x1F86, "Product code", Entry("Product code", UNSIGNED32, RW_OR_RO), clause=CIA302_2),
    array(0x1F87, "Revision number", Entry("Revision number", UNSIGNED32, RW_OR_RO), clause=CIA302_2),
    array(0x1F88, "Serial number", Entry("Serial number", UNSIGNED32, RW_OR_RO), clause=CIA302_2),
    var(0x1F89, "Boot time", UNSIGNED32, RW_OR_RO, clause=CIA302_2),
    array(0x1F8A, "Restore configuration", Entry("Restore configuration", None, RW_OR_RO), clause=CIA302_3),
    array(0x1FA0, "Object scanner list", Entry("Scan", UNSIGNED32, RW_OR_RO), last=0x1FCF),
    array(0x1FD0, "Object dispatching list", Entry("Dispatch", UNSIGNED64, RW_OR_RO), last=0x1FFF),
)  # fmt: skip

NOT_STANDARD = {
    0x100B: "Node-ID in DS 301 v3; reserved since CiA 301 v4",
    0x11F0: "in the reserved area between 1030h and 11FFh (a vendor's network configuration)",
    0x1F5F: "not defined by CiA 302-3 (a vendor's program download record)",
}
"""Indices in 1000h-1FFFh that real files use but neither CiA 301 nor CiA 302 defines: not checked."""

_BY_INDEX = {index: definition for definition in DEFINITIONS for index in definition.indices}


def definition(index: int) -> Definition | None:
    """The standard's definition of the object at `index` in 1000h-1FFFh, if it defines one."""
    return _BY_INDEX.get(index)


# The record data types CiA 301 defines at 0020h-0023h, each by the object whose layout it is.
_RECORD_TYPE_OBJECTS = {
    "PDO_COMMUNICATION_PARAMETER": COMM_BASE[RX],
    "PDO_MAPPING": MAP_BASE[RX],
    "SDO_PARAMETER": FIRST_SDO_SERVER,
    "IDENTITY": IDENTITY,
}


def record_type_layout(type_index: int) -> dict[int, int] | None:
    """Sub-index -> data type of a standard record data type (PDO_MAPPING, IDENTITY...), else None."""
    dtype = standard_type(type_index)
    index = _RECORD_TYPE_OBJECTS.get(dtype.name) if dtype is not None else None
    found = definition(index) if index is not None else None
    if found is None:
        return None
    subs = range(len(found.subs)) if found.rest is None else range(found.rest_until + 1)
    entries = ((sub, found.entry(sub)) for sub in subs)
    return {sub: entry.data_type for sub, entry in entries if entry is not None and entry.data_type is not None}
