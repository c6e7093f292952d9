"""The error-precision sweep (issue #41): every error `lint` reports on ../shared and on the CANopenNode projects
of this machine's snapshots, counted by code, and a reproducible sample of them to judge.

    python bench/bench_error_sweep.py                    # errors found, by code
    python bench/bench_error_sweep.py --draw 200         # + a stratified sample (seed 41) as TSV rows to judge
    python bench/bench_error_sweep.py --draw 200 --seed 7

The sample is stratified by code: every code that occurs at least once, and the others in proportion to how
often they occur. A row is file, code, line and the message (the judge replaces the message by a verdict and a
reason; tests/lint/error_precision.tsv keeps the judged rows).
"""

from __future__ import annotations

import argparse
import random
import sys
import tempfile
from collections import Counter, defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent / "tests"))

import errorsweep


def draw(found: list[errorsweep.Finding], size: int, seed: int) -> list[errorsweep.Finding]:
    """`size` findings in proportion to their codes' counts, at least one of each code, one per (file, code, line)."""
    units: dict[str, dict[tuple[str, int], errorsweep.Finding]] = defaultdict(dict)
    for finding in found:
        units[finding.code].setdefault((finding.key, finding.line), finding)
    total = sum(len(u) for u in units.values())
    chooser = random.Random(seed)
    sample = []
    for code in sorted(units):
        pool = sorted(units[code].values(), key=lambda f: (f.key, f.line))
        share = max(1, round(size * len(pool) / total))
        sample += chooser.sample(pool, min(share, len(pool)))
    return sorted(sample, key=lambda f: (f.key, f.line, f.code))


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--draw", type=int, default=0, help="sample size to draw (0: only count)")
    parser.add_argument("--seed", type=int, default=41)
    args = parser.parse_args()
    keys = errorsweep.shared_keys() + errorsweep.mirror_keys()
    with tempfile.TemporaryDirectory() as scratch:
        found = errorsweep.errors(keys, Path(scratch))
    by_code = Counter(f.code for f in found)
    print(f"# {len(keys)} files, {len(found)} errors in {len({f.key for f in found})} files, {len(by_code)} codes")
    print("# " + ", ".join(f"{code} {n}" for code, n in sorted(by_code.items(), key=lambda kv: (-kv[1], kv[0]))))
    for finding in draw(found, args.draw, args.seed) if args.draw else []:
        print(f"{finding.key}\t{finding.code}\t{finding.line}\t{finding.message}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
