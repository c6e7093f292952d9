"""What a CANopenNode project says about an object beyond CiA 301, and where each file format says it.

CANopenEditor keeps these settings as `<property name="CO_...">` elements in its XDD/XPD projects
(`PROPERTIES`), and CANopenNode EDS exports keep the storage group as a `;StorageLocation=` comment
(`STORAGE_LOCATION`). Sources fill `CanopenNodeInfo` in where the file says it; the CANopenNode target infers
what is missing (and says so).
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


# CANopenEditor's XDD/XPD properties, by the CanopenNodeInfo field each fills, in the order it writes them.
PROPERTIES: dict[str, str] = {
    "CO_disabled": "disabled",
    "CO_countLabel": "count_label",
    "CO_storageGroup": "storage_group",
    "CO_flagsPDO": "flags_pdo",
    "CO_accessSRDO": "access_srdo",
    "CO_stringLengthMin": "string_length_min",
}
TEXT_PROPERTIES = ("CO_storageGroup", "CO_countLabel")  # any text
FLAG_PROPERTIES = ("CO_disabled", "CO_flagsPDO")  # "true" or "false"
SRDO_PROPERTY = "CO_accessSRDO"  # a SrdoAccess word
LENGTH_PROPERTY = "CO_stringLengthMin"  # a decimal count

# The EDS keys CANopenNode's tools write as comment lines in an object section (`;StorageLocation=RAM`);
# python-canopen reads the storage group as a plain key of the same name.
STORAGE_LOCATION = "StorageLocation"
DETECT_COS = "TPDODetectCos"
EDS_COMMENT_KEYS = (f";{STORAGE_LOCATION}", f";{DETECT_COS}")
STORAGE_LOCATION_PREFIX = f";{STORAGE_LOCATION}="
PROPERTY_PREFIX = "CO_"
_MAX_DIGITS = 64  # as the EDS reader takes a number


def read_property(name: str, text: str) -> tuple[str, bool | int | str | SrdoAccess] | None:
    """The CanopenNodeInfo field a CANopenEditor property fills and its value; None when the name is not one of
    `PROPERTIES` or the text is not of its kind."""
    if name in TEXT_PROPERTIES:
        return PROPERTIES[name], text
    if name in FLAG_PROPERTIES and text in ("true", "false"):
        return PROPERTIES[name], text == "true"
    if name == SRDO_PROPERTY and text in SrdoAccess.__members__.values():
        return PROPERTIES[name], SrdoAccess(text)
    if name == LENGTH_PROPERTY and text.isascii() and text.isdecimal() and len(text) <= _MAX_DIGITS:
        return PROPERTIES[name], int(text)
    return None


DISABLED_PROPERTY = next(name for name, field in PROPERTIES.items() if field == "disabled")  # for messages
