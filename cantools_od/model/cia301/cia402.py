"""The CiA 402 drive profile objects of the first logical device (6000h-67FFh), in the table form of
`definitions`: applied to a device whose 1000h says device profile 402.

Source: CiA 402-2 (IEC 61800-7-201), the object dictionary of the drive profile. Access: the
values a drive measures or reports are read-only (6041h statusword, 6061h, 6064h, 606Ch, 6077h,
...); the commands a master writes are read-write (6040h controlword, 6060h, 607Ah, 60FFh,
6071h); a parameter may be read-write or made read-only by the drive, but never write-only.
PDO mapping: the profile's predefined PDOs map the controlword into the first RPDO and the statusword into the
first TPDO (CiA 402-3), so a drive lets a master map both (Mapping.DEFAULT). Every other entry is left open:
drives map almost every process value, or none (a static mapping), and the profile lets them.
Data types: the objects of CiA 402-2 that drives still carry; the obsolete ones of the older DSP 402 (the notation
and dimension indices 6089h-608Eh, the factors 6093h-6095h), objects whose type depends on the mode (60C1h
interpolation data record) and ones real drives lay out otherwise (60E4h/60E5h, which some drives make a VAR; the
homing method list 60E3h, UNSIGNED8 in some) are left out, so nothing is claimed for them.

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
    VISIBLE_STRING,
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
MEASURED = frozenset({0x603F, 0x6041, 0x6043, 0x6044, 0x6061, 0x6062, 0x6063, 0x6064, 0x6069, 0x606B, 0x606C,
                      0x6074, 0x6077, 0x6078, 0x6079, 0x60B9, 0x60BA, 0x60BB, 0x60BC, 0x60BD, 0x60D5, 0x60D6,
                      0x60D7, 0x60D8, 0x60F4, 0x60FA, 0x60FC, 0x60FD, 0x6502})  # fmt: skip
"""Read-only: what the drive reports."""
COMMANDS = frozenset({0x6040, 0x6042, 0x6060, 0x6071, 0x607A, 0x60FF})
"""Read-write: what the master commands."""
# The profile's record data types (of 60C2h and of 60C4h).
INTERPOLATION_TIME_PERIOD_TYPE, INTERPOLATION_DATA_CONFIGURATION_TYPE = 0x0080, 0x0081
_O = Mapping.OPTIONAL
PREDEFINED_MAPPING = frozenset({0x6040, 0x6041})
"""Mapped by the profile's predefined PDOs (the first RPDO and TPDO): they must be mappable."""


def _access(index: int) -> frozenset[AccessType]:
    """What the profile lets the object's entries be: never write-only."""
    return RO if index in MEASURED else RW if index in COMMANDS else RW_OR_RO


def _var(index: int, name: str, data_type: int) -> Definition:
    # Drives map almost every process value, and the profile allows it: mapping is left open but for the two
    # objects the predefined PDOs map.
    mapping = Mapping.DEFAULT if index in PREDEFINED_MAPPING else _O
    return Definition(index, name, ObjectKind.VAR, CLAUSE, (Entry(name, data_type, _access(index), mapping),))


def _array(index: int, name: str, data_type: int) -> Definition:
    # Every ARRAY of the profile have two elements (a range's ends, a ratio's two numbers, two homing speeds):
    # a further sub-index is the vendor's, of the vendor's type.
    count = count_entry("Highest sub-index supported", RO)
    return array(index, name, Entry(name, data_type, _access(index), _O), count, CLAUSE, until=2)


def _ramp(index: int, name: str) -> Definition:
    """A velocity mode ramp (6048h, 6049h, 604Ah): a speed step and the time it takes."""
    return record(index, name, count_entry("Highest sub-index supported", RO),
                  Entry("Delta speed", UNSIGNED32, RW_OR_RO, _O), Entry("Delta time", UNSIGNED16, RW_OR_RO, _O),
                  clause=CLAUSE)  # fmt: skip


