"""The files a network plan becomes: each slave's concise DCF (`<name>.bin`) and DCF (`<name>.dcf`), and
the master's DCF (`master.dcf`, with the objects of CiA 302 and the PDOs that mirror the slaves',
laid out as lely's master reads it) and concise DCF (`master.bin`, when it has writes)."""

from __future__ import annotations

from collections.abc import Iterator, Mapping
from pathlib import Path

from ..model import ValueKind
from ..model.cia301 import master as m
from ..model.cia301.cobid import VALID
from ..model.cia301.objects import (
    COB_ID_EMCY,
    COMM_BASE,
    DEVICE_TYPE,
    ERROR_REGISTER,
    GUARD_TIME,
    IDENTITY,
    IDENTITY_PRODUCT_CODE,
    IDENTITY_REVISION,
    IDENTITY_SERIAL,
    IDENTITY_VENDOR_ID,
    LIFE_TIME_FACTOR,
    MAP_BASE,
    RX,
    TX,
)
from ..model.cia301.pdo import dummy_type, is_dummy_index
from ..model.cia301.slots import slot
from ..model.datatypes import STANDARD_TYPES
from .plan import NetworkPlan, PlannedPdo, SlavePlan, Write, device_type

Section = tuple[str, list[tuple[str, object]]]


MANIFEST = ".cantools-od-network"
"""The list of files `network -o` wrote into a folder: on the next run, those it no longer writes
(a node removed from the bus) are removed, and nothing else there is touched."""


def manifest(files: dict[Path, bytes]) -> bytes:
    names = sorted(path.name for path in files)
    return (
        "# written by cantools-od network; removed from here when no longer written\n" + "\n".join(names) + "\n"
    ).encode()


def stale(outdir: Path, files: dict[Path, bytes]) -> list[Path]:
    """The files an earlier run wrote into `outdir` (its manifest) that this run does not write."""
    try:
        listed = (outdir / MANIFEST).read_text(encoding="utf-8").splitlines()
    except (OSError, UnicodeDecodeError):
        return []
    written = {path.name for path in files} | {MANIFEST}
    names = [name for name in listed if name and not name.startswith("#") and name not in written]
    return [outdir / name for name in names if Path(name).name == name and (outdir / name).is_file()]


def concise(writes: list[Write]) -> bytes:
    return m.concise_dcf(write.as_tuple() for write in writes)


def outputs(plan: NetworkPlan, outdir: Path, node_dcfs: bool = True, remote_pdo: bool = False) -> dict[Path, bytes]:
    """Every file of the network, by path."""
    files: dict[Path, bytes] = {}
    for slave in plan.slaves:
        if slave.writes:
            files[outdir / f"{slave.slave.name}.bin"] = concise(slave.writes)
        if node_dcfs:
            files[outdir / f"{slave.slave.name}.dcf"] = node_dcf(plan, slave)
    files[outdir / "master.dcf"] = master_dcf(plan, remote_pdo).encode("ascii", errors="replace")
    if plan.master_writes:
        files[outdir / "master.bin"] = concise(plan.master_writes)
    return files


def node_dcf(plan: NetworkPlan, slave: SlavePlan) -> bytes:
    """The slave's DCF: its node-ID and bit rate, and every value the master writes as its ParameterValue."""
    from ..api import dumps
    from ..model.device import Commissioning

    device = slave.device.model_copy(deep=True)
    device._original = slave.device._original
    for write in slave.writes:
        found = slot(device, write.index, write.sub)
        dtype = device.entry_type(found.var, found.owner) if found is not None else None
        if found is None or dtype is None:
            continue
        found.var.parameter_value = _decoded(dtype.kind, write.data)
    device.node_id = slave.node_id
    if device.commissioning is None:
        device.commissioning = Commissioning()
    device.commissioning.node_id = slave.node_id
    device.commissioning.baudrate = plan.master.baudrate
    return dumps(device, "dcf", style="canonical")


def _decoded(kind: ValueKind, data: bytes) -> int | float | str | bytes:
    import struct

    if kind is ValueKind.SIGNED:
        return int.from_bytes(data, "little", signed=True)
    if kind in (ValueKind.UNSIGNED, ValueKind.BOOL):
        return int.from_bytes(data, "little")
    if kind is ValueKind.REAL:
        return float(struct.unpack("<f" if len(data) == 4 else "<d", data)[0])
    if kind in (ValueKind.STRING,):
        return data.decode("utf-8", errors="replace")
    return data


