"""What the CANopenNode v4 stack needs to know about an object beyond CiA 301.

CANopenEditor keeps these as `<property name="CO_...">` elements in its XDD/XPD
projects, and CANopenNode EDS exports keep the storage group as a
`;StorageLocation=` comment. Sources fill this in when the file says it; the
CANopenNode target infers what is missing (and says so).
"""

from __future__ import annotations

from enum import StrEnum

from pydantic import BaseModel, ConfigDict


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


# The OD_CNT_<label> macros the stack counts, by the index ranges of CiA 301/304 that hold their objects
# (CANopen.c checks them with #error and sizes its object arrays from them).
_COUNT_RANGES: tuple[tuple[int, int, str], ...] = (
    (0x1000, 0x1000, "NMT"),
    (0x1001, 0x1001, "EM"),
    (0x1005, 0x1005, "SYNC"),
    (0x1006, 0x1006, "SYNC_PROD"),
    (0x1010, 0x1010, "STORAGE"),
    (0x1012, 0x1012, "TIME"),
    (0x1014, 0x1014, "EM_PROD"),
    (0x1016, 0x1016, "HB_CONS"),
    (0x1017, 0x1017, "HB_PROD"),
    (0x1200, 0x127F, "SDO_SRV"),
    (0x1280, 0x12FF, "SDO_CLI"),
    (0x1300, 0x1300, "GFC"),
    (0x1301, 0x1340, "SRDO"),
    (0x1400, 0x15FF, "RPDO"),
    (0x1800, 0x19FF, "TPDO"),
)

# Communication-area objects whose values are states or commands, not configuration: kept in RAM.
_RAM_IN_COMM_AREA = frozenset({0x1001, 0x1002, 0x1003, 0x1010, 0x1011, 0x1013, 0x1200})

RAM = "RAM"
PERSIST_COMM = "PERSIST_COMM"


def standard_count_label(index: int) -> str | None:
    """The count label the stack expects on the object at `index`, or None when it counts no object there."""
    for low, high, label in _COUNT_RANGES:
        if low <= index <= high:
            return label
    return None


def standard_storage_group(index: int) -> str:
    """The storage group for an object with none stated: communication parameters persist, the rest is RAM."""
    if 0x1000 <= index <= 0x1FFF and index not in _RAM_IN_COMM_AREA:
        return PERSIST_COMM
    return RAM


def count_label_for(index: int, info: CanopenNodeInfo | None) -> str | None:
    """The object's count label: the stated one ("" for none), else the standard one for its index."""
    if info is not None and info.count_label is not None:
        return info.count_label or None
    return standard_count_label(index)


# Limits CANopen.c checks with #error (or that its init loops rely on): label → (least, most).
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
    "SDO_SRV": (1, 128),
    "SDO_CLI": (0, 128),
    "RPDO": (0, 512),
    "TPDO": (0, 512),
    "SRDO": (0, 64),
}

# Objects the stack's init walks by position from the first one: label → (first index, partner offset).
# RPDO i uses 1400h+i and 1600h+i, TPDO i 1800h+i and 1A00h+i, SRDO i 1301h+i and 1381h+i.
CONSECUTIVE: dict[str, tuple[int, int | None]] = {
    "SDO_SRV": (0x1200, None),
    "SDO_CLI": (0x1280, None),
    "RPDO": (0x1400, 0x200),
    "TPDO": (0x1800, 0x200),
    "SRDO": (0x1301, 0x80),
}

# COB-IDs to which the stack adds the node-ID itself: only there is `$NODEID+n` stored as n harmlessly.
NODEID_AREAS: tuple[tuple[int, int], ...] = ((0x1014, 0x1014), (0x1200, 0x12FF), (0x1400, 0x15FF), (0x1800, 0x19FF))

# Communication objects the stack extends with its own read/write functions (EM history, storage):
# like CANopenEditor, an entry of theirs without a default gets no memory.
_STACK_EXTENDED = frozenset({0x1003, 0x1010, 0x1011})


def stack_reads_at_init(index: int) -> bool:
    """Whether CO_CANopenInit reads the object's value from the OD: it then needs memory even without a default."""
    return 0x1000 <= index <= 0x1FFF and index not in _STACK_EXTENDED
