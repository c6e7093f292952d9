"""Reading a bus description (lely dcfgen's `bus.yml`, with ros2_canopen's `defaults`/`nodes` and
`@NAME@` placeholders) into the typed `Network`, every refusal one line at `file:line`."""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

from ..names import suggest
from .model import Mapped, Master, Network, Options, PdoConfig, SdoEntry, Slave
from .yamltree import Located, NetworkError, read_yaml, substitute

Convert = Callable[[Any], Any]


def _int(value: Any) -> int:
    if isinstance(value, bool):
        raise ValueError("a number, not true/false")
    if isinstance(value, int):
        return value
    if isinstance(value, str):
        try:
            return int(value.strip(), 0)
        except ValueError:
            pass
    raise ValueError(f"a whole number, not {value!r}")


def _bool(value: Any) -> bool:
    if isinstance(value, bool):
        return value
    if isinstance(value, int) and value in (0, 1):
        return bool(value)
    raise ValueError(f"true or false, not {value!r}")


def _float(value: Any) -> float:
    if isinstance(value, bool) or not isinstance(value, int | float):
        raise ValueError(f"a number, not {value!r}")
    return float(value)


def _str(value: Any) -> str:
    if isinstance(value, bool) or value is None or isinstance(value, list | dict):
        raise ValueError(f"a text, not {value!r}")
    return str(value)


def _behavior(value: Any) -> dict[int, int]:
    if not isinstance(value, dict):
        raise ValueError("a mapping of sub-index to error behavior")
    return {_int(key): _int(item) for key, item in value.items()}


def _cob_id(value: Any) -> int | str:
    return "auto" if value == "auto" else _int(value)


def _anything(value: Any) -> Any:
    return value


COMMON = {
    "node_id": _int,
    "revision_number": _int,
    "serial_number": _int,
    "heartbeat_multiplier": _float,
    "heartbeat_consumer": _bool,
    "heartbeat_producer": _int,
    "time_cob_id": _int,
    "error_behavior": _behavior,
}
MASTER_KEYS: dict[str, Convert] = {
    **COMMON,
    **{name: _int for name in ("baudrate", "vendor_id", "product_code", "sync_period", "sync_window")},
    **{name: _int for name in ("sync_overflow", "emcy_inhibit_time", "nmt_inhibit_time", "boot_time")},
    **{name: _bool for name in ("start", "start_nodes", "start_all_nodes", "reset_all_nodes", "stop_all_nodes")},
}
SLAVE_KEYS: dict[str, Convert] = {
    **COMMON,
    "dcf": _str,
    "dcf_path": _str,
    "guard_time": _int,
    "life_time_factor": _int,
    "retry_factor": _int,
    "boot": _bool,
    "mandatory": _bool,
    "reset_communication": _bool,
    "software_file": _str,
    "software_version": _int,
    "configuration_file": _str,
    "restore_configuration": _int,
}
PDO_KEYS: dict[str, Convert] = {
    "enabled": _bool,
    "cob_id": _cob_id,
    **{name: _int for name in ("transmission", "inhibit_time", "event_timer", "event_deadline", "sync_start")},
}
OPTION_KEYS: dict[str, Convert] = {"dcf_path": _str, "heartbeat_multiplier": _float, "retry_factor": _int}
ROS2_MASTER_KEYS = frozenset({"driver", "package", "namespace", "boot_timeout", "non_transmit_timeout"})
"""Keys ros2_canopen reads from the master's section for its own driver: kept, not used to configure the bus."""
ROS2_SLAVE_KEYS = frozenset(
    {"driver", "package", "namespace", "enable_lazy_load", "sdo_timeout_ms", "boot_timeout_ms", "period"}
    | {"polling", "diagnostics", "remappings", "position_mode", "velocity_mode", "effort_mode", "switching_state"}
    | {"homing_timeout_seconds", "num_channels", "channel_names", "channels", "non_transmit_timeout"}
    | {f"scale_{what}_{way}_dev" for what in ("pos", "vel", "eff") for way in ("to", "from")}
    | {f"offset_pos_{way}_dev" for way in ("to", "from")}
)
"""Keys ros2_canopen's drivers read from a node's section (its documentation and sources)."""
SECTIONS = ("options", "master", "defaults", "nodes")
NODE_KEYS = frozenset(SLAVE_KEYS) | {"rpdo", "tpdo", "sdo"} | ROS2_SLAVE_KEYS
BELONGS = {
    "options": ("in `options`", frozenset(OPTION_KEYS)),
    "master": ("in `master`", frozenset(MASTER_KEYS) | ROS2_MASTER_KEYS),
    "node": ("in a node's section (or `defaults`)", NODE_KEYS),
}
"""Where each key of a bus description takes effect: one written elsewhere is ignored by dcfgen (and
ros2_canopen), so it is a warning naming where it belongs, not an error."""


