"""The example firmware project (examples/firmware) with the CMake package of cantools-od:
it builds with Ninja and with Makefiles, runs, regenerates when the EDS or its pin file changes,
and a build with nothing changed neither regenerates nor recompiles."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest
from ckit import ROOT, cli_command, tool

GENERATORS = {"Ninja": "ninja", "Unix Makefiles": "make"}


def cmake_args() -> list[str]:
    """Where the CMake package is (from `cantools-od cmake-dir`), and how to run cantools-od."""
    command = cli_command()
    found = subprocess.run([*command, "cmake-dir"], capture_output=True, text=True, check=True, timeout=60)
    args = [f"-Dcantools_od_DIR={found.stdout.strip()}"]
    if len(command) > 1:  # not installed: run the checkout's package (PYTHONPATH is inherited)
        args.append(f"-DCANTOOLS_OD_COMMAND={sys.executable};-m;cantools_od")
    return args


def run(args: list[str], cwd: Path) -> str:
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=300, env=dict(os.environ))
    assert result.returncode == 0, f"{' '.join(args)}:\n{result.stdout}\n{result.stderr}"
    return result.stdout + result.stderr


def bump(path: Path, old: str, new: str, newer_than: Path) -> None:
    """Edit a file so that its timestamp is later than `newer_than`'s, also on a coarse file-system clock."""
    text = path.read_text("utf-8")
    assert old in text
    path.write_text(text.replace(old, new), encoding="utf-8")
    while path.stat().st_mtime_ns <= newer_than.stat().st_mtime_ns:
        time.sleep(0.5)
        path.touch()


def assert_nothing_to_do(output: str, generator: str) -> None:
    # Only the checks of the optional files beside the EDS run (the pin file, the canopennode settings:
    # they may appear at any time, so they run every build), and CMake's own check of globbed source
    # folders where a project globs with CONFIGURE_DEPENDS.
    if generator == "Ninja":
        checks = re.compile(r"Re-checking globbed directories|Checking \S+'s (pin file|canopennode settings)$")
        steps = [line for line in output.splitlines() if line.startswith("[") and not checks.search(line)]
        assert "no work to do" in output or not steps, output
    assert "Generating" not in output, output
    assert "Building C object" not in output and "Linking" not in output, output


@pytest.mark.parametrize("generator", sorted(GENERATORS))
def test_example_firmware_builds_runs_and_tracks_the_eds(tmp_path: Path, generator: str) -> None:
    tool("cmake")
    tool("gcc")
    tool(GENERATORS[generator])
    project = tmp_path / "project"
    shutil.copytree(ROOT / "examples" / "firmware", project / "examples" / "firmware")
    (project / "eds").mkdir()
    eds = project / "eds" / "cia402_drive.eds"
    shutil.copy(ROOT / "eds" / "cia402_drive.eds", eds)
    source, build = project / "examples" / "firmware", tmp_path / "build"
    run(["cmake", "-S", str(source), "-B", str(build), "-G", generator, *cmake_args()], tmp_path)
    header = build / "cantools_od" / "drive.h"

    output = run(["cmake", "--build", str(build)], tmp_path)
    assert "Generating drive.h and drive.c from cia402_drive.eds" in output
    program = run([str(build / "firmware")], tmp_path)
    assert "heartbeat 500 ms" in program and "round trip ok" in program
    assert_nothing_to_do(run(["cmake", "--build", str(build)], tmp_path), generator)

    # A changed default value: generated again, the header changes, the program sees the new value.
    bump(eds, "DefaultValue=500", "DefaultValue=750", header)
    output = run(["cmake", "--build", str(build)], tmp_path)
    assert "Generating drive.h" in output
    assert "#define DRIVE_PRODUCER_HEARTBEAT_TIME_DEFAULT ((uint16_t)750u)" in header.read_text("utf-8")
    assert "heartbeat 750 ms" in run([str(build / "firmware")], tmp_path)
    assert_nothing_to_do(run(["cmake", "--build", str(build)], tmp_path), generator)

    # A pin file created beside the EDS counts at once.
    pins = project / "eds" / "cia402_drive.ids.toml"
    pins.write_text('[identifiers]\n"6502" = "drive_modes"\n', encoding="utf-8")
    assert "Generating drive.h" in run(["cmake", "--build", str(build)], tmp_path)
    assert "DRIVE_DRIVE_MODES_INDEX" in header.read_text("utf-8")
    bump(pins, "drive_modes", "supported_modes", header)
    assert "Generating drive.h" in run(["cmake", "--build", str(build)], tmp_path)
    assert "DRIVE_SUPPORTED_MODES_INDEX" in header.read_text("utf-8")
    assert "round trip ok" in run([str(build / "firmware")], tmp_path)
    assert_nothing_to_do(run(["cmake", "--build", str(build)], tmp_path), generator)


