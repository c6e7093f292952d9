"""Read a live node over SDO, entry by entry, against its description; report where the two disagree.

Every entry the description lists is uploaded (DOMAIN entries excepted: a program or a log can be large, and
reading one may have effects). What comes back is judged by `judge.py`, reported as lint reports (the PRB
codes of lint/probe.py). Nothing is written unless `check_writes`: then each writable entry gets back the value
just read, so the device keeps its values.
"""

from __future__ import annotations

import contextlib
import struct
import time
from collections.abc import Callable, Iterator
from dataclasses import dataclass, field
from typing import TYPE_CHECKING

from ..interop import to_canopen
from ..lint.rules import Context, Finding, LintOptions
from ..model import AccessType, Object, ObjectKind, Variable
from ..model.cia301 import aborts
from ..model.cia301.objects import (
    COMM_BASE,
    DEVICE_TYPE,
    MAP_BASE,
    PDO_SPAN,
    RESTORE_DEFAULTS,
    RX,
    STORE_PARAMETERS,
    TX,
)
from ..model.datatypes import DOMAIN
from .judge import Judge, Reading

if TYPE_CHECKING:
    import canopen

    from ..model import Device

PROGRAM_CONTROL = 0x1F51  # CiA 302-3: writing it starts or stops the application
# Writing back the value read has an effect here, or a device refuses it by the standard: a store or restore
# command, a program command, a mapping, and the inhibit time and SYNC start value (sub-indices 3 and 6 of a
# PDO's communication record), which CiA 301 lets change only while the PDO is disabled.
PDO_FIXED_WHILE_VALID = (3, 6)
NO_WRITE_BACK = (
    {STORE_PARAMETERS, RESTORE_DEFAULTS, PROGRAM_CONTROL}
    | set(range(MAP_BASE[RX], MAP_BASE[RX] + PDO_SPAN))
    | set(range(MAP_BASE[TX], MAP_BASE[TX] + PDO_SPAN))
)
PDO_COMMUNICATION = set(range(COMM_BASE[RX], COMM_BASE[RX] + PDO_SPAN)) | set(
    range(COMM_BASE[TX], COMM_BASE[TX] + PDO_SPAN)
)


STOPPED_ANSWERING = 3  # reads in a row without an answer: the node is gone, not slow


class NoAnswer(Exception):
    """The node does not answer SDO at all: nothing can be probed."""


@dataclass(frozen=True)
class ProbeOptions:
    timeout: float = 0.5  # seconds one SDO request waits for its response
    wait: float = 0.0  # seconds to wait for the node to answer its first SDO
    check_writes: bool = False


@dataclass
class ProbeResult:
    findings: list[Finding] = field(default_factory=list)
    readings: list[Reading] = field(default_factory=list)
    transfers: int = 0  # SDO uploads and downloads
    skipped: int = 0  # entries not read (write-only, DOMAIN)
    seconds: float = 0.0

    @property
    def read(self) -> int:
        return sum(reading.data is not None for reading in self.readings)


Entry = tuple[Object, int, Variable]


