"""The plan of a network: for each slave, the SDO writes its master makes at boot (its concise DCF) and
the PDOs it then has; for the master, what it mirrors and writes to itself.

The writes follow lely dcfgen's order (time stamp COB-ID, heartbeat producer, guard time, life time
factor, error behavior, RPDOs then TPDOs as the YAML lists them, the YAML's `sdo` list; the master's
heartbeat consumer entry first), so that our concise DCFs decode to the same writes as its. Two
additions: the DCF's `ParameterValue`s that differ from the defaults come first (a DCF's configured
values only reach a device when written; `parameter_values=False` leaves them out and takes them as
what the device holds, as dcfgen does), and a PDO configured `enabled: false` is not mirrored.
"""

from __future__ import annotations

import os
import struct
from dataclasses import dataclass, field

from ..model import Device, NodeIdExpr, ValueKind, Variable
from ..model.cia301.cobid import PREDEFINED, VALID
from ..model.cia301.connections import predefined_cob_base
from ..model.cia301.master import EXPECTED_SOFTWARE, REVISION_NUMBER, SERIAL_NUMBER
from ..model.cia301.objects import (
    COB_ID_TIME,
    COMM_BASE,
    CONSUMER_HEARTBEAT,
    DEVICE_TYPE,
    ERROR_BEHAVIOR,
    GUARD_TIME,
    IDENTITY,
    IDENTITY_PRODUCT_CODE,
    IDENTITY_REVISION,
    IDENTITY_SERIAL,
    IDENTITY_VENDOR_ID,
    LIFE_TIME_FACTOR,
    MAP_BASE,
    MAX_ENTRIES,
    PDO_AREA,
    PRODUCER_HEARTBEAT,
    RX,
    TX,
)
from ..model.cia301.pdo import dummy_type, is_dummy_index
from ..model.cia301.slots import as_int, slot
from ..model.datatypes import UNSIGNED32, DataType
from .model import Master, Network, PdoConfig, Slave
from .yamltree import NetworkError

FIRST_FREE_COB = 0x680  # dcfgen's first COB-ID for `cob_id: auto` beyond the four pre-defined PDOs
LAST_FREE_COB = 0x6DF


@dataclass(frozen=True)
class Write:
    """One SDO write of a concise DCF, with the YAML line that asked for it (0: the DCF's values)."""

    index: int
    sub: int
    data: bytes
    line: int = 0

    def as_tuple(self) -> tuple[int, int, bytes]:
        return self.index, self.sub, self.data


@dataclass(frozen=True)
class Signal:
    """One object a PDO carries, at its bit offset."""

    index: int
    sub: int
    offset: int
    bits: int
    dtype: DataType | None
    name: str
    dummy: bool = False
    unit: str = ""


@dataclass
class PlannedPdo:
    direction: str  # as the slave sees it
    number: int
    cob_id: int
    transmission: int
    inhibit_time: int
    event_timer: int
    event_deadline: int
    sync_start: int
    signals: list[Signal]
    active: bool
    line: int = 0

    @property
    def bits(self) -> int:
        return sum(signal.bits for signal in self.signals)

    @property
    def name(self) -> str:
        return f"{'R' if self.direction == RX else 'T'}PDO{self.number}"


