"""Who sends what to whom on a bus: the nodes and the messages between them, for the bus picture.

A slave's TPDO is consumed by the master (which receives every PDO a slave sends, as dcfgen configures it) and
by every slave whose RPDO listens on its CAN-ID; a slave's RPDO that no slave feeds is sent by the master. SYNC
goes from the master to every slave; a heartbeat from its producer to the master where the master consumes
heartbeats. Rates and the share of the bus each node takes come from the bus load (load.py), so the picture and
`--load` never disagree.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from ..model.cia301.cobid import BASE_29BIT, HEARTBEAT_BASE, SYNC_ID
from ..model.cia301.objects import CONSUMER_HEARTBEAT, RX, TX
from ..model.cia301.slots import as_int
from .load import Frame, Load, bus_load
from .plan import NetworkPlan, PlannedPdo, SlavePlan

MASTER = "master"


@dataclass(frozen=True)
class Node:
    name: str
    node_id: int
    is_master: bool
    load: float  # % of the bus its frames take, per second


@dataclass(frozen=True)
class Message:
    kind: str  # "pdo", "sync" or "heartbeat"
    can_id: int
    name: str
    producer: str
    consumers: tuple[str, ...]
    timing: str  # when it is sent, as the bus load reads it

    @property
    def can_id_text(self) -> str:
        return f"{self.can_id:03X}"

    @property
    def label(self) -> str:
        return f"{self.can_id_text}h  {self.name}  {self.timing}"


@dataclass(frozen=True)
class BusPicture:
    title: str
    nodes: tuple[Node, ...]
    messages: tuple[Message, ...]


def bus_picture(plan: NetworkPlan, data_rate: int | None = None) -> BusPicture:
    load = bus_load(plan, data_rate)
    master = plan.master
    nodes = [Node(MASTER, master.node_id, True, _share(load, MASTER))]
    nodes += [Node(s.slave.name, s.node_id, False, _share(load, s.slave.name)) for s in plan.slaves]
    messages: list[Message] = []
    slaves = tuple(s.slave.name for s in plan.slaves)
    if master.sync_period:
        messages.append(Message("sync", SYNC_ID, "SYNC", MASTER, slaves, _timing(load, MASTER, SYNC_ID)))
    for slave in plan.slaves:
        messages += _pdos(plan, slave, load)
    if master.heartbeat_producer:
        beat = HEARTBEAT_BASE + master.node_id
        listeners = tuple(s.slave.name for s in plan.slaves if master.node_id in _heartbeats_consumed(s))
        messages.append(Message("heartbeat", beat, "master heartbeat", MASTER, listeners, _timing(load, MASTER, beat)))
    for slave in plan.slaves:
        if slave.heartbeat_producer:
            beat = HEARTBEAT_BASE + slave.node_id
            consumers = (MASTER,) if master.heartbeat_consumer else ()
            name = f"{slave.slave.name} heartbeat"
            messages.append(
                Message("heartbeat", beat, name, slave.slave.name, consumers, _timing(load, slave.slave.name, beat))
            )
    per_second = f"bus load {load.percent_per_second():.1f} % per second"
    worst = f", {load.percent_per_sync():.1f} % in the worst SYNC period" if load.sync_period else ""
    title = f"{Path(plan.network.file).name} · {master.baudrate} kbit/s · {per_second}{worst}"
    return BusPicture(title, tuple(nodes), tuple(messages))


def _can_id(pdo: PlannedPdo) -> int:
    return pdo.cob_id & BASE_29BIT


def _pdos(plan: NetworkPlan, slave: SlavePlan, load: Load) -> list[Message]:
    """The slave's TPDOs with their consumers, and its RPDOs that only the master can feed."""
    name = slave.slave.name
    found = []
    for pdo in slave.active(TX):
        listeners = [other.slave.name for other in plan.slaves if other is not slave and _listens(other, _can_id(pdo))]
        consumers = (MASTER, *listeners)
        found.append(
            Message("pdo", _can_id(pdo), f"{name} {pdo.name}", name, consumers, _timing(load, name, _can_id(pdo)))
        )
    for pdo in slave.active(RX):
        if any(_sends(other, _can_id(pdo)) for other in plan.slaves if other is not slave):
            continue  # drawn with the TPDO that feeds it
        timing = _timing(load, MASTER, _can_id(pdo))
        found.append(Message("pdo", _can_id(pdo), f"{name} {pdo.name}", MASTER, (name,), timing))
    return found


def _heartbeats_consumed(slave: SlavePlan) -> set[int]:
    """The node-IDs whose heartbeat the slave's 1016h watches (bits 23-16 of an entry with a time)."""
    consumer = slave.device.objects.get(CONSUMER_HEARTBEAT)
    if consumer is None or not consumer.has_subs:
        return set()
    values = (as_int(var.value(slave.node_id)) for sub, var in consumer.subs.items() if sub)
    return {(value >> 16) & 0xFF for value in values if value is not None and value & 0xFFFF}


def _listens(slave: SlavePlan, can_id: int) -> bool:
    return any(_can_id(pdo) == can_id for pdo in slave.active(RX))


def _sends(slave: SlavePlan, can_id: int) -> bool:
    return any(_can_id(pdo) == can_id for pdo in slave.active(TX))


def _frame(load: Load, sender: str, can_id: int) -> Frame | None:
    return next((f for f in load.frames if f.sender == sender and f.can_id == can_id), None)


def _timing(load: Load, sender: str, can_id: int) -> str:
    frame = _frame(load, sender, can_id)
    return frame.note if frame is not None else "event-driven, rate not bounded"


def _share(load: Load, sender: str) -> float:
    rate = load.bit_rate * 1000
    return 100.0 * sum(f.bits * f.per_second for f in load.frames if f.sender == sender) / rate if rate else 0.0
