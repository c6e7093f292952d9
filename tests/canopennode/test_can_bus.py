"""End to end over a CAN bus: python-canopen against a CANopenNode device built with our OD.

The device is the real stack (CANopen.c, 301-305, storage) with the OD generated from
demoDevice.eds and a CAN driver of our own (hostcan/) whose bus is one TCP connection to
127.0.0.1. The test bridges that connection to python-can's `virtual` bus, where python-canopen,
loaded with the same EDS, is the SDO client and NMT master. Loopback only; every wait is bounded
and the device process is always killed at the end.
"""

from __future__ import annotations

import contextlib
import socket
import struct
import subprocess
import threading
import uuid
from pathlib import Path

import pytest
from cnokit import DEMO, HERE, STACK, gen, run, stack
from demo_app import Application

NODE_ID = 10
FRAME = struct.Struct("<IB3x8s")  # identifier (bit 30: RTR), DLC, data: the hostcan driver's frame
RTR = 0x40000000
# Entries whose value is not the EDS default by design: the stack owns them at run time.
RUNTIME_OWNED = {0x1001, 0x1003}


def build_device(od_dir: Path, work: Path, application: Application | None = None) -> Path:
    """The stack with the OD in `od_dir` and the TCP driver; with `application`, its sources and hooks too."""
    sources = [STACK / "CANopen.c", STACK / "storage" / "CO_storage.c", HERE / "hostcan" / "CO_driver_tcp.c"]
    sources += [p for folder in ("301", "303", "304", "305") for p in sorted((STACK / folder).glob("*.c"))]
    flags = ["-DDEVICE_TCP", f"-I{HERE / 'hostcan'}", f"-I{od_dir}", f"-I{STACK}"]
    objects: list[Path] = []
    if application is not None:
        flags += [application.define, *(f"-I{folder}" for folder in application.includes)]
        for source in application.sources:
            # -I-: a file's own folder is not searched first, so a demo source in ../shared includes the OD.h
            # generated here, not CANopenEditor's next to it; then CO_driver.h needs its folder for CO_config.h
            objects.append(work / f"app_{source.stem}.o")
            run(["gcc", "-O1", "-I-", *flags, f"-I{STACK / '301'}", "-c", "-o", str(objects[-1]), str(source)])
    exe = work / "device"
    run(["gcc", "-O1", *flags, "-o", str(exe), str(HERE / "device_main.c"), str(od_dir / "OD.c"),
         *map(str, sources + objects)])  # fmt: skip
    return exe


class Bridge:
    """Copies frames between the device's TCP link and a python-can virtual bus channel."""

    def __init__(self, link: socket.socket, channel: str) -> None:
        import can

        self.link = link
        self.bus = can.Bus(interface="virtual", channel=channel)
        self.stop = threading.Event()
        self.threads = [
            threading.Thread(target=self.to_bus, daemon=True),
            threading.Thread(target=self.to_device, daemon=True),
        ]
        for thread in self.threads:
            thread.start()

    def to_bus(self) -> None:
        import can

        self.link.settimeout(0.1)
        buffer = b""
        while not self.stop.is_set():
            try:
                chunk = self.link.recv(4096)
            except TimeoutError:
                continue
            except OSError:
                return
            if not chunk:
                return
            buffer += chunk
            while len(buffer) >= FRAME.size:
                ident, dlc, data = FRAME.unpack(buffer[: FRAME.size])
                buffer = buffer[FRAME.size :]
                remote = bool(ident & RTR)
                message = can.Message(
                    arbitration_id=ident & 0x7FF, is_extended_id=False, is_remote_frame=remote, dlc=dlc,
                    data=b"" if remote else data[:dlc],
                )  # fmt: skip
                self.bus.send(message)

    def to_device(self) -> None:
        while not self.stop.is_set():
            message = self.bus.recv(0.05)
            if message is None:
                continue
            ident = message.arbitration_id | (RTR if message.is_remote_frame else 0)
            try:
                self.link.sendall(FRAME.pack(ident, message.dlc, bytes(message.data).ljust(8, b"\0")))
            except OSError:
                return

    def close(self) -> None:
        self.stop.set()
        for thread in self.threads:
            thread.join(timeout=2)
        self.bus.shutdown()