@dataclass
class SlavePlan:
    slave: Slave
    device: Device
    node_id: int
    writes: list[Write] = field(default_factory=list)
    pdos: list[PlannedPdo] = field(default_factory=list)
    heartbeat_producer: int = 0
    configuration_file: str = ""
    warnings: list[str] = field(default_factory=list)
    problems: list[tuple[int, str]] = field(default_factory=list)
    """(line, message) of each `sdo` entry the master could not write: left out, reported by the checks."""

    def active(self, direction: str) -> list[PlannedPdo]:
        return [pdo for pdo in self.pdos if pdo.direction == direction and pdo.active and pdo.signals]

    def identity(self, sub: int) -> int:
        found = slot(self.device, IDENTITY, sub)
        value = as_int(found.var.value(self.node_id)) if found is not None else None
        info = self.device.device_info
        from_info = {
            IDENTITY_VENDOR_ID: info.vendor_number,
            IDENTITY_PRODUCT_CODE: info.product_number,
            IDENTITY_REVISION: info.revision_number,
        }.get(sub)
        if sub == IDENTITY_REVISION and self.slave.revision_number is not None:
            return self.slave.revision_number
        if sub == IDENTITY_SERIAL and self.slave.serial_number is not None:
            return self.slave.serial_number
        return from_info if from_info is not None else (value or 0)  # DeviceInfo over 1018h, as dcfgen

    def has(self, index: int, sub: int) -> bool:
        return slot(self.device, index, sub) is not None

    def value(self, index: int, sub: int) -> int:
        found = slot(self.device, index, sub)
        return (as_int(found.var.value(self.node_id)) or 0) if found is not None else 0

    def cob_id(self, index: int, sub: int) -> int:
        """A COB-ID entry as the slave holds it; one the file gives no value takes its pre-defined
        connection set value (CiA 301: EMCY 80h + node-ID), not 000h, which is NMT's."""
        found = slot(self.device, index, sub)
        held = as_int(found.var.value(self.node_id)) if found is not None else None
        base = predefined_cob_base(index, sub)
        return base + self.node_id if held is None and base is not None else held or 0


@dataclass
class NetworkPlan:
    network: Network
    slaves: list[SlavePlan]
    master_writes: list[Write]

    @property
    def master(self) -> Master:
        return self.network.master


