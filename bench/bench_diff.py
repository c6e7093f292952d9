"""Time and peak memory of `diff` on the largest real revision pair, against one `load` of each file.

    python bench/bench_diff.py [--rounds N] [--json] [HISTORY]

HISTORY is a folder of old/new pairs (default ../shared/eds-history); the pair whose two files are largest
together is measured. `diff` here is what the command does: read both files, compare, and render the text,
Markdown and JSON reports. The goal: no worse than twice one load of each file, in time and in peak memory.
Medians over the rounds (time.perf_counter); peak memory by tracemalloc in a separate pass.
"""

from __future__ import annotations

import argparse
import json
import statistics
import sys
import time
import tracemalloc
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import installed  # noqa: F401  (first: the installed package is measured, see bench/installed.py)

from cantools_od import load
from cantools_od.changes import compare, jsonout, markdown, text

DEFAULT = Path(__file__).resolve().parent.parent.parent / "shared" / "eds-history"


def largest_pair(history: Path) -> tuple[Path, Path]:
    pairs = []
    for folder in sorted(p for p in history.iterdir() if p.is_dir()):
        sides = {f.stem: f for f in folder.iterdir()}
        if "old" in sides and "new" in sides:
            pairs.append((sides["old"].stat().st_size + sides["new"].stat().st_size, sides["old"], sides["new"]))
    _, old, new = max(pairs)
    return old, new


def run_diff(old: Path, new: Path) -> None:
    result = compare(load(old), load(new))
    text.render(result)
    markdown.render(result)
    jsonout.render(result)


def timed(action: Callable[[], object], rounds: int) -> float:
    times = []
    for _ in range(rounds):
        start = time.perf_counter()
        action()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def peak(action: Callable[[], object]) -> int:
    tracemalloc.start()
    action()
    _, top = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    return top


def main() -> int:
    parser = argparse.ArgumentParser()
    parser.add_argument("history", nargs="?", type=Path, default=DEFAULT)
    parser.add_argument("--rounds", type=int, default=5)
    parser.add_argument("--json", action="store_true")
    options = parser.parse_args()
    if not options.history.is_dir():
        print(f"{options.history}: no such folder", file=sys.stderr)
        return 2
    old, new = largest_pair(options.history)
    run_diff(old, new)  # warm up: imports, pydantic schemas
    result: dict[str, float] = {
        "bytes": old.stat().st_size + new.stat().st_size,
        "load_old_s": timed(lambda: load(old), options.rounds),
        "load_new_s": timed(lambda: load(new), options.rounds),
        "diff_s": timed(lambda: run_diff(old, new), options.rounds),
        "load_old_peak": peak(lambda: load(old)),
        "load_new_peak": peak(lambda: load(new)),
        "diff_peak": peak(lambda: run_diff(old, new)),
    }
    loads_s = result["load_old_s"] + result["load_new_s"]
    loads_peak = result["load_old_peak"] + result["load_new_peak"]
    result["time_ratio"] = result["diff_s"] / loads_s
    result["memory_ratio"] = result["diff_peak"] / loads_peak
    if options.json:
        print(json.dumps({"pair": old.parent.name, **result}, indent=2))
    else:
        print(f"pair {old.parent.name} ({result['bytes'] / 1000:.0f} KB)")
        print(f"load old + new: {loads_s:.2f} s, peak {loads_peak / 1e6:.0f} MB")
        print(f"diff:           {result['diff_s']:.2f} s, peak {result['diff_peak'] / 1e6:.0f} MB")
        print(f"ratio: time {result['time_ratio']:.2f}, memory {result['memory_ratio']:.2f} (goal: both <= 2)")
    return 0 if result["time_ratio"] <= 2 and result["memory_ratio"] <= 2 else 1


if __name__ == "__main__":
    sys.exit(main())