DEFINITIONS: tuple[Definition, ...] = (
    _var(0x6007, "Abort connection option code", INTEGER16),
    _var(0x603F, "Error code", UNSIGNED16),
    _var(0x6040, "Controlword", UNSIGNED16),
    _var(0x6041, "Statusword", UNSIGNED16),
    _var(0x6042, "vl target velocity", INTEGER16),
    _var(0x6043, "vl velocity demand", INTEGER16),
    _var(0x6044, "vl velocity actual value", INTEGER16),
    _array(0x6046, "vl velocity min max amount", UNSIGNED32),
    _ramp(0x6048, "vl velocity acceleration"),
    _ramp(0x6049, "vl velocity deceleration"),
    _ramp(0x604A, "vl velocity quick stop"),
    _array(0x604C, "vl dimension factor", INTEGER32),
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
    _var(0x6069, "Velocity sensor actual value", INTEGER32),
    _var(0x606A, "Sensor selection code", INTEGER16),
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
    _var(0x60A8, "SI unit position", UNSIGNED32),
    _var(0x60A9, "SI unit velocity", UNSIGNED32),
    _var(0x60AA, "SI unit acceleration", UNSIGNED32),
    _var(0x60AB, "SI unit jerk", UNSIGNED32),
    _var(0x60B0, "Position offset", INTEGER32),
    _var(0x60B1, "Velocity offset", INTEGER32),
    _var(0x60B2, "Torque offset", INTEGER16),
    _var(0x60B8, "Touch probe function", UNSIGNED16),
    _var(0x60B9, "Touch probe status", UNSIGNED16),
    _var(0x60BA, "Touch probe 1 positive edge", INTEGER32),
    _var(0x60BB, "Touch probe 1 negative edge", INTEGER32),
    _var(0x60BC, "Touch probe 2 positive edge", INTEGER32),
    _var(0x60BD, "Touch probe 2 negative edge", INTEGER32),
    _var(0x60C0, "Interpolation sub mode select", INTEGER16),
    record(0x60C2, "Interpolation time period", count_entry("Highest sub-index supported", RO, 2, 2),
           Entry("Interpolation time period value", UNSIGNED8, RW_OR_RO, _O),
           Entry("Interpolation time index", INTEGER8, RW_OR_RO, _O), clause=CLAUSE),
    # 60C4h: the buffer's size and organisation; the access of its entries differs by drive (sub-indices 5 and 6
    # are commands some drives make write-only), so only the types are the profile's.
    record(0x60C4, "Interpolation data configuration", count_entry("Highest sub-index supported", RO),
           Entry("Maximum buffer size", UNSIGNED32, mapping=_O), Entry("Actual buffer size", UNSIGNED32, mapping=_O),
           Entry("Buffer organization", UNSIGNED8, mapping=_O), Entry("Buffer position", UNSIGNED16, mapping=_O),
           Entry("Size of data record", UNSIGNED8, mapping=_O), Entry("Buffer clear", UNSIGNED8, mapping=_O),
           clause=CLAUSE),
    _var(0x60C5, "Max acceleration", UNSIGNED32),
    _var(0x60C6, "Max deceleration", UNSIGNED32),
    _var(0x60D5, "Touch probe 1 positive edge counter", UNSIGNED16),
    _var(0x60D6, "Touch probe 1 negative edge counter", UNSIGNED16),
    _var(0x60D7, "Touch probe 2 positive edge counter", UNSIGNED16),
    _var(0x60D8, "Touch probe 2 negative edge counter", UNSIGNED16),
    _var(0x60E0, "Positive torque limit value", UNSIGNED16),
    _var(0x60E1, "Negative torque limit value", UNSIGNED16),
    _var(0x60F2, "Positioning option code", UNSIGNED16),
    _var(0x60F4, "Following error actual value", INTEGER32),
    _var(0x60F8, "Max slippage", INTEGER32),
    _var(0x60FA, "Control effort", INTEGER32),
    _var(0x60FC, "Position demand internal value", INTEGER32),
    _var(0x60FD, "Digital inputs", UNSIGNED32),
    _array(0x60FE, "Digital outputs", UNSIGNED32),
    _var(0x60FF, "Target velocity", INTEGER32),
    _var(0x6402, "Motor type", UNSIGNED16),
    _var(0x6403, "Motor catalogue number", VISIBLE_STRING),
    _var(0x6404, "Motor manufacturer", VISIBLE_STRING),
    _var(0x6502, "Supported drive modes", UNSIGNED32),
    _var(0x6503, "Drive catalogue number", VISIBLE_STRING),
    _var(0x6504, "Drive manufacturer", VISIBLE_STRING),
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
