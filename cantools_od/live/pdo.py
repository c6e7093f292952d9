"""The simulated node's PDOs, as its communication and mapping parameters say (CiA 301 §7.2.2).

The parameters are read from the node's current values whenever the node enters OPERATIONAL or a PDO
parameter is written, so a master's remapping takes effect as on a device. A TPDO of transmission type 1-240
is sent on every n-th SYNC, type 0 on the SYNC after a mapped value changed, types 254/255 when a mapped value
changes (no sooner than the inhibit time after the last) and on the event timer. An RPDO's data is written into
the dictionary: at once for types 254/255, on the next SYNC for the synchronous ones.
"""

from __future__ import annotations

import threading
import time
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Protocol

from ..model.cia301.cobid import BASE_11BIT, BASE_29BIT, EXTENDED, SYNC_ID, VALID
from ..model.cia301.objects import COB_ID_SYNC, COMM_BASE, MAP_BASE, PDO_SPAN, RX, TX
from ..model.cia301.pdo import decode_entry, is_dummy_index

if TYPE_CHECKING:
    import threading

    import canopen


class Host(Protocol):
    """What the PDOs need of the node that runs them (the simulator): its lock, its python-canopen node and the
    network it is on."""

    lock: threading.RLock
    node: canopen.LocalNode
    network: canopen.Network


SYNC_TYPES = range(0, 241)  # 0: acyclic synchronous; 1-240: every n-th SYNC
EVENT_TYPES = (0xFE, 0xFF)
INHIBIT_UNIT = 0.0001  # the inhibit time counts 100 µs
IDLE = 3600.0  # how long the timer thread sleeps with nothing due


@dataclass
class Pdo:
    cob_id: int
    extended: bool
    transmission: int
    inhibit: float  # seconds
    event_timer: float  # seconds, 0: none
    entries: list[tuple[int, int, int]]  # (index, sub-index, bits)
    sync_count: int = 0
    changed: bool = False
    last_sent: float = 0.0
    next_event: float = 0.0
    pending: bytes | None = None  # a synchronous RPDO's data, applied on the next SYNC

    def maps(self, index: int, subindex: int) -> bool:
        return any(entry[:2] == (index, subindex) for entry in self.entries)


