"""Rule family: identity — mandatory objects, [DeviceInfo] against the object dictionary.

CiA 306 [DeviceInfo] and §5 (DCF); CiA 301 mandatory objects.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator

from ..eds.keys import BAUD_RATES
from ..model import Device, Object, Severity, Value
from ..model.cia301.objects import (
    IDENTITY,
    IDENTITY_PRODUCT_CODE,
    IDENTITY_REVISION,
    IDENTITY_SERIAL,
    IDENTITY_VENDOR_ID,
    MANDATORY,
)
from ..model.cia301.pdo import RX, TX, count_pdos, is_mapping
from . import examples as ex
from .common import file_start, present
from .rules import Clause, Context, Finding, Fix, Placement, rule

E, W = Severity.ERROR, Severity.WARNING

_IDENTITY = ((IDENTITY_VENDOR_ID, "VendorNumber", "vendor_number"), (IDENTITY_PRODUCT_CODE, "ProductNumber",
             "product_number"), (IDENTITY_REVISION, "RevisionNumber", "revision_number"))  # fmt: skip
_PDO_COUNTS = (("NrOfRXPDO", "nr_of_rx_pdo", RX, "RPDO"), ("NrOfTXPDO", "nr_of_tx_pdo", TX, "TPDO"))


def plain_int(value: Value | None) -> int | None:
    """An integer value, or None for anything else (booleans, `$NODEID` formulas, text)."""
    return value if isinstance(value, int) and not isinstance(value, bool) else None


@rule(
    "EDS011",
    E,
    "Mandatory object missing",
    """
Every CANopen device implements 1000h (device type), 1001h (error register) and, since CiA 301
v4.0, 1018h (identity object). Masters read them during boot-up to identify the device; a file
without them cannot describe a conforming device.""",
    "; no [1018]\n[MandatoryObjects]\nSupportedObjects=2\n1=0x1000\n2=0x1001",
    fixed=lambda: "[MandatoryObjects]\nSupportedObjects=3\n1=0x1000\n2=0x1001\n3=0x1018\n\n" + ex.identity(),
    placed=Placement(Clause.DEVICE_MISBEHAVES, "a master's boot-up reads 1000h/1001h/1018h and fails without them"),
)
def mandatory_objects(ctx: Context) -> Iterator[Finding]:
    listing = ctx.device.mandatory_objects
    where = ctx.at(listing) if listing is not None else file_start(ctx)
    for index, name in MANDATORY.items():
        if index not in ctx.device.objects:
            yield ctx.report("EDS011", f"mandatory object {index:04X}h ({name}) is missing", where)


@rule(
    "EDS040",
    E,
    "[DeviceInfo] identity differs from 1018h",
    """
VendorNumber, ProductNumber and RevisionNumber in [DeviceInfo] repeat the DefaultValue of the
identity object 1018h sub-indices 1, 2 and 3 (CiA 306, [DeviceInfo]); in a DCF, the ParameterValue
of a sub-index that has one, which is the configured device's own number. Masters and
configuration tools compare one or the other with the device; a mismatch (CANopenEditor #226:
RevisionNumber=0 while 1018h sub3 = 0x00010000) makes them reject the right device or accept the
wrong one.

Fix: the number 1018h states is written to [DeviceInfo]. Safe from a ParameterValue; unsafe
(`--unsafe-fixes`) from a DefaultValue, which may be a template's placeholder while [DeviceInfo]
holds the real number: which side is right only the device tells.""",
    "[DeviceInfo]\nRevisionNumber=0\n\n[1018sub3]\nParameterName=Revision number\nDataType=0x0007\n"
    "AccessType=ro\nDefaultValue=0x00010000",
    fixed=("[DeviceInfo]\nRevisionNumber=0x3"),
    placed=Placement(Clause.PEER_READS_OTHERWISE, "a master compares one number or the other with the device"),
)
def identity(ctx: Context) -> Iterator[Finding]:
    info, obj = ctx.device.device_info, ctx.device.objects.get(IDENTITY)
    if obj is None:
        return
    for subindex, key, field in _IDENTITY:
        stated, (described, source) = getattr(info, field), _stated_identity(obj, subindex)
        if stated is None or described is None or stated == described:
            continue
        # Safe only from a DCF's ParameterValue, the device's own number; a DefaultValue may be the template's.
        safe = source == "ParameterValue"
        fix = Fix(f"set {key}=0x{described:08X} from 1018h sub{subindex}", safe, _fix_identity(subindex, field))
        message = f"{key}=0x{stated:08X} but 1018h sub{subindex} {source}=0x{described:08X}"
        yield ctx.report("EDS040", message, ctx.value_at(info, key), fix)


def _stated_identity(obj: Object, subindex: int) -> tuple[int | None, str]:
    """The identity 1018h states in a sub-index: a DCF's ParameterValue (the configured device's own number)
    when it has one, else the DefaultValue; and the key that states it."""
    sub = obj.subs.get(subindex)
    if sub is None:
        return None, ""
    return plain_int(sub.held), sub.held_key


def _fix_identity(subindex: int, field: str) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        obj = device.objects.get(IDENTITY)
        value = _stated_identity(obj, subindex)[0] if obj is not None else None
        if value is not None:
            setattr(device.device_info, field, value)

    return apply


@rule(
    "EDS045",
    E,
    "LSS_SerialNumber differs from 1018h sub4",
    """
