"""Errors fail builds: an error in the input that touches generated code makes `gen` (and the CMake
build) fail and write nothing; `--keep-going` (CMake: KEEP_GOING) generates the rest, exits 0 and
says what it left out, on stderr and in every generated file."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

import pytest
from kit import GOOD, assert_failed_cleanly, run, snapshot

HEARTBEAT = b"ParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0006\nAccessType=rw\nDefaultValue=1000"
BROKEN = {
    "invalid-default": GOOD.replace(HEARTBEAT, HEARTBEAT.replace(b"=1000", b"=ten seconds")),
    "unclosed-header": GOOD.replace(b"[1017]\n", b"[1017\n"),
    "stray-line": GOOD.replace(HEARTBEAT, HEARTBEAT.replace(b"DataType", b"heartbeat in ms\nDataType")),
    "unmappable-pdo": GOOD.replace(b"DefaultValue=0x62000108", b"DefaultValue=0x7FFF0108"),
}
TARGETS = ["-t", "c", "-t", "rust", "-t", "python", "-t", "markdown"]
C_FLAGS = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_an_error_fails_gen_and_writes_nothing(tmp_path: Path, case: str) -> None:
    """Why: gen printed `error:` diagnostics, exited 0, and the affected macro silently disappeared."""
    (tmp_path / "io.eds").write_bytes(BROKEN[case])
    before = snapshot(tmp_path)
    ran = run("gen", "io.eds", *TARGETS, "-o", "out", "--depfile", "out.d", cwd=tmp_path)
    assert_failed_cleanly(ran)
    assert ran.returncode == 1, ran
    left_out = "RPDO1" if case == "unmappable-pdo" else "1017h"
    assert f"io.eds: error: nothing generated: errors touch {left_out}" in ran.stderr, ran
    assert snapshot(tmp_path) == before


@pytest.mark.parametrize("case", sorted(BROKEN))
def test_keep_going_generates_the_rest_and_says_what_it_left_out(tmp_path: Path, case: str) -> None:
    (tmp_path / "io.eds").write_bytes(BROKEN[case])
    ran = run("gen", "io.eds", *TARGETS, "-o", "out", "--keep-going", cwd=tmp_path)
    assert ran.returncode == 0, ran
    left_out = "RPDO1 (its packing code)" if case == "unmappable-pdo" else "1017h Producer heartbeat time"
    assert f"io.eds: warning: left out of the generated files: {left_out}" in ran.stderr, ran
    files = sorted((tmp_path / "out").iterdir())
    assert sorted({f.suffix for f in files}) == [".c", ".h", ".md", ".py", ".rs", ".svg"]  # .svg: the PDO pictures
    for path in files:
        head = path.read_text("utf-8")[:400].replace("\\", "")  # Markdown escapes ( and )
        said = "(keep going)" if path.suffix == ".svg" else "--keep-going"  # an XML comment may not hold --
        assert f"cantools-od gen {said} left out what errors in the input touch" in head, path.name
        assert left_out in head, path.name
    header = (tmp_path / "out" / "io.h").read_text("utf-8")
    assert "IO_DEVICE_TYPE_INDEX" in header  # the rest is there
    assert ("IO_PRODUCER_HEARTBEAT_TIME_INDEX" in header) == (case == "unmappable-pdo")
    if shutil.which("gcc") is None:
        pytest.skip("gcc is not installed")
    compiled = subprocess.run(["gcc", *C_FLAGS, "-c", "io.c", "-o", "io.o"], cwd=tmp_path / "out", capture_output=True)
    assert compiled.returncode == 0, compiled.stderr.decode()


def test_a_clean_file_has_no_note(tmp_path: Path) -> None:
    (tmp_path / "io.eds").write_bytes(GOOD)
    ran = run("gen", "io.eds", "-t", "c", "-o", "out", "--keep-going", cwd=tmp_path)
    assert ran.returncode == 0 and ran.stderr == "", ran
    assert "left out" not in (tmp_path / "out" / "io.h").read_text("utf-8")


CMAKE_PROJECT = """cmake_minimum_required(VERSION 3.13)
project(keep_going C)
find_package(cantools_od CONFIG REQUIRED)
add_library(od STATIC)
cantools_od_generate(od EDS ${CMAKE_CURRENT_SOURCE_DIR}/io.eds NAME io @OPTION@)
"""


@pytest.mark.parametrize("option", ["", "KEEP_GOING"])
def test_cmake_build_fails_on_errors_unless_keep_going(tmp_path: Path, option: str) -> None:
    if shutil.which("cmake") is None or shutil.which("gcc") is None:
        pytest.skip("cmake and gcc are needed")
    cmake_dir = run("cmake-dir", cwd=tmp_path).stdout.strip()
    source = tmp_path / "src"
    source.mkdir()
    (source / "io.eds").write_bytes(BROKEN["invalid-default"])
    (source / "CMakeLists.txt").write_text(CMAKE_PROJECT.replace("@OPTION@", option))
    build = tmp_path / "build"
    configure = ["cmake", "-S", str(source), "-B", str(build), "-G", "Unix Makefiles", f"-Dcantools_od_DIR={cmake_dir}"]
    configured = subprocess.run(configure, capture_output=True, text=True, timeout=300)
    assert configured.returncode == 0, configured.stdout + configured.stderr
    built = subprocess.run(["cmake", "--build", str(build)], capture_output=True, text=True, timeout=300)
    output = built.stdout + built.stderr
    if option:
        assert built.returncode == 0, output
        assert "left out of the generated files: 1017h" in output
    else:
        assert built.returncode != 0, output
        assert "io.eds: error: nothing generated: errors touch 1017h" in output
        assert not (build / "cantools_od" / "io.c").exists()
