"""PDOs as a DBC: each PDO a message at its CAN-ID, each mapped object a little-endian signal at its
bit offset, signed and float as its data type says, built and written by the `cantools` library.

CANopen data types carry no scaling: a signal's factor is 1 and its offset 0, its range the data
type's; a unit is written where the description gives one. Dummy entries are gaps, not signals.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import TYPE_CHECKING

from ..model import ValueKind
from ..model.cia301.cobid import BASE_11BIT, BASE_29BIT, EXTENDED, VALID
from ..model.cia301.objects import TX
from .plan import NetworkPlan, PlannedPdo, Signal

if TYPE_CHECKING:
    from cantools.database.can import Message as DbcMessage
    from cantools.database.can import Signal as DbcSignal

CLASSIC_BYTES = 8


def _identifier(text: str, fallback: str) -> str:
    """A DBC name: letters, digits and underscores, not starting with a digit."""
    name = re.sub(r"[^A-Za-z0-9_]+", "_", text).strip("_")
    if not name:
        name = fallback
    return f"_{name}" if name[0].isdigit() else name


def _signal(signal: Signal, taken: set[str]) -> DbcSignal:
    from cantools.database.can import Signal as DbcSignal
    from cantools.database.conversion import BaseConversion

    dtype = signal.dtype
    is_float = dtype is not None and dtype.kind is ValueKind.REAL
    signed = dtype is not None and dtype.kind is ValueKind.SIGNED
    name = _identifier(signal.name, f"o{signal.index:04X}")
    if name in taken:
        name = f"{name}_{signal.index:04X}sub{signal.sub:X}"
    taken.add(name)
    low_high = dtype.int_range() if dtype is not None and not is_float else None
    return DbcSignal(
        name=name,
        start=signal.offset,
        length=signal.bits,
        byte_order="little_endian",
        is_signed=signed,
        conversion=BaseConversion.factory(scale=1, offset=0, is_float=is_float),
        minimum=low_high[0] if low_high is not None else None,
        maximum=low_high[1] if low_high is not None else None,
        unit=signal.unit or None,
        comment=f"{signal.index:04X}sub{signal.sub:X} {signal.name}",
    )


def _message(pdo: PlannedPdo, sender: str, name: str) -> DbcMessage:
    from cantools.database.can import Message

    taken: set[str] = set()
    signals = [_signal(signal, taken) for signal in pdo.signals if not signal.dummy and signal.bits]
    extended = bool(pdo.cob_id & EXTENDED)
    length = (pdo.bits + 7) // 8
    return Message(
        frame_id=pdo.cob_id & (BASE_29BIT if extended else BASE_11BIT),
        name=name,
        length=length,
        signals=signals,
        senders=[sender],
        is_extended_frame=extended,
        is_fd=length > CLASSIC_BYTES,
        comment=f"{sender} {pdo.name} (transmission type {pdo.transmission})",
        strict=True,
    )


def dbc_text(messages: Iterable[tuple[PlannedPdo, str, str]]) -> bytes:
    """A DBC of the given (PDO, sender, message name); a CAN-ID already taken keeps its first message."""
    from cantools.database.can import Database, Node

    seen: set[tuple[bool, int]] = set()
    built = []
    senders: list[str] = []
    for pdo, sender, name in messages:
        if pdo.cob_id & VALID or not pdo.signals:
            continue
        key = (bool(pdo.cob_id & EXTENDED), pdo.cob_id & BASE_29BIT)
        if key in seen:
            continue
        seen.add(key)
        built.append(_message(pdo, sender, name))
        if sender not in senders:
            senders.append(sender)
    database = Database(messages=built, nodes=[Node(name) for name in senders])
    text: str = database.as_dbc_string()
    return text.encode("utf-8")


def network_dbc(plan: NetworkPlan) -> bytes:
    """Every active PDO of the network: the slaves' TPDOs sent by them, their RPDOs sent by the master."""
    messages = []
    for slave in plan.slaves:
        node = _identifier(slave.slave.name, f"node{slave.node_id}")
        for pdo in slave.pdos:
            if not pdo.active or not pdo.signals:
                continue
            sender = node if pdo.direction == TX else "master"
            messages.append((pdo, sender, f"{node}_{pdo.name}"))
    return dbc_text(messages)


def device_dbc(pdos: list[PlannedPdo], name: str) -> bytes:
    """One device's PDOs: its TPDOs sent by it, its RPDOs by the rest of the network."""
    node = _identifier(name, "device")
    messages = [(p, node if p.direction == TX else "network", f"{node}_{p.name}") for p in pdos if p.active]
    return dbc_text(messages)