def readable_defaults(node: object) -> list[tuple[int, int, object]]:
    """(index, sub-index, variable) of every readable entry with a default the stack stores."""
    import canopen

    found = []
    for obj in node.object_dictionary.values():  # type: ignore[attr-defined]
        variables = [obj] if isinstance(obj, canopen.objectdictionary.ODVariable) else list(obj.values())
        for var in variables:
            if obj.index in RUNTIME_OWNED or "r" not in var.access_type or var.default in (None, b"", ""):
                continue
            if var.data_type == canopen.objectdictionary.DOMAIN:
                continue
            found.append((obj.index, var.subindex, var))
    return found


def test_python_canopen_reads_writes_and_receives_a_tpdo(tmp_path: Path) -> None:
    stack()
    can = pytest.importorskip("can")
    canopen = pytest.importorskip("canopen")
    eds = DEMO / "demoDevice.eds"
    assert gen(eds, tmp_path / "od").returncode == 0
    exe = build_device(tmp_path / "od", tmp_path)
    server = socket.create_server(("127.0.0.1", 0))
    server.settimeout(20)
    device = subprocess.Popen([str(exe), "60000", str(server.getsockname()[1])], stdout=subprocess.PIPE, text=True)
    network = canopen.Network()
    bridge = None
    try:
        link, _ = server.accept()
        channel = f"cantools-od-{uuid.uuid4()}"
        bridge = Bridge(link, channel)
        network.connect(interface="virtual", channel=channel)
        node = canopen.RemoteNode(NODE_ID, str(eds))
        network.add_node(node)
        node.sdo.RESPONSE_TIMEOUT = 5.0  # a busy machine must not turn a slow answer into a failure

        checked = 0
        for index, subindex, var in readable_defaults(node):
            raw = node.sdo.upload(index, subindex)
            # python-canopen encodes VISIBLE_STRING as ASCII; the EDS (and the stack) hold UTF-8
            expected = var.default.encode() if isinstance(var.default, str) else var.encode_raw(var.default)
            assert raw == expected, f"{index:04X}sub{subindex}: {raw.hex()} != {expected.hex()}"
            checked += 1
        print(f"\nuploaded and compared {checked} entries")
        assert checked > 150

        writes = [(0x1017, 0, struct.pack("<H", 250)), (0x2110, 3, struct.pack("<i", -123456)),
                  (0x2120, 6, struct.pack("<H", 0xBEEF)), (0x2121, 1, b"abc")]  # fmt: skip
        for index, subindex, data in writes:
            node.sdo.download(index, subindex, data)
            assert node.sdo.upload(index, subindex) == data, f"{index:04X}sub{subindex}"

        received = threading.Event()
        frames: list[bytes] = []

        def on_tpdo(can_id: int, data: bytearray, timestamp: float) -> None:
            frames.append(bytes(data))
            received.set()

        network.subscribe(0x180 + NODE_ID, on_tpdo)
        node.sdo.download(0x1800, 5, struct.pack("<H", 50))  # event timer 50 ms
        assert not received.wait(0.3), "a TPDO before NMT start"
        node.nmt.state = "OPERATIONAL"
        assert received.wait(5.0), "no TPDO after NMT start"
        mapped = [node.sdo.upload(0x1A00, n) for n in range(1, node.sdo.upload(0x1A00, 0)[0] + 1)]
        length = sum(int.from_bytes(m, "little") & 0xFF for m in mapped) // 8
        assert len(frames[0]) == length
        print(f"TPDO1 {frames[0].hex()} after NMT start")
    finally:
        network.disconnect()
        if bridge is not None:
            bridge.close()
        server.close()
        with contextlib.suppress(subprocess.TimeoutExpired):
            device.wait(timeout=5)  # closing the link ends it
        device.kill()
        device.wait(timeout=5)
    del can