def _hex(value: int, digits: int = 8) -> str:
    return f"0x{value:0{digits}X}"


def _render(sections: list[Section]) -> str:
    lines: list[str] = []
    for name, keys in sections:
        if lines:
            lines.append("")
        lines.append(f"[{name}]")
        lines.extend(f"{key}={value}" for key, value in keys)
    return "\n".join(lines) + "\n"


def _var(name: str, dtype: int, access: str, default: object = None, **more: object) -> list[tuple[str, object]]:
    keys: list[tuple[str, object]] = [("ParameterName", name)]
    keys.extend((key, value) for key, value in more.items() if key == "ObjectType")
    keys.extend([("DataType", _hex(dtype, 4)), ("AccessType", access)])
    if default is not None:
        keys.append(("DefaultValue", default))
    keys.extend((key, value) for key, value in more.items() if key != "ObjectType")
    return keys


U8, U16, U32, DOMAIN = (STANDARD_TYPES[n].index for n in (5, 6, 7, 15))  # the data types master.dcf names


def master_dcf(plan: NetworkPlan, remote_pdo: bool = False) -> str:
    """master.dcf as lely's `dcfgen` lays it out (its template's sections, keys and values)."""
    master = plan.master
    rx_mirrors = [(slave, pdo) for slave in plan.slaves for pdo in slave.active(TX)]
    tx_mirrors = [(slave, pdo) for slave in plan.slaves for pdo in slave.active(RX)]
    configured = any(slave.configuration_file for slave in plan.slaves)
    software = any(slave.slave.software_file for slave in plan.slaves)
    rx_objects = _mirror_objects(plan, TX, m.MIRRORED_RPDO_OBJECTS)
    tx_objects = _mirror_objects(plan, RX, m.MIRRORED_TPDO_OBJECTS)
    sections: list[Section] = [
        ("DeviceComissioning", _commissioning(plan)),
        ("DeviceInfo", _device_info(plan, len(rx_mirrors), len(tx_mirrors))),
        ("DummyUsage", _dummies()),
        ("MandatoryObjects", _object_list([DEVICE_TYPE, ERROR_REGISTER, IDENTITY])),
    ]  # fmt: skip
    optional = [0x1003, 0x1005, 0x1006, 0x1007, 0x1012, 0x1013, COB_ID_EMCY, 0x1015]
    optional += [0x1016] if master.heartbeat_consumer else []
    optional += [0x1017, 0x1019, m.EMCY_CONSUMER, 0x1029, m.NMT_INHIBIT_TIME]
    optional += [COMM_BASE[RX] + i for i in range(len(rx_mirrors))] + [MAP_BASE[RX] + i for i in range(len(rx_mirrors))]
    optional += [COMM_BASE[TX] + i for i in range(len(tx_mirrors))] + [MAP_BASE[TX] + i for i in range(len(tx_mirrors))]
    optional += [m.CONCISE_DCF] if configured else []
    optional += [m.CONFIGURATION_REQUEST, m.EXPECTED_SOFTWARE] + ([m.PROGRAM_DATA] if software else [])
    optional += [m.NMT_STARTUP, m.SLAVE_ASSIGNMENT, m.REQUEST_NMT, m.DEVICE_TYPE_IDENTIFICATION]
    optional += [m.VENDOR_IDENTIFICATION, m.PRODUCT_CODE, m.REVISION_NUMBER, m.SERIAL_NUMBER, m.BOOT_TIME]
    optional += [m.RESTORE_CONFIGURATION]
    sections.append(("OptionalObjects", _object_list(optional)))
    manufacturer = sorted({index for index, _ in rx_objects}) + sorted({index for index, _ in tx_objects})
    if remote_pdo:
        for base, count in ((m.REMOTE_TPDO, len(rx_mirrors)), (m.REMOTE_TPDO_MAPPING, len(rx_mirrors))):
            manufacturer += [base + i for i in range(count)]
        for base, count in ((m.REMOTE_RPDO, len(tx_mirrors)), (m.REMOTE_RPDO_MAPPING, len(tx_mirrors))):
            manufacturer += [base + i for i in range(count)]
    sections.append(("ManufacturerObjects", _object_list(manufacturer)))
    sections.extend(_communication(plan))
    sections.extend(_mirrors(rx_mirrors, RX, m.MIRRORED_RPDO_OBJECTS))
    sections.extend(_mirrors(tx_mirrors, TX, m.MIRRORED_TPDO_OBJECTS))
    sections.extend(_manager(plan, configured, software))
    sections.extend(_mirror_sections(rx_objects, "RPDO", "rww"))
    sections.extend(_mirror_sections(tx_objects, "TPDO", "rwr"))
    if remote_pdo:
        sections.extend(_remote(rx_mirrors, m.REMOTE_TPDO, m.REMOTE_TPDO_MAPPING, "TPDO"))
        sections.extend(_remote(tx_mirrors, m.REMOTE_RPDO, m.REMOTE_RPDO_MAPPING, "RPDO"))
    return _render(sections)