In a DCF, [DeviceComissioning] LSS_SerialNumber is the serial number of the configured device,
which 1018h sub4 also states as its ParameterValue (CiA 306 §5.3). LSS masters address the
device by it; two different numbers cannot both be right. Not checked when either side is missing
or 0 (not configured). A DefaultValue is the EDS's default, not this device's number: it is not
compared.

Error: the LSS master looks for a device that does not exist.""",
    (
        lambda: (
            ex.NODE_5.replace("LSS_SerialNumber=0", "LSS_SerialNumber=0x17")
            + ex.identity(serial="0x18").replace("DefaultValue=0x18", "DefaultValue=0x18\nParameterValue=0x18")
        )
    ),
    fixed=(
        lambda: (
            ex.NODE_5.replace("LSS_SerialNumber=0", "LSS_SerialNumber=0x17")
            + ex.identity(serial="0x18").replace("DefaultValue=0x18", "DefaultValue=0x18\nParameterValue=0x17")
        )
    ),
    fix_safety="No automatic fix (which number is right is known only on the device).",
    placed=Placement(Clause.DEVICE_MISBEHAVES, "an LSS master addresses the device by the other number"),
)
def serial_number(ctx: Context) -> Iterator[Finding]:
    section, obj = ctx.device.commissioning, ctx.device.objects.get(IDENTITY)
    sub = obj.subs.get(IDENTITY_SERIAL) if obj is not None else None
    if section is None or not section.lss_serial_number or sub is None:
        return  # 0: not configured
    described = plain_int(sub.parameter_value)
    if described and described != section.lss_serial_number:
        message = f"LSS_SerialNumber=0x{section.lss_serial_number:08X} but 1018h sub4 is 0x{described:08X}"
        yield ctx.report("EDS045", message, ctx.value_at(section, "LSS_SerialNumber"))


@rule(
    "EDS041",
    W,
    "NrOfRXPDO/NrOfTXPDO differs from the PDOs present",
    """
NrOfRXPDO and NrOfTXPDO count the RPDO (1400h-15FFh) and TPDO (1800h-19FFh) communication
objects the device has, the ones CompactPDO implies included. Tools size their PDO tables from
these keys; a count that disagrees with the objects means a PDO is missing or the key is stale.""",
    (lambda: "[DeviceInfo]\nNrOfRXPDO=2\n\n" + ex.pdo("rx", "0x60400010") + ex.CONTROLWORD),
    fixed=(lambda: "[DeviceInfo]\nNrOfRXPDO=1\n\n" + ex.pdo("rx", "0x60400010") + ex.CONTROLWORD),
    placed=Placement(Clause.STYLE, "tools size their PDO tables from the keys; a stale count"),
)
def pdo_counts(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.device_info
    for key, field, direction, kind in _PDO_COUNTS:
        stated = getattr(info, field)
        present = count_pdos(ctx.device.objects, direction)
        if stated is not None and stated != present:
            fix = Fix(f"set {key}={present}", False, _fix_pdo_count(field, direction))
            message = f"{key}={stated} but {present} {kind} communication object{'s' if present != 1 else ''}"
            yield ctx.report("EDS041", message, ctx.value_at(info, key), fix)


def _fix_pdo_count(field: str, direction: str) -> Callable[[Device], None]:
    def apply(device: Device) -> None:
        setattr(device.device_info, field, count_pdos(device.objects, direction))

    return apply


@rule(
    "EDS042",
    W,
    "Granularity 0 with writable PDO mapping",
    """
