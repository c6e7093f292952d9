"""What the CANopenNode v4 stack needs to know about an object beyond CiA 301.

CANopenEditor keeps these as `<property name="CO_...">` elements in its XDD/XPD
projects, and CANopenNode EDS exports keep the storage group as a
`;StorageLocation=` comment. Sources fill this in when the file says it; the
CANopenNode target infers what is missing (and says so).
"""

from __future__ import annotations

import re
from enum import StrEnum
from typing import Any, NamedTuple, Protocol

from pydantic import BaseModel, ConfigDict

# cia301.objects imports nothing: this module, which model/__init__ loads first, may use it without a cycle.
from .cia301.objects import (
    COB_ID_EMCY,
    COB_ID_SYNC,
    COB_ID_TIME,
    COMM_BASE,
    COMM_CYCLE_PERIOD,
    COMMUNICATION_AREA,
    CONSUMER_HEARTBEAT,
    DEVICE_TYPE,
    ERROR_HISTORY,
    ERROR_REGISTER,
    FIRST_SDO_SERVER,
    GLOBAL_FAILSAFE_COMMAND,
    GUARD_TIME,
    HIGH_RESOLUTION_TIME_STAMP,
    INHIBIT_TIME_EMCY,
    LIFE_TIME_FACTOR,
    MANUFACTURER_STATUS,
    MAP_BASE,
    PDO_SPAN,
    PRODUCER_HEARTBEAT,
    RESTORE_DEFAULTS,
    RPDO_COMM,
    RX,
    SDO_CLIENTS,
    SDO_SERVERS,
    SRDO_COMM,
    SRDO_CONFIGURATION_VALID,
    SRDO_CRC,
    SRDO_MAP_OFFSET,
    STORE_PARAMETERS,
    SYNC_COUNTER_OVERFLOW,
    SYNC_WINDOW_LENGTH,
    TPDO_COMM,
    TX,
)
from .datatypes import DOMAIN, DataType, ValueKind


# What the profile's functions read of an entry, an object and a device: the model's classes have it, and this module,
# which model/objects.py imports for CanopenNodeInfo, need not import them back.
class Mappable(Protocol):
    @property
    def access(self) -> StrEnum | None: ...

    @property
    def stated_pdo_mapping(self) -> str | None: ...

    @property
    def pdo_mapping(self) -> bool | None: ...

    def pdo_mapping_kind(self) -> str | None: ...


class Typed(Protocol):
    @property
    def data_type(self) -> int | None: ...


class Owner(Typed, Protocol):
    @property
    def kind(self) -> int: ...

    @property
    def dtype(self) -> DataType | None: ...


class Types(Protocol):
    def entry_type(self, var: Any, obj: Any) -> DataType | None: ...


class SrdoAccess(StrEnum):
    """CO_accessSRDO: whether an entry may be mapped into an SRDO, and which way."""

    NO = "no"
    TX = "tx"
    RX = "rx"
    TRX = "trx"


class CanopenNodeInfo(BaseModel):
    """CANopenNode metadata of an object (storage, count label, flags) or a sub-object (SRDO, string length).

    Every field is None when the source does not state it.
    """

    model_config = ConfigDict(defer_build=True)

    storage_group: str | None = None
    """CO_storageGroup / ;StorageLocation=: the storage-group struct the value lives in (RAM, PERSIST_COMM...)."""
    count_label: str | None = None
    """CO_countLabel: the OD_CNT_<label> macro this object counts towards (NMT, EM, SDO_SRV, TPDO...)."""
    disabled: bool | None = None
    """CO_disabled: the object is kept in the project but left out of the generated OD."""
    flags_pdo: bool | None = None
    """CO_flagsPDO: the stack keeps per-sub-index TPDO request flags for this object."""
    access_srdo: SrdoAccess | None = None
    """CO_accessSRDO, per entry."""
    string_length_min: int | None = None
    """CO_stringLengthMin, per entry: bytes reserved for a string or octet string, at least its default's length."""

    def is_empty(self) -> bool:
        return all(value is None for value in self.__dict__.values())