def _dummies() -> list[tuple[str, object]]:
    """Every fixed-size basic type but REAL32/REAL64 as a dummy (as lely's master.dcf lists them)."""
    return [(f"Dummy{t.index:04X}", 1) for t in STANDARD_TYPES.values() if t.is_integer or t.kind is ValueKind.BOOL]


def _object_list(indices: list[int]) -> list[tuple[str, object]]:
    return [("SupportedObjects", len(indices))] + [(str(n), _hex(i, 4)) for n, i in enumerate(indices, 1)]


def _commissioning(plan: NetworkPlan) -> list[tuple[str, object]]:
    master = plan.master
    return [
        ("NodeID", master.node_id), ("NodeName", ""), ("NodeRefd", ""), ("Baudrate", master.baudrate),
        ("NetNumber", 1), ("NetworkName", ""), ("NetRefd", ""), ("CANopenManager", 1),
        ("LSS_SerialNumber", _hex(master.serial_number)),
    ]  # fmt: skip


def _device_info(plan: NetworkPlan, rx: int, tx: int) -> list[tuple[str, object]]:
    master = plan.master
    rates = [(f"BaudRate_{rate}", 1) for rate in (10, 20, 50, 125, 250, 500, 800, 1000)]
    return [
        ("VendorName", ""), ("VendorNumber", _hex(master.vendor_id)), ("ProductName", ""),
        ("ProductNumber", _hex(master.product_code)), ("RevisionNumber", _hex(master.revision_number)),
        ("OrderCode", ""), *rates, ("SimpleBootUpMaster", 1), ("SimpleBootUpSlave", 0), ("Granularity", 1),
        ("DynamicChannelsSupported", 0), ("GroupMessaging", 0), ("NrOfRxPDO", rx), ("NrOfTxPDO", tx),
        ("LSS_Supported", 1),
    ]  # fmt: skip


def _array(
    name: str, dtype: int, access: str, count: int, values: Mapping[int, object] | None, **more: object
) -> list[Section]:
    index_name = name
    kind = str(more.pop("kind", "0x08"))
    keys = [("ParameterName", more.pop("title")), ("ObjectType", kind), ("DataType", _hex(dtype, 4))]
    keys += [("AccessType", access)]
    if "default" in more:
        keys.append(("DefaultValue", more.pop("default")))
    keys.append(("CompactSubObj", count))
    sections: list[Section] = [(index_name, keys)]
    if values is not None:
        width = 2 if dtype == U8 else 8
        entries = [(str(sub), _hex(value, width) if isinstance(value, int) else value) for sub, value in values.items()]
        sections.append((f"{index_name}Value", [("NrOfEntries", len(values)), *entries]))
    return sections


