"""Load-time benchmark: cantools-od against python-canopen's `import_od`.

Run with `python bench/bench_load.py [CORPUS_DIR] [--json] [--rounds N]`.
See bench/README.md for what is measured.
"""

from __future__ import annotations

import argparse
import gc
import json
import os
import statistics
import sys
import tempfile
import time
import tracemalloc
from collections.abc import Callable
from pathlib import Path
from typing import Any, Literal

import canopen

sys.path.insert(0, str(Path(__file__).resolve().parent))
import installed  # noqa: F401  (first: the installed package is measured, see bench/installed.py)

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests"))

from peermatrix import quiet  # python-canopen logs and warns about every odd entry: none of it is measured

import cantools_od
from cantools_od import dumps, load, loads

DEFAULT_CORPUS = Path(__file__).resolve().parents[2] / "shared" / "eds-corpus" / "eds"
SYNTHETIC_OBJECTS = 5000

Result = dict[str, Any]


def corpus_files(corpus: Path) -> list[Path]:
    return sorted(p for p in corpus.iterdir() if p.is_file() and p.suffix.lower() in (".eds", ".dcf"))


def canopen_readable(files: list[Path]) -> tuple[list[Path], dict[str, str]]:
    """The files `canopen.import_od` reads without raising, and why it fails on the others."""
    readable: list[Path] = []
    failures: dict[str, str] = {}
    with quiet():
        for path in files:
            try:
                canopen.import_od(str(path))
            except Exception as error:  # any failure counts: we only want the files it can read
                failures[path.name] = f"{type(error).__name__}: {str(error)[:100]}"
            else:
                readable.append(path)
    return readable, failures


def timed(action: Callable[[], object]) -> float:
    start = time.perf_counter()
    action()
    return time.perf_counter() - start


def load_all_ours(files: list[Path]) -> Callable[[], object]:
    def run() -> object:
        return [load(path) for path in files]

    return run


def load_all_theirs(files: list[Path]) -> Callable[[], object]:
    def run() -> object:
        with quiet():
            return [canopen.import_od(str(path)) for path in files]

    return run


def alternate(ours: Callable[[], object], theirs: Callable[[], object], rounds: int) -> tuple[list[float], list[float]]:
    """Times both in turns (ours, theirs, ours, ...) so drift in machine load hits both alike."""
    ours_times: list[float] = []
    theirs_times: list[float] = []
    for _ in range(rounds):
        gc.collect()
        ours_times.append(timed(ours))
        gc.collect()
        theirs_times.append(timed(theirs))
    return ours_times, theirs_times


def repeat(action: Callable[[], object], rounds: int) -> list[float]:
    times: list[float] = []
    for _ in range(rounds):
        gc.collect()
        times.append(timed(action))
    return times


def summary(times: list[float]) -> Result:
    return {"median_s": statistics.median(times), "min_s": min(times), "max_s": max(times), "runs": len(times)}


# ---------------------------------------------------------------------------
# Synthetic EDS

# (data type, default value) pairs used in turn; all are CiA 301 basic types.
_VAR_TYPES: list[tuple[int, str]] = [
    (0x0005, "0x00"),
    (0x0006, "0x1234"),
    (0x0007, "0x00000000"),
    (0x0002, "-5"),
    (0x0003, "1000"),
    (0x0004, "-100000"),
    (0x0001, "0"),
    (0x0008, "1.5"),
    (0x0009, "text"),
    (0x0007, "$NODEID+0x180"),
]
_ACCESS = ["rw", "ro", "rww", "rwr", "const", "wo"]


def _entry_lines(name: str, object_type: int, data_type: int, access: str, default: str, pdo: int) -> list[str]:
    return [
        f"ParameterName={name}",
        f"ObjectType=0x{object_type:X}",
        f"DataType=0x{data_type:04X}",
        f"AccessType={access}",
        f"DefaultValue={default}",
        f"PDOMapping={pdo}",
    ]