class _Reader:
    def __init__(self, file: str, defines: Mapping[str, str], search: Sequence[Path]) -> None:
        self.file = file
        self.defines = defines
        self.search = search
        self.warnings: list[str] = []

    def warn(self, line: int, message: str) -> None:
        self.warnings.append(f"{self.file}:{line}: warning: {message}")

    def fail(self, line: int, message: str) -> NetworkError:
        return NetworkError(self.file, line, message)

    def section(self, data: Any, line: int, what: str) -> Located:
        if data is None:
            empty = Located()
            empty.line, empty.lines = line, {}
            return empty
        if not isinstance(data, Located):
            raise self.fail(line, f"{what} is a mapping of keys to values")
        return data

    def fields(
        self,
        data: Located,
        keys: Mapping[str, Convert],
        what: str,
        passed: frozenset[str] = frozenset(),
        kind: str = "",
    ) -> tuple[dict[str, Any], dict[str, Any]]:
        """The known keys converted, and the `passed` ones as written; a key of another `kind` of
        section (BELONGS) is a warning and left out, any other unknown key is refused."""
        known: dict[str, Any] = {}
        kept: dict[str, Any] = {}
        for key, raw in data.items():
            line = data.line_of(key)
            name = str(key)
            value = substitute(raw, self.defines, self.file, line)
            if name in passed:
                kept[name] = value
                continue
            convert = keys.get(name)
            elsewhere = [where for other, (where, valid) in BELONGS.items() if other != kind and name in valid]
            if convert is None and kind and elsewhere:
                self.warn(line, f"{what}: {name} has no effect here (dcfgen ignores it); it belongs {elsewhere[0]}")
                continue
            if convert is None:
                valid = set(keys) | passed
                raise self.fail(line, f"unknown key {name!r} in {what}; {suggest(name, valid)}")
            try:
                known[name] = convert(value)
            except ValueError as error:
                raise self.fail(line, f"{what}: {name} must be {error}") from None
        return known, kept

    def lines(self, data: Located) -> dict[str, Any]:
        return {"line": data.line, "lines": {str(key): line for key, line in data.lines.items()}}


