"""Scale: `cantools-od lint` and `cantools-od gen` of synthetic EDS files of growing size, as a user
runs them (one process each), with wall-clock time and peak resident memory of that process.

    python bench/bench_scale.py                   # 5, 25 and 50 MB; lint and gen -t c
    python bench/bench_scale.py 1M 5M -t c -t rust
    python bench/bench_scale.py --json
    python bench/bench_scale.py 25M 50M --max-ratio 10   # exit 1 when a run's peak RSS is above 10x

The files come from bench/synthetic_eds.py. Target (issue #9): peak RSS at most 10 times the file
size, and time growing linearly with it. See bench/README.md for figures. `-t canopennode` runs on a file
written with `synthetic_eds(size, canopennode=True)`, which passes that target's lint profile; its ratio is to
that file's size.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import time
from importlib.machinery import EXTENSION_SUFFIXES
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from synthetic_eds import parse_size, synthetic_eds

SOURCE = Path(__file__).resolve().parents[1] / "cantools_od"


def command() -> list[str]:
    script = Path(sys.executable).parent / "cantools-od"
    return [str(script)] if script.exists() else [sys.executable, "-m", "cantools_od"]


def user_env() -> dict[str, str]:
    """The environment a measured command runs in: this one without PYTHONPATH.

    When a script is started with `PYTHONPATH=.`, a command inheriting it would import the source tree
    instead of the installed package. Where bytecode is not written (PYTHONDONTWRITEBYTECODE, a read-only
    checkout) that tree is compiled again on every start, which added 0.1-0.3 s to each process here: a cost no
    user of the installed command pays."""
    return {key: value for key, value in os.environ.items() if key != "PYTHONPATH"}


def stale_install() -> str | None:
    """Why the installed package is not the source tree beside this folder (what the figures would belong to),
    or None when every module is the same."""
    shown = subprocess.run(
        [sys.executable, "-c", "import cantools_od; print(cantools_od.__file__)"],
        env=user_env(),
        capture_output=True,
        text=True,
        check=False,
        cwd=tempfile.gettempdir(),
    )
    if shown.returncode != 0:
        return "cantools_od is not installed in this interpreter"
    installed = Path(shown.stdout.strip()).parent
    if installed == SOURCE:
        return None  # an editable install runs the source itself
    differ = [
        str(module.relative_to(SOURCE))
        for module in sorted(SOURCE.rglob("*.py"))
        if not (installed / module.relative_to(SOURCE)).is_file()
        or (installed / module.relative_to(SOURCE)).read_bytes() != module.read_bytes()
    ]
    if not differ:
        return _uncompiled(installed)
    return f"the installed cantools_od differs from the source tree in {len(differ)} modules ({differ[0]}, ...)"


def _uncompiled(installed: Path) -> str | None:
    """What the installed package lacks of the extension modules the source tree has a C file for."""
    for source in sorted(SOURCE.rglob("_*.c")):
        folder = installed / source.parent.relative_to(SOURCE)
        if not any((folder / f"{source.stem}{suffix}").is_file() for suffix in EXTENSION_SUFFIXES):
            module = source.relative_to(SOURCE).with_suffix("").as_posix()
            return f"the installed cantools_od has no compiled {module} (built without a C compiler?)"
    return None


def refuse_stale() -> None:
    """Stops a benchmark, with one line, when its commands would measure other code than the source tree's."""
    reason = stale_install()
    if reason:
        sys.exit(f"{Path(sys.argv[0]).name}: {reason}; reinstall: {sys.executable} -m pip install --no-deps .")


def measure(args: list[str]) -> dict[str, float | int]:
    """Wall-clock seconds, peak RSS in bytes and exit status of one run of cantools-od."""
    start = time.perf_counter()
    process = subprocess.Popen(
        [*command(), *args], stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, env=user_env()
    )
    _, status, usage = os.wait4(process.pid, 0)
    seconds = time.perf_counter() - start
    process.returncode = os.waitstatus_to_exitcode(status)
    return {"seconds": round(seconds, 2), "peak_rss": usage.ru_maxrss * 1024, "exit": process.returncode}


def run(sizes: list[int], targets: list[str], folder: Path) -> list[dict[str, object]]:
    rows: list[dict[str, object]] = []
    for size in sizes:
        eds = folder / f"synthetic_{size}.eds"
        data = synthetic_eds(size)
        eds.write_bytes(data)
        row: dict[str, object] = {"bytes": len(data), "sections": data.count(b"\n[") + 1}
        del data
        row["lint"] = measure(["lint", str(eds)])
        for target in targets:
            if target != "canopennode":
                row[f"gen {target}"] = gen(eds, target, folder)
        eds.unlink()
        if "canopennode" in targets:  # on a file that passes the canopennode profile, else nothing is rendered
            data = synthetic_eds(size, canopennode=True)
            eds.write_bytes(data)
            row["gen canopennode"] = {**gen(eds, "canopennode", folder), "bytes": len(data)}
            del data
            eds.unlink()
        rows.append(row)
    return rows


def gen(eds: Path, target: str, folder: Path) -> dict[str, float | int]:
    return measure(["gen", str(eds), "-t", target, "-o", str(folder / "out"), "--name", "big"])


def report(rows: list[dict[str, object]]) -> str:
    runs = [key for key in rows[0] if key not in ("bytes", "sections")]
    head = f"{'file':>9} {'sections':>9}" + "".join(f" | {run:>24}" for run in runs)
    lines = [head, "-" * len(head)]
    for row in rows:
        size = int(row["bytes"])  # type: ignore[call-overload]
        cells = [cell(row[run], size) for run in runs]
        lines.append(f"{size / 1e6:>6.1f} MB {row['sections']:>9}" + "".join(f" | {c:>24}" for c in cells))
    return "\n".join(lines)


def cell(result: object, size: int) -> str:
    """One run as `time, peak RSS and its ratio to the file size`, with an unexpected exit status."""
    assert isinstance(result, dict)
    rss = result["peak_rss"]
    flag = "" if result["exit"] in (0, 1) else f" exit {result['exit']}"
    return f"{result['seconds']:>7.2f} s {rss / 1e6:>6.0f} MB {rss / result.get('bytes', size):>4.1f}x{flag}"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("sizes", nargs="*", type=parse_size, default=[parse_size(s) for s in ("5M", "25M", "50M")])
    parser.add_argument("-t", "--target", dest="targets", action="append", help="gen targets (default: c)")
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--max-ratio", type=float, help="exit 1 when a run's peak RSS exceeds this many times the file")
    args = parser.parse_args(argv)
    refuse_stale()
    with tempfile.TemporaryDirectory(prefix="bench_scale_") as folder:
        rows = run(args.sizes, args.targets or ["c"], Path(folder))
    print(json.dumps(rows, indent=2) if args.json else report(rows))
    over = [] if args.max_ratio is None else above(rows, args.max_ratio)
    for line in over:
        print(line, file=sys.stderr)
    return 1 if over else 0


def above(rows: list[dict[str, object]], ratio: float) -> list[str]:
    """One line per run whose peak RSS is more than `ratio` times its file's size."""
    lines = []
    for row in rows:
        size = int(row["bytes"])  # type: ignore[call-overload]
        for run, result in row.items():
            own = result.get("bytes", size) if isinstance(result, dict) else size
            if isinstance(result, dict) and result["peak_rss"] > ratio * own:
                lines.append(
                    f"{own / 1e6:.1f} MB {run}: peak RSS {result['peak_rss'] / own:.1f}x the file, above {ratio}x"
                )
    return lines


if __name__ == "__main__":
    sys.exit(main())