def encode(dtype: DataType | None, value: object, what: str) -> bytes:
    """The bytes an SDO write of `value` carries for a sub-object of type `dtype`; ValueError says why not."""
    if dtype is None:
        raise ValueError(f"{what} has no data type this tool can write")
    kind = dtype.kind
    if kind in (ValueKind.BOOL, ValueKind.UNSIGNED, ValueKind.SIGNED):
        if isinstance(value, bool) or not isinstance(value, int):
            raise ValueError(f"{what} is {dtype.name}: {value!r} is no whole number")
        low, high = dtype.int_range() or (0, 0)
        if not low <= value <= high:
            raise ValueError(f"{what} is {dtype.name}: {value} is out of its range {low}..{high}")
        size = max(1, ((dtype.bits or 8) + 7) // 8)
        return value.to_bytes(size, "little", signed=kind is ValueKind.SIGNED)
    if kind is ValueKind.REAL and isinstance(value, int | float) and not isinstance(value, bool):
        return struct.pack("<f" if dtype.bits == 32 else "<d", float(value))
    if kind in (ValueKind.STRING, ValueKind.UNICODE) and isinstance(value, str):
        return value.encode("utf-16-le" if kind is ValueKind.UNICODE else "utf-8")
    if kind is ValueKind.OCTETS and isinstance(value, bytes | str):
        try:
            return value if isinstance(value, bytes) else bytes.fromhex(value)
        except ValueError:
            pass
    raise ValueError(f"{what} is {dtype.name}: {value!r} cannot be written to it")


class _Slave:
    """The state of one slave while its writes are planned: what it holds after the writes so far."""

    def __init__(self, plan: SlavePlan, file: str, parameter_values: bool) -> None:
        self.plan = plan
        self.file = file
        self.parameter_values = parameter_values
        self.held: dict[tuple[int, int], object] = {}

    @property
    def device(self) -> Device:
        return self.plan.device

    def fail(self, line: int, message: str) -> NetworkError:
        return NetworkError(self.file, line, f"{self.plan.slave.name}: {message}")

    def baseline(self, index: int, sub: int) -> object:
        """What the slave holds before its configuration: the defaults (or its DCF's values, as dcfgen takes it)."""
        found = slot(self.device, index, sub)
        if found is None:
            return None
        var = found.var
        value = var.default if self.parameter_values or var.parameter_value is None else var.parameter_value
        return value.resolve(self.plan.node_id) if isinstance(value, NodeIdExpr) else value

    def holds(self, index: int, sub: int) -> int:
        value = self.held.get((index, sub), self.baseline(index, sub))
        return as_int(value) or 0

    def write(self, index: int, sub: int, value: object, line: int) -> Write:
        found = slot(self.device, index, sub)
        what = f"{index:04X}sub{sub:X}"
        if found is None:
            raise self.fail(line, f"object {what} does not exist in {self.plan.slave.dcf}")
        stated = not found.implicit  # CompactSubObj's sub-index 0: its access is not written in the file
        if stated and found.var.access is not None and not found.var.access.writable:
            raise self.fail(line, f"object {what} is {found.var.access.value}: the master cannot write it")
        try:
            data = encode(self.device.entry_type(found.var, found.owner), value, what)
            self._within_limits(found.var, value, what)
        except ValueError as error:
            raise self.fail(line, str(error)) from None
        self.held[(index, sub)] = value
        return Write(index, sub, data, line)

    def _within_limits(self, var: Variable, value: object, what: str) -> None:
        """A value below the sub-object's LowLimit or above its HighLimit is refused by the device."""
        if not isinstance(value, int | float) or isinstance(value, bool):
            return
        low = self.device.resolve(var.low_limit, self.plan.node_id)
        high = self.device.resolve(var.high_limit, self.plan.node_id)
        if isinstance(low, int | float) and not isinstance(low, bool) and value < low:
            raise ValueError(f"{what}: {value} is below its LowLimit {low}")
        if isinstance(high, int | float) and not isinstance(high, bool) and value > high:
            raise ValueError(f"{what}: {value} is above its HighLimit {high}")


def plan_network(network: Network, devices: dict[str, Device], parameter_values: bool = True) -> NetworkPlan:
    """Every slave's writes and PDOs, and the master's own writes; NetworkError when one cannot be made."""
    next_cob = [FIRST_FREE_COB]
    slaves = [_plan_slave(network, s, devices[s.name], next_cob, parameter_values) for s in network.slaves]
    _heartbeat_consumers(network, slaves)
    return NetworkPlan(network, slaves, _master_writes(network.master, slaves))


def node_id_of(slave: Slave, device: Device, file: str) -> int:
    node_id = slave.node_id if slave.node_id is not None else device.node_id
    if node_id is None or not 1 <= node_id <= 127:
        raise NetworkError(file, slave.line, f"{slave.name}: no node_id, and {slave.dcf} gives none")
    return node_id


def _plan_slave(
    network: Network, slave: Slave, device: Device, next_cob: list[int], parameter_values: bool
) -> SlavePlan:
    plan = SlavePlan(slave, device, node_id_of(slave, device, network.file))
    parameter_values = parameter_values and device.is_dcf  # an EDS's values are what the device holds
    state = _Slave(plan, network.file, parameter_values)
    configured = _configured_pdos(state) if parameter_values else {}
    if parameter_values:
        plan.writes.extend(_parameter_values(state))
    plan.writes.extend(_settings(state))
    for direction, configs in ((RX, slave.rpdo), (TX, slave.tpdo)):
        for config in configs:
            merged = _merge(configured.pop((direction, config.number), None), config)
            plan.writes.extend(_pdo(state, direction, merged, next_cob))
    for (direction, _), config in sorted(configured.items()):
        plan.writes.extend(_pdo(state, direction, config, next_cob))
    _sdo_list(state, network.file)
    plan.pdos = _final_pdos(state)
    plan.heartbeat_producer = state.holds(PRODUCER_HEARTBEAT, 0) if plan.has(PRODUCER_HEARTBEAT, 0) else 0
    if slave.heartbeat_producer is not None:
        plan.heartbeat_producer = slave.heartbeat_producer
    dcf_path = os.path.expandvars(slave.dcf_path if slave.dcf_path is not None else network.options.dcf_path)
    if slave.configuration_file is not None:
        plan.configuration_file = slave.configuration_file
    elif plan.writes:
        plan.configuration_file = os.path.join(dcf_path, slave.name + ".bin")
    return plan


def _sdo_list(state: _Slave, file: str) -> None:
    """The YAML's `sdo` writes; one the master cannot make is a problem, the same object written twice
    a warning (the later value stays: often another object was meant, 6083h twice for 6083h and 6084h)."""
    plan = state.plan
    first: dict[tuple[int, int], int] = {}
    for entry in plan.slave.sdo:
        key = (entry.index, entry.sub_index)
        if key in first:
            plan.warnings.append(
                f"{file}:{entry.line}: warning: {plan.slave.name}: {entry.index:04X}sub{entry.sub_index:X} is written "
                f"again (first on line {first[key]}): the later value stays; another object meant?"
            )
        first.setdefault(key, entry.line)
        try:
            plan.writes.append(state.write(entry.index, entry.sub_index, entry.value, entry.line))
        except NetworkError as error:
            plan.problems.append((entry.line, error.reason))


def device_pdos(device: Device, node_id: int, name: str = "device") -> list[PlannedPdo]:
    """A device's PDOs as its description configures them (ParameterValue, else DefaultValue)."""
    from .model import Slave as SlaveConfig

    plan = SlavePlan(SlaveConfig(name=name, dcf=device.source), device, node_id)
    return _final_pdos(_Slave(plan, device.source, parameter_values=False))


def _parameter_values(state: _Slave) -> list[Write]:
    """The DCF's configured values that differ from the defaults, outside the PDO records."""
    writes = []
    for obj in state.device.objects.values():
        if obj.index in PDO_AREA:
            continue
        entries = [(sub, var) for sub, var in obj.subs.items()] if obj.has_subs else [(0, obj)]
        for sub, var in entries:
            if var.parameter_value is None or var.access is None or not var.access.writable:
                continue
            value = state.device.resolve(var.parameter_value, state.plan.node_id)
            default = state.device.resolve(var.default, state.plan.node_id)
            if value != default and not isinstance(value, NodeIdExpr):
                writes.append(state.write(obj.index, sub, value, 0))
    return writes


def _settings(state: _Slave) -> list[Write]:
    slave = state.plan.slave
    writes = []
    for index, wanted in (
        (COB_ID_TIME, slave.time_cob_id),
        (PRODUCER_HEARTBEAT, slave.heartbeat_producer),
        (GUARD_TIME, slave.guard_time),
        (LIFE_TIME_FACTOR, slave.life_time_factor),
    ):
        if wanted is None:
            continue
        key = {COB_ID_TIME: "time_cob_id", PRODUCER_HEARTBEAT: "heartbeat_producer"}.get(index, "")
        line = slave.line_of(key or ("guard_time" if index == GUARD_TIME else "life_time_factor"))
        if not state.plan.has(index, 0):
            state.plan.warnings.append(f"{state.file}:{line}: warning: {slave.name}: object {index:04X} does not exist")
        elif wanted != state.holds(index, 0):
            writes.append(state.write(index, 0, wanted, line))
    for sub, value in slave.error_behavior.items():
        line = slave.line_of("error_behavior")
        if sub == 0 or not state.plan.has(ERROR_BEHAVIOR, sub):
            state.plan.warnings.append(
                f"{state.file}:{line}: warning: {slave.name}: sub-object {ERROR_BEHAVIOR:04X}sub{sub:X} does not exist"
            )
        elif value != state.holds(ERROR_BEHAVIOR, sub):
            writes.append(state.write(ERROR_BEHAVIOR, sub, value, line))
    return writes


def _configured_pdos(state: _Slave) -> dict[tuple[str, int], PdoConfig]:
    """The PDOs whose DCF values differ from their defaults, as configurations to write."""
    found: dict[tuple[str, int], PdoConfig] = {}
    for direction in (RX, TX):
        for number in range(1, 513):
            comm, mapping = COMM_BASE[direction] + number - 1, MAP_BASE[direction] + number - 1
            if comm not in state.device.objects:
                continue
            config = _configured(state, comm, mapping, number)
            if config is not None:
                found[(direction, number)] = config
    return found


def _param(state: _Slave, index: int, sub: int) -> int | None:
    """The DCF's ParameterValue of a sub-object when it differs from its default, else None."""
    found = slot(state.device, index, sub)
    if found is None or found.var.parameter_value is None:
        return None
    value = as_int(state.device.resolve(found.var.parameter_value, state.plan.node_id))
    return None if value == as_int(state.device.resolve(found.var.default, state.plan.node_id)) else value


def _configured(state: _Slave, comm: int, mapping: int, number: int) -> PdoConfig | None:
    cob = _param(state, comm, 1)
    fields = {
        "transmission": _param(state, comm, 2),
        "inhibit_time": _param(state, comm, 3),
        "event_timer": _param(state, comm, 5),
        "sync_start": _param(state, comm, 6),
    }
    count_changed = _param(state, mapping, 0) is not None
    entries_changed = any(_param(state, mapping, sub) is not None for sub in range(1, MAX_ENTRIES + 1))
    if cob is None and all(v is None for v in fields.values()) and not (count_changed or entries_changed):
        return None
    from .model import Mapped

    config = PdoConfig(number=number, **{k: v for k, v in fields.items() if v is not None})
    if cob is not None:
        config.cob_id = cob & ~VALID
        config.enabled = not cob & VALID
    if count_changed or entries_changed:
        count = as_int(_configured_value(state, mapping, 0)) or 0
        raws = [as_int(_configured_value(state, mapping, sub)) or 0 for sub in range(1, min(count, MAX_ENTRIES) + 1)]
        config.mapping = [Mapped(index=raw >> 16, sub_index=(raw >> 8) & 0xFF) for raw in raws if raw]
    return config


def _configured_value(state: _Slave, index: int, sub: int) -> object:
    found = slot(state.device, index, sub)
    return state.device.resolve(found.var.value(), state.plan.node_id) if found is not None else None


def _merge(configured: PdoConfig | None, given: PdoConfig) -> PdoConfig:
    """The YAML's settings over the DCF's configured ones."""
    if configured is None:
        return given
    merged = configured.model_copy()
    for name in given.model_fields_set:
        setattr(merged, name, getattr(given, name))
    merged.line, merged.lines = given.line, given.lines
    return merged


def _pdo(state: _Slave, direction: str, config: PdoConfig, next_cob: list[int]) -> list[Write]:
    """The writes that give one PDO its configuration (dcfgen's sequence: disable, settings, remap, enable)."""
    comm = COMM_BASE[direction] + config.number - 1
    mapping = MAP_BASE[direction] + config.number - 1
    kind = "Receive" if direction == RX else "Transmit"
    if comm not in state.device.objects:
        raise state.fail(config.line, f"{kind}-PDO {config.number} is not in {state.plan.slave.dcf}")
    held = state.holds(comm, 1)
    cob = held
    if config.cob_id == "auto":
        cob = _auto_cob(state, direction, config, next_cob)
    elif isinstance(config.cob_id, int):
        cob = config.cob_id
    writes = []
    if held != cob | VALID:
        writes.append(state.write(comm, 1, cob | VALID, config.line_of("cob_id")))
    if not cob & VALID:
        writes.extend(_pdo_settings(state, direction, comm, config))
        if config.mapping is not None:
            writes.extend(_remap(state, mapping, config))
        if config.enabled:
            writes.append(state.write(comm, 1, cob, config.line_of("enabled")))
    return writes


def _auto_cob(state: _Slave, direction: str, config: PdoConfig, next_cob: list[int]) -> int:
    if config.number <= len(PREDEFINED[direction]):
        return PREDEFINED[direction][config.number - 1] + state.plan.node_id
    cob = next_cob[0]
    if cob > LAST_FREE_COB:
        raise state.fail(config.line_of("cob_id"), "no free 11-bit COB-ID is left for `cob_id: auto`")
    next_cob[0] = cob + 1
    return cob


def _pdo_settings(state: _Slave, direction: str, comm: int, config: PdoConfig) -> list[Write]:
    writes = []
    tx = direction == TX
    for sub, name, value, applies in (
        (2, "transmission", config.transmission, True),
        (3, "inhibit_time", config.inhibit_time, tx),
        (5, "event_timer", config.event_timer, tx),
        (5, "event_deadline", config.event_deadline, not tx),
        (6, "sync_start", config.sync_start, tx),
    ):
        if value is not None and applies and value != state.holds(comm, sub):
            writes.append(state.write(comm, sub, value, config.line_of(name)))
    return writes


def _remap(state: _Slave, mapping: int, config: PdoConfig) -> list[Write]:
    entries = config.mapping or []
    writes = []
    if state.holds(mapping, 0) > 0 or entries:
        writes.append(state.write(mapping, 0, 0, config.line_of("mapping")))
    for position, entry in enumerate(entries, start=1):
        bits = _entry_bits(state, entry.index, entry.sub_index, entry.line)
        value = (entry.index << 16) | (entry.sub_index << 8) | bits
        if not state.plan.has(mapping, position):
            raise state.fail(entry.line, f"{mapping:04X}h holds {position - 1} mapping entries at most")
        writes.append(state.write(mapping, position, value, entry.line))
    if entries:
        writes.append(state.write(mapping, 0, len(entries), config.line_of("mapping")))
    return writes


def _entry_bits(state: _Slave, index: int, sub: int, line: int) -> int:
    if is_dummy_index(index):
        dtype = dummy_type(state.device, index)
        if dtype is None or dtype.bits is None:
            raise state.fail(line, f"dummy entry {index:04X}h names no fixed-size data type")
        return dtype.bits
    found = slot(state.device, index, sub)
    if found is None:
        raise state.fail(line, f"cannot map {index:04X}sub{sub:X}: no such object in {state.plan.slave.dcf}")
    dtype = state.device.entry_type(found.var, found.owner)
    if dtype is None or dtype.bits is None:
        raise state.fail(line, f"cannot map {index:04X}sub{sub:X}: its data type has no fixed size")
    return dtype.bits


def _final_pdos(state: _Slave) -> list[PlannedPdo]:
    """Every PDO of the slave as it is after the writes."""
    result = []
    for direction in (RX, TX):
        for number in range(1, 513):
            comm, mapping = COMM_BASE[direction] + number - 1, MAP_BASE[direction] + number - 1
            if comm not in state.device.objects:
                continue
            result.append(_final_pdo(state, direction, number, comm, mapping))
    return result


def _final_pdo(state: _Slave, direction: str, number: int, comm: int, mapping: int) -> PlannedPdo:
    cob = state.holds(comm, 1)
    count = state.holds(mapping, 0) if mapping in state.device.objects else 0
    signals = []
    offset = 0
    for position in range(1, min(count, MAX_ENTRIES) + 1):
        raw = state.holds(mapping, position)
        index, sub, bits = raw >> 16, (raw >> 8) & 0xFF, raw & 0xFF
        if not raw:
            continue
        signals.append(_signal(state, index, sub, offset, bits))
        offset += bits
    config = next((c for c in _configs(state, direction) if c.number == number), None)
    return PlannedPdo(
        direction=direction,
        number=number,
        cob_id=cob,
        transmission=state.holds(comm, 2),
        inhibit_time=state.holds(comm, 3),
        event_timer=state.holds(comm, 5) if direction == TX else 0,
        event_deadline=(config.event_deadline or 0) if config is not None else 0,
        sync_start=state.holds(comm, 6),
        signals=signals,
        active=not cob & VALID and (config is None or config.enabled),
        line=config.line if config is not None else 0,
    )


def _configs(state: _Slave, direction: str) -> list[PdoConfig]:
    return state.plan.slave.rpdo if direction == RX else state.plan.slave.tpdo


def _signal(state: _Slave, index: int, sub: int, offset: int, bits: int) -> Signal:
    if is_dummy_index(index):
        return Signal(index, sub, offset, bits, dummy_type(state.device, index), f"dummy{index:04X}", dummy=True)
    found = slot(state.device, index, sub)
    if found is None:
        return Signal(index, sub, offset, bits, None, f"{index:04X}sub{sub:X}")
    owner = found.owner
    name = owner.name if found.var is owner else f"{owner.name} {found.var.name}"
    return Signal(index, sub, offset, bits, state.device.entry_type(found.var, owner), name)


def _heartbeat_consumers(network: Network, slaves: list[SlavePlan]) -> None:
    """The slave's 1016h entry for the master's heartbeat, written first (as dcfgen does)."""
    master = network.master
    multiplier = master.heartbeat_multiplier or network.options.heartbeat_multiplier
    heartbeat = int(master.heartbeat_producer * multiplier)
    for plan in slaves:
        subs = _consumer_subs(plan)
        if plan.slave.heartbeat_consumer and heartbeat > 0:
            sub = next((s for s, v in subs if (v >> 16) & 0xFF == master.node_id), 0) or next(
                (s for s, v in subs if v & 0xFFFF == 0 or not 1 <= (v >> 16) & 0xFF <= 127), 0
            )
            line = plan.slave.line_of("heartbeat_consumer")
            if sub:
                value = ((master.node_id & 0xFF) << 16) | (heartbeat & 0xFFFF)
                plan.writes.insert(0, _raw_write(plan, CONSUMER_HEARTBEAT, sub, value, line))
            else:
                missing = "no free entry in" if CONSUMER_HEARTBEAT in plan.device.objects else "no object"
                plan.warnings.append(
                    f"{network.file}:{line}: warning: {plan.slave.name}: {missing} {CONSUMER_HEARTBEAT:04X}h"
                )
        else:
            for sub, value in subs:
                if value & 0xFFFF and (value >> 16) & 0xFF == master.node_id:
                    plan.writes.insert(0, _raw_write(plan, CONSUMER_HEARTBEAT, sub, master.node_id << 16, 0))


def _consumer_subs(plan: SlavePlan) -> list[tuple[int, int]]:
    obj = plan.device.objects.get(CONSUMER_HEARTBEAT)
    if obj is None or not obj.has_subs:
        return []
    return [(sub, plan.value(CONSUMER_HEARTBEAT, sub)) for sub in sorted(obj.subs) if sub]


def _raw_write(plan: SlavePlan, index: int, sub: int, value: int, line: int) -> Write:
    return Write(index, sub, value.to_bytes(4, "little"), line)


def _master_writes(master: Master, slaves: list[SlavePlan]) -> list[Write]:
    writes = []
    if master.serial_number:
        writes.append(Write(IDENTITY, IDENTITY_SERIAL, encode(UNSIGNED32, master.serial_number, "serial number")))
    for plan in slaves:
        node = plan.node_id
        if plan.slave.software_version:
            writes.append(Write(EXPECTED_SOFTWARE, node, encode(UNSIGNED32, plan.slave.software_version, "software")))
        revision = plan.identity(IDENTITY_REVISION)
        if revision and plan.has(IDENTITY, IDENTITY_REVISION):
            writes.append(Write(REVISION_NUMBER, node, encode(UNSIGNED32, revision, "revision")))
        serial = plan.identity(IDENTITY_SERIAL)
        if serial and plan.has(IDENTITY, IDENTITY_SERIAL):
            writes.append(Write(SERIAL_NUMBER, node, encode(UNSIGNED32, serial, "serial")))
    return writes


def device_type(plan: SlavePlan) -> int:
    return plan.value(DEVICE_TYPE, 0)
