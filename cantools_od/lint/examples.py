"""Rule examples as files: a documented example is an EDS fragment; `frame()` makes it a whole EDS.

The rule documentation (`cantools-od rules`, docs/rules.md) and the tests run every example
(see `exampleset`): the failing example must trigger its rule, the fixed one must not.

The frame holds what every EDS needs ([FileInfo], [DeviceInfo], [DummyUsage], the mandatory
objects 1000h, 1001h, 1018h and the three object lists, computed from the objects the file ends
up with), so that an example shows only what its rule is about. A section the fragment gives
replaces the frame's; a [DeviceInfo] it gives is completed with the frame's keys it does not set
(write `BaudRate_125=0` to say a key is 0). A section the fragment gives as an object replaces the
frame's object with its sub-objects. With `lint --profile canopennode` the frame also holds the
objects the CANopenNode stack requires (1003h, 1014h, 1016h, 1017h).
"""

from __future__ import annotations

import re
from collections.abc import Set

from ..model.cia301.objects import DATA_TYPE_AREA, MANDATORY, MANUFACTURER_AREA
from ..model.cia301.pdo import COMM_BASE, MAP_BASE, PREDEFINED, RX, TX, count_pdos

_SECTION = re.compile(r"^\[([^\]]+)\]", re.MULTILINE)
_FRAME = {
    "FileInfo": "FileName=example.eds\nFileVersion=1\nFileRevision=0\nEDSVersion=4.0\nDescription=Rule example\n"
    "CreationTime=12:00PM\nCreationDate=01-01-2025\nCreatedBy=cantools-od\nModificationTime=12:00PM\n"
    "ModificationDate=01-01-2025\nModifiedBy=cantools-od",
    "DeviceInfo": "VendorName=Example\nVendorNumber=0x1\nProductName=Example\nProductNumber=0x2\nRevisionNumber=0x3\n"
    "OrderCode=1\nBaudRate_10=0\nBaudRate_20=0\nBaudRate_50=0\nBaudRate_125=1\nBaudRate_250=1\nBaudRate_500=1\n"
    "BaudRate_800=0\nBaudRate_1000=1\nSimpleBootUpMaster=0\nSimpleBootUpSlave=1\nGranularity=8\n"
    "DynamicChannelsSupported=0\nGroupMessaging=0\nNrOfRXPDO={rx}\nNrOfTXPDO={tx}\nLSS_Supported=0",
    "DummyUsage": "\n".join(f"Dummy000{n}={int(n > 1)}" for n in range(1, 8)),
    "1000": "ParameterName=Device type\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x00000000\n"
    "PDOMapping=0",
    "1001": "ParameterName=Error register\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\nDefaultValue=0\n"
    "PDOMapping=1",
    "1018": "ParameterName=Identity object\nObjectType=0x9\nSubNumber=4",
    "1018sub0": "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
    "DefaultValue=3\nPDOMapping=0",
    "1018sub1": "ParameterName=Vendor-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x1\n"
    "PDOMapping=0",
    "1018sub2": "ParameterName=Product code\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x2\n"
    "PDOMapping=0",
    "1018sub3": "ParameterName=Revision number\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x3\n"
    "PDOMapping=0",
}
# What `lint --profile canopennode` needs besides (CNO005): the error history, the EMCY COB-ID, the heartbeat
# consumer and producer; the error register not mappable.
_CANOPENNODE_FRAME = {
    # PDOMapping=1 on a read-only entry is where the generator's bits differ from CANopenEditor's (CNO010)
    "1001": "ParameterName=Error register\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\nDefaultValue=0\n"
    "PDOMapping=0",
    "1003": "ParameterName=Pre-defined error field\nObjectType=0x8\nSubNumber=2",
    "1003sub0": "ParameterName=Number of errors\nObjectType=0x7\nDataType=0x0005\nAccessType=rw\nDefaultValue=0\n"
    "PDOMapping=0",
    "1003sub1": "ParameterName=Standard error field\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0\n"
    "PDOMapping=0",
    "1014": "ParameterName=COB-ID EMCY\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\nDefaultValue=$NODEID+0x80\n"
    "PDOMapping=0",
    "1016": "ParameterName=Consumer heartbeat time\nObjectType=0x8\nSubNumber=2",
    "1016sub0": "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
    "DefaultValue=1\nPDOMapping=0",
    "1016sub1": "ParameterName=Consumer heartbeat time 1\nObjectType=0x7\nDataType=0x0007\nAccessType=rw\n"
    "DefaultValue=0\nPDOMapping=0",
    "1017": "ParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\n"
    "PDOMapping=0",
}
_LISTS = ("MandatoryObjects", "OptionalObjects", "ManufacturerObjects")
_OBJECT = re.compile(r"^\[([0-9A-Fa-f]{4})(?:\]|[ \t]*$)", re.MULTILINE)