def synthetic_eds(count: int = SYNTHETIC_OBJECTS) -> str:
    """An EDS with `count` manufacturer objects at 0x2000 upward: 60 % VAR, 40 % RECORD/ARRAY of 4-8 subs."""
    lines = [
        "[FileInfo]",
        "FileName=synthetic.eds",
        "FileVersion=1",
        "FileRevision=0",
        "EDSVersion=4.0",
        "Description=synthetic benchmark device",
        "CreationTime=09:00AM",
        "CreationDate=01-15-2025",
        "CreatedBy=bench_load.py",
        "",
        "[DeviceInfo]",
        "VendorName=bench",
        "VendorNumber=0x00000CA7",
        "ProductName=synthetic",
        "ProductNumber=0x00000001",
        "RevisionNumber=0x00010000",
        "BaudRate_125=1",
        "BaudRate_250=1",
        "BaudRate_500=1",
        "BaudRate_1000=1",
        "SimpleBootUpSlave=1",
        "Granularity=8",
        "NrOfRXPDO=4",
        "NrOfTXPDO=4",
        "LSS_Supported=1",
        "",
        "[DummyUsage]",
        *(f"Dummy{t:04X}=1" for t in range(1, 8)),
        "",
    ]
    mandatory = [0x1000, 0x1001, 0x1018]
    lines += ["[MandatoryObjects]", f"SupportedObjects={len(mandatory)}"]
    lines += [f"{n}=0x{index:04X}" for n, index in enumerate(mandatory, 1)]
    lines += ["", "[OptionalObjects]", "SupportedObjects=0", ""]
    manufacturer = list(range(0x2000, 0x2000 + count - len(mandatory)))
    lines += ["[ManufacturerObjects]", f"SupportedObjects={len(manufacturer)}"]
    lines += [f"{n}=0x{index:04X}" for n, index in enumerate(manufacturer, 1)]
    lines.append("")
    # The mandatory communication objects, so both readers see a plausible device.
    lines += ["[1000]", *_entry_lines("Device type", 7, 0x0007, "ro", "0x00000000", 0), ""]
    lines += ["[1001]", *_entry_lines("Error register", 7, 0x0005, "ro", "0", 1), ""]
    lines += ["[1018]", "ParameterName=Identity object", "ObjectType=0x9", "SubNumber=5", ""]
    lines += ["[1018sub0]", *_entry_lines("Highest sub-index supported", 7, 0x0005, "const", "4", 0), ""]
    for sub, name in enumerate(("Vendor-ID", "Product code", "Revision number", "Serial number"), 1):
        lines += [f"[1018sub{sub}]", *_entry_lines(name, 7, 0x0007, "ro", "0x00000000", 0), ""]
    for n, index in enumerate(manufacturer):
        section = f"{index:04X}"
        if n % 5 < 3:  # VAR
            data_type, default = _VAR_TYPES[n % len(_VAR_TYPES)]
            access = _ACCESS[n % len(_ACCESS)]
            lines += [f"[{section}]", *_entry_lines(f"Parameter {n}", 7, data_type, access, default, n % 2), ""]
            continue
        subs = 4 + n % 5  # 4..8 sub-objects, sub 0 included
        is_array = n % 5 == 3
        lines += [f"[{section}]", f"ParameterName={'Array' if is_array else 'Record'} {n}"]
        lines += [f"ObjectType={'0x8' if is_array else '0x9'}", f"SubNumber={subs}", ""]
        lines += [f"[{section}sub0]", *_entry_lines("Highest sub-index supported", 7, 0x0005, "ro", str(subs - 1), 0)]
        lines.append("")
        for sub in range(1, subs):
            if is_array:
                data_type, default = 0x0006, f"0x{sub:04X}"
            else:
                data_type, default = _VAR_TYPES[(n + sub) % len(_VAR_TYPES)]
            access = _ACCESS[(n + sub) % len(_ACCESS)]
            lines += [f"[{section}sub{sub:X}]", *_entry_lines(f"Entry {sub}", 7, data_type, access, default, sub % 2)]
            lines.append("")
    return "\r\n".join(lines)


