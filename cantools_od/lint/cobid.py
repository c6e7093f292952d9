"""Rule family: cobid. COB-IDs (CiA 301 §7.2-7.3) and the PDO communication parameters."""

from __future__ import annotations

from collections.abc import Callable, Iterator

from ..canopennode.profile import stack_adds_node_id
from ..model import Device, NodeIdExpr, Severity, standard_type
from ..model.assemble import construct
from ..model.cia301.cobid import (
    BASE_11BIT,
    BASE_29BIT,
    EXTENDED,
    HIGH_BITS,
    RTR,
    SDO_RX_BASE,
    SDO_TX_BASE,
    SERVICE_IDS,
    VALID,
    Cob,
    cob_of,
    collisions,
    default_cob,
    known_node_id,
    predefined_pdo,
    restricted,
)
from ..model.cia301.connections import cob_entries, predefined_cob_base, producers
from ..model.cia301.objects import COB_ID_EMCY, FIRST_SDO_SERVER
from ..model.cia301.pdo import COMM_SUBS, PREDEFINED, RX, TX, Pdo
from ..model.cia301.slots import Slot, slot
from . import examples as ex
from .pdoread import device_pdos, first, int_value, node_ids, with_severity
from .rules import Clause, Context, Finding, Fix, Placement, rule

E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO


def _type_name(index: int) -> str:
    dtype = standard_type(index)
    return dtype.name if dtype is not None else f"{index:04X}h"


def _pdo_cobs(ctx: Context) -> Iterator[tuple[Pdo, Cob]]:
    for pdo in device_pdos(ctx):
        cob = pdo.cob()
        if cob is not None:
            yield pdo, cob


# --- COB-IDs -----------------------------------------------------------------------------------


def _high_bits(cob: Cob, node_id: int) -> bool:
    value = cob.at(node_id)
    return not value & EXTENDED and bool(value & HIGH_BITS)


@rule(
    "COB001",
    E,
    "COB-ID with bits 28-11 set in an 11-bit frame",
    """
Bit 29 of a COB-ID selects the frame format: 0 for an 11-bit CAN-ID, whose bits 28-11 must
then be 0; 1 for a 29-bit CAN-ID. An 11-bit COB-ID with higher bits set is not a CAN-ID, and
devices refuse it. Checked for PDOs, SYNC, TIME, EMCY and SDO COB-IDs.""",
    lambda: ex.pdo("tx", "0x60410010", number=5, cob="0x80000981") + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010", number=5, cob="0x80000181") + ex.STATUSWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "not a CAN-ID: devices refuse it"),
)
def check_frame_bits(ctx: Context) -> Iterator[Finding]:
    ids = node_ids(ctx)
    for cob in cob_entries(ctx.device, device_pdos(ctx)):
        node_id = first(cob, ids, _high_bits)
        if node_id is not None:
            yield ctx.report(
                "COB001",
                f"{cob.role}: COB-ID {cob.shown(node_id)} sets bits 28-11 of an 11-bit CAN-ID (bit 29 is 0)",
                cob.location(ctx),
            )


def _valid_11bit(cob: Cob, node_id: int) -> int | None:
    extended, can_id = cob.can_id(node_id)
    return can_id if cob.valid(node_id) and not extended else None


def _restricted(cob: Cob, node_id: int) -> bool:
    can_id = _valid_11bit(cob, node_id)
    return can_id is not None and restricted(can_id)


def _service_id(cob: Cob, node_id: int) -> bool:
    can_id = _valid_11bit(cob, node_id)
    return can_id is not None and can_id in SERVICE_IDS


