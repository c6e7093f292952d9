"""PDOs as a DBC: each PDO a message at its CAN-ID, each mapped object a little-endian signal at its
bit offset, signed and float as its data type says, built and written by the `cantools` library.

CANopen data types carry no scaling: a signal's factor is 1 and its offset 0, its range the data
type's; a unit is written where the description gives one. Dummy entries are gaps, not signals.
Each signal names the nodes that receive its PDO; a cyclic PDO (synchronous 1-240, or an event
timer) and SYNC carry their cycle as GenMsgCycleTime.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from ..model import ValueKind
from ..model.cia301.cobid import BASE_11BIT, BASE_29BIT, EXTENDED, SYNC_ID, VALID
from ..model.cia301.objects import RX, TX
from .load import pdo_period
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


def _signal(signal: Signal, taken: set[str], receivers: list[str]) -> DbcSignal:
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
        receivers=list(receivers),
    )


@dataclass
class Sent:
    """One PDO of the DBC: who sends it, its message name, who receives it, its cycle in µs (None: events)."""

    pdo: PlannedPdo
    sender: str
    name: str
    receivers: list[str] = field(default_factory=list)
    cycle: int | None = None


def _cycle_ms(cycle: int | None) -> int | None:
    """GenMsgCycleTime is whole milliseconds: a cycle below 1 ms is written as 1."""
    return max(1, round(cycle / 1000)) if cycle else None


def _message(sent: Sent) -> DbcMessage:
    from cantools.database.can import Message

    pdo = sent.pdo
    taken: set[str] = set()
    signals = [_signal(signal, taken, sent.receivers) for signal in pdo.signals if not signal.dummy and signal.bits]
    extended = bool(pdo.cob_id & EXTENDED)
    length = (pdo.bits + 7) // 8
    return Message(
        frame_id=pdo.cob_id & (BASE_29BIT if extended else BASE_11BIT),
        name=sent.name,
        length=length,
        signals=signals,
        senders=[sent.sender],
        is_extended_frame=extended,
        is_fd=length > CLASSIC_BYTES,
        comment=f"{sent.sender} {pdo.name} (transmission type {pdo.transmission})",
        cycle_time=_cycle_ms(sent.cycle),
        strict=True,
    )


def dbc_text(messages: Iterable[Sent], nodes: Iterable[str] = (), extra: Iterable[DbcMessage] = ()) -> bytes:
    """A DBC of the given PDOs (a CAN-ID already taken keeps its first message) and `extra` messages;
    its nodes (BU_) are `nodes` and every sender and receiver."""
    from cantools.database.can import Database, Node

    seen: set[tuple[bool, int]] = set()
    built = [*extra]
    names: list[str] = list(nodes)
    for sent in messages:
        pdo = sent.pdo
        if pdo.cob_id & VALID or not pdo.signals:
            continue
        key = (bool(pdo.cob_id & EXTENDED), pdo.cob_id & BASE_29BIT)
        if key in seen:
            continue
        seen.add(key)
        built.append(_message(sent))
        names.extend(name for name in [sent.sender, *sent.receivers] if name not in names)
    database = Database(messages=built, nodes=[Node(name) for name in dict.fromkeys(names)])
    text: str = database.as_dbc_string()
    return text.encode("utf-8")


def _receivers(plan: NetworkPlan) -> dict[int, list[str]]:
    """Who receives each 11/29-bit CAN-ID: the master every slave's TPDO (it mirrors them all), each
    slave what its active RPDOs listen to."""
    found: dict[int, list[str]] = {}
    for slave in plan.slaves:
        for pdo in slave.active(TX):
            found.setdefault(pdo.cob_id & BASE_29BIT, []).append(MASTER)
        node = _identifier(slave.slave.name, f"node{slave.node_id}")
        for pdo in slave.active(RX):
            found.setdefault(pdo.cob_id & BASE_29BIT, []).append(node)
    return found


MASTER = "master"


def network_dbc(plan: NetworkPlan) -> bytes:
    """Every active PDO of the network: the slaves' TPDOs sent by them, their RPDOs sent by the master;
    each with its receivers and, when it is cyclic, its cycle time (GenMsgCycleTime); SYNC when the
    master sends it. Every node is in BU_, one that only receives too."""
    from cantools.database.can import Message

    receivers = _receivers(plan)
    period = plan.master.sync_period
    nodes = [MASTER] + [_identifier(s.slave.name, f"node{s.node_id}") for s in plan.slaves]
    messages = []
    for slave, node in zip(plan.slaves, nodes[1:], strict=True):
        for pdo in slave.pdos:
            if not pdo.active or not pdo.signals:
                continue
            sender = node if pdo.direction == TX else MASTER
            heard = [name for name in dict.fromkeys(receivers.get(pdo.cob_id & BASE_29BIT, [])) if name != sender]
            messages.append(Sent(pdo, sender, f"{node}_{pdo.name}", heard, pdo_period(pdo, period)))
    sync = []
    if period:
        sync.append(
            Message(
                frame_id=SYNC_ID,
                name="SYNC",
                length=0,
                signals=[],
                senders=[MASTER],
                comment=f"SYNC, every {period} µs",
                cycle_time=_cycle_ms(period),
            )
        )
    return dbc_text(messages, nodes, sync)


def device_dbc(pdos: list[PlannedPdo], name: str) -> bytes:
    """One device's PDOs: its TPDOs sent by it to the rest of the network, its RPDOs sent by the rest."""
    node = _identifier(name, "device")
    messages = [
        Sent(p, node, f"{node}_{p.name}", ["network"], pdo_period(p, 0))
        if p.direction == TX
        else Sent(p, "network", f"{node}_{p.name}", [node])
        for p in pdos
        if p.active
    ]
    return dbc_text(messages, [node])
