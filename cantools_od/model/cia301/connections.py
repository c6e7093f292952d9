"""The COB-ID entries of a device, as configured: what it sends and what it receives."""

from __future__ import annotations

from collections.abc import Iterator

from ..assemble import construct
from ..device import Device
from ..values import NodeIdExpr
from .cobid import EMCY_BASE, HEARTBEAT_BASE, RTR, SDO_RX_BASE, SDO_TX_BASE, VALID, Cob, cob_of
from .objects import COB_ID_EMCY, COB_ID_SYNC, COB_ID_TIME, SDO_CLIENTS, SDO_SERVERS
from .pdo import COMM_BASE, PREDEFINED, TX, Pdo, pdos
from .slots import slot


def predefined_cob_base(index: int, subindex: int) -> int | None:
    """The pre-defined connection set's base of the COB-ID entry at index/sub-index, else None."""
    if index == COB_ID_EMCY and subindex == 0:
        return EMCY_BASE
    if index == SDO_SERVERS[0] and subindex in (1, 2):
        return SDO_RX_BASE if subindex == 1 else SDO_TX_BASE
    for direction, base in COMM_BASE.items():
        if subindex == 1 and 0 <= index - base < len(PREDEFINED[direction]):
            return PREDEFINED[direction][index - base]
    return None


def cob_entries(device: Device, pdo_list: list[Pdo]) -> Iterator[Cob]:
    """Every COB-ID entry as configured: PDOs, SYNC, TIME, EMCY, SDO server and client."""
    for pdo in pdo_list:
        cob = pdo.cob()
        if cob is not None:
            yield cob
    for index, role in ((COB_ID_SYNC, "SYNC"), (COB_ID_TIME, "TIME"), (COB_ID_EMCY, "EMCY")):
        cob = cob_of(slot(device, index, 0), role)
        if cob is not None:
            yield cob
    for cob, _ in sdo_cobs(device):
        yield cob


def sdo_cobs(device: Device) -> Iterator[tuple[Cob, bool]]:
    """SDO COB-IDs with whether this device produces frames with them."""
    for index in range(SDO_SERVERS[0], SDO_CLIENTS[-1] + 1):
        if index not in device.objects:
            continue
        server = index in SDO_SERVERS
        kind = "server" if server else "client"
        for subindex, direction in ((1, "rx" if server else "tx"), (2, "tx" if server else "rx")):
            cob = cob_of(slot(device, index, subindex), f"SDO {kind} {index:04X}h ({direction})")
            if cob is not None:
                yield cob, direction == "tx"


def producers(device: Device, pdo_list: list[Pdo] | None = None) -> list[Cob]:
    """Every COB-ID this device sends frames with (validity is left to the caller)."""
    found: list[Cob] = []
    for pdo in pdo_list if pdo_list is not None else pdos(device):
        cob = pdo.cob() if pdo.direction == TX else None
        if cob is not None:
            found.append(cob)
    emcy = cob_of(slot(device, COB_ID_EMCY, 0), "EMCY")
    if emcy is not None:
        found.append(emcy)
    found.extend(cob for cob, produced in sdo_cobs(device) if produced)
    for index, role in ((COB_ID_SYNC, "SYNC"), (COB_ID_TIME, "TIME")):
        cob = cob_of(slot(device, index, 0), role)
        if cob is not None and isinstance(cob.value, int) and cob.value & RTR:  # bit 30: produces
            found.append(Cob(cob.slot, cob.value & ~(VALID | RTR), role))
    heartbeat = construct(NodeIdExpr, {"offset": HEARTBEAT_BASE, "text": f"$NODEID+0x{HEARTBEAT_BASE:X}"})
    found.append(Cob(None, heartbeat, "NMT error control (heartbeat)"))
    return found
