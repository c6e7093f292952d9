"""The communication-profile objects CiA 301 fixes by index (§7.5.2), and the index areas of §7.4.1."""

from __future__ import annotations

DEVICE_TYPE, ERROR_REGISTER, ERROR_HISTORY = 0x1000, 0x1001, 0x1003
COB_ID_SYNC, COB_ID_TIME, COB_ID_EMCY = 0x1005, 0x1012, 0x1014
IDENTITY = 0x1018
IDENTITY_VENDOR_ID, IDENTITY_PRODUCT_CODE, IDENTITY_REVISION, IDENTITY_SERIAL = 1, 2, 3, 4
SDO_SERVERS = range(0x1200, 0x1280)
SDO_CLIENTS = range(0x1280, 0x1300)
FIRST_SDO_SERVER = SDO_SERVERS[0]

# Every device implements these (1018h since CiA 301 v4.0); the rest of the dictionary is optional.
MANDATORY: dict[int, str] = {DEVICE_TYPE: "device type", ERROR_REGISTER: "error register", IDENTITY: "identity object"}

COMMUNICATION_AREA = range(0x1000, 0x2000)
MANUFACTURER_AREA = range(0x2000, 0x6000)
DATA_TYPE_AREA = range(0x0001, 0x1000)  # data-type definitions (0000h is not used): what a dummy entry names
