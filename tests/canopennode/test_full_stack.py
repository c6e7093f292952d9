"""The whole CANopenNode stack with the blank driver builds with the generated OD.h (its #error checks
pass) and CO_CANopenInit and the main loop run without error, with one OD and with CO_MULTIPLE_OD."""

from __future__ import annotations

import threading
from pathlib import Path

import pytest
from cnokit import DEMO, HERE, STACK, STACK_DEFAULTS, WARNINGS, gen, load_accepted, parallel, run, stack, write_od

from support import corpus_files

# CO_storageEeprom.c is left out: it needs a target's EEPROM fields in CO_storage_entry_t (the blank
# driver has CO_storageBlank.c for that role).
STACK_SOURCES = [
    "CANopen.c",
    *(f"{folder}/{p.name}" for folder in ("301", "303", "304", "305") for p in sorted((STACK / folder).glob("*.c"))),
    "storage/CO_storage.c",
    "example/CO_storageBlank.c",
]


_LIBRARIES: dict[tuple[str, ...], Path] = {}
_LOCK = threading.Lock()


def stack_library(work: Path, defines: tuple[str, ...]) -> Path:
    """The stack without CANopen.c (the one file that includes OD.h), built once per set of defines."""
    with _LOCK:
        if defines not in _LIBRARIES:
            work.mkdir(parents=True, exist_ok=True)
            flags = [*defines, f"-I{STACK}", f"-I{STACK / 'example'}"]
            objects = []
            for source in [*(STACK / s for s in STACK_SOURCES[1:]), STACK / "example" / "CO_driver_blank.c"]:
                objects.append(str(work / (source.parent.name + "_" + source.stem + ".o")))
                run(["gcc", "-Wall", *flags, "-c", str(source), "-o", objects[-1]])
            run(["ar", "rcs", str(work / "libstack.a"), *objects])
            _LIBRARIES[defines] = work / "libstack.a"
        return _LIBRARIES[defines]


def build_and_run(od_dir: Path, work: Path, *defines: str) -> str:
    """CANopen.c, the generated OD and device_main.c on the stack library; run 2000 loop passes."""
    work.mkdir(parents=True, exist_ok=True)
    library = stack_library(work.parent / ("stack" + "".join(defines)), defines)
    flags = [*defines, f"-I{od_dir}", f"-I{STACK}", f"-I{STACK / 'example'}"]
    objects = [str(work / "CANopen.o"), str(work / "OD.o"), str(work / "device_main.o")]
    run(["gcc", "-Wall", *flags, "-c", str(STACK / "CANopen.c"), "-o", objects[0]])
    for source, target in ((od_dir / "OD.c", objects[1]), (HERE / "device_main.c", objects[2])):  # ours: warning-free
        run(["gcc", *WARNINGS, *flags, "-c", str(source), "-o", target])
    exe = work / "device"
    run(["gcc", "-o", str(exe), *objects, str(library)])
    return run([str(exe), "2000"], timeout=60).stdout


def test_demo_device_runs_in_the_stack_single_and_multiple_od(tmp_path: Path) -> None:
    stack()
    source = DEMO / "demoDevice.eds"
    assert gen(source, tmp_path / "od").returncode == 0
    jobs = [(tmp_path / "single",), (tmp_path / "multiple", "-DCO_MULTIPLE_OD")]
    results = parallel(lambda job: build_and_run(tmp_path / "od", *job), jobs)
    assert all("operational after 2000 iterations" in r for r in results), results


def test_accepted_corpus_files_run_in_the_stack(tmp_path: Path) -> None:
    stack()
    devices, _ = load_accepted([STACK / "example" / "DS301_profile.eds", *corpus_files()], STACK_DEFAULTS)
    if len(devices) < 2:
        pytest.skip("../shared/eds-corpus is absent")
    sample = devices[:: max(1, len(devices) // 6)]  # a spread of the corpus keeps the test short

    def one(job: tuple[int, object]) -> str:
        n, device = job
        write_od(device, tmp_path / f"od{n}")  # type: ignore[arg-type]
        return build_and_run(tmp_path / f"od{n}", tmp_path / f"work{n}")

    results = parallel(one, list(enumerate(sample)))
    assert all("after 2000 iterations" in r for r in results), results
