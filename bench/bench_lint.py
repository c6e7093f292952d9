"""Linter speed: one typical file as a user runs it (process start-up included), and the whole corpus.

    python bench/bench_lint.py [CORPUS_DIR] [--runs N] [--json]

Target (issue #3): one typical file lints in under 300 ms wall-clock, start-up included.
"""

from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_scale import command, refuse_stale, user_env

ROOT = Path(__file__).resolve().parent.parent
DEFAULT_CORPUS = ROOT.parent / "shared" / "eds-corpus" / "eds"


def wall_clock(args: list[str], runs: int) -> list[float]:
    times = []
    for _ in range(runs):
        start = time.perf_counter()
        subprocess.run([*command(), *args], capture_output=True, check=False, env=user_env())
        times.append(time.perf_counter() - start)
    return times


def typical_file(corpus: Path) -> Path:
    """The corpus file of median size: what a typical vendor EDS looks like."""
    files = sorted(
        (p for p in corpus.iterdir() if p.suffix.lower() in (".eds", ".dcf")), key=lambda p: p.stat().st_size
    )
    return files[len(files) // 2]


def corpus_in_process(corpus: Path) -> tuple[int, int, float]:
    from cantools_od import load
    from cantools_od.lint import lint

    files = sorted(p for p in corpus.iterdir() if p.suffix.lower() in (".eds", ".dcf"))
    start = time.perf_counter()
    findings = sum(len(lint(load(path))) for path in files)
    return len(files), findings, time.perf_counter() - start


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("corpus", nargs="?", type=Path, default=DEFAULT_CORPUS)
    parser.add_argument("--runs", type=int, default=10)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()
    refuse_stale()
    results: dict[str, object] = {}
    example = ROOT / "eds" / "cia402_drive.eds"
    results["version_ms"] = 1000 * statistics.median(wall_clock(["--version"], args.runs))
    results["example_file"] = example.name
    results["example_ms"] = 1000 * statistics.median(wall_clock(["lint", str(example)], args.runs))
    if args.corpus.is_dir():
        typical = typical_file(args.corpus)
        results["typical_file"] = typical.name
        results["typical_bytes"] = typical.stat().st_size
        results["typical_ms"] = 1000 * statistics.median(wall_clock(["lint", str(typical)], args.runs))
        files, findings, seconds = corpus_in_process(args.corpus)
        results.update(corpus_files=files, corpus_findings=findings, corpus_s=seconds)
        start = time.perf_counter()
        names = map(str, sorted(args.corpus.iterdir()))
        subprocess.run([*command(), "lint", *names], capture_output=True, check=False, env=user_env())
        results["corpus_one_command_s"] = time.perf_counter() - start
    else:
        print(f"corpus not found at {args.corpus}: only the example file is measured", file=sys.stderr)
    if args.json:
        print(json.dumps(results, indent=2))
        return 0
    rows = [("cantools-od --version", f"{results['version_ms']:.0f} ms", f"median of {args.runs} runs")]
    rows.append((f"lint {results['example_file']}", f"{results['example_ms']:.0f} ms", "shipped example"))
    if "typical_ms" in results:
        rows.append((f"lint {results['typical_file']}", f"{results['typical_ms']:.0f} ms", "corpus median size"))
        rows.append(("lint whole corpus, one command", f"{results['corpus_one_command_s']:.2f} s", ""))
        rows.append(
            ("lint whole corpus, in process", f"{results['corpus_s']:.2f} s", f"{results['corpus_findings']} findings")
        )
    for label, value, note in rows:
        print(f"{label:<44} {value:>9}  {note}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
