"""CiA 306 key names: canonical spelling, order, and the model field each fills.

Key names are matched case-insensitively and without blanks
(`Supported Objects` is `SupportedObjects`).
"""

from __future__ import annotations

import re
from enum import Enum
from functools import lru_cache


class Kind(Enum):
    STR = "str"
    INT = "int"
    BOOL = "bool"
    OBJECT_TYPE = "object_type"
    ACCESS = "access"
    VALUE = "value"  # typed by the entry's data type

    # Members are singletons: hashing by identity keeps the reader's caches keyed by kind cheap
    # (Enum's own hash is a Python call on the member's name).
    __hash__ = object.__hash__


KeySpec = tuple[str, str, Kind]  # canonical spelling, model field, kind


@lru_cache(maxsize=1024)  # the few key spellings of a file, each seen once per section
def normalize(key: str) -> str:
    return key.replace(" ", "").replace("\t", "").lower()


MAX_DIGITS = 64
"""More digits than any number in a device description can need (UNSIGNED64 has 20 decimal, 16 hex):
a longer one is text, never an int (Python refuses `int()` of over 4300 digits, and prints none)."""


def is_decimal(text: str) -> bool:
    """A decimal number in ASCII digits of a sane length: `str.isdigit` also takes `²` or Arabic-Indic digits,
    which `int` then refuses or misreads."""
    return text.isascii() and text.isdigit() and len(text) <= MAX_DIGITS


def plain_int(text: str) -> int | None:
    """A decimal, `0x` hex (or `0o`/`0b`) integer of at most MAX_DIGITS characters, else None."""
    text = text.strip()
    if len(text) > MAX_DIGITS or not text.isascii():
        return None
    try:
        return int(text, 0)
    except ValueError:
        return None


def list_number(text: str) -> int | None:
    """The number of a numbered key (`3` in an object list, `Line3`'s tail): decimal from 1 in ASCII
    digits without leading zeros, else None (the key is then kept as text)."""
    if not is_decimal(text) or text.startswith("0"):
        return None
    return int(text)


def _table(*specs: KeySpec) -> dict[str, KeySpec]:
    return {normalize(spec[0]): spec for spec in specs}


OBJECT_KEYS = _table(
    ("ParameterName", "name", Kind.STR),
    ("ObjectType", "object_type", Kind.OBJECT_TYPE),
    ("DataType", "data_type", Kind.INT),
    ("AccessType", "access", Kind.ACCESS),
    ("DefaultValue", "default", Kind.VALUE),
    ("LowLimit", "low_limit", Kind.VALUE),
    ("HighLimit", "high_limit", Kind.VALUE),
    ("PDOMapping", "pdo_mapping", Kind.BOOL),
    ("ObjFlags", "obj_flags", Kind.INT),
    ("SubNumber", "sub_number", Kind.INT),
    ("CompactSubObj", "compact_sub_obj", Kind.INT),
    ("ParameterValue", "parameter_value", Kind.VALUE),
    ("Denotation", "denotation", Kind.STR),
    ("ParamRefd", "param_refd", Kind.STR),
    ("UploadFile", "upload_file", Kind.STR),
    ("DownloadFile", "download_file", Kind.STR),
)
SUB_ONLY_EXCLUDED = {"subnumber", "compactsubobj"}  # keys a sub-object section has no field for

FILE_INFO_KEYS = _table(
    ("FileName", "file_name", Kind.STR),
    ("FileVersion", "file_version", Kind.INT),
    ("FileRevision", "file_revision", Kind.INT),
    ("LastEDS", "last_eds", Kind.STR),
    ("EDSVersion", "eds_version", Kind.STR),
    ("Description", "description", Kind.STR),
    ("CreationTime", "creation_time", Kind.STR),
    ("CreationDate", "creation_date", Kind.STR),
    ("CreatedBy", "created_by", Kind.STR),
    ("ModificationTime", "modification_time", Kind.STR),
    ("ModificationDate", "modification_date", Kind.STR),
    ("ModifiedBy", "modified_by", Kind.STR),
)

BAUD_RATES = (10, 20, 50, 125, 250, 500, 800, 1000)

