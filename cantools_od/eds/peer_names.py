"""The names python-canopen's EDS reader looks up, spelled as it spells them.

It matches section and key names case-sensitively and knows one spelling of each (`import_od`: a RawConfigParser
with `optionxform = str`). A name written otherwise (`[DeviceCommissioning]`, `NrOfRxPDO`) is one it does not find;
respelled as CiA 306 spells it, the name is found, and python-canopen reads a value it did not read before (a
node-ID, a bit rate, a PDO count). So no rewrite that must not change what peers read (`fmt`, a safe `lint --fix`)
respells such a name; one it never looks up can be respelled freely.
"""

from __future__ import annotations

import re

from ..canopennode.info import STORAGE_LOCATION

_NAMES = frozenset({"DeviceInfo", "DeviceComissioning", "Comments", "DummyUsage", "Lines", "NodeID",
    "Baudrate", "ParameterName", "ObjectType", "DataType", "AccessType", "DefaultValue", "ParameterValue", "LowLimit",
    "HighLimit", "PDOMapping", "CompactSubObj", "NrOfEntries", "Factor", "Description", "Unit", STORAGE_LOCATION,
    "VendorName", "VendorNumber", "ProductName", "ProductNumber", "RevisionNumber", "OrderCode", "SimpleBootUpMaster",
    "SimpleBootUpSlave", "Granularity", "DynamicChannelsSupported", "GroupMessaging", "NrOfRXPDO", "NrOfTXPDO",
    "LSS_Supported"})  # fmt: skip
_PATTERN = re.compile(r"(?:BaudRate_[0-9]+|Line[0-9]+|Dummy[0-9A-F]{4}|[0-9A-F]{4}(?:sub[0-9A-F]+)?)\Z")


def python_canopen_reads(name: str) -> bool:
    """Whether python-canopen looks up `name` (a section or key name as CiA 306 spells it)."""
    return name in _NAMES or _PATTERN.match(name) is not None


def peer_spelling(canonical: str, written: str | None) -> str:
    """The name a rewrite writes: CiA 306's, unless the file spelled it otherwise (`written`) and python-canopen
    looks the CiA 306 name up, where the respelling would make it read what it did not."""
    return written if written is not None and python_canopen_reads(canonical) else canonical
