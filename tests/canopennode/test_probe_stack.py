"""`probe` against the real CANopenNode stack: the demo device as CANopenDemo's authors build it (the stack, the
OD generated from demoDevice.eds, the demo's application: CO_application.c and the sources it initialises) behind
the TCP driver of test_can_bus.py, bridged to python-can's `virtual` bus; probed with its own EDS and with the
EDS changed: each change gives exactly its finding. Without the snapshot of CANopenDemo (the application's other
sources), the device with the demo's CO_identificators.c alone, from ../shared."""

from __future__ import annotations

import contextlib
import re
import socket
import struct
import subprocess
import uuid
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import cast

import mirrors
import pytest
from cnokit import DEMO, gen, stack
from demo_app import REPO, Application, demo_application, ident_string, identificators
from test_can_bus import NODE_ID, Bridge, build_device

from cantools_od.api import load, loads
from cantools_od.lint import Finding
from cantools_od.live.probe import ProbeOptions, Prober, ProbeResult
from cantools_od.model import Device
from cantools_od.model.cia301 import aborts
from cantools_od.model.cia301.objects import ERROR_HISTORY

EDS = DEMO / "demoDevice.eds"


@dataclass(frozen=True)
class Built:
    exe: Path
    application: Application


def _built(factory: pytest.TempPathFactory, name: str, application_of: Callable[[Path], Application]) -> Built:
    stack()
    work = factory.mktemp(name)
    application = application_of(work)
    assert gen(EDS, work / "od").returncode == 0
    return Built(build_device(work / "od", work, application), application)


@pytest.fixture(scope="module")
def demo_device(tmp_path_factory: pytest.TempPathFactory) -> Built:
    """The stack, our OD and the demo's whole application (skipped without the snapshot of CANopenDemo)."""
    return _built(tmp_path_factory, "demo-device", demo_application)


@pytest.fixture(scope="module")
def identified_device(tmp_path_factory: pytest.TempPathFactory) -> Built:
    """The stack, our OD and CO_identificators.c from ../shared, with the identity the EDS describes."""
    return _built(tmp_path_factory, "identified-device", lambda work: identificators(work, load(EDS)))


@pytest.fixture(scope="module")
def device(request: pytest.FixtureRequest) -> Built:
    """The demo device; without the snapshot of CANopenDemo, the device ../shared alone builds."""
    return cast(Built, request.getfixturevalue("demo_device" if mirrors.git_dir(REPO) else "identified_device"))


@pytest.fixture(scope="module")
def baseline(device: Built) -> ProbeResult:
    """What probe --check-writes reports on the device with the unchanged EDS: each change must add exactly its
    own finding to it."""
    return probed(device.exe, load(EDS, node_id=NODE_ID), check_writes=True)


@contextlib.contextmanager
def running(exe: Path) -> Iterator[str]:
    """The device process, its CAN on a virtual channel whose name is yielded."""
    server = socket.create_server(("127.0.0.1", 0))
    server.settimeout(20)
    process = subprocess.Popen([str(exe), "60000", str(server.getsockname()[1])], stdout=subprocess.PIPE, text=True)
    bridge = None
    try:
        link, _ = server.accept()
        channel = f"cantools-od-probe-{uuid.uuid4()}"
        bridge = Bridge(link, channel)
        yield channel
    finally:
        if bridge is not None:
            bridge.close()
        server.close()
        with contextlib.suppress(subprocess.TimeoutExpired):
            process.wait(timeout=5)
        process.kill()
        process.wait(timeout=5)


def probed(exe: Path, described: Device, check_writes: bool = False) -> ProbeResult:
    import canopen

    with running(exe) as channel:
        network = canopen.Network()
        network.connect(interface="virtual", channel=channel)
        try:
            return Prober(
                described, NODE_ID, network, ProbeOptions(timeout=5.0, wait=5.0, check_writes=check_writes)
            ).run()
        finally:
            network.disconnect()


ENTRY = re.compile(r"^\[([0-9A-F]{4})(?:sub([0-9A-F]+))?\]")


def _entry(finding: Finding) -> tuple[int, int]:
    found = ENTRY.match(finding.message)
    assert found is not None, finding.message
    return int(found[1], 16), int(found[2] or "0", 16)


def without_storage(od_c: str) -> set[tuple[int, int]]:
    """The entries the generated OD.c gives no data (`.dataOrig = NULL`): the stack answers a read of one
    with 0609 0011h (CO_ODinterface.c, OD_readOriginal), whatever the EDS says."""
    found = set()
    for block in re.split(r"\n    \.o_", od_c)[1:]:
        index = int(block[:4], 16)
        if re.match(r"\w+ = \{\s*\.dataOrig = NULL", block[5:]):
            found.add((index, 0))
        found |= {(index, int(sub)) for sub in re.findall(r"\.dataOrig = NULL,\s*\.subIndex = (\d+)", block)}
    return found


def _values(result: ProbeResult) -> dict[tuple[int, int], bytes | None]:
    return {(reading.index, reading.subindex): reading.data for reading in result.readings}