@rule(
    "COB004",
    E,
    "Valid PDO with a restricted CAN-ID",
    """
CiA 301 reserves CAN-IDs for NMT (000h), SYNC/EMCY area below 080h, the SDO (581h-5FFh,
601h-67Fh), NMT error control (701h-77Fh) and other services (101h-180h, 6E0h-6FFh, 780h-7FFh);
a PDO must not use them. With `$NODEID` the COB-ID is checked for every node-ID the device may
have, and the first one that fails is named.

A CANopenNode project (written by CANopenEditor, or checked with `--profile canopennode`) may store
a PDO's pre-defined base (0x180): the stack sends on it + node-ID (CO_PDO.c), every other tool on
the restricted 180h. The finding then says so and offers `$NODEID+0x180` (unsafe: what peers read
changes).""",
    lambda: ex.NODE_5 + ex.pdo("tx", "0x60410010", cob="0x585") + ex.STATUSWORD,
    fixed=lambda: ex.NODE_5 + ex.pdo("tx", "0x60410010", cob="0x185") + ex.STATUSWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the PDO collides with a CiA 301 service on the bus"),
)
def check_restricted(ctx: Context) -> Iterator[Finding]:
    ids = node_ids(ctx)
    for pdo, cob in _pdo_cobs(ctx):
        node_id = first(cob, ids, _restricted)
        if node_id is None:
            continue
        message = f"{pdo.name}: COB-ID {cob.shown(node_id)} is a restricted CAN-ID"
        fix = None
        if _stack_rebased(ctx, cob):
            base = construct(NodeIdExpr, {"offset": cob.at(0)})
            message = (
                f"{pdo.name}: COB-ID {cob.written} is the pre-defined base: CANopenNode sends on it + node-ID, "
                f"but every other tool reads the restricted CAN-ID {cob.describe(0)}; write {base.canonical()}"
            )
            fix = Fix(f"write {base.canonical()}", False, _hold(cob, base))
        yield ctx.report("COB004", message, cob.location(ctx), fix)


def _hold(cob: Cob, value: NodeIdExpr) -> Callable[[Device], None]:
    assert cob.slot is not None
    index, subindex = cob.slot.owner.index, cob.slot.subindex

    def apply(device: Device) -> None:
        found = slot(device, index, subindex)
        if found is not None:
            found.var.hold(value)

    return apply


@rule(
    "COB005",
    W,
    "Valid PDO on the SYNC, EMCY or TIME CAN-ID",
    """
CAN-IDs 080h (SYNC), 081h-0FFh (EMCY of the pre-defined connection set) and 100h (TIME) belong
to those services by default. A PDO there collides as soon as a node uses them, and its high
priority starves other traffic.""",
    lambda: ex.NODE_5 + ex.pdo("tx", "0x60410010", cob="0x90") + ex.STATUSWORD,
    fixed=lambda: ex.NODE_5 + ex.pdo("tx", "0x60410010", cob="0x185") + ex.STATUSWORD,
    placed=Placement(Clause.BEYOND_THE_PEERS, "collides as soon as a node uses SYNC, EMCY or TIME"),
)
def check_service_ids(ctx: Context) -> Iterator[Finding]:
    ids = node_ids(ctx)
    for pdo, cob in _pdo_cobs(ctx):
        node_id = first(cob, ids, _service_id)
        if node_id is not None:
            yield ctx.report(
                "COB005",
                f"{pdo.name}: COB-ID {cob.shown(node_id)} is the CAN-ID of SYNC, EMCY or TIME",
                cob.location(ctx),
            )


def _predefined(ctx: Context) -> Iterator[tuple[Cob, int]]:
    """Default COB-IDs that CiA 301's pre-defined connection set fixes, with their base."""
    for pdo in device_pdos(ctx):
        if pdo.number <= 4:
            cob = default_cob(pdo.comm_slot(1), pdo.name)
            if cob is not None:
                yield cob, PREDEFINED[pdo.direction][pdo.number - 1]
    sdo = FIRST_SDO_SERVER
    for index, subindex, role in ((COB_ID_EMCY, 0, "EMCY"), (sdo, 1, f"SDO server {sdo:04X}h (rx)"),
                                  (sdo, 2, f"SDO server {sdo:04X}h (tx)")):  # fmt: skip
        cob = default_cob(slot(ctx.device, index, subindex), role)
        base = predefined_cob_base(index, subindex)
        if cob is not None and base is not None:
            yield cob, base