def bench_synthetic(rounds: int) -> Result:
    text = synthetic_eds()
    data = text.encode("ascii")
    ours = repeat(lambda: loads(data, source="synthetic.eds"), rounds)
    device = loads(data, source="synthetic.eds")
    sub_count = sum(len(obj.subs) for obj in device.objects.values())
    errors = [d for d in device.diagnostics if d.severity.value == "error"]

    gc.collect()
    tracemalloc.start()
    loads(data, source="synthetic.eds")
    _, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()

    handle, name = tempfile.mkstemp(suffix=".eds", prefix="bench_synthetic_")
    try:
        with os.fdopen(handle, "wb") as out:
            out.write(data)
        theirs: list[float] | None = repeat(load_all_theirs([Path(name)]), rounds)
        theirs_error = None
    except Exception as error:
        theirs, theirs_error = None, f"{type(error).__name__}: {error}"
    finally:
        Path(name).unlink(missing_ok=True)

    result: Result = {
        "objects": len(device.objects),
        "sub_objects": sub_count,
        "bytes": len(data),
        "lines": text.count("\n") + 1,
        "diagnostic_errors": len(errors),
        "ours": summary(ours),
        "peak_memory_bytes": peak,
        "theirs": summary(theirs) if theirs else None,
        "theirs_error": theirs_error,
    }
    if theirs:
        result["ratio"] = result["ours"]["median_s"] / result["theirs"]["median_s"]
    return result


def bench_dumps(largest: Path, rounds: int) -> Result:
    device = load(largest)
    fmt: Literal["eds", "dcf"] = "dcf" if device.is_dcf else "eds"
    canonical = repeat(lambda: dumps(device, fmt, "canonical"), rounds)
    preserve = repeat(lambda: dumps(device, fmt, "preserve"), rounds)
    as_json = repeat(lambda: dumps(device, "json"), rounds)
    return {
        "file": largest.name,
        "bytes": largest.stat().st_size,
        "objects": len(device.objects),
        "canonical": summary(canonical),
        "preserve": summary(preserve),
        "json": summary(as_json),
    }


def ours_readable(files: list[Path]) -> tuple[list[Path], dict[str, str]]:
    """The files cantools-od reads, and why it refuses the others (an empty file is no device description)."""
    readable: list[Path] = []
    refused: dict[str, str] = {}
    for path in files:
        try:
            load(path)
        except Exception as error:  # a refusal is a result to count, not a reason to stop the benchmark
            refused[path.name] = f"{type(error).__name__}: {str(error)[:100]}"
        else:
            readable.append(path)
    return readable, refused


def bench_largest(files: list[Path], rounds: int) -> Result:
    """The largest file both read, alone: ours and theirs alternating."""
    largest = max(files, key=lambda p: p.stat().st_size)
    ours, theirs = alternate(load_all_ours([largest]), load_all_theirs([largest]), rounds)
    result: Result = {"file": largest.name, "bytes": largest.stat().st_size, "ours": summary(ours)}
    result["theirs"] = summary(theirs)
    result["ratio"] = result["ours"]["median_s"] / result["theirs"]["median_s"]
    return result


def run(corpus: Path, rounds: int) -> Result:
    files = corpus_files(corpus)
    if not files:
        raise SystemExit(f"bench_load: no .eds/.dcf files in {corpus}")
    # The first passes also warm both readers up (imports, caches).
    theirs_read, failures = canopen_readable(files)
    ours_read, refused = ours_readable(files)
    readable = [path for path in theirs_read if path in ours_read]

    ours, theirs = alternate(load_all_ours(readable), load_all_theirs(readable), rounds)
    common: Result = {
        "files": len(readable),
        "bytes": sum(p.stat().st_size for p in readable),
        "ours": summary(ours),
        "theirs": summary(theirs),
    }
    common["ratio"] = common["ours"]["median_s"] / common["theirs"]["median_s"]

    everything = repeat(load_all_ours(ours_read), rounds)
    all_files: Result = {
        "files": len(ours_read),
        "bytes": sum(p.stat().st_size for p in ours_read),
        "ours": summary(everything),
        "canopen_fails": len(failures),
        "canopen_failures": failures,
        "corpus_files": len(files),
        "refused": len(refused),
        "refusals": refused,
    }

    largest = max(ours_read, key=lambda p: p.stat().st_size)
    return {
        "corpus": str(corpus),
        "rounds": rounds,
        "python": sys.version.split()[0],
        "cantools_od": cantools_od.__version__,
        "canopen": getattr(canopen, "__version__", "?"),
        "corpus_common": common,
        "corpus_all": all_files,
        "largest": bench_largest(readable, rounds),
        "synthetic": bench_synthetic(rounds),
        "dumps_largest": bench_dumps(largest, rounds),
    }


