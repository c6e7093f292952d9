"""`probe` against the real CANopenNode stack: the device of test_can_bus.py (the stack with the OD generated
from demoDevice.eds, its CAN bridged from TCP to python-can's `virtual` bus), probed with its own EDS and with
the EDS changed: each change gives exactly its finding."""

from __future__ import annotations

import contextlib
import re
import socket
import subprocess
import uuid
from collections.abc import Iterator
from pathlib import Path

import pytest
from cnokit import DEMO, gen, stack
from test_can_bus import NODE_ID, Bridge, build_device

from cantools_od.api import load, loads
from cantools_od.lint import Finding
from cantools_od.live.probe import ProbeOptions, Prober, ProbeResult
from cantools_od.model import Device

EDS = DEMO / "demoDevice.eds"


@pytest.fixture(scope="module")
def device_exe(tmp_path_factory: pytest.TempPathFactory) -> Path:
    stack()
    work = tmp_path_factory.mktemp("probe-stack")
    assert gen(EDS, work / "od").returncode == 0
    return build_device(work / "od", work)


@pytest.fixture(scope="module")
def baseline(device_exe: Path) -> set[tuple[str, str]]:
    """What probe --check-writes reports with the unchanged EDS (the entries without storage, and writes the
    stack refuses in its present state): each change must add exactly its own finding to it."""
    found = probed(device_exe, load(EDS, node_id=NODE_ID), check_writes=True).findings
    return {(finding.code, finding.message) for finding in found}


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


def test_probe_of_the_stack_with_its_own_eds_finds_only_entries_the_stack_stores_nothing_for(
    device_exe: Path,
) -> None:
    """The generated OD gives some entries no data (an empty DefaultValue; 100Ah, which the EDS makes a
    REAL64 and CiA 301 a VISIBLE_STRING): the stack says they do not exist. Everything else agrees."""
    result = probed(device_exe, load(EDS, node_id=NODE_ID))
    assert {f.code for f in result.findings} == {"PRB001"}, [f.format() for f in result.findings]
    od_c = (device_exe.parent / "od" / "OD.c").read_text(encoding="utf-8")
    read = {(reading.index, reading.subindex) for reading in result.readings}  # DOMAIN entries are not read
    assert {_entry(f) for f in result.findings} == without_storage(od_c) & read
    assert result.read > 150
    print(f"\nprobe read {result.read} entries of the CANopenNode device in {result.seconds:.2f} s")


def test_writing_back_every_writable_entry_is_refused_nowhere(baseline: set[tuple[str, str]]) -> None:
    """--check-writes on the stack: no write of a value just read is refused (the inhibit time and SYNC start
    value of a valid TPDO, which the stack refuses as CiA 301 says, are not written)."""
    assert {code for code, _ in baseline} == {"PRB001"}, sorted(baseline)


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
    device_exe: Path, baseline: set[tuple[str, str]], old: str, new: str, code: str
) -> None:
    text = EDS.read_text(encoding="utf-8")
    assert text.count(old) >= 1, old
    changed = loads(text.replace(old, new, 1), source=str(EDS), node_id=NODE_ID)
    found = [f for f in probed(device_exe, changed, check_writes=True).findings if (f.code, f.message) not in baseline]
    assert [f.code for f in found] == [code], [f.format() for f in found]