DEVICE_INFO_KEYS = _table(
    ("VendorName", "vendor_name", Kind.STR),
    ("VendorNumber", "vendor_number", Kind.INT),
    ("ProductName", "product_name", Kind.STR),
    ("ProductNumber", "product_number", Kind.INT),
    ("RevisionNumber", "revision_number", Kind.INT),
    ("OrderCode", "order_code", Kind.STR),
    *((f"BaudRate_{rate}", f"baud_rates.{rate}", Kind.BOOL) for rate in BAUD_RATES),
    ("SimpleBootUpMaster", "simple_boot_up_master", Kind.BOOL),
    ("SimpleBootUpSlave", "simple_boot_up_slave", Kind.BOOL),
    ("Granularity", "granularity", Kind.INT),
    ("DynamicChannelsSupported", "dynamic_channels_supported", Kind.INT),
    ("GroupMessaging", "group_messaging", Kind.BOOL),
    ("NrOfRXPDO", "nr_of_rx_pdo", Kind.INT),
    ("NrOfTXPDO", "nr_of_tx_pdo", Kind.INT),
    ("LSS_Supported", "lss_supported", Kind.BOOL),
    ("CompactPDO", "compact_pdo", Kind.INT),
    ("CANopenSafetySupported", "canopen_safety_supported", Kind.BOOL),
)

COMMISSIONING_KEYS = _table(
    ("NodeID", "node_id", Kind.INT),
    ("NodeName", "node_name", Kind.STR),
    ("NodeRefd", "node_refd", Kind.STR),
    ("Baudrate", "baudrate", Kind.INT),
    ("NetNumber", "net_number", Kind.INT),
    ("NetworkName", "network_name", Kind.STR),
    ("NetRefd", "net_refd", Kind.STR),
    ("CANopenManager", "canopen_manager", Kind.BOOL),
    ("LSS_SerialNumber", "lss_serial_number", Kind.INT),
)

# Section names (normalized) → canonical spelling.
FILE_INFO = "FileInfo"
DEVICE_INFO = "DeviceInfo"
DUMMY_USAGE = "DummyUsage"
COMMENTS = "Comments"
OBJECT_LISTS = {
    "mandatoryobjects": ("MandatoryObjects", "mandatory_objects"),
    "optionalobjects": ("OptionalObjects", "optional_objects"),
    "manufacturerobjects": ("ManufacturerObjects", "manufacturer_objects"),
}
COMMISSIONING = "DeviceComissioning"
COMMISSIONING_SPELLINGS = {"devicecomissioning", "devicecommissioning"}
SECTION_SPELLINGS = {
    "fileinfo": FILE_INFO,
    "deviceinfo": DEVICE_INFO,
    "dummyusage": DUMMY_USAGE,
    "comments": COMMENTS,
    **{name: spelling for name, (spelling, _) in OBJECT_LISTS.items()},
    **{name: COMMISSIONING for name in COMMISSIONING_SPELLINGS},
}
"""The sections of a file's own (no object's), by their name in lower case, and how CiA 306 spells each."""
OBJECT_SECTION = re.compile(
    r"([0-9a-fA-F]{1,4})(?:[sS][uU][bB]([0-9a-fA-F]{1,3})|(name|value|denotation|objectlinks))?\Z",
    re.IGNORECASE,
)
"""An object's section (`1000`), a sub-object's (`1018sub1`) or a compact one's (`2000Name`): index, sub-index,
compact kind."""
MODULE_SECTION = re.compile(r"(?:m\d+\D.*|supportedmodules|connectedmodules)\Z", re.IGNORECASE)
"""The module sections of a modular device (CiA 306 §6)."""
OTHER_SECTION = re.compile(r"(?:tools|tool[1-9][0-9]*|dynamicchannels)\Z", re.IGNORECASE)
"""CiA 306 sections the model keeps as they are: the tool list and dynamic channels."""


def is_file_section(name: str) -> bool:
    """Whether `name` (as between the brackets) is a CiA 306 section of the file's own, of its modules, or of
    its tools and dynamic channels."""
    name = name.strip()
    known = name.lower() in SECTION_SPELLINGS
    return known or MODULE_SECTION.match(name) is not None or OTHER_SECTION.match(name) is not None
