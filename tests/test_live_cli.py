"""The installed `simulate` and `probe` as a user runs them, each in its own process, on python-can's
`udp_multicast` bus over loopback (configured as python-can users do, by CAN_INTERFACE, CAN_CHANNEL and
CAN_CONFIG): probe against simulate, python-canopen as the master of simulate, and every way they end
(Ctrl-C, SIGTERM, a bus that cannot be opened, a node that does not answer, a broken script): one line and the
exit code, never a traceback."""

from __future__ import annotations

import itertools
import os
import selectors
import signal
import subprocess
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import can
import canopen
import pytest
from livekit import received_on_sync

from cantools_od.api import load

from support import EXAMPLES, cli_command

DRIVE = EXAMPLES / "cia402_drive.eds"
NODE = 5
GROUP = "239.0.0.1"
PORTS = itertools.count(43500 + 40 * (os.getpid() % 50))  # a port per bus: buses of other tests stay apart
pytestmark = pytest.mark.xdist_group("live-processes")


def _env(port: int) -> dict[str, str]:
    config = {"CAN_INTERFACE": "udp_multicast", "CAN_CHANNEL": GROUP, "CAN_CONFIG": f'{{"port": {port}}}'}
    return {**os.environ, **config}


@contextmanager
def simulate(port: int, *args: str, file: Path = DRIVE, cwd: Path | None = None) -> Iterator[subprocess.Popen[str]]:
    """`cantools-od simulate FILE --node-id 5` running, once it says what it serves; stopped with Ctrl-C."""
    process = subprocess.Popen(
        [*cli_command(), "simulate", str(file), "--node-id", str(NODE), *args],
        env=_env(port), cwd=cwd, stderr=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
    )  # fmt: skip
    try:
        line = _line(process, 30)
        assert "Ctrl-C stops" in line, line + (process.stderr.read() if process.stderr else "")
        yield process
    finally:
        if process.poll() is None:
            process.send_signal(signal.SIGINT)
        process.wait(10)


def _line(process: subprocess.Popen[str], timeout: float) -> str:
    assert process.stderr is not None
    with selectors.DefaultSelector() as selector:
        selector.register(process.stderr, selectors.EVENT_READ)
        if not selector.select(timeout):
            return "(nothing within the timeout)"
    return process.stderr.readline()


def probe(port: int, *args: str, file: Path = DRIVE, cwd: Path | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*cli_command(), "probe", str(file), "--node-id", str(NODE), *args],
        env=_env(port), cwd=cwd, capture_output=True, text=True, timeout=120,
    )  # fmt: skip


def _one_line_no_traceback(text: str) -> None:
    assert "Traceback" not in text and "Error:" not in text, text
    assert len(text.strip().splitlines()) == 1, text


