"""Codes `probe` reports (family probe): where a live device disagrees with its description.

They are not checks of a file: `cantools-od probe` reads the device over SDO and reports them (cantools_od/live).
Each example runs as a user would: `simulate` serves the device's own description (device.eds) on a bus between
processes (python-can's udp_multicast, configured by its environment variables), and `probe` reads it against
the description under test (example.eds). Each example has a port of its own, so that examples run at the same
time do not hear each other.
"""

from __future__ import annotations

from collections.abc import Callable

from ..model import Severity
from ..model.datatypes import STANDARD_TYPES
from . import examples as ex
from .rules import Clause, Placement, declare

E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO
U16, U32 = (STANDARD_TYPES[n].index for n in (6, 7))  # the data types of the examples' entries


def _speed() -> str:
    return ex.var(0x2000, "Speed", U32, "rw", 5, 0)


Made = Callable[[], str]
_PROBE = "`probe` reads every entry of the description over SDO (docs/probe.md)."


def _example(port: int, device: str, described: str, probe: str = "", script: str = "") -> str:
    """A rule example: the device's description, the one probed, a `--script` for simulate, the command line."""
    files = f"; file: device.eds\n{device}; file: example.eds\n{described}"
    simulate = "cantools-od simulate device.eds --node-id 5 --duration 30"
    if script:
        files += f"; whole file: script.py\n{script}\n"
        simulate += " --script script.py"
    bus = f"export CAN_INTERFACE=udp_multicast CAN_CHANNEL=239.0.0.1 CAN_CONFIG='{{\"port\": {port}}}'"
    run = f"cantools-od probe example.eds --node-id 5 --wait 20{probe}"
    return f"{files}; $ {bus}; {simulate} & {run}; kill %1; wait\n"


def _declare(code: str, severity: Severity, summary: str, why: str, port: int, device: Made, described: Made,
             fix: str, probe: str = "", script: str = "", *, placed: Placement) -> None:  # fmt: skip
    """A probe code; its fixed example probes the device with the description it serves (and no script). The
    examples are made when read, not when lint imports this module."""
    declare(
        code, severity, summary, f"{why.strip()}\n\n{_PROBE}",
        lambda: _example(port, device(), described(), probe, script), family="probe",
        fixed=lambda: _example(port + 100, described(), described(), probe),
        fix_safety=f"No automatic fix: {fix}", refs="CiA 301 §7.2.4.3.17 (SDO abort codes)", placed=placed,
    )  # fmt: skip