def _one(index: int) -> range:
    return range(index, index + 1)


# The OD_CNT_<label> macros the stack counts, by the index ranges of CiA 301/304 that hold their objects
# (CANopen.c checks them with #error and sizes its object arrays from them).
_COUNT_RANGES: tuple[tuple[range, str], ...] = (
    (_one(DEVICE_TYPE), "NMT"),
    (_one(ERROR_REGISTER), "EM"),
    (_one(COB_ID_SYNC), "SYNC"),
    (_one(COMM_CYCLE_PERIOD), "SYNC_PROD"),
    (_one(STORE_PARAMETERS), "STORAGE"),
    (_one(COB_ID_TIME), "TIME"),
    (_one(COB_ID_EMCY), "EM_PROD"),
    (_one(CONSUMER_HEARTBEAT), "HB_CONS"),
    (_one(PRODUCER_HEARTBEAT), "HB_PROD"),
    (SDO_SERVERS, "SDO_SRV"),
    (SDO_CLIENTS, "SDO_CLI"),
    (_one(GLOBAL_FAILSAFE_COMMAND), "GFC"),
    (SRDO_COMM, "SRDO"),
    (RPDO_COMM, "RPDO"),
    (TPDO_COMM, "TPDO"),
)

# Communication-area objects whose values are states or commands, not configuration: kept in RAM.
_RAM_IN_COMM_AREA = frozenset(
    {ERROR_REGISTER, MANUFACTURER_STATUS, ERROR_HISTORY, STORE_PARAMETERS, RESTORE_DEFAULTS,
     HIGH_RESOLUTION_TIME_STAMP, FIRST_SDO_SERVER}
)  # fmt: skip

RAM = "RAM"
PERSIST_COMM = "PERSIST_COMM"


def standard_count_label(index: int) -> str | None:
    """The count label the stack expects on the object at `index`, or None when it counts no object there."""
    for area, label in _COUNT_RANGES:
        if index in area:
            return label
    return None


def standard_storage_group(index: int) -> str:
    """The storage group for an object with none stated: communication parameters persist, the rest is RAM."""
    if index in COMMUNICATION_AREA and index not in _RAM_IN_COMM_AREA:
        return PERSIST_COMM
    return RAM


def count_label_for(index: int, info: CanopenNodeInfo | None) -> str | None:
    """The object's count label: the stated one ("" for none), else the standard one for its index."""
    if info is not None and info.count_label is not None:
        return info.count_label or None
    return standard_count_label(index)


# Limits CANopen.c checks with #error (or that its init loops rely on): label → (least, most). The
# stack allows as many SDOs, PDOs and SRDOs as their index ranges hold.
COUNT_LIMITS: dict[str, tuple[int, int]] = {
    "NMT": (1, 1),
    "EM": (1, 1),
    "HB_PROD": (1, 1),
    "EM_PROD": (1, 1),
    "HB_CONS": (0, 1),
    "SYNC": (0, 1),
    "SYNC_PROD": (0, 1),
    "TIME": (0, 1),
    "GFC": (0, 1),
    "STORAGE": (0, 1),
    "SDO_SRV": (1, len(SDO_SERVERS)),
    "SDO_CLI": (0, len(SDO_CLIENTS)),
    "RPDO": (0, PDO_SPAN),
    "TPDO": (0, PDO_SPAN),
    "SRDO": (0, len(SRDO_COMM)),
}

# Counts CANopen.c needs, each with the object that usually carries it (CO_CANopenInit uses them).
REQUIRED_COUNTS: tuple[tuple[str, int], ...] = (
    ("NMT", DEVICE_TYPE), ("EM", ERROR_REGISTER), ("EM_PROD", COB_ID_EMCY), ("HB_CONS", CONSUMER_HEARTBEAT),
    ("HB_PROD", PRODUCER_HEARTBEAT),
)  # fmt: skip
# Objects the stack uses beside a counted one: label → the indices it then reads too.
COMPANIONS: tuple[tuple[str, tuple[int, ...]], ...] = (
    ("EM", (ERROR_HISTORY,)), ("SYNC", (COMM_CYCLE_PERIOD,)), ("SRDO", (SRDO_CONFIGURATION_VALID, SRDO_CRC)),
)  # fmt: skip

