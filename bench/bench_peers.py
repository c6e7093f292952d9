"""Peer-reader matrix: how python-canopen and lely's dcfchk read what `fmt`, `convert` (EDS -> DCF) and
`lint --fix` write, against how they read the original (the corpus, then probes of REAL values written as
bit patterns and as decimals); and how many lines `fmt` changes per radix style.

Run with `python bench/bench_peers.py [CORPUS_DIR] [--json]`. See bench/README.md.
"""

from __future__ import annotations

import argparse
import dataclasses
import difflib
import json
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import installed  # noqa: F401  (first: the installed package is measured, see bench/installed.py)

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from peermatrix import judge_all, real_probes, table, tally

from cantools_od.api import dumps, format_for, load
from cantools_od.eds.format import IntStyle, Radix

DEFAULT_CORPUS = Path(__file__).resolve().parents[2] / "shared" / "eds-corpus" / "eds"


def fmt_changes(files: list[Path]) -> dict[str, dict[str, int]]:
    """Per radix style: files `fmt` would change, and the diff lines it would write."""
    out: dict[str, dict[str, int]] = {}
    for radix in Radix:
        changed = lines = 0
        for path in files:
            original = path.read_bytes()
            formatted = dumps(load(path), format_for(path), style="canonical", int_style=IntStyle(radix))
            if formatted == original:
                continue
            changed += 1
            diff = difflib.unified_diff(
                original.decode("utf-8", "replace").splitlines(), formatted.decode("utf-8").splitlines(), lineterm=""
            )
            lines += sum(1 for line in diff if line[:1] in "+-" and line[:3] not in ("+++", "---"))
        out[radix.value] = {"files changed": changed, "diff lines": lines}
    return out


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("corpus", nargs="?", type=Path, default=DEFAULT_CORPUS)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    if not args.corpus.is_dir():
        print(f"no corpus at {args.corpus}", file=sys.stderr)
        return 2
    files = sorted(p for p in args.corpus.iterdir() if p.suffix.lower() in (".eds", ".dcf"))
    start = time.perf_counter()
    with tempfile.TemporaryDirectory() as folder:
        results = judge_all(files, Path(folder) / "corpus", full=True)
        probes = real_probes(Path(folder) / "real")
        real_rows = tally(judge_all(probes, Path(folder) / "judged", full=True))
    matrix_seconds = time.perf_counter() - start
    rows = tally(results)
    changes = fmt_changes(files)
    if args.json:
        matrix = [dataclasses.asdict(r) for r in rows]
        real = [dataclasses.asdict(r) for r in real_rows]
        print(json.dumps({"matrix": matrix, "real": real, "fmt": changes}, indent=2))
        return 0
    print(f"peer-reader matrix over {len(files)} files ({matrix_seconds:.1f} s)\n")
    print(table(rows))
    print(f"\nREAL32/REAL64 values as bit patterns and decimals ({len(probes)} probe files)\n")
    print(table(real_rows))
    print("\nfmt per integer-radix style")
    for radix, counts in changes.items():
        print(f"  {radix:<11} {counts['files changed']:>3} files changed, {counts['diff lines']:>6} diff lines")
    return 0


if __name__ == "__main__":
    sys.exit(main())