def _listing(name: str, indices: list[int]) -> str:
    lines = [f"SupportedObjects={len(indices)}"] + [f"{n}=0x{index:04X}" for n, index in enumerate(indices, 1)]
    return f"[{name}]\n" + "\n".join(lines) + "\n"


def _merged_info(fragment: list[tuple[str, int]], frame_keys: list[str]) -> list[tuple[str, int | None]]:
    """The fragment's lines (with their numbers), the frame's [DeviceInfo] keys it does not set added
    at the end of its [DeviceInfo] section (numbered None)."""
    out: list[tuple[str, int | None]] = []
    in_info, given = False, set()
    for line, number in fragment:
        if line.startswith("["):
            if in_info:
                out += [(key, None) for key in frame_keys if key.split("=", 1)[0].lower() not in given]
            in_info = line.strip().lower() == "[deviceinfo]"
        elif in_info and "=" in line:
            given.add(line.split("=", 1)[0].strip().lower())
        out.append((line, number))
    if in_info:
        out += [(key, None) for key in frame_keys if key.split("=", 1)[0].lower() not in given]
    return out


def _left_out(name: str, given: set[str]) -> bool:
    """Whether the frame leaves section `name` out: the fragment gives it (or, for a sub-object, its
    object: the fragment's object is all of it), or says the file has none."""
    name = name.lower()
    return name in given or ("sub" in name and name.split("sub", 1)[0] in given)


def framed_lines(
    fragment: list[tuple[str, int]], omit: Set[str] = frozenset(), profile: str | None = None
) -> tuple[str, dict[int, int]]:
    """The framed text of a fragment given as (line, its number), and for each line of the framed text
    that comes from the fragment, the fragment's number. `omit`: sections (lower case) the file has not."""
    while fragment and not fragment[0][0].strip():
        fragment = fragment[1:]
    given = {name.lower() for line, _ in fragment for name in _SECTION.findall(line)} | omit
    frame = {**_FRAME, **(_CANOPENNODE_FRAME if profile == "canopennode" else {})}
    parts = [f"[{name}]\n{body}\n" for name, body in frame.items() if not _left_out(name, given)]
    head = "\n".join(parts) + "\n"
    info = [] if "deviceinfo" in omit else _FRAME["DeviceInfo"].splitlines()
    body = _merged_info(fragment, info)
    first = head.count("\n") + 1
    origin = {first + i: number for i, (_, number) in enumerate(body) if number is not None}
    text = head + "".join(line + "\n" for line, _ in body)
    objects = sorted({int(m, 16) for m in _OBJECT.findall(text)} - set(DATA_TYPE_AREA))  # data types are not listed
    text = text.replace("NrOfRXPDO={rx}", f"NrOfRXPDO={count_pdos(objects, RX)}")
    text = text.replace("NrOfTXPDO={tx}", f"NrOfTXPDO={count_pdos(objects, TX)}")
    areas = {
        "MandatoryObjects": [i for i in objects if i in MANDATORY],
        "OptionalObjects": [i for i in objects if i not in MANDATORY and i not in MANUFACTURER_AREA],
        "ManufacturerObjects": [i for i in objects if i in MANUFACTURER_AREA],
    }
    lists = [_listing(name, areas[name]) for name in _LISTS if name.lower() not in given]
    return text + "\n" + "\n".join(lists), origin


def _numbered(fragment: str) -> list[tuple[str, int]]:
    return [(line, number) for number, line in enumerate(fragment.splitlines(), 1)]


def frame(fragment: str) -> str:
    """The fragment inside a clean EDS: the frame's sections it does not give, its [DeviceInfo]
    completed with the frame's keys it does not set."""
    return framed_lines(_numbered(fragment.strip()))[0]


# --- builders for the PDO and COB-ID rule examples -----------------------------------------------------------


def section(name: str, **keys: object) -> str:
    return f"[{name}]\n" + "".join(f"{key}={value}\n" for key, value in keys.items())


def var(index: int, name: str, dtype: int, access: str = "rw", default: object = 0, mapping: int = 1) -> str:
    """A VAR object section."""
    return section(
        f"{index:04X}", ParameterName=name, ObjectType="0x7", DataType=f"0x{dtype:04X}", AccessType=access,
        DefaultValue=default, PDOMapping=mapping,
    )  # fmt: skip