class Prober:
    """Probes `device` as the node `node_id` on `network`."""

    def __init__(self, device: Device, node_id: int, network: canopen.Network, options: ProbeOptions) -> None:
        import canopen

        self.device, self.options = device, options
        self.od = to_canopen(device, node_id)
        self.node = canopen.RemoteNode(node_id, self.od)
        network.add_node(self.node)
        self.node.sdo.RESPONSE_TIMEOUT = options.timeout
        self.node.sdo.MAX_RETRIES = 1  # one request each: a node that does not answer is reported, not retried
        self.result = ProbeResult()
        self.judge = Judge(Context(device, LintOptions(node_id=node_id)), self.od)
        self.current: tuple[int, int] | None = None  # the transfer under way, to abort on Ctrl-C

    def entries(self) -> list[Entry]:
        """What the description lists, in index order, as python-canopen's dictionary holds it."""
        found: list[Entry] = []
        for index in sorted(self.device.objects):
            obj = self.device.objects[index]
            if obj.kind in (ObjectKind.NULL, ObjectKind.DEFTYPE, ObjectKind.DEFSTRUCT) or index not in self.od:
                continue
            if obj.has_subs:
                found += [(obj, sub, obj.subs[sub]) for sub in sorted(obj.subs)]
            else:
                found.append((obj, 0, obj))
        return found

    def run(self, step: Callable[[str], None] = lambda label: None) -> ProbeResult:
        started = time.monotonic()
        self._first_answer()
        missing: set[int] = set()
        silent = 0  # reads in a row without an answer
        for owner, sub, var in self.entries():
            step(f"{owner.index:04X}sub{sub:X}")
            if owner.index in missing:
                continue
            reading = self._read(owner, sub, var)
            if reading is None:
                continue
            self.result.readings.append(reading)
            silent = silent + 1 if reading.abort == aborts.TIMEOUT else 0
            if silent >= STOPPED_ANSWERING:
                raise NoAnswer(f"node {self.node.id} stopped answering SDO (from {owner.index:04X}sub{sub:X} on)")
            if reading.abort == aborts.NO_OBJECT:
                missing.add(owner.index)
            self.result.findings += self.judge.reading(owner, sub, var, reading)
            if self.options.check_writes and reading.data is not None and self._writes_back(owner, sub, var):
                self.result.findings += self.judge.written(owner, sub, var, self._write(owner.index, sub, reading))
        self.result.seconds = time.monotonic() - started
        return self.result

    def _first_answer(self) -> None:
        """Device type (1000h) answers, or an abort does: the node is there. No answer within the wait: NoAnswer."""
        deadline = time.monotonic() + self.options.wait
        while True:
            outcome = self._upload(DEVICE_TYPE, 0)
            if outcome.abort != aborts.TIMEOUT:
                return
            if time.monotonic() >= deadline:
                raise NoAnswer(
                    f"node {self.node.id} does not answer SDO (no response to a read of 1000h within "
                    f"{self.options.timeout:g} s)"
                )

    def _read(self, owner: Object, sub: int, var: Variable) -> Reading | None:
        if var.access is AccessType.WO or self.device.entry_type(var, owner) in (DOMAIN, None):
            self.result.skipped += 1
            return None
        return self._upload(owner.index, sub)

    def _upload(self, index: int, sub: int) -> Reading:
        from canopen import SdoAbortedError, SdoCommunicationError

        self.result.transfers += 1
        self.current = (index, sub)
        try:
            return Reading(index, sub, data=self._uploaded(index, sub))
        except SdoAbortedError as error:
            return Reading(index, sub, abort=error.code)
        except SdoCommunicationError:
            return Reading(index, sub, abort=aborts.TIMEOUT)
        finally:
            self.current = None

    def _uploaded(self, index: int, sub: int) -> bytes:
        """The bytes as sent: python-canopen's `upload` would cut a longer answer to the type's length."""
        with self.node.sdo.open(index, sub, buffering=0) as stream:
            size, data = stream.size, bytes(stream.read())
        variable = self.od.get_variable(index, sub)
        if size is None and variable is not None and variable.fixed_size:
            return data[: len(variable) // 8]  # an expedited answer that does not say its length
        return data

    def _writes_back(self, owner: Object, sub: int, var: Variable) -> bool:
        if var.access is None or not var.access.writable or owner.index in NO_WRITE_BACK:
            return False
        return not (owner.index in PDO_COMMUNICATION and sub in PDO_FIXED_WHILE_VALID)

    def _write(self, index: int, sub: int, reading: Reading) -> int | None:
        """Download the bytes just read; the abort code when the device refuses (TIMEOUT: no answer)."""
        from canopen import SdoAbortedError, SdoCommunicationError

        self.result.transfers += 1
        self.current = (index, sub)
        try:
            self.node.sdo.download(index, sub, reading.data or b"")
        except SdoAbortedError as error:
            return int(error.code)
        except SdoCommunicationError:
            return aborts.TIMEOUT
        finally:
            self.current = None
        return None

    def interrupted(self) -> None:
        """Ctrl-C during a transfer: abort it, so the server does not wait for the rest of a segmented one."""
        if self.current is None:
            return
        index, sub = self.current
        abort = struct.pack("<BHBI", aborts.ABORT_TRANSFER, index, sub, aborts.GENERAL_ERROR)
        with contextlib.suppress(Exception):  # the bus is gone: the server's own timeout ends the transfer
            self.node.network.send_message(self.node.sdo.rx_cobid, abort)


def walk(readings: list[Reading]) -> Iterator[tuple[tuple[int, int], bytes]]:
    """The values read, by (index, sub-index)."""
    for reading in readings:
        if reading.data is not None:
            yield (reading.index, reading.subindex), reading.data


def describe_abort(code: int | None) -> str:
    return "no answer" if code == aborts.TIMEOUT else f"abort {aborts.describe(code or 0)}"
