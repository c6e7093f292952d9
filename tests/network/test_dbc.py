"""DBC output as trace tools meet it: cantools' decoding of our DBC equals python-canopen's PDO decoding."""

from __future__ import annotations

import random
import subprocess
from pathlib import Path

import canopen
import cantools

from support import EXAMPLES, cli_command

FRAMES = 10_000


def gen_dbc(eds: Path, out: Path, *extra: str) -> subprocess.CompletedProcess[str]:
    args = [*cli_command(), "gen", str(eds), "-t", "dbc", "-o", str(out), *extra]
    return subprocess.run(args, capture_output=True, text=True, timeout=120)


def test_cia402_dbc_decodes_as_python_canopen(tmp_path: Path) -> None:
    eds = EXAMPLES / "cia402_drive.eds"
    result = gen_dbc(eds, tmp_path, "--node-id", "5")
    assert result.returncode == 0, result.stderr
    database = cantools.database.load_file(str(tmp_path / "cia402_drive.dbc"))
    network = canopen.Network()
    node = canopen.RemoteNode(5, str(eds))
    network.add_node(node)
    node.tpdo.read(from_od=True)
    node.rpdo.read(from_od=True)
    maps = [m for m in [*node.tpdo.map.values(), *node.rpdo.map.values()] if m.enabled and m.map]
    assert {m.cob_id for m in maps} == {message.frame_id for message in database.messages}
    rng = random.Random(24)
    for number in range(FRAMES):
        pdo = maps[number % len(maps)]
        message = database.get_message_by_frame_id(pdo.cob_id)
        assert message.length == (sum(v.length for v in pdo.map) + 7) // 8
        payload = bytes(rng.getrandbits(8) for _ in range(message.length))
        pdo.on_message(pdo.cob_id, payload, 0)
        theirs = [variable.raw for variable in pdo.map]
        decoded = message.decode(payload, decode_choices=False)
        ours = [decoded[signal.name] for signal in sorted(message.signals, key=lambda s: s.start)]
        assert ours == theirs, (hex(pdo.cob_id), payload.hex())


def test_dbc_needs_a_node_id(tmp_path: Path) -> None:
    result = gen_dbc(EXAMPLES / "cia402_drive.eds", tmp_path)
    assert result.returncode == 2 and "--node-id" in result.stderr and result.stderr.count("\n") == 1
    assert not list(tmp_path.iterdir())
