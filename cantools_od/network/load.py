"""Bus load: how much of the bus a planned network's frames take, in the worst case.

A classical CAN data frame (ISO 11898-1) has 34 bits (11-bit identifier) or 54 bits (29-bit) before
its data that are subject to bit stuffing, then 8 bits per data byte, then CRC delimiter, ACK slot,
ACK delimiter, end of frame and intermission (13 bits) that are not. In the worst case a stuff bit
follows every 4 bits after the first of the stuffed part: an 8-byte frame takes 135 bit times
(11-bit identifier) or 160 (29-bit).

How often each frame is sent follows its transmission type: 1-240 every n-th SYNC, 0 at most once
per SYNC, 254/255 on events, as often as the inhibit time allows (else every event timer period;
with neither the rate is unknown and the PDO is listed as not counted), 252/253 only on request
(not counted). SYNC is sent every `sync_period` µs, heartbeats every producer time.

The worst SYNC period holds every frame that can fall into one period of T µs: SYNC and each
synchronous PDO once (a PDO sent every n-th SYNC may fall into any one), and each frame sent at
least Δ µs apart (an event-driven PDO's inhibit time, else its event timer; a heartbeat's producer
time) ceil(T / Δ) times. Its load is Σ bits * count / (bit rate * T). EMCY, SDO and NMT frames
have no bound and are not counted (the report says so).

A PDO longer than 8 bytes can only travel in a CAN FD frame: its worst case follows ISO 11898-1:2015
(arbitration and the frame's end at the nominal rate, control, data, stuff count and CRC at the data
rate), counted in nominal bit times; the load at other bit rates keeps the ratio of the two rates.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from ..model.cia301.cobid import BASE_29BIT, EXTENDED, HEARTBEAT_BASE, SYNC_ID
from ..model.cia301.objects import RX, TX
from .plan import NetworkPlan, PlannedPdo

STUFFED_BITS = {False: 34, True: 54}  # SOF, arbitration, control and CRC bits ahead of/after the data, stuffed
UNSTUFFED_BITS = 13  # CRC delimiter, ACK slot, ACK delimiter, EOF (7), intermission (3)
SYNC_LAST = 240
ACYCLIC_SYNC = 0
RTR_ONLY = (252, 253)
BIT_RATES = (10, 20, 50, 125, 250, 500, 800, 1000)  # kbit/s, CiA 301's


def frame_bits(data_bytes: int, extended: bool = False) -> int:
    """Worst-case bit times of a classical CAN data frame, stuff bits included."""
    stuffed = STUFFED_BITS[extended] + 8 * data_bytes
    return stuffed + (stuffed - 1) // 4 + UNSTUFFED_BITS


FD_LENGTHS = (0, 1, 2, 3, 4, 5, 6, 7, 8, 12, 16, 20, 24, 32, 48, 64)  # the data lengths a CAN FD DLC can state
FD_ARBITRATION = {False: 17, True: 36}  # SOF, identifier, RRS, IDE, (SRR), FDF, res, BRS: at the nominal rate
FD_CONTROL = 5  # ESI, DLC: at the data rate
FD_TAIL = 12  # ACK slot, ACK delimiter, EOF (7), intermission (3): at the nominal rate
FD_CRC_SPLIT = 16  # data bytes up to which the CRC has 17 bits, 21 above


def fd_frame_time(data_bytes: int, nominal: int, data_rate: int, extended: bool = False) -> float:
    """Worst-case duration in µs of a CAN FD data frame (ISO 11898-1:2015) with bit rate switching from
    `nominal` to `data_rate` kbit/s: dynamic stuff bits up to the end of the data, then the stuff count
    (4 bits) and the CRC (17 or 21 bits) with their fixed stuff bits (one before, one after every 4)."""
    length = next(size for size in FD_LENGTHS if size >= data_bytes)
    arbitration = FD_ARBITRATION[extended]
    stuffed = arbitration + FD_CONTROL + 8 * length
    stuff_bits = (stuffed - 1) // 4
    nominal_stuff = (arbitration - 1) // 4
    crc = 17 if length <= FD_CRC_SPLIT else 21
    fixed = 1 + (4 + crc) // 4
    nominal_bits = arbitration + nominal_stuff + 1 + FD_TAIL  # the CRC delimiter counted at the nominal rate
    data_bits = FD_CONTROL + 8 * length + (stuff_bits - nominal_stuff) + 4 + crc + fixed
    return 1000 * nominal_bits / nominal + 1000 * data_bits / data_rate


@dataclass(frozen=True)
class Frame:
    name: str
    bits: int
    per_second: float
    note: str = ""
    spacing: int = 0
    """The least time between two of these frames in µs; 0: sent once per SYNC at most."""
    sender: str = ""  # the node that sends it: "master" or a slave's name
    can_id: int = 0

    def in_period(self, period: int) -> int:
        """How many of these frames can fall into `period` µs (one SYNC period): ceil(period / spacing)."""
        return 1 if not self.spacing else -(-period // self.spacing)


@dataclass
class Load:
    file: str
    bit_rate: int  # kbit/s
    sync_period: int  # µs, 0: no SYNC
    frames: list[Frame] = field(default_factory=list)
    not_counted: list[str] = field(default_factory=list)

    def percent_per_second(self, bit_rate: int | None = None) -> float:
        rate = (bit_rate or self.bit_rate) * 1000
        return 100.0 * sum(frame.bits * frame.per_second for frame in self.frames) / rate

    def percent_per_sync(self, bit_rate: int | None = None) -> float:
        if not self.sync_period:
            return 0.0
        rate = (bit_rate or self.bit_rate) * 1000
        busy = sum(frame.bits * frame.in_period(self.sync_period) for frame in self.frames) / rate
        return 100.0 * busy / (self.sync_period / 1e6)

    @property
    def peak_percent(self) -> float:
        return max(self.percent_per_second(), self.percent_per_sync())


CLASSIC_BYTES = 8


def pdo_bits(pdo: PlannedPdo, nominal: int, data_rate: int) -> int:
    """Worst-case bit times of the PDO's frame at the nominal rate: a classical frame up to 8 bytes,
    a CAN FD frame (its data phase at `data_rate`) above."""
    size, extended = (pdo.bits + 7) // 8, bool(pdo.cob_id & EXTENDED)
    if size <= CLASSIC_BYTES:
        return frame_bits(size, extended)
    return math.ceil(fd_frame_time(size, nominal, data_rate, extended) * nominal / 1000)


def pdo_period(pdo: PlannedPdo, sync_period: int) -> int | None:
    """The cycle of a PDO sent cyclically in µs (transmission 1-240: every n-th SYNC; 254/255 with an
    event timer: the timer), None for one sent on events, on request or acyclically."""
    if 1 <= pdo.transmission <= SYNC_LAST:
        return pdo.transmission * sync_period or None
    if pdo.transmission > max(RTR_ONLY) and pdo.direction == TX and pdo.event_timer:
        return pdo.event_timer * 1000
    return None


def _pdo_frame(pdo: PlannedPdo, who: str, sync_hz: float, rates: tuple[int, int]) -> Frame | str:
    """The PDO's frame and rate, or why it is not counted."""
    name = f"{who} {pdo.name} ({pdo.cob_id & BASE_29BIT:03X}h)"
    bits = pdo_bits(pdo, *rates)
    kind = pdo.transmission
    if kind <= SYNC_LAST:
        if not sync_hz:
            return f"{name}: synchronous, but the master sends no SYNC"
        every = 1 if kind == ACYCLIC_SYNC else kind
        note = "acyclic, at most every SYNC" if kind == ACYCLIC_SYNC else f"every {every}. SYNC"
        return Frame(name, bits, sync_hz / every, note)
    if kind in RTR_ONLY:
        return f"{name}: sent on request (RTR) only"
    if pdo.direction == TX and pdo.inhibit_time:
        spacing = pdo.inhibit_time * 100
        return Frame(name, bits, 1e6 / spacing, f"events, inhibit time {spacing} µs", spacing)
    if pdo.direction == TX and pdo.event_timer:
        note = f"event timer {pdo.event_timer} ms (events in between: no inhibit time bounds them)"
        return Frame(name, bits, 1000 / pdo.event_timer, note, pdo.event_timer * 1000)
    return f"{name}: event-driven without event timer or inhibit time: its rate is the application's"


