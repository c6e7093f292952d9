"""A node the description describes, served on a CAN bus with python-canopen's `LocalNode`.

What python-canopen's local node does is kept: its SDO server (aborts 0601 0001h/0002h for the access,
0602 0000h/0609 0011h for what the dictionary lacks, 0607 0010h for a length that is not the type's) and its
NMT slave. Added here: every entry holds its value from the start (ParameterValue, else DefaultValue, else
zero), so reads answer what the file says; writes outside LowLimit/HighLimit abort (0609 0031h/0032h); reset
commands restore the values and send the boot-up again; the heartbeat follows 1017h; PDOs (live/pdo.py) run in
OPERATIONAL.

The Python API a `--script` uses: `get`/`set` a value, `emcy`, `every` (call a function periodically),
`nmt_state`.
"""

from __future__ import annotations

import sys
import threading
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from ..interop import to_canopen
from ..model.cia301 import aborts, bootcheck, nmt
from ..model.cia301.objects import COB_ID_SYNC, COMMUNICATION_AREA, PDO_AREA, PRODUCER_HEARTBEAT
from .pdo import PdoRunner

if TYPE_CHECKING:
    import canopen

    from ..model import Device

Key = tuple[int, int]


class CannotServe(Exception):
    """python-canopen cannot make a node of the description; the message says why, in one line."""


class Simulator:
    """The node of `device` at `node_id`, on `network` (a python-canopen Network, connected or not)."""

    def __init__(self, device: Device, node_id: int, network: canopen.Network) -> None:
        import canopen

        self.device = device
        self.node_id = node_id
        self.network = network
        self.od = to_canopen(device, node_id)
        try:
            self.node: Any = canopen.LocalNode(node_id, self.od)  # partly annotated: used as untyped
        except (KeyError, ValueError, TypeError) as error:  # its PDO set-up wants each PDO's both records
            raise CannotServe(f"python-canopen cannot build a node from it: {' '.join(str(error).split())}") from error
        self.initial = _initial_values(self.od) | _boot_check_values(device, self.od)
        self.node.data_store = _store(self.initial)
        self.node._write_callbacks.insert(0, self._check_limits)  # before the NMT slave starts a heartbeat
        self.node._write_callbacks.append(self._written)
        self.lock = threading.RLock()
        self.pdo = PdoRunner(self)
        self._timers: list[threading.Event] = []
        self.silent: set[Key] = set()
        network.add_node(self.node)
        network.unsubscribe(self.node.sdo.rx_cobid, self.node.sdo.on_request)
        network.subscribe(self.node.sdo.rx_cobid, self._sdo_request)
        network.subscribe(0, self._nmt_command)

    # The services ------------------------------------------------------------------------------------

    def start(self) -> None:
        """Boot: the boot-up message, then PRE-OPERATIONAL with the heartbeat of 1017h."""
        self.node.nmt.send_command(nmt.RESET_NODE)  # INITIALISING: sends the boot-up message
        self.node.nmt._state = nmt.PRE_OPERATIONAL
        self.node.nmt.start_heartbeat(self._heartbeat_ms())

    def stop(self) -> None:
        for event in self._timers:
            event.set()
        self.pdo.stop()
        self.node.nmt.stop_heartbeat()
        self.network.unsubscribe(0, self._nmt_command)

    def _heartbeat_ms(self) -> int:
        data = self.node.data_store.get(PRODUCER_HEARTBEAT, {}).get(0, b"")
        return int.from_bytes(data[:2], "little") if len(data) >= 2 else 0

    def _nmt_command(self, can_id: int, data: bytearray, timestamp: float) -> None:
        """After python-canopen's NMT slave took the new state: what the state change does to the node."""
        if len(data) < 2 or data[1] not in (nmt.ALL_NODES, self.node_id):
            return
        command = data[0]
        with self.lock:
            if command in nmt.RESETS:
                self._reset(communication_only=command == nmt.RESET_COMMUNICATION)
            self.pdo.follow(self.node.nmt._state == nmt.OPERATIONAL)

    def _reset(self, communication_only: bool) -> None:
        for (index, sub), data in self.initial.items():
            if not communication_only or index in COMMUNICATION_AREA:
                self.node.data_store.setdefault(index, {})[sub] = data
        self.start()

    def _sdo_request(self, can_id: int, data: bytearray, timestamp: float) -> None:
        """To python-canopen's SDO server, but for the initiating requests of a silenced entry."""
        initiating = len(data) >= 4 and data[0] >> 5 in (1, 2)  # initiate download, initiate upload
        if initiating and (int.from_bytes(data[1:3], "little"), data[3]) in self.silent:
            return
        self.node.sdo.on_request(can_id, data, timestamp)

    def _check_limits(self, index: int, subindex: int, od: Any, data: bytes, **_: Any) -> None:
        """LowLimit/HighLimit of the description, as an SDO abort."""
        from canopen import SdoAbortedError

        if (od.min is None and od.max is None) or not od.fixed_size:
            return
        try:
            value = od.decode_raw(data)
        except Exception:  # a length the type does not have: python-canopen aborts it already (0607 0010h)
            return
        if od.min is not None and value < od.min:
            raise SdoAbortedError(aborts.VALUE_TOO_LOW)
        if od.max is not None and value > od.max:
            raise SdoAbortedError(aborts.VALUE_TOO_HIGH)

    def _written(self, index: int, subindex: int, od: Any, data: bytes, **_: Any) -> None:
        """A write by SDO: stored before python-canopen stores it, so that the PDOs it changes see it."""
        with self.lock:
            self.node.data_store.setdefault(index, {})[subindex] = bytes(data)
            if index in PDO_AREA or index == COB_ID_SYNC:
                self.pdo.follow(self.node.nmt._state == nmt.OPERATIONAL)
            else:
                self.pdo.changed(index, subindex)

    # The Python API ----------------------------------------------------------------------------------

    def get(self, index: int, subindex: int = 0) -> Any:
        """The value the node holds, decoded by its data type."""
        od = self._variable(index, subindex)
        return od.decode_raw(self.node.data_store[index][subindex])

    def set(self, index: int, subindex: int, value: Any) -> None:
        """Change a value as the application would: a TPDO mapping it sends on change (types 254/255)."""
        od = self._variable(index, subindex)
        with self.lock:
            self.node.data_store.setdefault(index, {})[subindex] = od.encode_raw(value)
            self.pdo.changed(index, subindex)

    def get_raw(self, index: int, subindex: int = 0) -> bytes:
        return bytes(self.node.data_store[index][subindex])

    def emcy(self, code: int, register: int = 0, data: bytes = b"") -> None:
        """Send an emergency message (CiA 301 §7.2.7): error code, error register 1001h, 5 bytes of data."""
        self.node.emcy.send(code, register, data)

    def every(self, seconds: float, action: Callable[[Simulator], None]) -> None:
        """Call `action(simulator)` every `seconds` until the simulation stops."""
        stopped = threading.Event()
        self._timers.append(stopped)

        def repeat() -> None:
            while not stopped.wait(seconds):
                try:
                    with self.lock:
                        action(self)
                except Exception as error:  # the script's fault: said in one line, its timer stops
                    print(f"simulate: error: {getattr(action, '__name__', 'action')}: {error}", file=sys.stderr)
                    return

        threading.Thread(target=repeat, name="simulate-every", daemon=True).start()

    def silence(self, index: int, subindex: int = 0) -> None:
        """Answer no SDO request for this entry (a device that drops requests, for testing a master's timeouts)."""
        self.silent.add((index, subindex))

    @property
    def nmt_state(self) -> str:
        return str(self.node.nmt.state)

    def _variable(self, index: int, subindex: int) -> Any:
        found = self.od.get_variable(index, subindex)
        if found is None:
            raise KeyError(f"{index:04X}sub{subindex:X}: no such entry")
        return found

    def served(self) -> tuple[int, int]:
        """How many objects and entries (sub-objects and VAR objects) the node serves."""
        return len(self.node.data_store), sum(len(subs) for subs in self.node.data_store.values())