def _communication(plan: NetworkPlan) -> Iterator[Section]:
    master = plan.master
    network = plan.network
    yield f"{DEVICE_TYPE:04X}", _var("Device type", U32, "ro", "0x00000000")
    yield f"{ERROR_REGISTER:04X}", _var("Error register", U8, "ro")
    yield from _array("1003", U32, "ro", 254, None, title="Pre-defined error field")
    yield "1005", _var("COB-ID SYNC message", U32, "rw", "0x40000080")
    yield "1006", _var("Communication cycle period", U32, "rw", master.sync_period)
    yield "1007", _var("Synchronous window length", U32, "rw", master.sync_window)
    yield "1012", _var("COB-ID time stamp object", U32, "rw", _hex(master.time_cob_id))
    yield "1013", _var("High resolution time stamp", U32, "rw", None, PDOMapping=1)
    yield "1014", _var("COB-ID EMCY", U32, "rw", "$NODEID+0x80")
    yield "1015", _var("Inhibit time EMCY", U16, "rw", master.emcy_inhibit_time)
    if master.heartbeat_consumer:
        beats = {}
        for n, slave in enumerate([s for s in plan.slaves if s.heartbeat_producer], 1):
            multiplier = slave.slave.heartbeat_multiplier or network.options.heartbeat_multiplier
            beats[n] = ((slave.node_id & 0xFF) << 16) | (int(slave.heartbeat_producer * multiplier) & 0xFFFF)
        yield from _array("1016", U32, "rw", 127, beats, title="Consumer heartbeat time")
    yield "1017", _var("Producer heartbeat time", U16, "rw", master.heartbeat_producer)
    yield "1018", [("SubNumber", 5), ("ParameterName", "Identity Object"), ("ObjectType", "0x09")]
    yield "1018sub0", _var("Highest sub-index supported", U8, "const", 4)
    for sub, title, value in (
        (IDENTITY_VENDOR_ID, "Vendor-ID", master.vendor_id),
        (IDENTITY_PRODUCT_CODE, "Product code", master.product_code),
        (IDENTITY_REVISION, "Revision number", master.revision_number),
    ):
        yield f"1018sub{sub}", _var(title, U32, "ro", _hex(value))
    yield f"1018sub{IDENTITY_SERIAL}", _var("Serial number", U32, "ro")
    yield "1019", _var("Synchronous counter overflow value", U8, "rw", master.sync_overflow)
    emcy = {s.node_id: s.cob_id(COB_ID_EMCY, 0) for s in plan.slaves if s.has(COB_ID_EMCY, 0)}
    emcy = {node: cob for node, cob in emcy.items() if not cob & VALID}
    yield from _array("1028", U32, "rw", 127, emcy, title="Emergency consumer object", default="0x80000000")
    yield from _array("1029", U8, "rw", 254, dict(sorted(master.error_behavior.items())), title="Error behavior object")
    yield f"{m.NMT_INHIBIT_TIME:04X}", _var("NMT inhibit time", U16, "rw", master.nmt_inhibit_time)


def _mirrors(mirrors: list[tuple[SlavePlan, PlannedPdo]], direction: str, objects_base: int) -> Iterator[Section]:
    """The master's PDOs that receive what the slaves send (RX) and send what they receive (TX)."""
    word = "RPDO" if direction == RX else "TPDO"
    for n, (_, pdo) in enumerate(mirrors):
        name = f"{COMM_BASE[direction] + n:04X}"
        top = 5 if direction == RX else 6
        yield (
            name,
            [("SubNumber", top + 1), ("ParameterName", f"{word} communication parameter"), ("ObjectType", "0x09")],
        )
        yield f"{name}sub0", _var("highest sub-index supported", U8, "const", top)
        yield f"{name}sub1", _var(f"COB-ID used by {word}", U32, "rw", _hex(pdo.cob_id))
        yield f"{name}sub2", _var("transmission type", U8, "rw", _hex(pdo.transmission, 2))
        if direction == RX:
            yield f"{name}sub3", _var("inhibit time", U16, "rw")
            yield f"{name}sub4", _var("compatibility entry", U8, "rw")
            yield f"{name}sub5", _var("event-timer", U16, "rw", pdo.event_deadline)
        else:
            yield f"{name}sub3", _var("inhibit time", U16, "rw", pdo.inhibit_time)
            yield f"{name}sub4", _var("reserved", U8, "rw")
            yield f"{name}sub5", _var("event timer", U16, "rw", pdo.event_timer)
            yield f"{name}sub6", _var("SYNC start value", U8, "rw", pdo.sync_start)
    placed = _placement(mirrors, objects_base)
    for n, (slave, pdo) in enumerate(mirrors):
        name = f"{MAP_BASE[direction] + n:04X}"
        entries = [placed[(id(slave), signal.index, signal.sub)] for signal in pdo.signals]
        values = dict(enumerate(entries, 1))
        yield from _array(name, U32, "rw", len(entries), values, title=f"{word} mapping parameter", kind="0x09")