def bus_load(plan: NetworkPlan, data_rate: int | None = None) -> Load:
    """The network's frames and rates; PDOs above 8 bytes are CAN FD frames whose data phase runs at
    `data_rate` kbit/s (the nominal rate when not given)."""
    master = plan.master
    rates = (master.baudrate, data_rate or master.baudrate)
    load = Load(plan.network.file, master.baudrate, master.sync_period)
    sync_hz = 1e6 / master.sync_period if master.sync_period else 0.0
    if sync_hz:
        note = f"every {master.sync_period} µs"
        load.frames.append(Frame(f"master SYNC ({SYNC_ID:03X}h)", frame_bits(0), sync_hz, note, 0, "master", SYNC_ID))
    if master.heartbeat_producer:
        beat = HEARTBEAT_BASE + master.node_id
        load.frames.append(_heartbeat("master heartbeat", master.heartbeat_producer, "master", beat))
    for slave in plan.slaves:
        name = slave.slave.name
        for direction, who in ((TX, name), (RX, f"master → {name}")):
            for pdo in slave.active(direction):
                result = _pdo_frame(pdo, who, sync_hz, rates)
                if isinstance(result, str):
                    load.not_counted.append(result)
                else:
                    sender = name if direction == TX else "master"
                    load.frames.append(replace(result, sender=sender, can_id=pdo.cob_id & BASE_29BIT))
        if slave.heartbeat_producer:
            beat = HEARTBEAT_BASE + slave.node_id
            load.frames.append(_heartbeat(f"{name} heartbeat ({beat:03X}h)", slave.heartbeat_producer, name, beat))
    load.not_counted.append("EMCY, SDO and NMT frames: sent on errors and requests, without a bound")
    return load