@rule(
    "COB006",
    W,
    "Default COB-ID is not the pre-defined `$NODEID+...`",
    """
CiA 301's pre-defined connection set gives EMCY (80h), the default SDO server (600h/580h) and
PDOs 1-4 (RPDO 200h/300h/400h/500h, TPDO 180h/280h/380h/480h) COB-IDs of base + node-ID. An EDS
describes every node of its kind, so it writes them as `$NODEID+0x180`: a literal such as
`0x181` fits one node-ID only, and another base breaks the convention masters rely on.
A disabled PDO without CAN-ID (0x80000000) is accepted. Not checked in DCFs.

A fixed COB-ID is advised `$NODEID+base` only where it is base + a node-ID the device may have. An
RPDO on another pre-defined PDO's CAN-ID (190h: TPDO1 of node 16), or a TPDO on one (210h: RPDO1 of
node 16), usually consumes or feeds another node's PDO: `$NODEID` would break that link, so the
finding says what it links to and advises nothing. In a CANopenNode project a COB-ID that stores the
base itself (0x180) is what the stack adds the node-ID to (CO_PDO.c); other tools read it as is.""",
    lambda: ex.pdo("tx", "0x60410010", cob="0x181") + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD,
    placed=Placement(Clause.STYLE, "a literal fits one node-ID; the convention masters rely on"),
)
def check_predefined(ctx: Context) -> Iterator[Finding]:
    if ctx.device.is_dcf:
        return
    for cob, base in _predefined(ctx):
        value = cob.value
        if isinstance(value, NodeIdExpr):
            if value.offset & VALID or value.offset & ~RTR == base:
                continue
            problem = f"{value.canonical()} is not the pre-defined $NODEID+0x{base:X}"
        elif value & VALID and not value & BASE_29BIT:
            continue
        elif _stack_rebased(ctx, cob) and _restricted(cob, 0):
            continue  # COB004 says it: valid on the base, a restricted CAN-ID to every other reader
        else:
            problem = _fixed_id(ctx, cob, value, base)
        yield ctx.report("COB006", f"{cob.role}: default COB-ID {problem}", cob.location(ctx))


def _fixed_id(ctx: Context, cob: Cob, value: int, base: int) -> str:
    """What a literal default COB-ID means: this node's own pre-defined CAN-ID for one node-ID (advise $NODEID),
    the base CANopenNode adds the node-ID to, or another node's PDO it links to (no advice: $NODEID breaks it)."""
    wanted = construct(NodeIdExpr, {"offset": (value & (VALID | RTR)) | base}).canonical()
    can_id = value & (BASE_29BIT if value & EXTENDED else BASE_11BIT)
    if can_id == base:
        if _stack_rebased(ctx, cob):
            return f"0x{value:X} is the base CANopenNode adds the node-ID to; other tools read it as is: write {wanted}"
        return f"0x{value:X} is the base without a node-ID; write {wanted}"
    if can_id - base in node_ids(ctx) and not value & EXTENDED:
        return f"0x{value:X} fits one node-ID only; write {wanted}"
    linked = predefined_pdo(can_id) if cob.role[1:4] == "PDO" and not value & EXTENDED else None
    if linked is not None:
        direction, number, node = linked
        kind = "TPDO" if direction == TX else "RPDO"
        return (
            f"0x{value:X} is the pre-defined CAN-ID of {kind}{number} of node-ID {node}: likely a link to "
            f"another node's PDO, which $NODEID+0x{base:X} would break; keep it if so"
        )
    return f"0x{value:X} is not this node's pre-defined CAN-ID: a fixed CAN-ID fits one network only"


def _stack_rebased(ctx: Context, cob: Cob) -> bool:
    """A CANopenNode device stores the pre-defined base and sends on base + node-ID (literal COB-IDs only)."""
    slot_ = cob.slot
    if not ctx.for_canopennode or slot_ is None or isinstance(cob.value, NodeIdExpr):
        return False
    return stack_adds_node_id(slot_.owner.index, slot_.subindex, cob.value)


