"""Rule family: network. Checks across the nodes of one network (several DCFs, `lint --network`)."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, NamedTuple

from ..model import Device, Location, Severity
from ..model.cia301.cobid import (
    ALL_NODE_IDS,
    BASE_11BIT,
    EMCY_BASE,
    HEARTBEAT_BASE,
    PREDEFINED,
    RTR,
    SDO_TX_BASE,
    SYNC_ID,
    VALID,
    Cob,
    cob_of,
    known_node_id,
    restricted,
)
from ..model.cia301.connections import producers
from ..model.cia301.objects import COB_ID_EMCY, COB_ID_SYNC
from ..model.cia301.pdo import RX, TX, MapEntry, Pdo, pdos
from ..model.cia301.slots import slot
from ..model.source import location
from . import examples as ex
from .pdoread import with_severity
from .rules import Clause, Context, Finding, LintOptions, Placement, rule

if TYPE_CHECKING:
    from ..network.plan import NetworkPlan, PlannedPdo

UNCONFIGURED_NODE_ID = 255  # a master's node-ID left to LSS
SYNC_TRANSMISSION_LAST = 240  # transmission types 0-240: sent or taken over on SYNC


@rule(
    "COB011",
    Severity.ERROR,
    "Network: node-IDs, CAN-ID producers, PDO layouts or SYNC producers disagree",
    """
Checked by `lint --network` over the DCFs of one network. Each node needs its own node-ID; each
CAN-ID has one producer; an RPDO reads what the TPDO with its CAN-ID sends, so both must agree
on the total length and on where each mapped object starts and ends; one node at most produces
SYNC (1005h bit 30). Errors: shared node-IDs, shared producers, layouts that differ, several SYNC
producers. Warnings: an RPDO no node sends, objects of one length but different data types, a
node without a node-ID (its `$NODEID` COB-IDs are then skipped).

