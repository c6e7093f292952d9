"""SDO abort codes (CiA 301 §7.2.4.3.17): what a server answers when it cannot do a transfer.

Both ends of a live bus use this table: `simulate` answers with these codes, `probe` reads them.
"""

from __future__ import annotations

ABORT_TRANSFER = 0x80  # the command byte of an abort frame (ccs/scs 4)

TIMEOUT = 0x05040000
UNSUPPORTED_ACCESS = 0x06010000
WRITE_ONLY = 0x06010001  # a read of a write-only object
READ_ONLY = 0x06010002  # a write of a read-only object
NO_OBJECT = 0x06020000
NOT_MAPPABLE = 0x06040041
PDO_TOO_LONG = 0x06040042
LENGTH_MISMATCH = 0x06070010
LENGTH_TOO_HIGH = 0x06070012
LENGTH_TOO_LOW = 0x06070013
NO_SUB_INDEX = 0x06090011
INVALID_VALUE = 0x06090030
VALUE_TOO_HIGH = 0x06090031
VALUE_TOO_LOW = 0x06090032
GENERAL_ERROR = 0x08000000
CANNOT_STORE = 0x08000020
CANNOT_STORE_LOCAL = 0x08000021
CANNOT_STORE_STATE = 0x08000022
NO_DATA = 0x08000024

MEANING = {
    TIMEOUT: "SDO protocol timed out",
    UNSUPPORTED_ACCESS: "unsupported access to an object",
    WRITE_ONLY: "attempt to read a write only object",
    READ_ONLY: "attempt to write a read only object",
    NO_OBJECT: "object does not exist in the object dictionary",
    NOT_MAPPABLE: "object cannot be mapped to the PDO",
    PDO_TOO_LONG: "the mapped objects would exceed the PDO length",
    LENGTH_MISMATCH: "data type does not match, length of service parameter does not match",
    LENGTH_TOO_HIGH: "data type does not match, length of service parameter too high",
    LENGTH_TOO_LOW: "data type does not match, length of service parameter too low",
    NO_SUB_INDEX: "sub-index does not exist",
    INVALID_VALUE: "invalid value for parameter",
    VALUE_TOO_HIGH: "value of parameter written too high",
    VALUE_TOO_LOW: "value of parameter written too low",
    GENERAL_ERROR: "general error",
    CANNOT_STORE: "data cannot be transferred or stored to the application",
    CANNOT_STORE_LOCAL: "data cannot be transferred or stored because of local control",
    CANNOT_STORE_STATE: "data cannot be transferred or stored because of the present device state",
    NO_DATA: "no data available",
}

MISSING = frozenset({NO_OBJECT, NO_SUB_INDEX})
LENGTH = frozenset({LENGTH_MISMATCH, LENGTH_TOO_HIGH, LENGTH_TOO_LOW})
ACCESS = frozenset({UNSUPPORTED_ACCESS, WRITE_ONLY, READ_ONLY})


def describe(code: int) -> str:
    """`0602 0000h (object does not exist in the object dictionary)`, as CiA 301 writes a code."""
    meaning = MEANING.get(code)
    written = f"{code >> 16:04X} {code & 0xFFFF:04X}h"
    return f"{written} ({meaning})" if meaning else written