def _placement(mirrors: list[tuple[SlavePlan, PlannedPdo]], base: int) -> dict[tuple[int, int, int], str]:
    """Where each mirrored object lives in the master: index base + PDO number - 1, the next free sub."""
    placed: dict[tuple[int, int, int], str] = {}
    for n, (slave, pdo) in enumerate(mirrors):
        position = 0
        for signal in pdo.signals:
            key = (id(slave), signal.index, signal.sub)
            if key not in placed:
                position += 1
                placed[key] = _hex(((base + n) << 16) | (position << 8) | signal.bits)
    return placed


def _mirror_objects(
    plan: NetworkPlan, slave_direction: str, base: int
) -> list[tuple[int, tuple[SlavePlan, int, int, int]]]:
    """(master index, (slave, object index, sub, data type)) of each object the mirrored PDOs carry."""
    found = []
    n = 0
    for slave in plan.slaves:
        seen: set[tuple[int, int]] = set()
        for pdo in slave.active(slave_direction):
            n += 1
            for signal in pdo.signals:
                if (signal.index, signal.sub) in seen:
                    continue
                seen.add((signal.index, signal.sub))
                dtype = signal.dtype.index if signal.dtype is not None else 0
                found.append((base + n - 1, (slave, signal.index, signal.sub, dtype)))
    return found


def _mirror_sections(
    objects: list[tuple[int, tuple[SlavePlan, int, int, int]]], word: str, access: str
) -> Iterator[Section]:
    by_index: dict[int, list[tuple[SlavePlan, int, int, int]]] = {}
    for index, entry in objects:
        by_index.setdefault(index, []).append(entry)
    for index, entries in sorted(by_index.items()):
        name = f"{index:04X}"
        number = index & 0x1FF
        yield (
            name,
            [
                ("SubNumber", len(entries) + 1),
                ("ParameterName", f"Mapped application objects for {word} {number + 1}"),
                ("ObjectType", "0x09"),
            ],
        )
        yield f"{name}sub0", _var("Highest sub-index supported", U8, "const", len(entries))
        for sub, (slave, obj, obj_sub, dtype) in enumerate(entries, 1):
            yield (
                f"{name}sub{sub:X}",
                _var(f"{slave.slave.name}: {_title(slave, obj, obj_sub)}", dtype, access, None, PDOMapping=1),
            )


def _title(slave: SlavePlan, index: int, sub: int) -> str:
    """A mirrored object's name: its own, or its data type's for a dummy entry (as dcfgen names it)."""
    found = slot(slave.device, index, sub)
    if found is not None:
        return found.var.name
    dummy = dummy_type(slave.device, index) if is_dummy_index(index) else None
    return dummy.name if dummy is not None else f"{index:04X}sub{sub:X}"