@rule(
    "COB012",
    W,
    "Default SDO server COB-ID changed or disabled",
    """
CiA 301 fixes the default SDO server (1200h): its COB-IDs are 600h + node-ID (client to server)
and 580h + node-ID (server to client), read-only. Masters reach every node there without reading
the file, and CANopenNode writes these values into 1200h at start-up whatever the file stores. A
file that disables them (bit 31) or moves them tells a tool that trusts it that the device has no
SDO server, or another one. A disabled one is reported here; a moved one in an EDS by COB006, in a
DCF here (against the commissioned node-ID).""",
    lambda: ex.sdo_server(rx="0x80000000", tx="0x80000000"),
    fixed=lambda: ex.sdo_server(),
    placed=Placement(
        Clause.PORTABILITY,
        "CANopenNode writes 600h/580h + node-ID whatever the file says; a tool that trusts the file does not",
    ),
)
def check_default_sdo_server(ctx: Context) -> Iterator[Finding]:
    node_id = known_node_id(ctx.device, ctx.options.node_id)
    for subindex, base in ((1, SDO_RX_BASE), (2, SDO_TX_BASE)):
        role = f"SDO server {FIRST_SDO_SERVER:04X}h sub{subindex}"
        cob = cob_of(slot(ctx.device, FIRST_SDO_SERVER, subindex), role)
        problem = _sdo_server_problem(cob, base, node_id if ctx.device.is_dcf else None) if cob else None
        if cob is not None and problem:
            message = f"{role}: {problem}; CiA 301 fixes the default SDO server at 0x{base:X} + node-ID"
            yield ctx.report("COB012", message, cob.location(ctx))


def _sdo_server_problem(cob: Cob, base: int, commissioned: int | None) -> str:
    """Disabled anywhere; moved in a DCF, against its node-ID (in an EDS COB006 says a moved one)."""
    if cob.at(1) & VALID:
        return f"{cob.written} disables it"
    if commissioned is not None and cob.at(commissioned) != base + commissioned:
        return f"{cob.written} is not 0x{base + commissioned:X} for node-ID {commissioned}"
    return ""


@rule(
    "COB007",
    W,
    "PDO 5 or higher valid by default",
    """
The pre-defined connection set ends at PDO 4; PDOs 5 to 512 have no default CAN-ID, so their
default COB-ID should be invalid (bit 31 set, e.g. 0x80000000) until a master assigns one.
`$NODEID` there is legal CiA 306, but CANopenNode rebases only PDOs 1-4, so firmware and EDS
then disagree. Not checked in DCFs.""",
    lambda: ex.pdo("rx", "0x60400010", number=5, cob="$NODEID+0x1C0") + ex.CONTROLWORD,
    fixed=lambda: ex.pdo("rx", "0x60400010", number=5) + ex.CONTROLWORD,
    placed=Placement(Clause.PORTABILITY, "`$NODEID` is legal; CANopenNode rebases only PDOs 1-4"),
)
def check_extra_pdos_invalid(ctx: Context) -> Iterator[Finding]:
    if ctx.device.is_dcf:
        return
    for pdo in device_pdos(ctx):
        cob = default_cob(pdo.comm_slot(1), pdo.name) if pdo.number > 4 else None
        if cob is not None and not cob.at(1) & VALID:
            yield ctx.report(
                "COB007",
                f"{pdo.name}: default COB-ID {cob.written} is valid; PDOs above 4 have no "
                "pre-defined CAN-ID (set bit 31)",
                cob.location(ctx),
            )


def _pair(first_cob: Cob, second: Cob, node_id: int) -> str:
    where = f" for node-ID {node_id}" if first_cob.symbolic or second.symbolic else ""
    return f"{first_cob.role} and {second.role} both use CAN-ID {second.describe(node_id)}{where}"


@rule(
    "COB009",
    E,
    "Two producers of this device share a CAN-ID",
    """
Each CAN-ID has exactly one producer on the bus. Two valid TPDOs of one device, or a TPDO and
another message the device sends (EMCY, SDO server response, SDO client request, SYNC or TIME
when produced, NMT error control at 700h + node-ID), on one CAN-ID collide: arbitration fails
and receivers mix up the data. `$NODEID` COB-IDs are compared for every node-ID the device may
have.""",
    lambda: (
        ex.NODE_5
        + ex.pdo("tx", "0x60410010", cob="0x185")
        + ex.pdo("tx", "0x60640020", number=2, cob="0x185")
        + ex.STATUSWORD
        + ex.POSITION
    ),
    fixed=lambda: (
        ex.NODE_5
        + ex.pdo("tx", "0x60410010", cob="0x185")
        + ex.pdo("tx", "0x60640020", number=2, cob="0x285")
        + ex.STATUSWORD
        + ex.POSITION
    ),
    placed=Placement(Clause.DEVICE_MISBEHAVES, "two producers on one CAN-ID: arbitration fails"),
)
def check_own_collisions(ctx: Context) -> Iterator[Finding]:
    cobs = producers(ctx.device, device_pdos(ctx))
    for earlier, later, node_id in collisions(cobs, node_ids(ctx)):
        located = later if later.slot is not None else earlier
        yield ctx.report("COB009", _pair(earlier, later, node_id), located.location(ctx))


