"""Time identifier assignment for a large device (5,000 objects whose names collide).

    python bench/bench_identifiers.py [--rounds N]

Prints the median wall-clock time of `cantools_od.identifiers.assign` over the rounds.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import installed  # noqa: F401  (first: the installed package is measured, see bench/installed.py)

from cantools_od.identifiers import assign
from cantools_od.model import Device, Object, ObjectKind, SubObject


def large_colliding_device() -> Device:
    """The device of tests/test_identifiers.py's large case: 1,000 VARs and 4,000 RECORDs of 8 entries."""
    objects = {}
    for k in range(5000):
        index = 0x2000 + k
        if k % 5 == 0:
            objects[index] = Object(index=index, name=f"Parameter value {k}")
            continue
        subs = {
            s: SubObject(name="Highest sub-index supported" if s == 0 else f"Setting {s % 4} of channel {k}")
            for s in range(8)
        }
        objects[index] = Object(
            index=index, name=f"Motor channel {k % 50} settings", object_type=ObjectKind.RECORD, subs=subs
        )
    return Device(objects=objects)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=5)
    args = parser.parse_args()
    device: Device = large_colliding_device()
    times = []
    for _ in range(args.rounds):
        start = time.perf_counter()
        assign(device)
        times.append(time.perf_counter() - start)
    print(
        f"identifiers.assign, 5,000 objects / 33,000 entries: "
        f"{1000 * statistics.median(times):.0f} ms (median of {args.rounds})"
    )


if __name__ == "__main__":
    main()
