"""The CiA 402 drive profile objects of the first logical device (6000h-67FFh), in the table form of
`definitions`: applied to a device whose 1000h says device profile 402.

Source: CiA 402-2 (IEC 61800-7-201), the object dictionary of the drive profile. Access: the
values a drive measures or reports are read-only (6041h statusword, 6061h, 6064h, 606Ch, 6077h,
...); the commands a master writes are read-write (6040h controlword, 6060h, 607Ah, 60FFh,
6071h); a parameter may be read-write or made read-only by the drive, but never write-only.
PDO mapping is left open: the profile lets a drive map almost every process value.

CiA 301 gives each logical device 800h objects from 6000h; a further logical device's device type
is its object 67FFh + n x 800h (the first one's is 1000h).
"""

from __future__ import annotations

from ..objects import AccessType, ObjectKind
from .definitions import (
    INTEGER8,
    INTEGER16,
    INTEGER32,
    RO,
    RW,
    RW_OR_RO,
    UNSIGNED8,
    UNSIGNED16,
    UNSIGNED32,
    Definition,
    Entry,
    Mapping,
    array,
    count_entry,
    record,
)

PROFILE = 402
CLAUSE = "CiA 402-2"
AREA = range(0x6000, 0x6800)  # the first logical device's profile objects
LOGICAL_DEVICE_SPAN = 0x800
LOGICAL_DEVICES = 8  # 6000h-9FFFh
DEVICE_TYPE_OFFSET = 0x7FF  # a logical device's own device type: its last object (67FFh, 6FFFh, ...)
MEASURED = frozenset({0x603F, 0x6041, 0x6061, 0x6062, 0x6063, 0x6064, 0x606B, 0x606C, 0x6074, 0x6077, 0x6078, 0x6079,
                      0x60F4, 0x60FC, 0x60FD, 0x6502})  # fmt: skip
"""Read-only: what the drive reports."""
COMMANDS = frozenset({0x6040, 0x6060, 0x6071, 0x607A, 0x60FF})
"""Read-write: what the master commands."""
# The profile's record data types (of 60C2h and of 60C4h).
INTERPOLATION_TIME_PERIOD_TYPE, INTERPOLATION_DATA_CONFIGURATION_TYPE = 0x0080, 0x0081
_O = Mapping.OPTIONAL


def _access(index: int) -> frozenset[AccessType]:
    """What the profile lets the object's entries be: never write-only."""
    return RO if index in MEASURED else RW if index in COMMANDS else RW_OR_RO


def _var(index: int, name: str, data_type: int) -> Definition:
    # Drives map almost every process value, and the profile allows it: mapping is left open.
    return Definition(index, name, ObjectKind.VAR, CLAUSE, (Entry(name, data_type, _access(index), _O),))


def _array(index: int, name: str, data_type: int) -> Definition:
    # Every ARRAY of the profile has two elements (a range's ends, a ratio's two numbers, two homing speeds):
    # a further sub-index is the vendor's, of the vendor's type.
    count = count_entry("Highest sub-index supported", RO)
    return array(index, name, Entry(name, data_type, RW_OR_RO, _O), count, CLAUSE, until=2)