def read_network(
    path: str, defines: Mapping[str, str] | None = None, search: Sequence[Path] = (), cogen: bool = True
) -> Network:
    """The network `path` describes; NetworkError (one line) when it cannot be read or is not one.

    `defines` give the `@NAME@` placeholders' values; a node's `dcf` is looked for beside the
    description, then in the `search` folders. With `cogen` (ros2_canopen's build), a file with
    `nodes` is read as ros2_canopen's `cogen` rewrites it for dcfgen; without, as written."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except OSError as error:
        raise NetworkError(path, 0, f"cannot read: {error.strerror or error}") from None
    except UnicodeDecodeError:
        raise NetworkError(path, 0, "not YAML: not UTF-8 text") from None
    data = read_yaml(text, path)
    reader = _Reader(path, defines or {}, [Path(path).parent, *search])
    return _network(reader, data, cogen)


def _network(reader: _Reader, data: Located, cogen: bool) -> Network:
    options_data = reader.section(data.get("options"), data.line_of("options"), "options")
    known, _ = reader.fields(options_data, OPTION_KEYS, "options", kind="options")
    options = Options(**known, **reader.lines(options_data))
    master = _master(reader, reader.section(data.get("master"), data.line_of("master"), "master"))
    defaults = reader.section(data.get("defaults"), data.line_of("defaults"), "defaults")
    nodes, cogen = _nodes(reader, data, cogen)
    slaves = [_slave(reader, name, _with_defaults(reader, name, defaults, node, cogen), cogen) for name, node in nodes]
    network = Network(file=reader.file, options=options, master=master, slaves=slaves, warnings=reader.warnings)
    _ros2_rules(reader, network, "master" in data)
    if "master" not in data:
        raise reader.fail(data.line, "no `master` section: a network needs its master (node_id, ...)")
    for slave in network.slaves:
        slave.dcf_file = str(_find(reader, slave.dcf, slave.line_of("dcf"), slave.name))
    return network


def _nodes(reader: _Reader, data: Located, cogen: bool) -> tuple[list[tuple[str, Located]], bool]:
    """The slaves' sections: by name at the top level (dcfgen's layout) and in `nodes` (ros2_canopen's).

    ros2_canopen's cogen writes `nodes` out with `yaml.dump`, which sorts the keys: dcfgen then
    meets the nodes by name, and each PDO table by number; it keeps only `options`, `master` and
    `nodes`, so a node at the top level beside `nodes` is not built (a warning). A file without
    `nodes` is dcfgen's own layout, which cogen does not take: it is read as written (False)."""
    top: list[tuple[str, Located]] = []
    grouped: list[tuple[str, Located]] = []
    for key, value in data.items():
        name = str(key)
        if name in ("options", "master", "defaults") or name.startswith("."):
            continue
        if name == "nodes":
            group = reader.section(value, data.line_of(key), "nodes")
            grouped.extend((str(n), reader.section(v, group.line_of(n), str(n))) for n, v in group.items())
        else:
            top.append((name, reader.section(value, data.line_of(key), name)))
    if not cogen or "nodes" not in data:
        return top + grouped, False
    for name, node in top:
        reader.warn(node.line, f"{name}: ros2_canopen's cogen keeps only `nodes`: this node is not built")
    return sorted(grouped, key=lambda item: item[0]), True


def _with_defaults(reader: _Reader, name: str, defaults: Located, node: Located, cogen: bool) -> Located:
    """The node with ros2_canopen's `defaults`: copied over the node's own keys as its cogen does
    (`nodes[node_name][entry_name] = defaults[entry_name]`), a key so replaced a warning; without
    `cogen`, the node's own keys win."""
    first, second = (node, defaults) if cogen else (defaults, node)
    merged = Located({**first, **second})
    merged.line = node.line
    merged.lines = {**first.lines, **second.lines}
    for key in node.keys() & defaults.keys() if cogen else ():
        if node[key] != defaults[key]:
            reader.warn(
                node.line_of(key),
                f"{name}: {key} is replaced by `defaults` (line {defaults.line_of(key)}), as ros2_canopen's "
                "cogen copies defaults over each node (--no-cogen: the node's own value)",
            )
    return merged


def _master(reader: _Reader, data: Located) -> Master:
    known, kept = reader.fields(data, MASTER_KEYS, "master", ROS2_MASTER_KEYS, "master")
    node_id = known.get("node_id", 255)
    if not (1 <= node_id <= 127 or node_id == 255):
        raise reader.fail(data.line_of("node_id"), f"master: node_id {node_id} is not 1-127 (or 255: unconfigured)")
    return Master(**known, extra=kept, **reader.lines(data))


def _slave(reader: _Reader, name: str, data: Located, by_number: bool) -> Slave:
    """One slave; `by_number`: its PDO tables in number order (as cogen's `yaml.dump` sorts them)."""
    keys = {**SLAVE_KEYS, "rpdo": _anything, "tpdo": _anything, "sdo": _anything}
    known, kept = reader.fields(data, keys, name, ROS2_SLAVE_KEYS, "node")
    if "dcf" not in known:
        raise reader.fail(data.line, f"{name}: no `dcf` (the EDS/DCF that describes the node)")
    node_id = known.get("node_id")
    if node_id is not None and not 1 <= node_id <= 127:
        raise reader.fail(data.line_of("node_id"), f"{name}: node_id {node_id} is not 1-127")
    for direction in ("rpdo", "tpdo"):
        if direction in known:
            pdos = _pdos(reader, name, direction, known[direction], data.line_of(direction))
            known[direction] = sorted(pdos, key=lambda pdo: pdo.number) if by_number else pdos
    if "sdo" in known:
        known["sdo"] = _sdos(reader, name, known["sdo"], data.line_of("sdo"))
    return Slave(name=name, **known, extra=kept, **reader.lines(data))


def _find(reader: _Reader, dcf: str, line: int, name: str) -> Path:
    for folder in reader.search:
        candidate = folder / dcf
        if candidate.is_file():
            return candidate
    where = ", ".join(str(folder) or "." for folder in reader.search)
    raise reader.fail(line, f"{name}: dcf {dcf!r} is not in {where} (give its folder with --dcf-dir)")


def _pdos(reader: _Reader, name: str, direction: str, data: Any, line: int) -> list[PdoConfig]:
    table = reader.section(data, line, f"{name}.{direction}")
    result = []
    for key, value in table.items():
        key_line = table.line_of(key)
        try:
            number = _int(key)
        except ValueError:
            number = 0
        if not 1 <= number <= 512:
            raise reader.fail(key_line, f"{name}.{direction}: {key!r} is no PDO number (1-512)")
        where = f"{name}.{direction}.{number}"
        pdo = reader.section(value, key_line, where)
        known, _ = reader.fields(pdo, {**PDO_KEYS, "mapping": _anything}, where)
        if "mapping" in known:
            known["mapping"] = _mapping(reader, where, known["mapping"], pdo.line_of("mapping"))
        result.append(PdoConfig(number=number, **known, **reader.lines(pdo)))
    return result


def _mapping(reader: _Reader, where: str, data: Any, line: int) -> list[Mapped]:
    if data is None:
        return []
    if not isinstance(data, list):
        raise reader.fail(line, f"{where}.mapping is a list of {{index, sub_index}}")
    entries = []
    for item in data:
        entry = reader.section(item, line, f"{where}.mapping entry")
        known, _ = reader.fields(entry, {"index": _int, "sub_index": _int}, f"{where}.mapping entry")
        if "index" not in known:
            raise reader.fail(entry.line, f"{where}.mapping entry without `index`")
        entries.append(Mapped(**known, **reader.lines(entry)))
    return entries


def _sdos(reader: _Reader, name: str, data: Any, line: int) -> list[SdoEntry]:
    if data is None:
        return []
    if not isinstance(data, list):
        raise reader.fail(line, f"{name}.sdo is a list of {{index, sub_index, value}}")
    entries = []
    for item in data:
        entry = reader.section(item, line, f"{name}.sdo entry")
        keys: dict[str, Convert] = {"index": _int, "sub_index": _int, "value": _sdo_value}
        known, _ = reader.fields(entry, keys, f"{name}.sdo entry")
        if "index" not in known:
            raise reader.fail(entry.line, f"{name}.sdo entry without `index`")
        entries.append(SdoEntry(**known, **reader.lines(entry)))
    return entries


def _sdo_value(value: Any) -> int | float | str:
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, int | float | str):
        return value
    raise ValueError(f"a number or a text, not {value!r}")


def _ros2_rules(reader: _Reader, network: Network, has_master: bool) -> None:
    """ros2_canopen loads each node's driver from `driver` and `package`: once one section names a
    driver, every section needs both, and every node-ID must be given."""
    sections: list[Master | Slave] = [network.master, *network.slaves] if has_master else [*network.slaves]
    if not any("driver" in part.extra or "package" in part.extra for part in sections):
        return
    for part in sections:
        who = "master" if isinstance(part, Master) else part.name
        for key in ("driver", "package"):
            if key not in part.extra:
                raise reader.fail(part.line, f"{who}: no `{key}` (ros2_canopen loads each node's driver by it)")
        if "node_id" not in part.lines:
            raise reader.fail(part.line, f"{who}: no `node_id` (ros2_canopen needs each node's)")