def _manager(plan: NetworkPlan, configured: bool, software: bool) -> Iterator[Section]:
    master = plan.master
    by_node = {slave.node_id: slave for slave in plan.slaves}
    if configured:
        yield from _per_node(
            m.CONCISE_DCF, "Concise DCF", "Node-ID", {n: s.configuration_file for n, s in by_node.items()}
        )
    yield from _array(f"{m.CONFIGURATION_REQUEST:04X}", U8, "wo", 127, None, title="Configuration request")
    yield from _array(f"{m.EXPECTED_SOFTWARE:04X}", U32, "rw", 127, None, title="Expected software identification")
    if software:
        files = {n: s.slave.software_file for n, s in by_node.items()}
        yield from _per_node(m.PROGRAM_DATA, "Program data", "Program data of node-ID", files)
    startup = m.STARTUP_MASTER
    startup |= m.STARTUP_ALL_NODES if master.start_all_nodes else 0
    startup |= 0 if master.start else m.STARTUP_NO_SELF_START
    startup |= 0 if master.start_nodes else m.STARTUP_NO_SLAVE_START
    startup |= m.STARTUP_RESET_ALL if master.reset_all_nodes else 0
    startup |= m.STARTUP_STOP_ALL if master.stop_all_nodes else 0
    yield f"{m.NMT_STARTUP:04X}", _var("NMT startup", U32, "rw", _hex(startup))
    assignment = {slave.node_id: _assignment(plan, slave) for slave in plan.slaves}
    yield from _array(f"{m.SLAVE_ASSIGNMENT:04X}", U32, "rw", 127, assignment, title="NMT slave assignment")
    yield from _array(f"{m.REQUEST_NMT:04X}", U8, "rw", 127, None, title="Request NMT")
    types = {s.node_id: device_type(s) for s in plan.slaves if device_type(s)}
    yield from _array(f"{m.DEVICE_TYPE_IDENTIFICATION:04X}", U32, "rw", 127, types, title="Device type identification")
    vendors = {s.node_id: s.identity(IDENTITY_VENDOR_ID) for s in plan.slaves if s.identity(IDENTITY_VENDOR_ID)}
    yield from _array(f"{m.VENDOR_IDENTIFICATION:04X}", U32, "rw", 127, vendors, title="Vendor identification")
    products = {
        s.node_id: s.identity(IDENTITY_PRODUCT_CODE)
        for s in plan.slaves
        if s.identity(IDENTITY_PRODUCT_CODE) and s.has(IDENTITY, IDENTITY_PRODUCT_CODE)
    }
    yield from _array(f"{m.PRODUCT_CODE:04X}", U32, "rw", 127, products, title="Product code")
    yield from _array(f"{m.REVISION_NUMBER:04X}", U32, "rw", 127, None, title="Revision_number")
    yield from _array(f"{m.SERIAL_NUMBER:04X}", U32, "rw", 127, None, title="Serial number")
    yield f"{m.BOOT_TIME:04X}", _var("Boot time", U32, "rw", master.boot_time)
    restore = {s.node_id: s.slave.restore_configuration for s in plan.slaves if s.slave.restore_configuration}
    yield from _array(f"{m.RESTORE_CONFIGURATION:04X}", U8, "rw", 127, restore, title="Restore configuration")


def _assignment(plan: NetworkPlan, slave: SlavePlan) -> int:
    config = slave.slave
    value = m.ASSIGN_SLAVE
    value |= m.ASSIGN_BOOT if config.boot else 0
    value |= m.ASSIGN_MANDATORY if config.mandatory else 0
    value |= 0 if config.reset_communication else m.ASSIGN_NO_RESET
    value |= m.ASSIGN_CHECK_SOFTWARE if config.software_version else 0
    value |= m.ASSIGN_UPDATE_SOFTWARE if config.software_file else 0
    value |= m.ASSIGN_RESTORE if config.restore_configuration else 0
    retry = config.retry_factor if config.retry_factor is not None else plan.network.options.retry_factor
    value |= (retry & 0xFF) << 8
    guard = slave.value(GUARD_TIME, 0) if config.guard_time is None else config.guard_time
    if slave.heartbeat_producer and slave.value(LIFE_TIME_FACTOR, 0):
        guard = 0
    return value | ((guard & 0xFFFF) << 16)


def _remote(mirrors: list[tuple[SlavePlan, PlannedPdo]], base: int, map_base: int, word: str) -> Iterator[Section]:
    """lely's remote PDO objects: which slave PDO each mirror stands for, and that PDO's own mapping."""
    for n, (slave, pdo) in enumerate(mirrors):
        value = f"0x{pdo.number:06X}{slave.node_id:02X}"
        yield f"{base + n:04X}", _var(f"Remote {word} number and node-ID", U32, "rw", value)
    for n, (_, pdo) in enumerate(mirrors):
        entries = {i: (s.index << 16) | (s.sub << 8) | s.bits for i, s in enumerate(pdo.signals, 1)}
        yield from _array(
            f"{map_base + n:04X}", U32, "rw", len(entries), entries, title=f"Remote {word} mapping parameter"
        )


def _per_node(index: int, title: str, item: str, files: dict[int, str]) -> Iterator[Section]:
    name = f"{index:04X}"
    yield name, [("SubNumber", 128), ("ParameterName", title), ("ObjectType", "0x08")]
    yield f"{name}sub0", _var("Highest sub-index supported", U8, "const", 127)
    for node in range(1, 128):
        more = {"UploadFile": files[node]} if files.get(node) else {}
        yield f"{name}sub{node:X}", _var(f"{item} {node}", DOMAIN, "ro", None, **more)
