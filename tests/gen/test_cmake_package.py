"""The CMake integration as a user meets it: `pip install` cantools-od into a fresh virtual
environment, put its bin folder on the PATH, and `find_package(cantools_od CONFIG REQUIRED)` works
with no -D option; the pin file beside the EDS is a dependency of generation whether it exists or
not (creating, editing or deleting it regenerates once; an unchanged tree regenerates nothing)."""

from __future__ import annotations

import os
import subprocess
import sys
import sysconfig
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from ckit import ROOT, tool

# Its tests share one module fixture: under pytest-xdist they run on one worker, which makes it once.
pytestmark = pytest.mark.xdist_group("cmake_package")

GENERATORS = {"Ninja": "ninja", "Unix Makefiles": "make"}

PROJECT = """\
cmake_minimum_required(VERSION 3.13)
project(pinned LANGUAGES C)
find_package(cantools_od CONFIG REQUIRED)
add_executable(app main.c)
cantools_od_generate(app EDS eds/drive.eds NAME drive)
"""

MAIN = """\
#include <stdio.h>
#include "drive.h"
int main(void) { printf("%u\\n", (unsigned)DRIVE_OBJECT_COUNT); return 0; }
"""


@pytest.fixture(scope="module")
def venv(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    """A fresh venv with the wheel built from this checkout installed by pip, as a user installs it.

    Its dependencies come from the test environment's site-packages (a .pth file), so no network is
    needed; cantools-od itself and everything pip puts under the prefix come from the wheel."""
    if not (ROOT / "pyproject.toml").is_file():
        pytest.skip("needs the source checkout to build the wheel")
    base = tmp_path_factory.mktemp("package")
    wheels = base / "wheels"
    build = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-w", str(wheels), str(ROOT)]
    subprocess.run(build, check=True, capture_output=True, timeout=300)
    env = base / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(env)], check=True, timeout=120)
    python = env / "bin" / "python"
    purelib = subprocess.run(
        [str(python), "-c", "import sysconfig; print(sysconfig.get_path('purelib'))"],
        check=True, capture_output=True, text=True,
    ).stdout.strip()  # fmt: skip
    wheel = next(wheels.glob("cantools_od-*.whl"))
    install = [sys.executable, "-m", "pip", "--python", str(python), "install", "--no-deps", str(wheel)]
    result = subprocess.run(install, capture_output=True, text=True, timeout=300)
    if result.returncode != 0 and "--python" in result.stderr:  # pip older than 22.3
        install = [sys.executable, "-m", "pip", "install", "--no-deps", "--prefix", str(env), str(wheel)]
        result = subprocess.run(install, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    assert (env / "bin" / "cantools-od").is_file(), result.stdout
    # Only now, so that pip did not see the copy installed in the test environment.
    (Path(purelib) / "test_dependencies.pth").write_text(sysconfig.get_path("purelib") + "\n", encoding="utf-8")
    yield env


def user_env(venv: Path) -> dict[str, str]:
    """The environment of a user who activated the venv: its bin first on the PATH, no CMake hints."""
    ours = str(Path(sys.executable).parent)
    path = [str(venv / "bin"), *(p for p in os.environ.get("PATH", "").split(os.pathsep) if p and p != ours)]
    env = {k: v for k, v in os.environ.items() if not k.startswith(("CMAKE_", "cantools_od", "CANTOOLS_OD"))}
    env.pop("PYTHONPATH", None)
    return {**env, "PATH": os.pathsep.join(path), "VIRTUAL_ENV": str(venv)}


def run(args: list[str], cwd: Path, env: dict[str, str]) -> str:
    result = subprocess.run(args, cwd=cwd, capture_output=True, text=True, timeout=300, env=env)
    assert result.returncode == 0, f"{' '.join(args)}:\n{result.stdout}\n{result.stderr}"
    return result.stdout + result.stderr


def later(path: Path, newer_than: Path) -> None:
    """Make `path`'s timestamp later than `newer_than`'s, also on a coarse file-system clock."""
    while path.stat().st_mtime_ns <= newer_than.stat().st_mtime_ns:
        time.sleep(0.2)
        path.touch()


def regenerated(output: str) -> int:
    return output.count("Generating drive.h and drive.c")


@pytest.mark.parametrize("generator", sorted(GENERATORS))
def test_find_package_without_options_and_pin_file_tracking(tmp_path: Path, venv: Path, generator: str) -> None:
    tool("cmake")
    tool("gcc")
    tool(GENERATORS[generator])
    env = user_env(venv)
    source, build = tmp_path / "source", tmp_path / "build"
    (source / "eds").mkdir(parents=True)
    (source / "CMakeLists.txt").write_text(PROJECT, encoding="utf-8")
    (source / "main.c").write_text(MAIN, encoding="utf-8")
    eds = source / "eds" / "drive.eds"
    eds.write_bytes((ROOT / "eds" / "cia402_drive.eds").read_bytes())
    pins = source / "eds" / "drive.ids.toml"

    run(["cmake", "-S", str(source), "-B", str(build), "-G", generator], tmp_path, env)
    cache = (build / "CMakeCache.txt").read_text("utf-8")
    found = next(line for line in cache.splitlines() if line.startswith("cantools_od_DIR:"))
    assert found.endswith(str(venv / "share" / "cmake" / "cantools_od")), found
    header = build / "cantools_od" / "drive.h"

    def build_once() -> str:
        return run(["cmake", "--build", str(build)], tmp_path, env)

    assert regenerated(build_once()) == 1
    assert "DRIVE_MODES_OF_OPERATION_INDEX" in header.read_text("utf-8")
    assert run([str(build / "app")], tmp_path, env).strip().isdigit()

    def write(name: str) -> Callable[[], object]:
        return lambda: pins.write_text(f'[identifiers]\n"6060" = "{name}"\n', encoding="utf-8")

    steps = [
        ("created", write("op_mode"), "DRIVE_OP_MODE_INDEX"),
        ("edited", write("mode"), "DRIVE_MODE_INDEX"),
        ("deleted", pins.unlink, "DRIVE_MODES_OF_OPERATION_INDEX"),
    ]
    for what, change, expected in steps:
        assert regenerated(build_once()) == 0, "an unchanged tree regenerates nothing"
        change()
        if pins.exists():
            later(pins, header)
        output = build_once()
        assert regenerated(output) == 1, f"pin file {what}: {output}"
        assert expected in header.read_text("utf-8"), what
    assert regenerated(build_once()) == 0
    assert "Building C object" not in build_once()