Given a bus description (`lint --network bus.yml`, and `network` before it writes anything), the
network is the one the master configures (CiA 302-2): the slaves' PDOs as the YAML remaps them and
the master's mirrors of their RPDOs. Errors, at the YAML's line: shared node-IDs, a CAN-ID sent by
two nodes (or in a range CiA 301 reserves), an RPDO that reads another slave's TPDO with another
length or layout, a `sdo` entry the master cannot write (no such object, not writable, outside its
data type or its LowLimit/HighLimit), a slave producing SYNC besides the master, a heartbeat
multiplier below 1. Warnings: an RPDO listening to a node's pre-defined TPDO CAN-ID that the node
does not send, a slave consuming a heartbeat the master does not produce, synchronous PDOs without
a SYNC producer.""",
    "; file: a.dcf\n" + ex.NODE_5 + "; file: b.dcf\n" + ex.NODE_5 + "; $ cantools-od lint --network a.dcf b.dcf",
    fixed="; file: a.dcf\n"
    + ex.NODE_5
    + "; file: b.dcf\n"
    + ex.NODE_5.replace("NodeID=5", "NodeID=6")
    + "; $ cantools-od lint --network a.dcf b.dcf",
    fix_safety="No automatic fix: which node changes its node-ID or its COB-IDs is the integrator's decision.",
    placed=Placement(Clause.DEVICE_MISBEHAVES, "nodes on one network collide or read each other's PDOs wrong"),
)
def check_single_device(ctx: Context) -> Iterable[Finding]:
    """COB011 needs the whole network: `lint_network` reports it, a single file has nothing to say."""
    return ()


@dataclass
class _Node:
    device: Device
    ctx: Context
    node_id: int | None
    pdos: list[Pdo]

    @property
    def name(self) -> str:
        return self.device.source or "<input>"

    def resolves(self, cob: Cob) -> int | None:
        """The node-ID to resolve `cob` with; None when it needs one this node does not have."""
        if not cob.symbolic:
            return 1
        return self.node_id


def _report(node: _Node, message: str, location: Location, severity: Severity = Severity.ERROR) -> Finding:
    finding = node.ctx.report("COB011", message, location)
    return finding if severity is Severity.ERROR else with_severity(finding, severity)


def lint_network(devices: list[Device], options: LintOptions) -> list[Finding]:
    """Findings about the devices as one network, each located in the file at fault."""
    nodes: list[_Node] = []
    for device in (device.as_built() for device in devices):
        node_id = known_node_id(device, options.node_id if device.node_id is None else None)
        nodes.append(_Node(device, Context(device, options), node_id, pdos(device)))
    findings = [*_node_ids(nodes)]
    distinct = _distinct(nodes)
    findings.extend(_shared_producers(distinct))
    findings.extend(_consumers(distinct))
    findings.extend(_sync_producers(nodes))
    return findings


def _node_id_location(node: _Node) -> Location:
    return node.ctx.at(node.device.commissioning, "NodeID")


def _node_ids(nodes: list[_Node]) -> Iterator[Finding]:
    owner: dict[int, _Node] = {}
    for node in nodes:
        if node.node_id is None:
            yield _report(
                node,
                "no node-ID (1-127): its $NODEID COB-IDs are not checked",
                _node_id_location(node),
                Severity.WARNING,
            )
        elif node.node_id in owner:
            yield _report(
                node,
                f"node-ID {node.node_id} is also the node-ID of {owner[node.node_id].name}",
                _node_id_location(node),
            )
        else:
            owner[node.node_id] = node


def _distinct(nodes: list[_Node]) -> list[_Node]:
    """The nodes without a node-ID taken before: a shared node-ID is reported once, not per COB-ID."""
    seen: set[int] = set()
    kept = []
    for node in nodes:
        if node.node_id is None or node.node_id not in seen:
            kept.append(node)
        if node.node_id is not None:
            seen.add(node.node_id)
    return kept


def _produced(nodes: list[_Node]) -> Iterator[tuple[_Node, Cob, tuple[bool, int]]]:
    """Every valid COB-ID a node sends, resolved for its node-ID."""
    for node in nodes:
        for cob in producers(node.device, node.pdos):
            if cob.role == "SYNC":  # several SYNC producers: `_sync_producers`
                continue
            node_id = node.resolves(cob)
            if node_id is not None and cob.valid(node_id) and cob.can_id(node_id)[1]:
                yield node, cob, cob.can_id(node_id)


def _shared_producers(nodes: list[_Node]) -> Iterator[Finding]:
    first: dict[tuple[bool, int], tuple[_Node, Cob]] = {}
    for node, cob, can_id in _produced(nodes):
        other = first.setdefault(can_id, (node, cob))
        if other[0] is not node:
            where = cob.location(node.ctx) if cob.slot is not None else node.ctx.at(None)
            yield _report(
                node,
                f"{cob.role} sends CAN-ID {_hex(can_id)}, which {other[0].name} ({other[1].role}) sends too",
                where,
            )


def _hex(can_id: tuple[bool, int]) -> str:
    return f"{can_id[1]:08X}h (29-bit)" if can_id[0] else f"{can_id[1]:03X}h"


def _consumers(nodes: list[_Node]) -> Iterator[Finding]:
    senders: dict[tuple[bool, int], tuple[_Node, Cob]] = {}
    for node, cob, can_id in _produced(nodes):
        senders.setdefault(can_id, (node, cob))
    tpdos = {(id(node), pdo.comm_index): pdo for node in nodes for pdo in node.pdos if pdo.direction == TX}
    for node in nodes:
        for pdo in node.pdos:
            mine = pdo.cob() if pdo.direction == RX else None
            node_id = node.resolves(mine) if mine is not None else None
            if mine is None or node_id is None or not mine.valid(node_id) or not mine.can_id(node_id)[1]:
                continue
            can_id = mine.can_id(node_id)
            sender = senders.get(can_id)
            if sender is None:
                message = f"{pdo.name} receives CAN-ID {_hex(can_id)}, which no node of the network sends"
                yield _report(node, message, mine.location(node.ctx), Severity.WARNING)
                continue
            source, source_cob = sender
            slot_ = source_cob.slot
            producer = tpdos.get((id(source), slot_.owner.index)) if slot_ is not None else None
            if producer is None:
                message = f"{pdo.name} receives CAN-ID {_hex(can_id)}, which is {source.name}'s {source_cob.role}"
                yield _report(node, message, mine.location(node.ctx))
            else:
                yield from _layout(node, pdo, source, producer)


def _layout(node: _Node, rpdo: Pdo, source: _Node, tpdo: Pdo) -> Iterator[Finding]:
    """An RPDO against the TPDO that feeds it: same total, each mapped object on a producer entry."""
    theirs = f"{source.name} {tpdo.name}"
    received, sent = rpdo.mapped(), tpdo.mapped()
    total_in, total_out = sum(e.bits for e in received), sum(e.bits for e in sent)
    count = rpdo.count_slot()
    if total_in != total_out and count is not None:
        message = f"{rpdo.name} maps {total_in} bits, but {theirs} sends {total_out} bits"
        yield _report(node, message, count.location(node.ctx))
        return
    by_offset = {entry.offset: entry for entry in sent}
    for entry in received:
        if entry.is_dummy:
            continue
        match = by_offset.get(entry.offset)
        if match is None or match.bits != entry.bits:
            there = _describe(match) if match is not None else "no entry starts there"
            message = f"{rpdo.name} maps {entry.target} at bits {_bits(entry)}, but {theirs} does not ({there})"
            yield _report(node, message, entry.slot.location(node.ctx))
            return
        mine, their_type = _type_name(node.device, entry), _type_name(source.device, match)
        if mine and their_type and mine != their_type:
            message = (
                f"{rpdo.name} receives {entry.target} as {mine}, but {theirs} sends {match.target} as {their_type}"
            )
            yield _report(node, message, entry.slot.location(node.ctx), Severity.WARNING)


def _bits(entry: MapEntry) -> str:
    return f"{entry.offset}-{entry.offset + entry.bits - 1}"


def _describe(entry: MapEntry) -> str:
    return f"it sends {entry.target} at bits {_bits(entry)}"


def _type_name(device: Device, entry: MapEntry) -> str | None:
    if entry.is_dummy:
        return None
    found = slot(device, entry.index, entry.subindex)
    dtype = device.entry_type(found.var, found.owner) if found is not None else None
    return dtype.name if dtype is not None else None


def _sync_producers(nodes: list[_Node]) -> Iterator[Finding]:
    first: _Node | None = None
    for node in nodes:
        cob = cob_of(slot(node.device, COB_ID_SYNC, 0), "SYNC")
        if cob is None or not isinstance(cob.value, int) or not cob.value & RTR:
            continue
        if first is None:
            first = node
        else:
            message = f"SYNC producer (1005h bit 30), but {first.name} produces SYNC too"
            yield _report(node, message, cob.location(node.ctx))


# A bus description (bus.yml): the same family of checks, over the network its plan gives, at the YAML's lines.


class _Sender(NamedTuple):
    who: str
    what: str
    line: int
    pdo: PlannedPdo | None = None


def lint_bus(plan: NetworkPlan) -> list[Finding]:
    """COB011 findings about a planned network (node-IDs, CAN-ID producers, PDO feeds and layouts,
    heartbeats, SYNC), each at the line of the bus description that causes it; shared node-IDs first."""
    file = plan.network.file
    causes = sorted(_bus_node_ids(plan, file), key=lambda f: f.location.line)
    findings = [_bus_finding(file, line, message) for slave in plan.slaves for line, message in slave.problems]
    senders = _bus_senders(plan)
    findings.extend(_bus_collisions(senders, file))
    findings.extend(_bus_consumers(plan, senders, file))
    findings.extend(_bus_heartbeats(plan, file))
    findings.extend(_bus_sync(plan, file))
    # a shared node-ID first: the CAN-ID clashes of its heartbeat, SDO and EMCY follow from it
    return causes + sorted(findings, key=lambda f: (f.location.line, f.message))


def _bus_finding(file: str, line: int, message: str, severity: Severity = Severity.ERROR) -> Finding:
    return Finding("COB011", severity, message, location(file, line, 1))


def _bus_node_ids(plan: NetworkPlan, file: str) -> Iterator[Finding]:
    owner: dict[int, str] = {}
    if plan.master.node_id != UNCONFIGURED_NODE_ID:
        owner[plan.master.node_id] = "the master"
    for slave in plan.slaves:
        if slave.node_id in owner:
            line = slave.slave.line_of("node_id")
            yield _bus_finding(
                file, line, f"{slave.slave.name}: node-ID {slave.node_id} is also {owner[slave.node_id]}'s"
            )
        else:
            owner[slave.node_id] = slave.slave.name


def _bus_senders(plan: NetworkPlan) -> dict[int, list[_Sender]]:
    """Every 11-bit CAN-ID sent on the bus, with who sends it: slaves' TPDOs, EMCY, heartbeats and SDO
    responses, and the master's mirrors of the slaves' RPDOs and its SYNC."""
    senders: dict[int, list[_Sender]] = {}

    def add(can_id: int, sender: _Sender) -> None:
        senders.setdefault(can_id & BASE_11BIT, []).append(sender)

    if plan.master.sync_period:
        add(SYNC_ID, _Sender("the master", "SYNC", plan.master.line_of("sync_period")))
    for slave in plan.slaves:
        name, line = slave.slave.name, slave.slave.line
        node = slave.node_id
        for pdo in slave.active(TX):
            add(pdo.cob_id, _Sender(name, pdo.name, pdo.line or line, pdo))
        for pdo in slave.active(RX):
            add(pdo.cob_id, _Sender("the master", f"its mirror of {name}'s {pdo.name}", pdo.line or line, pdo))
        add(HEARTBEAT_BASE + node, _Sender(name, "heartbeat", slave.slave.line_of("node_id")))
        add(SDO_TX_BASE + node, _Sender(name, "SDO response", slave.slave.line_of("node_id")))
        emcy = slave.cob_id(COB_ID_EMCY, 0) if slave.has(COB_ID_EMCY, 0) else EMCY_BASE + node
        if not emcy & VALID:
            add(emcy, _Sender(name, "EMCY", slave.slave.line_of("node_id")))
    return senders


def _bus_collisions(senders: dict[int, list[_Sender]], file: str) -> Iterator[Finding]:
    for can_id, group in sorted(senders.items()):
        for sender in group:
            if sender.pdo is not None and restricted(can_id):
                message = f"{sender.who}: {sender.what} uses CAN-ID {can_id:03X}h, which CiA 301 reserves"
                yield _bus_finding(file, sender.line, message)
        for later in group[1:]:
            first = group[0]
            if first.pdo is not None and later.pdo is not None and _same_master_mirror(first, later):
                continue
            message = (
                f"{later.who}: {later.what} sends CAN-ID {can_id:03X}h, which {first.who} ({first.what}) sends too"
            )
            yield _bus_finding(file, later.line, message)


def _same_master_mirror(first: _Sender, later: _Sender) -> bool:
    """Two slaves' RPDOs on one CAN-ID with one layout: one frame of the master feeds both (a broadcast)."""
    assert first.pdo is not None and later.pdo is not None
    both_master = first.who == later.who == "the master"
    return both_master and _layout_of(first.pdo) == _layout_of(later.pdo)


