"""The communication-profile objects CiA 301 fixes by index (§7.5.2), the index areas of §7.4.1, and
the PDO and SDO record ranges.

This module imports nothing: any module of the model (the CANopenNode profile included, which
`model/__init__` loads before the device) can use these numbers without an import cycle.
"""

from __future__ import annotations

DEVICE_TYPE, ERROR_REGISTER, MANUFACTURER_STATUS, ERROR_HISTORY = 0x1000, 0x1001, 0x1002, 0x1003
COB_ID_SYNC, COMM_CYCLE_PERIOD, SYNC_WINDOW_LENGTH = 0x1005, 0x1006, 0x1007
GUARD_TIME, LIFE_TIME_FACTOR = 0x100C, 0x100D
STORE_PARAMETERS, RESTORE_DEFAULTS = 0x1010, 0x1011
COB_ID_TIME, HIGH_RESOLUTION_TIME_STAMP, COB_ID_EMCY, INHIBIT_TIME_EMCY = 0x1012, 0x1013, 0x1014, 0x1015
CONSUMER_HEARTBEAT, PRODUCER_HEARTBEAT = 0x1016, 0x1017
IDENTITY = 0x1018
IDENTITY_VENDOR_ID, IDENTITY_PRODUCT_CODE, IDENTITY_REVISION, IDENTITY_SERIAL = 1, 2, 3, 4
SYNC_COUNTER_OVERFLOW = 0x1019
ERROR_BEHAVIOR = 0x1029
SDO_SERVERS = range(0x1200, 0x1280)
SDO_CLIENTS = range(0x1280, 0x1300)
FIRST_SDO_SERVER = SDO_SERVERS[0]

# CiA 304 (safety-relevant data objects) keeps its objects in the communication area too.
GLOBAL_FAILSAFE_COMMAND = 0x1300
SRDO_COMM = range(0x1301, 0x1341)  # SRDO n: communication 1301h + n - 1, mapping 1381h + n - 1
SRDO_MAP_OFFSET = 0x80
SRDO_CONFIGURATION_VALID, SRDO_CRC = 0x13FE, 0x13FF

# Every device implements these (1018h since CiA 301 v4.0); the rest of the dictionary is optional.
MANDATORY: dict[int, str] = {DEVICE_TYPE: "device type", ERROR_REGISTER: "error register", IDENTITY: "identity object"}

COMMUNICATION_AREA = range(0x1000, 0x2000)
MANUFACTURER_AREA = range(0x2000, 0x6000)
DATA_TYPE_AREA = range(0x0001, 0x1000)  # data-type definitions (0000h is not used): what a dummy entry names

# PDOs: communication record 1400h/1800h + n - 1 and mapping record 1600h/1A00h + n - 1 (§7.5.2.35-38).
RX, TX = "rx", "tx"
COMM_BASE = {RX: 0x1400, TX: 0x1800}
MAP_BASE = {RX: 0x1600, TX: 0x1A00}
PDO_SPAN = 0x200  # 512 PDOs per direction
PDO_AREA = range(COMM_BASE[RX], MAP_BASE[TX] + PDO_SPAN)  # 1400h-1BFFh
MAX_ENTRIES = 0x40  # mapping entries of one PDO
RPDO_COMM = range(COMM_BASE[RX], COMM_BASE[RX] + PDO_SPAN)
TPDO_COMM = range(COMM_BASE[TX], COMM_BASE[TX] + PDO_SPAN)
