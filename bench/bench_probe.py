"""`probe` against `simulate` of the largest corpus file python-canopen can serve, each command in its own
process on python-can's udp_multicast bus over loopback, as a user runs them: the time probe reports, the wall
time of the probe process (start-up included) and its SDO count.

    python bench/bench_probe.py [--rounds N] [--port PORT]
"""

from __future__ import annotations

import argparse
import os
import re
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT.parent / "shared" / "eds-corpus" / "eds"
SUMMARY = re.compile(r"probe: node \d+: (\d+) entries read in ([\d.]+) s \((\d+) SDO transfers")
NODE = "5"


def _largest_served() -> Path:
    """The largest corpus file the simulation can serve (python-canopen builds a node of it)."""
    import can
    import canopen

    from cantools_od.api import load
    from cantools_od.live.simulator import CannotServe, Simulator

    for path in sorted(CORPUS.iterdir(), key=lambda p: p.stat().st_size, reverse=True):
        try:
            Simulator(load(path, node_id=5), 5, canopen.Network(can.Bus(interface="virtual", channel="bench")))
        except (CannotServe, Exception):
            continue
        return path
    raise SystemExit("no corpus file can be served")


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--port", type=int, default=43900)
    args = parser.parse_args()
    if not CORPUS.is_dir():
        print(f"{CORPUS} is absent", file=sys.stderr)
        return 2
    path = _largest_served()
    env = {**os.environ, "CAN_INTERFACE": "udp_multicast", "CAN_CHANNEL": "239.0.0.1",
           "CAN_CONFIG": f'{{"port": {args.port}}}'}  # fmt: skip
    tool = str(Path(sys.executable).parent / "cantools-od")
    simulate = subprocess.Popen([tool, "simulate", str(path), "--node-id", NODE], env=env, stderr=subprocess.PIPE)
    try:
        assert simulate.stderr is not None
        simulate.stderr.readline()  # serving
        reported, walls = [], []
        for _ in range(args.rounds):
            started = time.perf_counter()
            done = subprocess.run(
                [tool, "probe", str(path), "--node-id", NODE], env=env, capture_output=True, text=True
            )
            walls.append(time.perf_counter() - started)
            found = SUMMARY.search(done.stderr)
            assert found is not None and done.returncode == 0, done.stderr
            entries, seconds, transfers = int(found[1]), float(found[2]), int(found[3])
            reported.append(seconds)
        print(f"{path.name} ({path.stat().st_size // 1024} KB): {entries} entries read, {transfers} SDO transfers")
        print(f"probe's own time: median {statistics.median(reported):.2f} s; process wall time: median "
              f"{statistics.median(walls):.2f} s ({args.rounds} rounds)")  # fmt: skip
    finally:
        simulate.terminate()
        simulate.wait(10)
    return 0


if __name__ == "__main__":
    sys.exit(main())
