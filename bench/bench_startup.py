"""Start-up of each command as a user runs it: CPU time (user + system) of whole processes of the installed
`cantools-od`, and optionally of a second one (another checkout's venv, for before/after), alternating process
by process so that other jobs on the machine hit both alike.

    .venv/bin/python bench/bench_startup.py                               # this venv's cantools-od, 9 runs each
    .venv/bin/python bench/bench_startup.py --against ../main/.venv/bin/cantools-od --runs 15
    .venv/bin/python bench/bench_startup.py --gc                          # also the garbage collector's share

The commands: `--version`, and `lint`, `dump`, `fmt --check`, `gen -t c`, `gen -t rust` of the repository's
eds/cia402_drive.eds (10 KB, nearly all start-up), each in a temporary folder (no configuration file found).
`--gc` runs each command once more in process with a `gc.callbacks` hook and prints the time the cyclic
collector took and its number of passes.
"""

from __future__ import annotations

import argparse
import os
import shutil
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from bench_scale import command as installed
from bench_scale import refuse_stale, user_env
from bench_sizes import run_once

SMALL = Path(__file__).resolve().parents[1] / "eds" / "cia402_drive.eds"
COMMANDS = {
    "--version": ["--version"],
    "lint": ["lint", "small.eds"],
    "dump": ["dump", "small.eds"],
    "fmt --check": ["fmt", "--check", "small.eds"],
    "gen -t c": ["gen", "-t", "c", "small.eds", "-o", "out"],
    "gen -t rust": ["gen", "-t", "rust", "small.eds", "-o", "out-rust"],
}

_GC_HOOK = """
import gc, sys, time
spent, passes, start = [0.0], [0], [0.0]
def hook(phase, info):
    if phase == "start":
        start[0] = time.process_time()
    else:
        spent[0] += time.process_time() - start[0]
        passes[0] += 1
gc.callbacks.append(hook)
sys.argv = ["cantools-od", *sys.argv[1:]]
from cantools_od.cli import main
try:
    main()
except SystemExit:
    pass
sys.stderr.write(f"GC {spent[0] * 1000:.1f} {passes[0]}\\n")
"""


def _gc_share(python: str, args: list[str], folder: Path) -> str:
    done = subprocess.run([python, "-c", _GC_HOOK, *args], cwd=folder, capture_output=True, text=True, env=user_env())
    line = next((x for x in done.stderr.splitlines() if x.startswith("GC ")), "GC ? ?").split()
    return f"gc {line[1]} ms in {line[2]} passes"


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--runs", type=int, default=9, help="processes per command and executable (default 9)")
    parser.add_argument("--against", help="a second cantools-od executable, run alternately with this one")
    parser.add_argument("--gc", action="store_true", help="also the collector's time, in process")
    args = parser.parse_args(argv)
    refuse_stale()
    tools = {"this": installed()} | ({"against": [args.against]} if args.against else {})
    print(f"load average before: {'/'.join(f'{x:.1f}' for x in os.getloadavg())}")
    with tempfile.TemporaryDirectory(prefix="bench_startup_") as name:
        folder = Path(name)
        shutil.copy(SMALL, folder / "small.eds")
        (folder / "out").mkdir()
        os.chdir(folder)
        for label, command in COMMANDS.items():
            cpu: dict[str, list[float]] = {tool: [] for tool in tools}
            for _ in range(args.runs):
                for tool, exe in tools.items():
                    cpu[tool].append(run_once([*exe, *command])[3])
            shown = "  ".join(
                f"{tool} {statistics.median(v) * 1000:4.0f} ms (min {min(v) * 1000:.0f})" for tool, v in cpu.items()
            )
            if args.against:
                shown += f"  ratio {statistics.median(cpu['this']) / statistics.median(cpu['against']):.2f}"
            if args.gc:
                shown += f"  {_gc_share(sys.executable, command, folder)}"
            print(f"{label:12} {shown}", flush=True)
    print(f"load average after: {'/'.join(f'{x:.1f}' for x in os.getloadavg())}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