def _average(values: dict[tuple[int, int], bytes | None]) -> float:
    """What objectAccessOD.c answers for 2120sub5: the mean of sub-indices 1 to 4 (INTEGER64, UNSIGNED64,
    REAL32, REAL64), summed as doubles in that order."""
    numbers = [struct.unpack(f"<{kind}", values[0x2120, sub] or b"")[0] for sub, kind in enumerate("qQfd", 1)]
    return sum(float(number) for number in numbers) / 4


def test_probe_of_the_demo_device_with_its_own_eds_finds_only_its_power_on_counter(demo_device: Built) -> None:
    """Every entry the EDS lists answers, with its type's length, its identity, and the value the EDS gives it.
    The entries the OD holds no data for answer from the application: 1008h-100Ah the strings of its
    CO_ident_defs.h (CO_identificators.c), 2120sub5 the average objectAccessOD.c computes. The one difference
    is true, and an info: app_programStart counts the start in 2106h, whose DefaultValue is 0."""
    result = probed(demo_device.exe, load(EDS, node_id=NODE_ID))
    assert [(f.code, _entry(f)) for f in result.findings] == [("PRB005", (0x2106, 0))], [
        f.format() for f in result.findings
    ]
    assert "the device holds 1," in result.findings[0].message
    assert result.read > 150
    unanswered = {(r.index, r.abort) for r in result.readings if r.data is None}
    assert unanswered <= {(ERROR_HISTORY, aborts.NO_DATA)}, unanswered  # an error history without errors
    values, ident_defs = _values(result), demo_device.application.ident_defs
    for index, name in ((0x1008, "CO_DEVICE_NAME"), (0x1009, "CO_HW_VERSION"), (0x100A, "CO_SW_VERSION")):
        assert values[index, 0] == ident_string(ident_defs, name), f"{index:04X}"
    assert values[0x2120, 5] == struct.pack("<d", _average(values))
    print(f"\nprobe read {result.read} entries of the demo device in {result.seconds:.2f} s")


def test_writing_back_every_writable_entry_is_refused_nowhere(device: Built, baseline: ProbeResult) -> None:
    """--check-writes: every writable entry gets back the value just read (the inhibit time and SYNC start value
    of a valid TPDO, which the stack refuses as CiA 301 says, excepted), and the device refuses none: the
    findings are those of the reads alone."""
    reads = probed(device.exe, load(EDS, node_id=NODE_ID))
    writes = baseline.transfers - reads.transfers
    assert [(f.code, f.message) for f in baseline.findings] == [(f.code, f.message) for f in reads.findings]
    assert writes > 100
    print(f"\nwrote back {writes} entries")


def test_probe_of_the_stack_with_the_demos_identificators_alone(identified_device: Built) -> None:
    """The device ../shared alone builds: the stack, our OD and CO_identificators.c. The entries the generated
    OD gives no data (`.dataOrig = NULL`) and nothing serves do not exist for the stack (0609 0011h,
    CO_ODinterface.c's OD_readOriginal): only 2120sub5, which objectAccessOD.c would serve."""
    result = probed(identified_device.exe, load(EDS, node_id=NODE_ID))
    od_c = (identified_device.exe.parent / "od" / "OD.c").read_text(encoding="utf-8")
    read = {(reading.index, reading.subindex) for reading in result.readings}  # DOMAIN entries are not read
    served = {(0x1008, 0), (0x1009, 0), (0x100A, 0)}
    assert {f.code for f in result.findings} == {"PRB001"}, [f.format() for f in result.findings]
    assert {_entry(f) for f in result.findings} == (without_storage(od_c) & read) - served == {(0x2120, 5)}
    values = _values(result)
    assert values[0x1008, 0] == ident_string(identified_device.application.ident_defs, "CO_DEVICE_NAME")


@pytest.mark.parametrize(
    ("old", "new", "code"),
    [
        pytest.param("[1018]", "[2F00]\nParameterName=Extra\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\n"
                     "DefaultValue=0\n\n[1018]", "PRB001", id="missing object"),
        pytest.param(
            "ParameterName=Producer heartbeat time\nObjectType=0x7\n;StorageLocation=PERSIST_COMM\nDataType=0x0006",
            "ParameterName=Producer heartbeat time\nObjectType=0x7\n;StorageLocation=PERSIST_COMM\nDataType=0x0007",
            "PRB002",
            id="wrong type size"),
        pytest.param("ParameterName=Vendor-ID\nObjectType=0x7\n;StorageLocation=RAM\nDataType=0x0007\nAccessType=ro",
                     "ParameterName=Vendor-ID\nObjectType=0x7\n;StorageLocation=RAM\nDataType=0x0007\nAccessType=rw",
                     "PRB007", id="wrong access"),
        pytest.param("VendorNumber=0\n", "VendorNumber=0x1234\n", "PRB004", id="wrong identity"),
    ],
)  # fmt: skip
def test_each_change_of_the_eds_gives_exactly_its_finding(
    device: Built, baseline: ProbeResult, old: str, new: str, code: str
) -> None:
    text = EDS.read_text(encoding="utf-8")
    assert text.count(old) >= 1, old
    changed = loads(text.replace(old, new, 1), source=str(EDS), node_id=NODE_ID)
    before = {(f.code, f.message) for f in baseline.findings}
    found = [f for f in probed(device.exe, changed, check_writes=True).findings if (f.code, f.message) not in before]
    assert [f.code for f in found] == [code], [f.format() for f in found]