# Objects the stack's init walks by position from the first one: label → (first index, partner offset).
# RPDO i uses 1400h+i and 1600h+i, TPDO i 1800h+i and 1A00h+i, SRDO i 1301h+i and 1381h+i.
CONSECUTIVE: dict[str, tuple[int, int | None]] = {
    "SDO_SRV": (SDO_SERVERS[0], None),
    "SDO_CLI": (SDO_CLIENTS[0], None),
    "RPDO": (COMM_BASE[RX], MAP_BASE[RX] - COMM_BASE[RX]),
    "TPDO": (COMM_BASE[TX], MAP_BASE[TX] - COMM_BASE[TX]),
    "SRDO": (SRDO_COMM[0], SRDO_MAP_OFFSET),
}

# COB-IDs to which the stack adds the node-ID itself: only there is `$NODEID+n` stored as n harmlessly.
_NODEID_AREAS = (_one(COB_ID_EMCY), range(SDO_SERVERS[0], SDO_CLIENTS[-1] + 1), RPDO_COMM, TPDO_COMM)
NODEID_AREAS: tuple[tuple[int, int], ...] = tuple((area[0], area[-1]) for area in _NODEID_AREAS)

# Communication objects the stack extends with its own read/write functions (EM history, storage):
# like CANopenEditor, an entry of theirs without a default gets no memory.
_STACK_EXTENDED = frozenset({ERROR_HISTORY, STORE_PARAMETERS, RESTORE_DEFAULTS})

# The entries CO_config_t points at (NAME_INIT_CONFIG), in the order of its members: the stack looks them up.
CONFIG_ENTRIES = (
    PRODUCER_HEARTBEAT, CONSUMER_HEARTBEAT, GUARD_TIME, LIFE_TIME_FACTOR, ERROR_REGISTER, COB_ID_EMCY,
    INHIBIT_TIME_EMCY, ERROR_HISTORY, SDO_SERVERS[0], SDO_CLIENTS[0], COB_ID_TIME, COB_ID_SYNC, COMM_CYCLE_PERIOD,
    SYNC_WINDOW_LENGTH, SYNC_COUNTER_OVERFLOW, COMM_BASE[RX], MAP_BASE[RX], COMM_BASE[TX], MAP_BASE[TX],
    GLOBAL_FAILSAFE_COMMAND, SRDO_COMM[0], SRDO_COMM[0] + SRDO_MAP_OFFSET, SRDO_CONFIGURATION_VALID, SRDO_CRC,
)  # fmt: skip
# The arrays whose element count CO_config_t carries (CNT_ARR_1016, CNT_ARR_1003).
CONFIG_ARRAYS = (CONSUMER_HEARTBEAT, ERROR_HISTORY)


# The objects CO_CANopenInit reads through CO_config_t: the entries it names, and the SDO, PDO and SRDO objects
# it walks from the first one of each kind. OD_get_value fails on an entry without memory, and so does the init.
_READ_AT_INIT = frozenset(
    {*CONFIG_ENTRIES, *SDO_SERVERS, *SDO_CLIENTS, *RPDO_COMM, *TPDO_COMM, *SRDO_COMM,
     *(index + MAP_BASE[RX] - COMM_BASE[RX] for index in RPDO_COMM),
     *(index + MAP_BASE[TX] - COMM_BASE[TX] for index in TPDO_COMM),
     *(index + SRDO_MAP_OFFSET for index in SRDO_COMM)}
) - _STACK_EXTENDED  # fmt: skip


def stack_reads_at_init(index: int) -> bool:
    """Whether CO_CANopenInit reads the object's value from the OD: it then needs memory even without a default.

    Other communication objects (1000h, 1018h, 1029h, the program download objects 1F51h-1F57h...) the stack
    never reads; the application serves them, and without a default they get no memory, as in CANopenEditor."""
    return index in _READ_AT_INIT