_declare(
    "PRB001",
    E,
    "The device has no such object or sub-index",
    """
The description lists an entry the device does not have: its read aborts with 0602 0000h (no object) or
0609 0011h (no sub-index). A master that configures it, or a tool that trusts the description, fails on it.""",
    43201,
    _speed,
    lambda: _speed() + ex.var(0x2001, "Torque", U16, "rw", 0, 0),
    "remove the entry from the description, or implement it in the firmware.",
    placed=Placement(Clause.DEVICE_MISBEHAVES, "a master configuring the entry fails on the device"),
)
_declare(
    "PRB002",
    E,
    "The device's data length is not the data type's",
    """
The device answers a read with another number of bytes than the description's data type has, or aborts it
with 0607 0010h/0012h/0013h: the description and the firmware disagree on the type. A PDO mapping or a write
built from the description then fails (abort 0607 0010h) or reads the wrong bytes.""",
    43202,
    _speed,
    lambda: _speed().replace("DataType=0x0007", "DataType=0x0006"),
    "give the entry the data type the firmware implements.",
    placed=Placement(
        Clause.DEVICE_MISBEHAVES, "a mapping or write built from the description fails (abort 0607 0010h)"
    ),
)
_declare(
    "PRB003",
    E,
    "The device refuses to read an entry the description says is readable",
    """
The description says the entry can be read (ro, rw, rwr, rww, const) but the device aborts the read: 0601 0001h
(write only), 0601 0000h (unsupported access) or another abort code.""",
    43203,
    lambda: _speed().replace("AccessType=rw", "AccessType=wo"),
    _speed,
    "give the entry the access type the firmware implements.",
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device refuses a read the description promises"),
)
_declare(
    "PRB004",
    E,
    "Device type or identity differs from the description",
    """
Device type (1000h) or identity (1018h sub-indices 1-3, and the serial number when a DCF gives it) as read
differs from what the description gives a master to compare: [DeviceInfo]'s VendorNumber, ProductNumber or
RevisionNumber when not 0, else the entry's value. A master's boot-up check compares exactly these (CiA 302-2,
1F84h-1F88h, which lely's dcfgen and ros2_canopen fill in from the description; 0 is not checked), and
refuses to start the node when they differ.""",
    43204,
    lambda: ex.var(0x1000, "Device type", U32, "ro", "0x00040192", 0) + _speed(),
    lambda: ex.var(0x1000, "Device type", U32, "ro", "0x00020192", 0) + _speed(),
    "describe the device as it is (its 1000h/1018h and [DeviceInfo]), or probe the device the description is for.",
    placed=Placement(Clause.DEVICE_MISBEHAVES, "a master's boot-up check (1F84h-1F88h) rejects the device"),
)
_declare(
    "PRB005",
    INFO,
    "A value differs from the description's",
    """
The device holds another value than the description's ParameterValue (a DCF) or DefaultValue: a default that
was never true, or a device configured since. Values the device produces itself (read-only process inputs,
its error state) are not compared. `probe -o actual.dcf` keeps what the device holds.""",
    43205,
    lambda: _speed().replace("DefaultValue=5", "DefaultValue=7"),
    _speed,
    "correct the default, or restore the device's defaults (1011h) if it was configured by mistake.",
    placed=Placement(Clause.DECISION, "a default that was never true, or a device configured since"),
)
_declare(
    "PRB006",
    W,
    "A communication parameter differs from the description's",
    """
A value of the communication area (1000h-1FFFh: COB-IDs, PDO transmission, heartbeat, ...) differs from the
description's: a master or a network tool planning from the description expects other traffic than the device
sends.""",
    43206,
    lambda: ex.var(0x1017, "Producer heartbeat time", U16, "rw", 100, 0) + _speed(),
    lambda: ex.var(0x1017, "Producer heartbeat time", U16, "rw", 0, 0) + _speed(),
    "correct the description, or configure the device as it says.",
    placed=Placement(Clause.BEYOND_THE_PEERS, "a network tool planning from the description expects other traffic"),
)
_declare(
    "PRB007",
    E,
    "The device refuses a write of an entry the description says is writable",
    """
With `--check-writes`, `probe` writes each writable entry back with the value it just read (so the device keeps
its values): the device aborts the write (0601 0002h: read only, or another code). Store and restore commands
(1010h/1011h), program control (1F51h), PDO mappings, and a PDO's inhibit time and SYNC start value (which
CiA 301 lets change only while the PDO is disabled) are not written.""",
    43207,
    lambda: _speed().replace("AccessType=rw", "AccessType=ro"),
    _speed,
    "give the entry the access type the firmware implements.",
    probe=" --check-writes",
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device refuses a write the description promises"),
)
_declare(
    "PRB008",
    E,
    "The device does not answer a read",
    """
The device answered other reads but not this one within the timeout (`--timeout`): it may be busy computing
the value, or its SDO server drops the request. A node that answers nothing is not probed: `probe` exits 2.""",
    43208,
    _speed,
    _speed,
    "find why the firmware does not answer, or give a longer --timeout.",
    script="def setup(node):\n    node.silence(0x2000, 0)  # its SDO server drops the requests for 2000h",
    placed=Placement(Clause.DEVICE_MISBEHAVES, "the device does not answer within the timeout"),
)