LIBRARY_PROJECT = """
cmake_minimum_required(VERSION 3.20)
project(library LANGUAGES C)
include("${CANTOOLS_OD_CMAKE_DIR}/cantools_od.cmake")
add_library(od STATIC)
cantools_od_generate(od EDS "${EDS}" TARGETS c markdown OUTPUT_DIR generated CAN_FD)
add_executable(app app.c)
target_link_libraries(app PRIVATE od)
"""

LIBRARY_APP = """
#include "io_device.h"
int main(void) { return IO_DEVICE_PDO_MAX_DLC == 64u && IO_DEVICE_OBJECT_COUNT > 0u ? 0 : 1; }
"""


def _configure_ninja(tmp_path: Path, project: str, app: str, definition: str) -> Path:
    """A project of CMakeLists.txt and app.c, configured with Ninja and the -D definition; its build folder."""
    tool("cmake")
    tool("gcc")
    tool("ninja")
    source, build = tmp_path / "source", tmp_path / "build"
    source.mkdir()
    (source / "CMakeLists.txt").write_text(project, encoding="utf-8")
    (source / "app.c").write_text(app, encoding="utf-8")
    args = cmake_args()
    folder = args[0].split("=", 1)[1]
    run(["cmake", "-S", str(source), "-B", str(build), "-G", "Ninja", f"-DCANTOOLS_OD_CMAKE_DIR={folder}",
         definition, *args[1:]], tmp_path)  # fmt: skip
    return build


def test_library_with_include_output_dir_and_more_targets(tmp_path: Path) -> None:
    """include(cantools_od.cmake), a library whose users get the include folder, TARGETS c markdown."""
    build = _configure_ninja(tmp_path, LIBRARY_PROJECT, LIBRARY_APP, f"-DEDS={ROOT / 'eds' / 'io_device.eds'}")
    output = run(["cmake", "--build", str(build)], tmp_path)
    assert "Generating markdown for io_device" in output
    names = {p.name for p in (build / "generated").iterdir()}
    assert {"io_device.c", "io_device.h"} <= names and any(n.endswith(".md") for n in names)
    run([str(build / "app")], tmp_path)  # exits 0: the library's include folder and CAN FD reached the app
    assert_nothing_to_do(run(["cmake", "--build", str(build)], tmp_path), "Ninja")


XDD_PROJECT = """
cmake_minimum_required(VERSION 3.20)
project(xdd_firmware LANGUAGES C)
include("${CANTOOLS_OD_CMAKE_DIR}/cantools_od.cmake")
add_executable(app app.c)
cantools_od_generate(app XDD "${XDD}" NAME demo)
"""

XDD_APP = """
#include "demo.h"
int main(void) { return DEMO_OBJECT_COUNT > 0u && DEMO_DEVICE_TYPE_INDEX == 0x1000u ? 0 : 1; }
"""


def test_xdd_as_the_input(tmp_path: Path) -> None:
    """cantools_od_generate(... XDD <file>): CANopenDemo's demoDevice.xdd builds into a firmware."""
    xdd = ROOT.parent / "shared" / "third_party" / "CANopenDemo-demo" / "demoDevice.xdd"
    if not xdd.is_file():
        pytest.skip("../shared is absent")
    build = _configure_ninja(tmp_path, XDD_PROJECT, XDD_APP, f"-DXDD={xdd}")
    assert "Generating demo.h and demo.c from demoDevice.xdd" in run(["cmake", "--build", str(build)], tmp_path)
    run([str(build / "app")], tmp_path)