# --- the stack's build configuration (301/CO_config.h) ---------------------------------------

# The flags of the CO_CONFIG_* switches that decide whether CANopen.c uses an object, as 301/CO_config.h
# defines them, and the stack's defaults of those switches (what a CO_driver_target.h that says nothing gets).
STACK_FLAGS: dict[str, int] = {
    "CO_CONFIG_EM_PRODUCER": 0x01, "CO_CONFIG_EM_PROD_CONFIGURABLE": 0x02, "CO_CONFIG_EM_PROD_INHIBIT": 0x04,
    "CO_CONFIG_EM_HISTORY": 0x08, "CO_CONFIG_EM_STATUS_BITS": 0x10, "CO_CONFIG_EM_CONSUMER": 0x20,
    "CO_CONFIG_HB_CONS_ENABLE": 0x01, "CO_CONFIG_SYNC_ENABLE": 0x01, "CO_CONFIG_SYNC_PRODUCER": 0x02,
    "CO_CONFIG_SRDO_ENABLE": 0x01,
}  # fmt: skip
STACK_DEFAULTS: dict[str, int] = {
    "CO_CONFIG_EM": 0x01 | 0x08, "CO_CONFIG_HB_CONS": 0x01, "CO_CONFIG_SYNC": 0x01 | 0x02, "CO_CONFIG_SRDO": 0,
}  # fmt: skip


class StackSwitch(NamedTuple):
    """One function of the stack that needs an object: `flag` set in `switch` turns it on."""

    switch: str  # CO_CONFIG_HB_CONS
    flag: str  # CO_CONFIG_HB_CONS_ENABLE

    def spelled(self) -> str:
        return f"{self.switch} & {self.flag}"


# Counts and companion objects CANopen.c needs only with a function on: label → the switch; for companions,
# the label of the counted object → the switch (1003h with the EM history, 1006h with SYNC, 13FEh/13FFh with SRDO).
SWITCHED_COUNTS: dict[str, StackSwitch] = {
    "EM_PROD": StackSwitch("CO_CONFIG_EM", "CO_CONFIG_EM_PRODUCER"),
    "HB_CONS": StackSwitch("CO_CONFIG_HB_CONS", "CO_CONFIG_HB_CONS_ENABLE"),
}
SWITCHED_COMPANIONS: dict[str, StackSwitch] = {
    "EM": StackSwitch("CO_CONFIG_EM", "CO_CONFIG_EM_HISTORY"),
    "SYNC": StackSwitch("CO_CONFIG_SYNC", "CO_CONFIG_SYNC_ENABLE"),
    "SRDO": StackSwitch("CO_CONFIG_SRDO", "CO_CONFIG_SRDO_ENABLE"),
}


class StackConfig(NamedTuple):
    """The build configuration a project declares: its CO_CONFIG_* values (the rest keep the stack's defaults).

    `declared` is False when the project said nothing: whether a switched function is on is then unknown.
    """

    switches: tuple[tuple[str, int], ...] = ()
    declared: bool = False
    editor_pdo: bool = False  # keep CANopenEditor's ODA_*PDO bits where ours differ on purpose
    sources: tuple[str, ...] = ()  # where it was declared, for messages

    def value(self, switch: str) -> int:
        return dict(self.switches).get(switch, STACK_DEFAULTS.get(switch, 0))

    def needs(self, need: StackSwitch) -> bool | None:
        """Whether the declared build uses the function; None when no configuration was declared."""
        if not self.declared:
            return None
        return bool(self.value(need.switch) & STACK_FLAGS[need.flag])


# --- PDO attributes ----------------------------------------------------------------------------


def sdo_directions(access: str | None) -> str:
    """The ODA_SDO_* bits of an access type: "R" (ro, const), "W" (wo), "RW" (rw, rwr, rww) or ""."""
    if access is None:
        return ""
    return {"ro": "R", "const": "R", "wo": "W"}.get(access, "RW")