@rule(
    "COB013",
    E,
    "RPDO on a CAN-ID this device sends",
    """
An RPDO receives what another node sends. On a CAN-ID this device produces itself (one of its
TPDOs, its EMCY, its SDO responses, its heartbeat) it waits for its own frames, which a CAN
controller does not receive, and no other node may send there without colliding with it: the RPDO
never receives. `$NODEID` COB-IDs are compared for every node-ID the device may have; where they
meet for one node-ID only and the node-ID is not known, it is a warning (the device cannot be that
node: oresat's GPS consumes node 1's TPDO1 on 181h).""",
    lambda: (
        ex.NODE_5
        + ex.pdo("tx", "0x60410010", cob="0x185")
        + ex.pdo("rx", "0x60400010", cob="0x185")
        + ex.STATUSWORD
        + ex.CONTROLWORD
    ),
    fixed=lambda: (
        ex.NODE_5
        + ex.pdo("tx", "0x60410010", cob="0x185")
        + ex.pdo("rx", "0x60400010", cob="0x205")
        + ex.STATUSWORD
        + ex.CONTROLWORD
    ),
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the RPDO never receives: a controller does not receive its own frames"),
)
def check_rpdo_on_own_producer(ctx: Context) -> Iterator[Finding]:
    sent = producers(ctx.device, device_pdos(ctx))
    for pdo, cob in _pdo_cobs(ctx):
        if pdo.direction != RX:
            continue
        for producer, later, node_id in collisions([*sent, cob], node_ids(ctx)):
            if later is not cob or _restricted(cob, node_id):
                continue  # two producers: COB009; a restricted CAN-ID: COB004
            message = f"{pdo.name} receives on {cob.describe(node_id)}, which this device sends as {producer.role}"
            if (cob.symbolic or producer.symbolic) and known_node_id(ctx.device, ctx.options.node_id) is None:
                # one node-ID of many: the device only cannot take that one
                message += f" if it is node-ID {node_id}"
                yield with_severity(ctx.report("COB013", message, cob.location(ctx)), W)
            else:
                yield ctx.report("COB013", message, cob.location(ctx))
            break


@rule(
    "COB010",
    INFO,
    "Two RPDOs share a CAN-ID",
    """
Two valid RPDOs with one CAN-ID both receive every frame of that producer. CiA 301 allows it
(one TPDO feeding several mappings, or a broadcast to several nodes); it is reported so that it
is a decision, not an accident.""",
    lambda: (
        ex.NODE_5
        + ex.pdo("rx", "0x60400010", cob="0x205")
        + ex.pdo("rx", "0x607A0020", number=2, cob="0x205")
        + ex.CONTROLWORD
        + ex.TARGET_POSITION
    ),
    fixed=lambda: (
        ex.NODE_5
        + ex.pdo("rx", "0x60400010", cob="0x205")
        + ex.pdo("rx", "0x607A0020", number=2, cob="0x305")
        + ex.CONTROLWORD
        + ex.TARGET_POSITION
    ),
    placed=Placement(Clause.DECISION, "CiA 301 allows one producer feeding several RPDOs"),
)
def check_shared_rpdo_ids(ctx: Context) -> Iterator[Finding]:
    cobs = [cob for pdo, cob in _pdo_cobs(ctx) if pdo.direction == RX]
    for earlier, later, node_id in collisions(cobs, node_ids(ctx)):
        yield ctx.report("COB010", _pair(earlier, later, node_id), later.location(ctx))


# --- communication record ----------------------------------------------------------------------


def _comm_subs(ctx: Context) -> Iterator[tuple[Pdo, Slot]]:
    for pdo in device_pdos(ctx):
        if pdo.comm is not None and pdo.comm.has_subs:
            for subindex, sub in pdo.comm.subs.items():
                yield pdo, Slot(pdo.comm, subindex, sub)