def test_probe_against_simulate_finds_nothing_and_writes_the_values_read(tmp_path: Path) -> None:
    port = next(PORTS)
    before = DRIVE.read_bytes()
    with simulate(port):
        result = probe(port, "-o", "actual.dcf", "--check-writes", cwd=tmp_path)
        again = probe(port, "-o", "after.dcf", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stdout == "1 file checked: no findings\n"
    assert "probe: node 5: 59 entries read in" in result.stderr and "0 findings" in result.stderr
    actual = load(tmp_path / "actual.dcf")
    assert actual.node_id == NODE
    assert actual.objects[0x1018].subs[1].parameter_value == 0x0CA7
    assert (tmp_path / "after.dcf").read_bytes() == (tmp_path / "actual.dcf").read_bytes()  # writes left it as found
    assert again.returncode == 0 and DRIVE.read_bytes() == before


def test_probe_reports_as_lint_and_exits_1_on_errors(tmp_path: Path) -> None:
    port = next(PORTS)
    described = tmp_path / "described.eds"
    described.write_bytes(DRIVE.read_bytes().replace(b"VendorNumber=0x00000CA7", b"VendorNumber=0x00000CA8"))
    with simulate(port):
        text = probe(port, file=described)
        sarif = probe(port, "--format", "sarif", file=described)
    assert text.returncode == 1
    assert text.stdout.startswith(f"{described}:") and "[PRB004]" in text.stdout, text.stdout
    assert '"ruleId": "PRB004"' in sarif.stdout and sarif.returncode == 1


def test_python_canopen_master_against_simulate() -> None:
    """SDO, the heartbeat a consumer watches, and a TPDO on SYNC, as python-canopen's master meets them."""
    port = next(PORTS)
    with simulate(port):
        network = canopen.Network(can.Bus(interface="udp_multicast", channel=GROUP, port=port))
        network.connect()
        try:
            node = network.add_node(NODE, str(DRIVE))
            assert node.sdo[0x1018][1].raw == 0x0CA7
            node.sdo[0x1017].raw = 50
            assert node.nmt.wait_for_heartbeat(2) == "PRE-OPERATIONAL"
            node.tpdo.read(from_od=True)
            node.nmt.state = "OPERATIONAL"
            synchronous = next(p for p in node.tpdo.map.values() if p.enabled and p.trans_type == 1)
            time.sleep(0.2)
            assert received_on_sync(network, synchronous)
            assert node.nmt.wait_for_heartbeat(2) == "OPERATIONAL"
        finally:
            network.disconnect()


def test_ctrl_c_during_probe_is_one_line_and_130(tmp_path: Path) -> None:
    port = next(PORTS)
    script = tmp_path / "quiet.py"
    script.write_text("def setup(node):\n    node.silence(0x6041)\n", encoding="utf-8")
    with simulate(port, "--script", str(script)):
        process = subprocess.Popen(
            [*cli_command(), "probe", str(DRIVE), "--node-id", str(NODE), "--timeout", "60"],
            env=_env(port), stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
        )  # fmt: skip
        time.sleep(3)  # reading 6041h, which the node does not answer
        process.send_signal(signal.SIGINT)
        out, err = process.communicate(timeout=20)
        after = probe(port, "--timeout", "0.3")
    assert process.returncode == 130
    _one_line_no_traceback(err)
    assert err.startswith("probe: interrupted") and out == ""  # "after N of M entries" once it has started
    assert "[PRB008]" in after.stdout and after.stdout.count("[PRB") == 1  # the node still serves, as found


def test_simulate_ends_cleanly_on_ctrl_c_and_sigterm() -> None:
    for stop in (signal.SIGINT, signal.SIGTERM):
        port = next(PORTS)
        with simulate(port) as process:
            process.send_signal(stop)
            _, err = process.communicate(timeout=10)
            assert process.returncode == 0
            assert err == "simulate: stopped\n"


@pytest.mark.parametrize("command", ["probe", "simulate"])
@pytest.mark.parametrize(
    ("bus", "reason"),
    [
        (["-i", "no-such-interface"], "cannot open the CAN bus (interface=no-such-interface)"),
        (["-i", "socketcan", "-c", "nosuch0"], "cannot open the CAN bus (interface=socketcan channel=nosuch0)"),
        (["-i", "udp_multicast", "-c", "not-a-group"], "cannot open the CAN bus (interface=udp_multicast"),
    ],
)
def test_a_bus_that_cannot_be_opened_is_one_line_and_2(command: str, bus: list[str], reason: str) -> None:
    result = subprocess.run(
        [*cli_command(), command, str(DRIVE), "--node-id", str(NODE), *bus],
        capture_output=True, text=True, timeout=60, env={**os.environ, "CAN_INTERFACE": ""},
    )  # fmt: skip
    assert result.returncode == 2
    _one_line_no_traceback(result.stderr)
    assert result.stderr.startswith(f"{command}: error: {reason}"), result.stderr


def test_no_interface_configured_says_how_to_give_one() -> None:
    env = {key: value for key, value in os.environ.items() if not key.startswith("CAN_")}
    result = subprocess.run(
        [*cli_command(), "probe", str(DRIVE), "--node-id", str(NODE)],
        capture_output=True, text=True, timeout=60, env={**env, "HOME": "/nonexistent"},
    )  # fmt: skip
    assert result.returncode == 2
    _one_line_no_traceback(result.stderr)
    assert "give --interface" in result.stderr


def test_a_node_that_does_not_answer_is_one_line_and_2() -> None:
    port = next(PORTS)
    started = time.monotonic()
    result = probe(port, "--timeout", "0.2")
    assert result.returncode == 2 and result.stdout == ""
    _one_line_no_traceback(result.stderr)
    assert result.stderr == "probe: error: node 5 does not answer SDO (no response to a read of 1000h within 0.2 s)\n"
    assert time.monotonic() - started < 20


def test_a_script_without_setup_is_one_line_and_2(tmp_path: Path) -> None:
    script = tmp_path / "nothing.py"
    script.write_text("x = 1\n", encoding="utf-8")
    result = subprocess.run(
        [*cli_command(), "simulate", str(DRIVE), "--node-id", str(NODE), "--script", str(script)],
        capture_output=True, text=True, timeout=60, env=_env(next(PORTS)),
    )  # fmt: skip
    assert result.returncode == 2
    _one_line_no_traceback(result.stderr)
    assert "defines no setup(node) function" in result.stderr


def test_probe_never_writes_its_values_over_the_description_or_a_read_only_file(tmp_path: Path) -> None:
    """`-o` goes through the one write path: onto the EDS it reads, or onto a read-only file, it is refused in one
    line (exit 2) and both stay byte for byte (tests/journeys/test_writing_options.py cannot run a live node)."""
    port = next(PORTS)
    description = tmp_path / "drive.eds"
    description.write_bytes(DRIVE.read_bytes())
    kept = tmp_path / "kept.dcf"
    kept.write_bytes(b"[FileInfo]\n")
    kept.chmod(0o444)
    with simulate(port):
        onto_input = probe(port, "-o", str(description), file=description, cwd=tmp_path)
        onto_read_only = probe(port, "-o", str(kept), file=description, cwd=tmp_path)
    assert onto_input.returncode == 2 and "drive.eds" in onto_input.stderr.splitlines()[-1], onto_input.stderr
    assert onto_read_only.returncode == 2 and "kept.dcf" in onto_read_only.stderr.splitlines()[-1]
    assert "Traceback" not in onto_input.stderr + onto_read_only.stderr
    assert description.read_bytes() == DRIVE.read_bytes() and kept.read_bytes() == b"[FileInfo]\n"
