"""What the master checks of each slave at boot (CiA 302-2, "check identification"): before it
configures a node, it reads 1000h and 1018h sub 1-4 and compares them with its own 1F84h-1F88h
entry for that node-ID; a mismatch stops the node's boot. A value 0 there is not checked.

The values are dcfgen's: device type from the node's 1000h, vendor-ID and product code from its
[DeviceInfo] (else 1018h), revision number from the YAML's `revision_number`, else [DeviceInfo]
RevisionNumber, else 1018h sub 3; serial number from the YAML's `serial_number`, else 1018h sub 4.
Revision and serial go to the master through master.bin, the others through master.dcf. Only the
last two can be relaxed from bus.yml (`revision_number: 0`, `serial_number: 0`): dcfgen reads no
vendor_id or product_code of a node, so those two and the device type follow the node's file.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

from ..model import Device
from ..model.cia301 import master as m
from ..model.cia301.objects import (
    DEVICE_TYPE,
    IDENTITY,
    IDENTITY_PRODUCT_CODE,
    IDENTITY_REVISION,
    IDENTITY_SERIAL,
    IDENTITY_VENDOR_ID,
)
from ..model.cia301.slots import as_int, slot
from .model import Slave

FROM_FILE_ONLY = "bus.yml cannot relax it (dcfgen has no key for it): 0 in the node's file"


@dataclass(frozen=True)
class BootCheck:
    index: int
    """The master's object: 1F84h (device type) to 1F88h (serial number)."""
    what: str
    value: int
    source: str
    relax: str


def boot_checks(device: Device, node_id: int, slave: Slave, file: str) -> list[BootCheck]:
    """The identity values the master checks of this slave at boot (those that are not 0)."""
    return [check for check in _candidates(device, node_id, slave, file) if check.value]


def _candidates(device: Device, node_id: int, slave: Slave, file: str) -> Iterator[BootCheck]:
    name = slave.dcf
    info = device.device_info
    yield BootCheck(m.DEVICE_TYPE_IDENTIFICATION, "device type", _held(device, node_id, DEVICE_TYPE, 0),
                    f"{name} {DEVICE_TYPE:04X}h", FROM_FILE_ONLY)  # fmt: skip
    vendor = _described(device, node_id, IDENTITY_VENDOR_ID, info.vendor_number, name, "VendorNumber")
    yield BootCheck(m.VENDOR_IDENTIFICATION, "vendor-ID", *vendor, FROM_FILE_ONLY)
    if slot(device, IDENTITY, IDENTITY_PRODUCT_CODE) is not None:
        product = _described(device, node_id, IDENTITY_PRODUCT_CODE, info.product_number, name, "ProductNumber")
        yield BootCheck(m.PRODUCT_CODE, "product code", *product, FROM_FILE_ONLY)
    for index, sub, key, stated, what in (
        (m.REVISION_NUMBER, IDENTITY_REVISION, "revision_number", info.revision_number, "RevisionNumber"),
        (m.SERIAL_NUMBER, IDENTITY_SERIAL, "serial_number", None, ""),
    ):
        if slot(device, IDENTITY, sub) is None:
            continue
        given: int | None = getattr(slave, key)
        value, source = _described(device, node_id, sub, stated, name, what)
        if given is not None:
            differs = f" (the node's {source} says 0x{value:08X})" if value and value != given else ""
            value, source = given, f"{file}:{slave.line_of(key)} {key}{differs}"
        yield BootCheck(index, key.replace("_", " "), value, source, f"`{key}: 0` in the node's section")


def _held(device: Device, node_id: int, index: int, sub: int) -> int:
    found = slot(device, index, sub)
    return (as_int(found.var.value(node_id)) or 0) if found is not None else 0


def _described(device: Device, node_id: int, sub: int, stated: int | None, name: str, key: str) -> tuple[int, str]:
    """[DeviceInfo]'s value where it states one (as dcfgen takes it), else 1018h's."""
    if stated is not None:
        return stated, f"{name} [DeviceInfo] {key}"
    return _held(device, node_id, IDENTITY, sub), f"{name} {IDENTITY:04X}sub{sub}"


def explain(checks: list[BootCheck], who: str, line: str) -> list[str]:
    """The lines that say what the master checks of one slave and how each check is relaxed."""
    if not checks:
        return [f"{line}: note: {who}: the master checks no identity value at boot"]
    lines = [f"{line}: note: {who}: at boot the master checks (a mismatch stops the node's boot):"]
    for check in checks:
        lines.append(
            f"  {check.index:04X}h {check.what} 0x{check.value:08X}, from {check.source}; to relax: {check.relax}"
        )
    return lines
