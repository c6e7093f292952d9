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