def pdo_directions(word: str | None, access: str | None) -> str:
    """The ODA_*PDO bits ("T", "R", "TR" or "") CANopenEditor gives a PDOmapping word and an access type.

    An explicit direction (RPDO, or the access rww) wins, then TPDO (or rwr); optional and default
    allow both directions whatever the access; no allows none.
    """
    if word == "RPDO" or access == "rww":
        return "R"
    if word == "TPDO" or access == "rwr":
        return "T"
    return "TR" if word in ("optional", "default") else ""


def editor_pdo_word(stated: str | None, mappable: bool | None) -> str:
    """The PDOmapping word CANopenEditor reads: an XDD's own, else an EDS's PDOMapping=1 as optional."""
    return stated if stated is not None else ("optional" if mappable else "no")


def pdo_bits_pair(var: Mappable) -> tuple[str, str]:
    """An entry's ODA_*PDO directions, ours and CANopenEditor's.

    They differ only on an EDS's PDOMapping=1 on a ro/const or wo entry: CANopenEditor reads it as
    `optional` and allows both directions; CiA 301 maps a read-only entry into TPDOs only and a
    write-only one into RPDOs only, so we keep the direction the access allows (CANopenEditor's own
    EDS export writes ro with PDOMapping=1 for its TPDO-only entries).
    """
    access = var.access.value if var.access else None
    ours = pdo_directions(var.pdo_mapping_kind(), access)
    return ours, pdo_directions(editor_pdo_word(var.stated_pdo_mapping, var.pdo_mapping), access)


def editor_octets(text: str) -> bytes | None:
    """An OCTET_STRING default as CANopenEditor reads it: hex bytes of one or two digits between blanks ("0",
    "1 2 A"), which CiA 306's even-length hex does not cover; None when the text is not of that form."""
    tokens = text.split()
    if not tokens or not all(len(t) <= 2 and all(c in "0123456789abcdefABCDEF" for c in t) for t in tokens):
        return None
    return bytes(int(t, 16) for t in tokens)


_C_FLOAT = re.compile(r"[+-]?(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[fF]")


def editor_real(text: str) -> float | None:
    """A REAL default written as a C float literal ("0.0f"), which CANopenEditor copies into OD.c as it is."""
    stripped = text.strip()
    return float(stripped[:-1]) if _C_FLOAT.fullmatch(stripped) else None


def editor_integer(text: str) -> int | None:
    """An integer as CANopenEditor reads it where the file's own type did not say how (an ARRAY element with
    DataType 0, whose ARRAY gives the type): 0x hex (U and L dropped), a leading 0 octal, else decimal."""
    stripped = text.strip()
    if re.fullmatch(r"0[xX][0-9A-Fa-f]+[uUlL]*", stripped):
        return int(stripped.rstrip("uUlL"), 16)
    if re.fullmatch(r"0[0-7]+", stripped):
        return int(stripped, 8)
    return int(stripped) if re.fullmatch(r"-?\d+", stripped) else None


def editor_reads(dtype: DataType, text: str) -> bool:
    """Whether CANopenEditor takes a default that CiA 306 cannot read: any DOMAIN default (it ignores them),
    short hex octets of an OCTET_STRING (`0`, `1 2 A`), a C float literal of a REAL (`0.0f`), an integer of an
    entry typed only by its ARRAY."""
    if dtype.index == DOMAIN.index:
        return True
    if dtype.kind is ValueKind.OCTETS:
        return editor_octets(text) is not None
    if dtype.kind in (ValueKind.UNSIGNED, ValueKind.SIGNED):
        return editor_integer(text) is not None
    return dtype.kind is ValueKind.REAL and editor_real(text) is not None


def editor_entry_type(device: Types, var: Typed, obj: Owner) -> DataType | None:
    """The entry's type as CANopenEditor takes it: its own, else, for an ARRAY element whose DataType is 0 or
    missing, the ARRAY's (old CANopenEditor projects write `dataType="0000"` on the elements)."""
    dtype = device.entry_type(var, obj)
    if dtype is None and var is not obj and obj.kind == 0x8 and not var.data_type:
        return obj.dtype
    return dtype