@rule(
    "PDO010",
    E,
    "Communication record sub0 does not match its sub-indices",
    """
Sub0 of a PDO communication record holds the highest sub-index the record supports (2..6).
Sub-objects above it do not exist for an SDO client, so an inhibit time or event timer
described there is never used. Above the highest sub-index described, it names entries a master
then reads and cannot (SDO abort). An RPDO's record ends at sub5 (CiA 301 §7.5.2.35), though RPDO
and TPDO records share one table: an RPDO that describes a sub6 and counts it is a warning.""",
    lambda: (
        ex.pdo("tx", "0x60410010", comm={5: ("Event timer", 0x0006, "rw", 0)}).replace(
            "DefaultValue=5\n", "DefaultValue=2\n", 1
        )
        + ex.STATUSWORD
    ),
    fixed=lambda: ex.pdo("tx", "0x60410010", comm={5: ("Event timer", 0x0006, "rw", 0)}) + ex.STATUSWORD,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "a master reads entries above sub0 and fails (SDO abort)"),
)
def check_comm_sub0(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        count_slot = pdo.comm_slot(0)
        highest = pdo.comm_int(0)
        if pdo.comm is None or count_slot is None or highest is None:
            continue
        above = [s for s in pdo.comm.subs if s > highest]
        where = f"{pdo.name}: {pdo.comm.index:04X}sub0 is {highest}"
        if above:
            yield ctx.report("PDO010", f"{where}, but sub{max(above)} is described", count_slot.location(ctx))
        elif highest > max(pdo.comm.subs):
            message = f"{where}, but only sub0-sub{max(pdo.comm.subs)} are described: reading sub{highest} fails"
            yield ctx.report("PDO010", message, count_slot.location(ctx))
        elif pdo.direction == RX and highest > _RPDO_LAST_SUB:
            message = (
                f"{where}, but an RPDO's sub-indices end at {_RPDO_LAST_SUB} (sub6, SYNC start value, is a TPDO's)"
            )
            yield with_severity(ctx.report("PDO010", message, count_slot.location(ctx)), W)


_RPDO_LAST_SUB = 5
"""CiA 301 §7.5.2.35: an RPDO communication record has sub-indices 1-5; sub6 (SYNC start value) is a TPDO's."""


@rule(
    "PDO011",
    W,
    "Inhibit time or SYNC start value set on an RPDO",
    """
Inhibit time (sub3) and SYNC start value (sub6) only govern transmission; an RPDO receives, so
a non-zero default there has no effect and suggests the record was copied from a TPDO.""",
    lambda: ex.pdo("rx", "0x60400010", comm={3: ("Inhibit time", 0x0006, "rw", 10)}) + ex.CONTROLWORD,
    fixed=lambda: ex.pdo("rx", "0x60400010") + ex.CONTROLWORD,
    placed=Placement(Clause.STYLE, "no effect on an RPDO; copied from a TPDO"),
)
def check_rpdo_tx_only(ctx: Context) -> Iterator[Finding]:
    for pdo, found in _comm_subs(ctx):
        value = int_value(found)
        if pdo.direction == RX and found.subindex in (3, 6) and value:
            what = "inhibit time" if found.subindex == 3 else "SYNC start value"
            yield ctx.report("PDO011", f"{pdo.name}: {what} {value} has no effect on an RPDO", found.location(ctx))


@rule(
    "PDO012",
    E,
    "Communication record sub-object of the wrong data type",
    """
CiA 301 fixes the types of the PDO communication record: transmission type (sub2), the
compatibility entry (sub4) and SYNC start value (sub6) are UNSIGNED8, the COB-ID (sub1) is
UNSIGNED32, inhibit time (sub3) and event timer (sub5) are UNSIGNED16. Masters write them
with these sizes; another size makes the SDO download fail.""",
    lambda: ex.pdo("tx", "0x60410010", tt=254, comm={5: ("Event timer", 0x0007, "rw", 100)}) + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010", tt=254, comm={5: ("Event timer", 0x0006, "rw", 100)}) + ex.STATUSWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "a master writes the standard size and the SDO download fails"),
)
def check_comm_types(ctx: Context) -> Iterator[Finding]:
    for pdo, found in _comm_subs(ctx):
        expected = COMM_SUBS[found.subindex][1] if found.subindex in COMM_SUBS else None  # sub0: EDS025
        dtype = ctx.device.entry_type(found.var, found.owner)
        if expected is not None and dtype is not None and dtype.index != expected:
            yield ctx.report(
                "PDO012",
                f"{pdo.name}: {found.name} is {dtype.name}, expected {_type_name(expected)}",
                found.key_location(ctx, "DataType"),
            )


@rule(
    "PDO013",
    W,
    "PDO communication parameter marked PDO-mappable",
    """
The sub-objects of a PDO communication record configure PDOs; CiA 301 does not map them into
PDOs. PDOMapping=1 there invites a tool to offer them for mapping.""",
    (
        lambda: (
            ex.pdo("tx", "0x60410010").replace("$NODEID+0x180\nPDOMapping=0", "$NODEID+0x180\nPDOMapping=1")
            + ex.STATUSWORD
        )
    ),
    fixed=(lambda: ex.pdo("tx", "0x60410010") + ex.STATUSWORD),
    placed=Placement(Clause.STYLE, "invites a tool to offer it for mapping"),
)
def check_comm_mappable(ctx: Context) -> Iterator[Finding]:
    for pdo, found in _comm_subs(ctx):
        if found.var.pdo_mapping and found.subindex > 0:
            yield ctx.report(
                "PDO013", f"{pdo.name}: {found.name} is marked PDO-mappable", found.key_location(ctx, "PDOMapping")
            )


@rule(
    "PDO020",
    E,
    "Reserved transmission type 241-251",
    """
Transmission types 241 to 251 are reserved by CiA 301; a device answers an SDO download of one
with an abort, and its behaviour with one as default is undefined.""",
    lambda: ex.pdo("tx", "0x60410010", tt=245) + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010", tt=1) + ex.STATUSWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device aborts the download of a reserved transmission type"),
)
def check_reserved_tt(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        found = pdo.comm_slot(2)
        tt = int_value(found)
        if found is not None and tt is not None and 241 <= tt <= 251:
            yield ctx.report("PDO020", f"{pdo.name}: transmission type {tt} is reserved", found.location(ctx))


@rule(
    "PDO021",
    E,
    "RTR-only transmission type 252/253 on an RPDO",
    """
Transmission types 252 (synchronous, RTR only) and 253 (asynchronous, RTR only) describe when a
TPDO answers a remote request; CiA 301 does not define them for an RPDO.""",
    lambda: ex.pdo("rx", "0x60400010", tt=253) + ex.CONTROLWORD,
    fixed=lambda: ex.pdo("rx", "0x60400010", tt=255) + ex.CONTROLWORD,
    placed=Placement(Clause.DEVICE_MISBEHAVES, "not defined for an RPDO"),
)
def check_rpdo_rtr(ctx: Context) -> Iterator[Finding]:
    for pdo in device_pdos(ctx):
        found = pdo.comm_slot(2)
        tt = int_value(found)
        if pdo.direction == RX and found is not None and tt in (252, 253):
            yield ctx.report("PDO021", f"{pdo.name}: transmission type {tt} is for TPDOs only", found.location(ctx))


def _timing(ctx: Context) -> Iterator[tuple[Pdo, int, Slot | None, Slot | None, Slot | None]]:
    """Each TPDO with a readable transmission type: (pdo, tt, inhibit, event timer, SYNC start)."""
    for pdo in device_pdos(ctx):
        tt = pdo.comm_int(2)
        if pdo.direction == TX and tt is not None:
            yield pdo, tt, pdo.comm_slot(3), pdo.comm_slot(5), pdo.comm_slot(6)


@rule(
    "PDO023",
    INFO,
    "Event-driven TPDO without an event timer",
    """
A TPDO with transmission type 254 or 255 is sent when the application or device profile
signals an event, or when its event timer expires. With the event timer at 0 it is sent only on
such events; if the mapped objects never raise one, the TPDO stays silent until a master sets a
timer. Informational, for valid TPDOs that map something: whether the application raises events
is not in the EDS.""",
    lambda: ex.pdo("tx", "0x60410010", tt=255, comm={5: ("Event timer", 0x0006, "rw", 0)}) + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010", tt=255, comm={5: ("Event timer", 0x0006, "rw", 100)}) + ex.STATUSWORD,
    placed=Placement(Clause.DECISION, "whether the application raises events is not in the file"),
)
def check_event_without_timer(ctx: Context) -> Iterator[Finding]:
    for pdo, tt, _, timer, _ in _timing(ctx):
        cob = pdo.cob()
        active = cob is not None and cob.valid(1) and bool(pdo.mapped())
        if tt in (254, 255) and timer is not None and int_value(timer) == 0 and active:
            yield ctx.report(
                "PDO023",
                f"{pdo.name}: transmission type {tt} with event timer 0 is sent only on application events",
                timer.location(ctx),
            )


@rule(
    "PDO024",
    W,
    "SYNC start value on a TPDO that is not cyclic synchronous",
    """
The SYNC start value (sub6) picks the SYNC counter value at which a cyclic synchronous TPDO
(transmission type 1-240) starts. For any other transmission type the device ignores it.""",
    lambda: ex.pdo("tx", "0x60410010", tt=0, comm={6: ("SYNC start value", 0x0005, "rw", 2)}) + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010", tt=1, comm={6: ("SYNC start value", 0x0005, "rw", 2)}) + ex.STATUSWORD,
    placed=Placement(Clause.STYLE, "the device ignores it"),
)
def check_sync_start(ctx: Context) -> Iterator[Finding]:
    for pdo, tt, _, _, start in _timing(ctx):
        value = int_value(start)
        if start is not None and value and not 1 <= tt <= 240:
            yield ctx.report(
                "PDO024",
                f"{pdo.name}: SYNC start value {value} has no effect with transmission type {tt}",
                start.location(ctx),
            )


@rule(
    "PDO032",
    W,
    "Event timer on a synchronous or RTR-only TPDO",
    """
The event timer (sub5, ms) triggers event-driven TPDOs (transmission type 254/255). A TPDO that
is sent on SYNC (0-240) or on request (252/253) ignores it, so a non-zero value promises a
period the device does not keep.""",
    lambda: ex.pdo("tx", "0x60410010", tt=1, comm={5: ("Event timer", 0x0006, "rw", 100)}) + ex.STATUSWORD,
    fixed=lambda: ex.pdo("tx", "0x60410010", tt=254, comm={5: ("Event timer", 0x0006, "rw", 100)}) + ex.STATUSWORD,
    placed=Placement(Clause.STYLE, "the device ignores it: a period it does not keep"),
)
def check_timer_ignored(ctx: Context) -> Iterator[Finding]:
    for pdo, tt, _, timer, _ in _timing(ctx):
        value = int_value(timer)
        if timer is not None and value and (tt <= 240 or tt in (252, 253)):
            yield ctx.report(
                "PDO032",
                f"{pdo.name}: event timer {value} ms is ignored with transmission type {tt}",
                timer.location(ctx),
            )


@rule(
    "PDO033",
    W,
    "Event timer shorter than the inhibit time",
    """
The inhibit time (sub3) counts in 100 us, the event timer (sub5) in ms. When the event period is
shorter than the inhibit time, the inhibit time wins and the TPDO is sent less often than the
event timer says; often the units were confused.""",
    lambda: (
        ex.pdo(
            "tx",
            "0x60410010",
            tt=254,
            comm={3: ("Inhibit time", 0x0006, "rw", 200), 5: ("Event timer", 0x0006, "rw", 10)},
        )
        + ex.STATUSWORD
    ),
    fixed=lambda: (
        ex.pdo(
            "tx",
            "0x60410010",
            tt=254,
            comm={3: ("Inhibit time", 0x0006, "rw", 50), 5: ("Event timer", 0x0006, "rw", 10)},
        )
        + ex.STATUSWORD
    ),
    placed=Placement(Clause.STYLE, "often confused units"),
)
def check_timer_vs_inhibit(ctx: Context) -> Iterator[Finding]:
    for pdo, tt, inhibit, timer, _ in _timing(ctx):
        period, gap = int_value(timer), int_value(inhibit)
        if timer is not None and period and gap and period * 10 < gap and tt in (254, 255):
            yield ctx.report(
                "PDO033",
                f"{pdo.name}: event timer {period} ms is shorter than the inhibit time {gap / 10:g} ms",
                timer.location(ctx),
            )
