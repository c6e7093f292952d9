"""Issue #23's figures in one run, on a machine other jobs may share: CPU-time ratios against python-canopen
measured alternating in one process, and each command line run as a user runs it.

    .venv/bin/python bench/bench_speed.py                  # everything (several minutes)
    .venv/bin/python bench/bench_speed.py --quick          # without 16 MB and the corpus lint
    .venv/bin/python bench/bench_speed.py --json

Rows (the load average is printed with each, as other jobs change what wall-clock time means):

- load, CPU time (`time.process_time`) of `cantools_od.load` against `canopen.import_od`, alternating in one
  process, medians over the rounds: every corpus file both read (one round is all of them); the largest of them
  (the 524 KB Sevcon Nano EDS); a synthetic file twice its size (bench/synthetic_eds.py).
- start-up and lint, each a process of the installed command (user + system CPU, and wall-clock): `--version`,
  `lint` of the repository's eds/cia402_drive.eds, of the largest corpus file and of the synthetic file twice
  its size.
- 1 MB and 16 MB synthetic `lint`: CPU, wall-clock, peak RSS and its ratio to the file size; CPU per MB after
  the start-up (`lint` of the small file), which is linear when the two agree within 20 %.
- the corpus in one `lint` call with `--jobs 1` and with `--jobs 2`, alternating (`--runs` pairs): wall-clock
  medians and the median ratio.
- the revision histories (../shared/eds-history) as two folders, old and new, in one `diff` call, the same way.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_load import DEFAULT_CORPUS, canopen_readable, corpus_files, load_all_ours, load_all_theirs, ours_readable
from bench_scale import command as cli
from bench_scale import refuse_stale
from synthetic_eds import synthetic_eds

REPO = Path(__file__).resolve().parents[1]
SMALL = REPO / "eds" / "cia402_drive.eds"
HISTORY = REPO.parent / "shared" / "eds-history"

Row = dict[str, object]


def _load_average() -> str:
    return "/".join(f"{x:.1f}" for x in os.getloadavg())


def _cpu(action: Callable[[], object]) -> float:
    start = time.process_time()
    action()
    return time.process_time() - start


def load_ratio(name: str, files: list[Path], rounds: int) -> Row:
    ours_run, theirs_run = load_all_ours(files), load_all_theirs(files)
    ours_run()  # warm-up, untimed
    theirs_run()
    ours: list[float] = []
    theirs: list[float] = []
    for _ in range(rounds):
        ours.append(_cpu(ours_run))
        theirs.append(_cpu(theirs_run))
    ratios = [a / b for a, b in zip(ours, theirs, strict=True)]
    return {
        "row": f"load {name}",
        "files": len(files),
        "ours_ms": round(statistics.median(ours) * 1000, 1),
        "canopen_ms": round(statistics.median(theirs) * 1000, 1),
        "ratio": round(statistics.median(ratios), 3),
        "load_average": _load_average(),
    }


# Runs one command and prints its figures. A process forked from this one would count the RSS it inherits (the
# corpus loaded here) as its own peak, so the commands are started from a small interpreter instead.
_RUNNER = """
import json, sys
sys.path.insert(0, sys.argv[1])
from bench_sizes import run_once
print(json.dumps(run_once(json.loads(sys.argv[2]))))
"""


def _run_lean(command: list[str]) -> tuple[float, int, int, float]:
    bench = str(Path(__file__).resolve().parent)
    shown = subprocess.run([sys.executable, "-c", _RUNNER, bench, json.dumps(command)], capture_output=True, check=True)
    wall, rss, status, cpu = json.loads(shown.stdout)
    return float(wall), int(rss), int(status), float(cpu)


def process(name: str, args: list[str], rounds: int, size: int = 0) -> Row:
    runs = [_run_lean([*cli(), *args]) for _ in range(rounds)]
    row: Row = {
        "row": name,
        "cpu_s": round(statistics.median(r[3] for r in runs), 3),
        "wall_s": round(statistics.median(r[0] for r in runs), 3),
        "peak_rss_mb": round(max(r[1] for r in runs) / 1e6, 1),
        "exit": runs[-1][2],
        "load_average": _load_average(),
    }
    if size:
        row["rss_per_file_size"] = round(max(r[1] for r in runs) / size, 2)
        row["size_mb"] = round(size / 1e6, 3)
    return row


def parallel(name: str, args: list[str], rounds: int) -> Row:
    """One command with `--jobs 1` and with `--jobs 2`, alternating for `rounds` pairs: wall-clock medians and
    the median of the pairs' ratios (single runs of either disagree by more than the target's margin)."""
    serial: list[float] = []
    both: list[float] = []
    for _ in range(rounds):
        serial.append(_run_lean([*cli(), args[0], "--jobs", "1", *args[1:]])[0])
        both.append(_run_lean([*cli(), args[0], "--jobs", "2", *args[1:]])[0])
    return {
        "row": f"{name} --jobs 2 against --jobs 1",
        "jobs1_wall_s": round(statistics.median(serial), 3),
        "jobs2_wall_s": round(statistics.median(both), 3),
        "ratio": round(statistics.median(b / a for a, b in zip(serial, both, strict=True)), 3),
        "load_average": _load_average(),
    }


def linearity(rows: list[Row]) -> Row:
    """Wall-clock per MB of the 1 MB and 16 MB `lint` after the start-up (the small file's `lint`), and their ratio:
    linear when it is within 1 +- 0.2."""
    small = float(str(next(r["wall_s"] for r in rows if str(r["row"]) == f"lint {SMALL.name}")))
    per_mb: list[float] = []
    for label in ("1 MB", "16 MB"):
        row = next(r for r in rows if r["row"] == f"lint synthetic {label}")
        size_mb = float(str(row["size_mb"]))
        per_mb.append((float(str(row["wall_s"])) - small) / size_mb)
    return {
        "row": "lint per MB after start-up, 1 MB and 16 MB",
        "s_per_mb_1": round(per_mb[0], 3),
        "s_per_mb_16": round(per_mb[1], 3),
        "ratio": round(per_mb[1] / per_mb[0], 3),
    }


def history_folders(root: Path) -> int:
    """root/old and root/new holding each history pair's sides by project and number; the number of pairs."""
    pairs = sorted(p for p in HISTORY.iterdir() if p.is_dir()) if HISTORY.is_dir() else []
    for pair in pairs:
        project, _, number = pair.name.rpartition("__")
        for side in pair.iterdir():
            target = root / side.stem / project / f"{number}{side.suffix}"
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_bytes(side.read_bytes())
    return len(pairs)


def show(row: Row) -> str:
    return "  ".join(f"{key}={value}" for key, value in row.items() if key != "row") + f"  [{row['row']}]"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("corpus", nargs="?", type=Path, default=DEFAULT_CORPUS)
    parser.add_argument("--rounds", type=int, default=7, help="alternating rounds per load row (default 7)")
    parser.add_argument("--runs", type=int, default=5, help="processes per command row below 10 MB (default 5)")
    parser.add_argument("--quick", action="store_true", help="leave out 16 MB and the corpus lint")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    refuse_stale()
    if not args.corpus.is_dir():
        print(f"{args.corpus}: no corpus folder", file=sys.stderr)
        return 2
    rows: list[Row] = []

    def add(row: Row) -> None:
        rows.append(row)
        if not args.json:
            print(show(row), flush=True)

    files, _ = ours_readable(corpus_files(args.corpus))
    both, _ = canopen_readable(files)
    largest = max(both, key=lambda p: p.stat().st_size)
    with tempfile.TemporaryDirectory(prefix="bench_speed_") as folder:
        double = Path(folder) / "double.eds"
        double.write_bytes(synthetic_eds(2 * largest.stat().st_size))
        add(load_ratio("corpus (files both read)", both, max(3, args.rounds // 2)))
        add(load_ratio(largest.name, [largest], args.rounds))
        add(load_ratio(f"synthetic {double.stat().st_size // 1000} KB (2x)", [double], args.rounds))
        add(process("--version", ["--version"], args.runs))
        add(process(f"lint {SMALL.name}", ["lint", str(SMALL)], args.runs))
        add(process(f"lint {largest.name}", ["lint", str(largest)], args.runs))
        add(process(f"lint synthetic {double.stat().st_size // 1000} KB (2x)", ["lint", str(double)], args.runs))
        if not args.quick:
            for size, runs in ((1_000_000, args.runs), (16_000_000, 1)):
                big = Path(folder) / f"synthetic_{size}.eds"
                big.write_bytes(synthetic_eds(size))
                add(process(f"lint synthetic {size // 1_000_000} MB", ["lint", str(big)], runs, big.stat().st_size))
                big.unlink()
            add(linearity(rows))
            names = [str(p) for p in corpus_files(args.corpus)]
            add(parallel(f"lint corpus ({len(names)} files)", ["lint", *names], args.runs))
            releases = Path(folder) / "history"
            pairs = history_folders(releases)
            if pairs:
                history = ["diff", str(releases / "old"), str(releases / "new")]
                add(parallel(f"diff history folders ({pairs} pairs)", history, args.runs))
    if args.json:
        print(json.dumps(rows, indent=2))
    return 0


if __name__ == "__main__":
    sys.exit(main())