def _layout_of(pdo: PlannedPdo) -> list[tuple[int, int]]:
    return [(signal.offset, signal.bits) for signal in pdo.signals]


def _bus_consumers(plan: NetworkPlan, senders: dict[int, list[_Sender]], file: str) -> Iterator[Finding]:
    """A slave RPDO listening to another slave's TPDO must read what it sends; one listening to a node's
    pre-defined TPDO CAN-ID that the node does not send is fed by no one but the master's mirror."""
    nodes = {slave.node_id: slave for slave in plan.slaves}
    for slave in plan.slaves:
        for pdo in slave.active(RX):
            line = pdo.line or slave.slave.line
            can_id = pdo.cob_id & BASE_11BIT
            feeding = [s for s in senders.get(can_id, []) if s.pdo is not None and s.pdo.direction == TX]
            if feeding:
                yield from _bus_layout(file, line, slave.slave.name, pdo, feeding[0])
                continue
            owner = _predefined_owner(can_id)
            if owner is not None and owner[0] in nodes and owner[0] != slave.node_id:
                message = (
                    f"{slave.slave.name}: {pdo.name} listens to CAN-ID {can_id:03X}h ({nodes[owner[0]].slave.name}'s "
                    f"TPDO{owner[1]}), which {nodes[owner[0]].slave.name} does not send"
                )
                yield _bus_finding(file, line, message, Severity.WARNING)


