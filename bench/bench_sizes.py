"""Per-size figures: `load`, `lint`, `fmt --check`, `gen -t c` and `diff` of a 30 KB, 300 KB, 1 MB and
16 MB file, each as a user runs it (one process, start-up included), with wall-clock time and peak RSS;
then the whole corpus in one `lint` call, on one core and on all of them.

    python bench/bench_sizes.py                     # 30K 300K 1M 16M, corpus at ../shared/eds-corpus/eds
    python bench/bench_sizes.py 30K 1M --rounds 5   # other sizes, median of 5 runs per cell
    python bench/bench_sizes.py --json

30 KB and 300 KB are the real corpus files nearest those sizes; where no corpus file is within 20 % of a
size (the largest real one is 524 KB), the file is synthetic (bench/synthetic_eds.py). `diff` compares the
file with a copy whose first ParameterName is changed. `load` is `cantools_od.load` in a fresh interpreter.
The corpus `lint` runs with `--jobs 1` and `--jobs N` (N = cores) when lint has `--jobs`, else once, serial.
Times (wall-clock, and CPU: user + system) are medians over the rounds (one round at 16 MB); peak RSS is
the largest over them.
"""

from __future__ import annotations

import argparse
import json
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_scale import cell, refuse_stale, user_env
from bench_scale import command as cli
from synthetic_eds import parse_size, synthetic_eds

DEFAULT_CORPUS = Path(__file__).resolve().parents[2] / "shared" / "eds-corpus" / "eds"
SIZES = ("30K", "300K", "1M", "16M")
LOAD = "import sys, cantools_od; cantools_od.load(sys.argv[1])"

Row = dict[str, object]


def run_once(command: list[str]) -> tuple[float, int, int, float]:
    """Wall-clock seconds, peak RSS in bytes, exit status and CPU seconds (user + system) of one process."""
    start = time.perf_counter()
    process = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=user_env())
    _, status, usage = os.wait4(process.pid, 0)
    cpu = usage.ru_utime + usage.ru_stime
    return time.perf_counter() - start, usage.ru_maxrss * 1024, os.waitstatus_to_exitcode(status), cpu


def measure(command: list[str], rounds: int) -> dict[str, float | int]:
    """Medians over the rounds; CPU time is what a busy machine (other jobs on the cores) distorts least."""
    runs = [run_once(command) for _ in range(rounds)]
    return {
        "seconds": round(statistics.median(r[0] for r in runs), 3),
        "cpu_seconds": round(statistics.median(r[3] for r in runs), 3),
        "peak_rss": max(r[1] for r in runs),
        "exit": runs[-1][2],
    }


def corpus_files(corpus: Path) -> list[Path]:
    if not corpus.is_dir():
        return []
    return sorted(p for p in corpus.iterdir() if p.is_file() and p.suffix.lower() in (".eds", ".dcf"))


def input_file(size: int, corpus: list[Path], folder: Path) -> tuple[Path, str]:
    """The corpus file nearest `size` when within 20 %, else a synthetic one; and where it came from."""
    nearest = min(corpus, key=lambda p: abs(p.stat().st_size - size), default=None)
    if nearest is not None and abs(nearest.stat().st_size - size) <= size * 0.2:
        return nearest, nearest.name
    path = folder / f"synthetic_{size}.eds"
    path.write_bytes(synthetic_eds(size))
    return path, "synthetic"


def changed_copy(path: Path, folder: Path) -> Path:
    """`path` with its first ParameterName changed: what `diff` compares it with."""
    data = path.read_bytes()
    at = data.lower().find(b"parametername=")
    end = data.find(b"\n", at)
    copy = folder / f"changed_{path.name}"
    copy.write_bytes(data[: at + 14] + b"Renamed by bench" + (data[end:] if end >= 0 else b"") if at >= 0 else data)
    return copy


def size_row(size: int, corpus: list[Path], folder: Path, rounds: int) -> Row:
    path, origin = input_file(size, corpus, folder)
    other = changed_copy(path, folder)
    out = folder / "gen"
    shutil.rmtree(out, ignore_errors=True)
    commands = {
        "load": [sys.executable, "-c", LOAD, str(path)],
        "lint": [*cli(), "lint", str(path)],
        "fmt --check": [*cli(), "fmt", "--check", str(path)],
        "gen -t c": [*cli(), "gen", str(path), "-t", "c", "-o", str(out), "--name", "bench"],
        "diff": [*cli(), "diff", str(path), str(other)],
    }
    row: Row = {"bytes": path.stat().st_size, "file": origin}
    for name, command in commands.items():
        row[name] = measure(command, rounds)
    other.unlink()
    if origin == "synthetic":
        path.unlink()
    return row


def has_jobs() -> bool:
    shown = subprocess.run([*cli(), "lint", "--help"], capture_output=True, text=True, check=False, env=user_env())
    return "--jobs" in shown.stdout


def corpus_row(corpus: list[Path], rounds: int) -> Row:
    names = [str(p) for p in corpus]
    row: Row = {"files": len(corpus), "bytes": sum(p.stat().st_size for p in corpus)}
    if has_jobs():
        cores = os.cpu_count() or 1
        row["lint --jobs 1"] = measure([*cli(), "lint", "--jobs", "1", *names], rounds)
        row[f"lint --jobs {cores}"] = measure([*cli(), "lint", "--jobs", str(cores), *names], rounds)
    else:
        row["lint (serial, no --jobs)"] = measure([*cli(), "lint", *names], rounds)
    return row


def report(rows: list[Row], corpus: Row | None) -> str:
    runs = [key for key in rows[0] if key not in ("bytes", "file")] if rows else []
    head = f"| file | {' | '.join(runs)} |"
    lines = [head, "|" + "---:|" * (len(runs) + 1)]
    for row in rows:
        size = int(row["bytes"])  # type: ignore[call-overload]
        cells = [f"{cell(row[run], size).strip()}, cpu {row[run]['cpu_seconds']:.2f} s" for run in runs]  # type: ignore[index]
        lines.append(f"| {size / 1e3:,.0f} KB {row['file']} | {' | '.join(cells)} |")
    if corpus is not None:
        lines += ["", f"corpus, one lint call: {corpus['files']} files, {int(corpus['bytes']) / 1e6:.1f} MB"]  # type: ignore[call-overload]
        for run, result in corpus.items():
            if isinstance(result, dict):
                lines.append(
                    f"  {run}: {result['seconds']:.2f} s (cpu {result['cpu_seconds']:.2f} s), "
                    f"peak {result['peak_rss'] / 1e6:.0f} MB"
                )
    return "\n".join(lines)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sizes", nargs="*", type=parse_size, default=[parse_size(s) for s in SIZES])
    parser.add_argument("--corpus", type=Path, default=DEFAULT_CORPUS, help="folder of .eds/.dcf files")
    parser.add_argument("--rounds", type=int, default=3, help="runs per cell below 10 MB (default 3)")
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args(argv)
    refuse_stale()
    corpus = corpus_files(args.corpus)
    with tempfile.TemporaryDirectory(prefix="bench_sizes_") as folder:
        rows = [size_row(size, corpus, Path(folder), 1 if size >= 10_000_000 else args.rounds) for size in args.sizes]
    whole = corpus_row(corpus, args.rounds) if corpus else None
    print(json.dumps({"sizes": rows, "corpus": whole}, indent=2) if args.json else report(rows, whole))
    return 0


if __name__ == "__main__":
    sys.exit(main())
