"""What the CANopenNode v4 stack needs of an object dictionary beyond CiA 301: count labels, storage groups, the
counts CANopen.c checks, the objects CO_CANopenInit reads, the build configuration (CO_CONFIG_*), and the C names
of its attributes and object types.
"""

from __future__ import annotations

from typing import NamedTuple

from ..model.cia301.cobid import BASE_11BIT, EXTENDED
from ..model.cia301.connections import predefined_cob_base

# model/cia301/objects.py imports nothing: model/objects.py, which takes CanopenNodeInfo from here, meets no cycle.
from ..model.cia301.objects import (
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
from .info import CanopenNodeInfo


def _one(index: int) -> range:
    return range(index, index + 1)


# The OD_CNT_<label> macros the stack counts, by the index ranges of CiA 301/304 that hold their objects
# (CANopen.c checks them with #error and sizes its object arrays from them).
HEARTBEAT_CONSUMERS = "HB_CONS"  # the label of 1016h, whose ARRAY size the heartbeat consumer takes
_COUNT_RANGES: tuple[tuple[range, str], ...] = (
    (_one(DEVICE_TYPE), "NMT"),
    (_one(ERROR_REGISTER), "EM"),
    (_one(COB_ID_SYNC), "SYNC"),
    (_one(COMM_CYCLE_PERIOD), "SYNC_PROD"),
    (_one(STORE_PARAMETERS), "STORAGE"),
    (_one(COB_ID_TIME), "TIME"),
    (_one(COB_ID_EMCY), "EM_PROD"),
    (_one(CONSUMER_HEARTBEAT), HEARTBEAT_CONSUMERS),
    (_one(PRODUCER_HEARTBEAT), "HB_PROD"),
    (SDO_SERVERS, "SDO_SRV"),
    (SDO_CLIENTS, "SDO_CLI"),
    (_one(GLOBAL_FAILSAFE_COMMAND), "GFC"),
    (SRDO_COMM, "SRDO"),
    (RPDO_COMM, "RPDO"),
    (TPDO_COMM, "TPDO"),
)

COUNT_LABELS = tuple(label for _, label in _COUNT_RANGES)

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


def stack_adds_node_id(index: int, subindex: int, value: int) -> bool:
    """Whether the CANopenNode stack reads a stored COB-ID as its pre-defined base + the node-ID, where other
    tools read it literally: a PDO 1-4 or EMCY COB-ID whose CAN-ID is the base itself (CO_PDO.c and
    CO_Emergency.c add the node-ID to a "default CAN-ID stored without node-ID"), or the first SDO server's,
    whose CAN-IDs the stack always makes 600h/580h + node-ID (CO_SDOserver.c)."""
    base = predefined_cob_base(index, subindex)
    return base is not None and (value & BASE_11BIT) == base and not value & EXTENDED


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

SWITCH_PREFIX = "CO_CONFIG_"  # the stack's build switches, as CO_driver_target.h sets them
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


# --- the C names of CO_ODinterface.h and CANopen.c ------------------------------------------------

COUNT_PREFIX = "OD_CNT_"  # OD_CNT_<label>: the number of objects counting towards a label
# CO_config_t members filled by OD_INIT_CONFIG: its count labels (CNT_<label>), in the order of its members.
CONFIG_COUNTS = ("NMT", "HB_CONS", "EM", "SDO_SRV", "SDO_CLI", "TIME", "SYNC", "RPDO", "TPDO", "LEDS",
                 "GFC", "SRDO", "LSS_SLV", "LSS_MST", "GTWA", "TRACE")  # fmt: skip
# The object types of OD_entry_t (ODT_*) with the struct of each one's description, by the view's kind.
OBJECT_TYPES = {"VAR": ("ODT_VAR", "OD_obj_var_t"), "ARR": ("ODT_ARR", "OD_obj_array_t"),
                "REC": ("ODT_REC", "OD_obj_record_t")}  # fmt: skip
# The OD attribute bits (ODA_*), by meaning: SDO, PDO and SRDO directions ("R", "W", "T", "TR"...), multi-byte, string.
ATTRIBUTE_PREFIX = "ODA_"
SDO_ATTRIBUTES = {"R": "ODA_SDO_R", "W": "ODA_SDO_W", "RW": "ODA_SDO_RW"}
PDO_ATTRIBUTES = {"T": "ODA_TPDO", "R": "ODA_RPDO", "TR": "ODA_TRPDO"}
SRDO_ATTRIBUTES = {"T": "ODA_TSRDO", "R": "ODA_RSRDO", "TR": "ODA_TRSRDO"}
MULTIBYTE_ATTRIBUTE = "ODA_MB"  # a 16/32/64-bit number the stack byte-swaps on big-endian targets
STRING_ATTRIBUTE = "ODA_STR"  # a shorter value may be written (VISIBLE_STRING, UNICODE_STRING)
# CO_accessSRDO's words (the overrides' access_srdo) as SRDO directions.
SRDO_DIRECTIONS = {"tx": "T", "rx": "R", "trx": "TR"}


def attribute_names(sdo: str, pdo: str, srdo: str, multibyte: bool, string: bool) -> list[str]:
    """The ODA_* names of an entry's attribute, in CANopenEditor's order (SDO, PDO, SRDO, MB, STR)."""
    names = [SDO_ATTRIBUTES[sdo]] if sdo else []
    names += [PDO_ATTRIBUTES[pdo]] if pdo else []
    names += [SRDO_ATTRIBUTES[srdo]] if srdo else []
    return names + [MULTIBYTE_ATTRIBUTE] * multibyte + [STRING_ATTRIBUTE] * string


def pdo_attribute_text(directions: str) -> str:
    """`ODA_TPDO`... for messages; "no PDO bit" for none."""
    return PDO_ATTRIBUTES[directions] if directions else "no PDO bit"


def count_macro(label: str) -> str:
    return COUNT_PREFIX + label