@dataclass
class PdoRunner:
    node: Host
    tpdos: list[Pdo] = field(default_factory=list)
    rpdos: dict[int, Pdo] = field(default_factory=dict)
    sync_id: int | None = None
    running: bool = False
    wake: threading.Event = field(default_factory=threading.Event)
    thread: threading.Thread | None = None

    def follow(self, operational: bool) -> None:
        """Run the PDOs the parameters give now when OPERATIONAL, none otherwise."""
        with self.node.lock:
            self._unsubscribe()
            self.running = operational
            self.tpdos = self._read(TX) if operational else []
            self.rpdos = {pdo.cob_id: pdo for pdo in self._read(RX)} if operational else {}
            for cob_id in self.rpdos:
                self.node.network.subscribe(cob_id, self._received)
            self.sync_id = self._sync_id() if operational else None
            if self.sync_id is not None:
                self.node.network.subscribe(self.sync_id, self._sync)
            now = time.monotonic()
            for pdo in self.tpdos:
                pdo.next_event = now + pdo.event_timer if pdo.event_timer else 0.0
                if pdo.transmission in EVENT_TYPES:
                    self._send(pdo, now)  # the first transmission on entering OPERATIONAL
        self._timer_thread()

    def stop(self) -> None:
        self.follow(False)
        self.wake.set()

    def changed(self, index: int, subindex: int) -> None:
        """A mapped value changed: event-driven TPDOs send (inhibit time permitting), type 0 ones on SYNC."""
        now = time.monotonic()
        for pdo in self.tpdos:
            if not pdo.maps(index, subindex):
                continue
            pdo.changed = True
            if pdo.transmission in EVENT_TYPES and now - pdo.last_sent >= pdo.inhibit:
                self._send(pdo, now)

    # Reading the parameters --------------------------------------------------------------------------

    def _read(self, direction: str) -> list[Pdo]:
        found = []
        for n in range(PDO_SPAN):
            pdo = self._pdo(COMM_BASE[direction] + n, MAP_BASE[direction] + n)
            if pdo is not None:
                found.append(pdo)
        return found

    def _pdo(self, comm: int, mapping: int) -> Pdo | None:
        store = self.node.node.data_store
        if comm not in store or mapping not in store:
            return None
        cob = self._u(comm, 1)
        if cob is None or cob & VALID:
            return None
        count = self._u(mapping, 0) or 0
        entries = [decode_entry(self._u(mapping, sub) or 0) for sub in range(1, count + 1)]
        return Pdo(
            cob_id=cob & (BASE_29BIT if cob & EXTENDED else BASE_11BIT),
            extended=bool(cob & EXTENDED),
            transmission=self._u(comm, 2) or 0,
            inhibit=(self._u(comm, 3) or 0) * INHIBIT_UNIT,
            event_timer=(self._u(comm, 5) or 0) / 1000,
            entries=entries,
        )

    def _u(self, index: int, subindex: int) -> int | None:
        data = self.node.node.data_store.get(index, {}).get(subindex)
        return int.from_bytes(data, "little") if data else None

    def _sync_id(self) -> int:
        cob = self._u(COB_ID_SYNC, 0)
        return (cob & BASE_29BIT if cob & EXTENDED else cob & BASE_11BIT) if cob is not None else SYNC_ID

    def _unsubscribe(self) -> None:
        for cob_id in self.rpdos:
            self.node.network.unsubscribe(cob_id, self._received)
        if self.sync_id is not None:
            self.node.network.unsubscribe(self.sync_id, self._sync)

    # Sending and receiving ---------------------------------------------------------------------------

    def _frame(self, pdo: Pdo) -> bytes:
        """The mapped values packed one after the other, least significant bit first."""
        bits, offset = 0, 0
        for index, subindex, length in pdo.entries:
            if not is_dummy_index(index):
                data = self.node.node.data_store.get(index, {}).get(subindex, b"")
                bits |= (int.from_bytes(data, "little") & ((1 << length) - 1)) << offset
            offset += length
        return bits.to_bytes((offset + 7) // 8, "little")

    def _send(self, pdo: Pdo, now: float) -> None:
        self.node.network.send_message(pdo.cob_id, self._frame(pdo))
        pdo.changed = False
        pdo.last_sent = now
        if pdo.event_timer:
            pdo.next_event = now + pdo.event_timer
            self.wake.set()

    def _sync(self, can_id: int, data: bytearray, timestamp: float) -> None:
        with self.node.lock:
            now = time.monotonic()
            for pdo in self.rpdos.values():
                if pdo.pending is not None:
                    self._apply(pdo, pdo.pending)
                    pdo.pending = None
            for pdo in self.tpdos:
                if pdo.transmission not in SYNC_TYPES:
                    continue
                pdo.sync_count += 1
                due = pdo.changed if pdo.transmission == 0 else pdo.sync_count >= pdo.transmission
                if due:
                    pdo.sync_count = 0
                    self._send(pdo, now)

    def _received(self, can_id: int, data: bytearray, timestamp: float) -> None:
        with self.node.lock:
            pdo = self.rpdos.get(can_id)
            if pdo is None:
                return
            if pdo.transmission in SYNC_TYPES:
                pdo.pending = bytes(data)
            else:
                self._apply(pdo, bytes(data))

    def _apply(self, pdo: Pdo, data: bytes) -> None:
        """Write each mapped value of a received RPDO into the dictionary (a frame too short is ignored)."""
        total = sum(length for _, _, length in pdo.entries)
        if len(data) * 8 < total:
            return
        bits, offset = int.from_bytes(data, "little"), 0
        for index, subindex, length in pdo.entries:
            if not is_dummy_index(index) and subindex in self.node.node.data_store.get(index, {}):
                value = (bits >> offset) & ((1 << length) - 1)
                size = len(self.node.node.data_store[index][subindex]) or (length + 7) // 8
                self.node.node.data_store[index][subindex] = value.to_bytes(size, "little")
            offset += length

    # The event timers --------------------------------------------------------------------------------

    def _timer_thread(self) -> None:
        if self.thread is None or not self.thread.is_alive():
            self.thread = threading.Thread(target=self._timers, name="simulate-pdo", daemon=True)
            self.thread.start()
        self.wake.set()

    def _timers(self) -> None:
        while True:
            self.wake.wait(self._due_in())
            self.wake.clear()
            with self.node.lock:
                if not self.running:
                    return
                now = time.monotonic()
                for pdo in self.tpdos:
                    if pdo.event_timer and pdo.transmission in EVENT_TYPES and now >= pdo.next_event:
                        self._send(pdo, now)

    def _due_in(self) -> float:
        due = [pdo.next_event for pdo in self.tpdos if pdo.event_timer and pdo.transmission in EVENT_TYPES]
        return max(0.0, min(due) - time.monotonic()) if due else IDLE