# ---------------------------------------------------------------------------
# Output


def _ms(seconds: float) -> str:
    return f"{seconds * 1000:9.1f} ms"


def _mib(size: int) -> str:
    return f"{size / (1 << 20):.2f} MiB"


def report(result: Result) -> str:
    common, every = result["corpus_common"], result["corpus_all"]
    synth, dumped, big = result["synthetic"], result["dumps_largest"], result["largest"]
    verdict = "OK" if common["ratio"] <= 0.5 else "SLOWER than target"
    out = [
        f"cantools-od {result['cantools_od']} vs python-canopen {result['canopen']} "
        f"(Python {result['python']}, median of {result['rounds']} alternating rounds)",
        f"corpus: {result['corpus']}",
        "",
        f"{'workload':<34}{'files':>6}{'bytes':>11}{'cantools-od':>14}{'canopen':>14}{'ratio':>8}",
        f"{'corpus, files canopen reads':<34}{common['files']:>6}{common['bytes']:>11}"
        f"{_ms(common['ours']['median_s']):>14}{_ms(common['theirs']['median_s']):>14}{common['ratio']:>8.2f}",
        f"{'corpus, all files read':<34}{every['files']:>6}{every['bytes']:>11}"
        f"{_ms(every['ours']['median_s']):>14}{'-':>14}{'-':>8}",
        f"{'largest: ' + big['file'][:25]:<34}{1:>6}{big['bytes']:>11}"
        f"{_ms(big['ours']['median_s']):>14}{_ms(big['theirs']['median_s']):>14}{big['ratio']:>8.2f}",
    ]
    theirs = synth["theirs"]
    out.append(
        f"{'synthetic ' + str(synth['objects']) + ' objects':<34}{1:>6}{synth['bytes']:>11}"
        f"{_ms(synth['ours']['median_s']):>14}"
        f"{(_ms(theirs['median_s']) if theirs else 'failed'):>14}"
        f"{(format(synth['ratio'], '.2f') if theirs else '-'):>8}"
    )
    out += [
        "",
        f"ratio ours/theirs on the common corpus: {common['ratio']:.2f} (target <= 0.50: {verdict})",
        f"canopen fails on {every['canopen_fails']} of {every['corpus_files']} corpus "
        f"files; cantools-od refuses {every['refused']}"
        + "".join(f"\n  refused {name}: {why}" for name, why in every["refusals"].items()),
        f"synthetic EDS: {synth['objects']} objects, {synth['sub_objects']} sub-objects, {synth['lines']} lines, "
        f"{_mib(synth['bytes'])}; {synth['diagnostic_errors']} error diagnostics",
        f"peak memory of one synthetic load (tracemalloc): {_mib(synth['peak_memory_bytes'])}",
    ]
    if synth["theirs_error"]:
        out.append(f"canopen on the synthetic EDS: {synth['theirs_error']}")
    out += [
        f"dumps of the largest corpus file ({dumped['file']}, {dumped['bytes']} bytes, {dumped['objects']} objects):",
        f"  canonical {_ms(dumped['canonical']['median_s']).strip()}"
        f", preserve {_ms(dumped['preserve']['median_s']).strip()}"
        f", json {_ms(dumped['json']['median_s']).strip()}",
    ]
    return "\n".join(out)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("corpus", nargs="?", type=Path, default=DEFAULT_CORPUS, help="folder of .eds/.dcf files")
    parser.add_argument("--json", action="store_true", help="print the results as JSON")
    parser.add_argument("--rounds", type=int, default=5, help="rounds per measurement (default 5)")
    args = parser.parse_args(argv)
    corpus: Path = args.corpus
    if not corpus.is_dir():
        print(
            f"bench_load: corpus folder {corpus} not found; pass a folder of .eds/.dcf files as the first argument",
            file=sys.stderr,
        )
        return 2
    if args.rounds < 1:
        parser.error("--rounds must be at least 1")
    result = run(corpus, args.rounds)
    print(json.dumps(result, indent=2) if args.json else report(result))
    return 0


if __name__ == "__main__":
    sys.exit(main())