def _heartbeat(name: str, period_ms: int, sender: str, can_id: int) -> Frame:
    return Frame(name, frame_bits(1), 1000 / period_ms, f"every {period_ms} ms", period_ms * 1000, sender, can_id)


def format_load(load: Load, threshold: float) -> str:
    lines = [f"{load.file}: bus load at {load.bit_rate} kbit/s (worst case, stuff bits included)"]
    width = max([len(frame.name) for frame in load.frames] + [5])
    lines.append(f"  {'frame':<{width}}  bits  frames/s  when")
    for frame in load.frames:
        count = f" ({frame.in_period(load.sync_period)} in a SYNC period)" if load.sync_period else ""
        lines.append(f"  {frame.name:<{width}}  {frame.bits:>4}  {frame.per_second:>8.1f}  {frame.note}{count}")
    for reason in load.not_counted:
        lines.append(f"  not counted: {reason}")
    per_second = load.percent_per_second()
    lines.append(f"  load per second: {per_second:.1f} %")
    if load.sync_period:
        lines.append(f"  load in the worst SYNC period ({load.sync_period} µs): {load.percent_per_sync():.1f} %")
    others = ", ".join(f"{rate} kbit/s {load.percent_per_second(rate):.1f} %" for rate in BIT_RATES)
    lines.append(f"  per second at each bit rate: {others}")
    if load.peak_percent > threshold:
        lines.append(f"{load.file}: warning: bus load {load.peak_percent:.1f} % is above {threshold:g} %")
    return "\n".join(lines) + "\n"