def _initial_values(od: canopen.ObjectDictionary) -> dict[Key, bytes]:
    """Each entry's bytes at boot: ParameterValue, else DefaultValue, else zero (an empty string or domain)."""
    values: dict[Key, bytes] = {}
    for obj in od.values():
        variables = obj.subindices.values() if hasattr(obj, "subindices") else [obj]
        for var in variables:
            values[var.index, var.subindex] = _encoded(var)
    return values


def _boot_check_values(device: Device, od: canopen.ObjectDictionary) -> dict[Key, bytes]:
    """The identity [DeviceInfo] gives, where it gives one: what a master's boot-up check expects of the
    node (lely's dcfgen takes it over the 1018h values, which many descriptions leave 0)."""
    values: dict[Key, bytes] = {}
    for index, sub in bootcheck.CHECKED_BY:
        variable = od.get_variable(index, sub)
        number = bootcheck.device_info_number(device, index, sub)
        if variable is not None and number:
            values[index, sub] = _encoded(variable, number)
    return values


def _encoded(var: Any, *first: Any) -> bytes:
    for value in (*first, var.value, var.default):
        if value is None:
            continue
        try:
            data: bytes = var.encode_raw(value)
            return data
        except (ValueError, TypeError, UnicodeError, OverflowError):
            continue
    return bytes(len(var) // 8) if var.fixed_size else b""


def _store(values: dict[Key, bytes]) -> dict[int, dict[int, bytes]]:
    store: dict[int, dict[int, bytes]] = {}
    for (index, sub), data in values.items():
        store.setdefault(index, {})[sub] = data
    return store