def _sub(index: int, subindex: int, name: str, dtype: int, access: str, default: object) -> str:
    return section(
        f"{index:04X}sub{subindex:X}", ParameterName=name, ObjectType="0x7", DataType=f"0x{dtype:04X}",
        AccessType=access, DefaultValue=default, PDOMapping=0,
    )  # fmt: skip


def record(index: int, name: str, subs: dict[int, tuple[str, int, str, object]]) -> str:
    """A RECORD with its sub-objects {sub-index: (name, data type, access, default)}."""
    text = section(f"{index:04X}", ParameterName=name, ObjectType="0x9", SubNumber=len(subs))
    return text + "".join(_sub(index, sub, *spec) for sub, spec in sorted(subs.items()))


def pdo(
    direction: str,
    *entries: str,
    number: int = 1,
    cob: str | None = None,
    tt: object = None,
    count: object = None,
    comm: dict[int, tuple[str, int, str, object]] | None = None,
    parts: str = "comm+map",
) -> str:
    """A PDO: its communication record (COB-ID, transmission type, `comm` sub-objects) and its mapping;
    `parts` "comm" or "map" leaves the other record out."""
    rx = direction == "rx"
    base = COMM_BASE[RX if rx else TX] + number - 1
    predefined = PREDEFINED[RX if rx else TX][min(number, 4) - 1]
    cob_id = cob or (f"$NODEID+0x{predefined:X}" if number <= 4 else "0x80000000")
    subs = {
        1: ("COB-ID", 0x0007, "rw", cob_id),
        2: ("Transmission type", 0x0005, "rw", tt if tt is not None else (255 if rx else 1)),
        **(comm or {}),
    }
    kind = "RPDO" if rx else "TPDO"
    highest = ("Highest sub-index supported", 0x0005, "ro", max(subs))
    text = "" if parts == "map" else record(base, f"{kind}{number} communication parameter", {0: highest, **subs})
    mapped = {position: (f"Mapped object {position}", 0x0007, "rw", entry) for position, entry in enumerate(entries, 1)}
    number_of = len(entries) if count is None else count
    if parts == "comm":
        return text
    count_sub = ("Number of mapped objects", 0x0005, "rw", number_of)
    map_index = MAP_BASE[RX if rx else TX] + number - 1
    return text + record(map_index, f"{kind}{number} mapping parameter", {0: count_sub, **mapped})


# 1000h of a drive: device profile 402 in the low 16 bits (servo drive in the high ones).
DEVICE_TYPE_402 = var(0x1000, "Device type", 0x0007, "ro", "0x00020192", mapping=0)
STATUSWORD = var(0x6041, "Statusword", 0x0006, "ro")
CONTROLWORD = var(0x6040, "Controlword", 0x0006, "rw")
POSITION = var(0x6064, "Position actual value", 0x0004, "ro")
VELOCITY = var(0x606C, "Velocity actual value", 0x0004, "ro")
TARGET_POSITION = var(0x607A, "Target position", 0x0004, "rw")
# [DeviceComissioning] of node 5: the example is a DCF, its values are configured ones.
NODE_5 = section(
    "DeviceComissioning", NodeID=5, NodeName="drive", Baudrate=500, NetNumber=1, NetworkName="net", CANopenManager=0,
    LSS_SerialNumber=0,
)  # fmt: skip


def identity(serial: str | None = None) -> str:
    """The identity object 1018h of the frame, with a serial number (sub4) when given."""
    subs = {
        1: ("Vendor-ID", 0x0007, "ro", "0x1"),
        2: ("Product code", 0x0007, "ro", "0x2"),
        3: ("Revision number", 0x0007, "ro", "0x3"),
        **({4: ("Serial number", 0x0007, "ro", serial)} if serial is not None else {}),
    }
    return record(0x1018, "Identity object", {0: ("Highest sub-index supported", 0x0005, "ro", max(subs)), **subs})


def sdo_server(rx: str = "$NODEID+0x600", tx: str = "$NODEID+0x580") -> str:
    """1200h, the default SDO server, with its two COB-IDs."""
    highest = ("Highest sub-index supported", 0x0005, "ro", 2)
    cobs = {1: ("COB-ID client to server", 0x0007, "ro", rx), 2: ("COB-ID server to client", 0x0007, "ro", tx)}
    return record(0x1200, "SDO server parameter", {0: highest, **cobs})