`Granularity=0` states that the PDO mapping cannot be changed (CiA 306, [DeviceInfo]). Mapping objects
(1600h-17FFh, 1A00h-1BFFh) with writable sub-objects say the opposite; configuration tools
either refuse to remap or remap a device that rejects it.""",
    (lambda: "[DeviceInfo]\nGranularity=0\n\n" + ex.pdo("tx", "0x60410010") + ex.STATUSWORD),
    fixed=(lambda: "[DeviceInfo]\nGranularity=8\n\n" + ex.pdo("tx", "0x60410010") + ex.STATUSWORD),
    placed=Placement(Clause.BEYOND_THE_PEERS, "configuration tools refuse to remap, or remap a device that rejects it"),
)
def static_mapping(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.device_info
    if info.granularity != 0:
        return
    writable = [
        f"{index:04X}h"
        for index, obj in ctx.device.objects.items()
        if is_mapping(index) and any(sub.access is not None and sub.access.writable for sub in obj.subs.values())
    ]
    if writable:
        more = f" and {len(writable) - 3} more" if len(writable) > 3 else ""
        message = f"Granularity=0 (static mapping) but mapping objects are writable: {', '.join(writable[:3])}{more}"
        yield ctx.report("EDS042", message, ctx.value_at(info, "Granularity"))


@rule(
    "EDS046",
    E,
    "Granularity above 64",
    """
Granularity is the PDO mapping granularity in bits: 0 (mapping not modifiable) or 1..64 (CiA 306,
[DeviceInfo]); a classic CAN frame holds 64 bits.""",
    "[DeviceInfo]\nGranularity=128",
    fixed=("[DeviceInfo]\nGranularity=8"),
    placed=Placement(Clause.DEVICE_MISBEHAVES, "a classic CAN frame holds 64 bits: no device maps at that granularity"),
)
def granularity_range(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.device_info
    if info.granularity is not None and not 0 <= info.granularity <= 64:
        message = f"Granularity={info.granularity}: must be 0..64"
        yield ctx.report("EDS046", message, ctx.value_at(info, "Granularity"))


@rule(
    "EDS043",
    W,
    "Commissioned baud rate not supported",
    """
[DeviceComissioning] Baudrate (kbit/s) is one of the rates [DeviceInfo] marks as supported with
`BaudRate_<rate>=1`; otherwise the node is configured for a bit rate it cannot use.""",
    "[DeviceInfo]\nBaudRate_250=1\nBaudRate_500=0\n\n[DeviceComissioning]\nNodeID=5\nBaudrate=500",
    fixed="[DeviceInfo]\nBaudRate_250=1\nBaudRate_500=1\n\n[DeviceComissioning]\nNodeID=5\nBaudrate=500",
    placed=Placement(Clause.STYLE, "the commissioned rate is one the device does not support"),
)
def commissioned_rate(ctx: Context) -> Iterator[Finding]:
    section, rates = ctx.device.commissioning, ctx.device.device_info.baud_rates
    if section is None or not section.baudrate or not any(rates.values()):
        return
    if not rates.get(section.baudrate):
        supported = ", ".join(str(rate) for rate in sorted(rates) if rates[rate])
        message = f"Baudrate={section.baudrate} kbit/s is not a supported rate ({supported})"
        yield ctx.report("EDS043", message, ctx.value_at(section, "Baudrate"))


@rule(
    "EDS044",
    W,
    "No supported baud rate",
    """
[DeviceInfo] marks the bit rates the device supports with `BaudRate_10`, `_20`, `_50`, `_125`,
`_250`, `_500`, `_800` and `_1000` (a missing key counts as 0). A device with none set cannot be
put on any network; usually the keys are missing or misspelt (`Baudrate_500`).""",
    (
        "[DeviceInfo]\nVendorName=Example\nBaudRate_10=0\nBaudRate_20=0\nBaudRate_50=0\nBaudRate_125=0\n"
        "BaudRate_250=0\nBaudRate_500=0\nBaudRate_800=0\nBaudRate_1000=0"
    ),
    fixed=(
        "[DeviceInfo]\nVendorName=Example\nBaudRate_10=0\nBaudRate_20=0\nBaudRate_50=0\nBaudRate_125=0\n"
        "BaudRate_250=0\nBaudRate_500=1\nBaudRate_800=0\nBaudRate_1000=0"
    ),
    placed=Placement(Clause.STYLE, "usually a missing or misspelt BaudRate key"),
)
def no_rates(ctx: Context) -> Iterator[Finding]:
    info = ctx.device.device_info
    if present(info) and not any(info.baud_rates.values()):
        keys = ", ".join(f"BaudRate_{rate}" for rate in BAUD_RATES)
        yield ctx.report("EDS044", f"none of {keys} is 1", ctx.at(info))