DEFINITIONS: tuple[Definition, ...] = (
    _var(0x6007, "Abort connection option code", INTEGER16),
    _var(0x603F, "Error code", UNSIGNED16),
    _var(0x6040, "Controlword", UNSIGNED16),
    _var(0x6041, "Statusword", UNSIGNED16),
    _var(0x605A, "Quick stop option code", INTEGER16),
    _var(0x605B, "Shutdown option code", INTEGER16),
    _var(0x605C, "Disable operation option code", INTEGER16),
    _var(0x605D, "Halt option code", INTEGER16),
    _var(0x605E, "Fault reaction option code", INTEGER16),
    _var(0x6060, "Modes of operation", INTEGER8),
    _var(0x6061, "Modes of operation display", INTEGER8),
    _var(0x6062, "Position demand value", INTEGER32),
    _var(0x6063, "Position actual internal value", INTEGER32),
    _var(0x6064, "Position actual value", INTEGER32),
    _var(0x6065, "Following error window", UNSIGNED32),
    _var(0x6066, "Following error time out", UNSIGNED16),
    _var(0x6067, "Position window", UNSIGNED32),
    _var(0x6068, "Position window time", UNSIGNED16),
    _var(0x606B, "Velocity demand value", INTEGER32),
    _var(0x606C, "Velocity actual value", INTEGER32),
    _var(0x606D, "Velocity window", UNSIGNED16),
    _var(0x606E, "Velocity window time", UNSIGNED16),
    _var(0x606F, "Velocity threshold", UNSIGNED16),
    _var(0x6070, "Velocity threshold time", UNSIGNED16),
    _var(0x6071, "Target torque", INTEGER16),
    _var(0x6072, "Max torque", UNSIGNED16),
    _var(0x6073, "Max current", UNSIGNED16),
    _var(0x6074, "Torque demand", INTEGER16),
    _var(0x6075, "Motor rated current", UNSIGNED32),
    _var(0x6076, "Motor rated torque", UNSIGNED32),
    _var(0x6077, "Torque actual value", INTEGER16),
    _var(0x6078, "Current actual value", INTEGER16),
    _var(0x6079, "DC link circuit voltage", UNSIGNED32),
    _var(0x607A, "Target position", INTEGER32),
    _array(0x607B, "Position range limit", INTEGER32),
    _var(0x607C, "Home offset", INTEGER32),
    _array(0x607D, "Software position limit", INTEGER32),
    _var(0x607E, "Polarity", UNSIGNED8),
    _var(0x607F, "Max profile velocity", UNSIGNED32),
    _var(0x6080, "Max motor speed", UNSIGNED32),
    _var(0x6081, "Profile velocity", UNSIGNED32),
    _var(0x6082, "End velocity", UNSIGNED32),
    _var(0x6083, "Profile acceleration", UNSIGNED32),
    _var(0x6084, "Profile deceleration", UNSIGNED32),
    _var(0x6085, "Quick stop deceleration", UNSIGNED32),
    _var(0x6086, "Motion profile type", INTEGER16),
    _var(0x6087, "Torque slope", UNSIGNED32),
    _var(0x6088, "Torque profile type", INTEGER16),
    _array(0x608F, "Position encoder resolution", UNSIGNED32),
    _array(0x6091, "Gear ratio", UNSIGNED32),
    _array(0x6092, "Feed constant", UNSIGNED32),
    _var(0x6098, "Homing method", INTEGER8),
    _array(0x6099, "Homing speeds", UNSIGNED32),
    _var(0x609A, "Homing acceleration", UNSIGNED32),
    _var(0x60B0, "Position offset", INTEGER32),
    _var(0x60B1, "Velocity offset", INTEGER32),
    _var(0x60B2, "Torque offset", INTEGER16),
    record(0x60C2, "Interpolation time period", count_entry("Highest sub-index supported", RO, 2, 2),
           Entry("Interpolation time period value", UNSIGNED8, RW_OR_RO, _O),
           Entry("Interpolation time index", INTEGER8, RW_OR_RO, _O), clause=CLAUSE),
    _var(0x60F4, "Following error actual value", INTEGER32),
    _var(0x60FC, "Position demand internal value", INTEGER32),
    _var(0x60FD, "Digital inputs", UNSIGNED32),
    _array(0x60FE, "Digital outputs", UNSIGNED32),
    _var(0x60FF, "Target velocity", INTEGER32),
    _var(0x6402, "Motor type", UNSIGNED16),
    _var(0x6502, "Supported drive modes", UNSIGNED32),
)  # fmt: skip

_BY_INDEX = {d.index: d for d in DEFINITIONS}


def definition(index: int) -> Definition | None:
    """The profile's definition of the object at `index` of the first logical device, if it has one (a further
    logical device's objects: at `index` minus n x 800h)."""
    return _BY_INDEX.get(index)


def logical_device(index: int) -> int | None:
    """Which logical device (0: the first) the profile object at `index` belongs to; None outside 6000h-9FFFh."""
    offset = index - AREA.start
    if not 0 <= offset < LOGICAL_DEVICES * LOGICAL_DEVICE_SPAN:
        return None
    return offset // LOGICAL_DEVICE_SPAN


def device_type_object(device: int) -> int:
    """The object holding the device type of logical device `device` (0: the first)."""
    return AREA.start + device * LOGICAL_DEVICE_SPAN + DEVICE_TYPE_OFFSET


def device_profile(device_type: int) -> int:
    """The device profile number in the low 16 bits of 1000h."""
    return device_type & 0xFFFF
