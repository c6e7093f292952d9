"""A long fuzz run: every command on randomly damaged corpus files, in-process (see tests/fuzzkit.py).

    python bench/fuzz.py [--seed N] [--count N] [--source NAME ...]

Prints each failing case (seed, source, mutations, command, what went wrong) and the rate; a
failure found here becomes a fixed-seed example in tests/test_fuzz.py. Exit 1 when a case failed.
"""

from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

from fuzzkit import cases, run, sources


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--seed", type=int, default=1)
    parser.add_argument("--count", type=int, default=20_000)
    parser.add_argument("--source", action="append", default=[], help="only these sources (file names)")
    args = parser.parse_args()
    originals = sources()
    failed = 0
    per_command: dict[str, float] = {}
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as scratch:
        os.chdir(scratch)
        for number, (case, data) in enumerate(cases(args.seed, args.count, args.source)):
            folder = Path(scratch) / str(number)
            began = time.perf_counter()
            problems = run(case, data, originals[case.source], folder)
            per_command[case.command] = per_command.get(case.command, 0.0) + time.perf_counter() - began
            if problems:
                failed += 1
                print(f"case {number}: {case}: {'; '.join(problems)}", flush=True)
    elapsed = time.perf_counter() - start
    print("time per command:", ", ".join(f"{name} {seconds:.1f} s" for name, seconds in sorted(per_command.items())))
    print(f"{args.count} cases in {elapsed:.1f} s ({1000 * elapsed / max(args.count, 1):.1f} ms each): {failed} failed")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