def _predefined_owner(can_id: int) -> tuple[int, int] | None:
    for number, base in enumerate(PREDEFINED[TX], 1):
        if base < can_id <= base + ALL_NODE_IDS[-1]:
            return can_id - base, number
    return None


def _bus_layout(file: str, line: int, name: str, rpdo: PlannedPdo, sender: _Sender) -> Iterator[Finding]:
    assert sender.pdo is not None
    tpdo = sender.pdo
    theirs = f"{sender.who}'s {tpdo.name}"
    if rpdo.bits != tpdo.bits:
        yield _bus_finding(
            file, line, f"{name}: {rpdo.name} maps {rpdo.bits} bits, but {theirs} sends {tpdo.bits} bits"
        )
        return
    starts = {(signal.offset, signal.bits) for signal in tpdo.signals}
    for signal in rpdo.signals:
        if not signal.dummy and (signal.offset, signal.bits) not in starts:
            bits = f"{signal.offset}-{signal.offset + signal.bits - 1}"
            message = f"{name}: {rpdo.name} reads {signal.name} at bits {bits}, but {theirs} has no object there"
            yield _bus_finding(file, line, message)
            return


def _bus_heartbeats(plan: NetworkPlan, file: str) -> Iterator[Finding]:
    master = plan.master
    multiplier = master.heartbeat_multiplier or plan.network.options.heartbeat_multiplier
    for slave in plan.slaves:
        config = slave.slave
        if config.heartbeat_consumer and not master.heartbeat_producer:
            message = (
                f"{config.name}: heartbeat_consumer, but the master sends no heartbeat (master heartbeat_producer)"
            )
            yield _bus_finding(file, config.line_of("heartbeat_consumer"), message, Severity.WARNING)
        own = config.heartbeat_multiplier or plan.network.options.heartbeat_multiplier
        if slave.heartbeat_producer and master.heartbeat_consumer and own < 1:
            message = f"{config.name}: heartbeat_multiplier {own} makes the master time out before each heartbeat"
            yield _bus_finding(file, config.line_of("heartbeat_multiplier"), message)
    if master.heartbeat_producer and multiplier < 1:
        message = f"master: heartbeat_multiplier {multiplier} makes the slaves time out before each heartbeat"
        yield _bus_finding(file, master.line_of("heartbeat_multiplier"), message)


def _bus_sync(plan: NetworkPlan, file: str) -> Iterator[Finding]:
    producers = ["the master"] if plan.master.sync_period else []
    for slave in plan.slaves:
        if slave.has(COB_ID_SYNC, 0) and slave.value(COB_ID_SYNC, 0) & RTR:
            if producers:
                message = f"{slave.slave.name}: produces SYNC (1005h bit 30), and so does {producers[0]}"
                yield _bus_finding(file, slave.slave.line, message)
            producers.append(slave.slave.name)
    for slave in plan.slaves:
        synchronous = [p for p in slave.active(TX) + slave.active(RX) if p.transmission <= SYNC_TRANSMISSION_LAST]
        if synchronous and not producers:
            pdo = synchronous[0]
            message = (
                f"{slave.slave.name}: {pdo.name} is synchronous (transmission {pdo.transmission}), "
                "but no node produces SYNC (master sync_period)"
            )
            yield _bus_finding(file, pdo.line or slave.slave.line, message, Severity.WARNING)
