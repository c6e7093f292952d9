"""`cantools_od_bus(<bus>)` in a CMake project laid out as a ros2_canopen configuration package (config/<bus>/
bus.yml with its EDS files beside it, as ros2_canopen's `cogen_dcf(<bus>)` reads it): the build writes master.dcf,
the concise DCFs and the installed bus.yml into build/config/<bus>, runs again only when bus.yml or an EDS
changes, and `cmake --install` puts both folders into share/<package>/config/<bus> with @BUS_CONFIG_PATH@
standing for that folder."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import time
from pathlib import Path

import pytest

from cantools_od.model.cia301.master import read_concise_dcf

from support import EXAMPLES

PACKAGE = """\
cmake_minimum_required(VERSION 3.13)
project(robot_config NONE)
find_package(cantools_od CONFIG REQUIRED)
cantools_od_bus(robot)
"""

BUS = """\
options:
  dcf_path: "@BUS_CONFIG_PATH@"
master:
  node_id: 1
  sync_period: 10000
  driver: "ros2_canopen::MasterDriver"
  package: "canopen_master_driver"
defaults:
  dcf: "io_device.eds"
  driver: "ros2_canopen::ProxyDriver"
  package: "canopen_proxy_driver"
  heartbeat_producer: 500
nodes:
  right_io:
    node_id: 3
  left_io:
    node_id: 2
"""

GENERATED = "Generating the robot bus configuration"


def cmake(*args: str, cwd: Path) -> str:
    found = shutil.which("cmake")
    if found is None:
        pytest.skip("cmake is not installed")
    env = {**os.environ, "PATH": os.pathsep.join([str(Path(sys.executable).parent), os.environ.get("PATH", "")])}
    result = subprocess.run([found, *args], cwd=cwd, capture_output=True, text=True, timeout=300, env=env)
    assert result.returncode == 0, f"cmake {' '.join(args)}:\n{result.stdout}\n{result.stderr}"
    return result.stdout + result.stderr


def later(path: Path, newer_than: Path) -> None:
    while path.stat().st_mtime_ns <= newer_than.stat().st_mtime_ns:
        time.sleep(0.2)
        path.touch()


def test_configuration_package_builds_installs_and_tracks_its_inputs(tmp_path: Path) -> None:
    if shutil.which("make") is None:
        pytest.skip("make is not installed")
    source, build, prefix = tmp_path / "robot_config", tmp_path / "build", tmp_path / "install"
    config = source / "config" / "robot"
    config.mkdir(parents=True)
    (source / "CMakeLists.txt").write_text(PACKAGE)
    (config / "bus.yml").write_text(BUS)
    eds = config / "io_device.eds"
    eds.write_bytes((EXAMPLES / "io_device.eds").read_bytes())
    module = subprocess.run(
        [str(Path(sys.executable).parent / "cantools-od"), "cmake-dir"], capture_output=True, text=True, check=True
    ).stdout.strip()
    cmake("-S", str(source), "-B", str(build), "-G", "Unix Makefiles", f"-Dcantools_od_DIR={module}",
          f"-DCMAKE_INSTALL_PREFIX={prefix}", cwd=tmp_path)  # fmt: skip
    assert GENERATED in cmake("--build", str(build), cwd=tmp_path)
    out = build / "config" / "robot"
    installed = prefix / "share" / "robot_config" / "config" / "robot"
    master = (out / "master.dcf").read_text()
    assert f"UploadFile={installed}/left_io.bin" in master and f"UploadFile={installed}/right_io.bin" in master
    assert master.index("left_io.bin") < master.index("right_io.bin")  # cogen's order: by name
    writes = read_concise_dcf((out / "left_io.bin").read_bytes())
    assert (0x1017, 0, (500).to_bytes(2, "little")) in writes
    # the bus.yml ros2_canopen's nodes read at run time: defaults copied into each node, the path replaced
    runtime = (out / "bus.yml").read_text()
    assert "@BUS_CONFIG_PATH@" not in runtime and f"dcf_path: '{installed}'" in runtime and "defaults" not in runtime

    assert GENERATED not in cmake("--build", str(build), cwd=tmp_path), "an unchanged package regenerates nothing"
    later(eds, out / "master.dcf")
    assert GENERATED in cmake("--build", str(build), cwd=tmp_path), "an EDS changed"
    (config / "bus.yml").write_text(BUS.replace("heartbeat_producer: 500", "heartbeat_producer: 250"))
    later(config / "bus.yml", out / "master.dcf")
    assert GENERATED in cmake("--build", str(build), cwd=tmp_path), "bus.yml changed"
    assert (0x1017, 0, (250).to_bytes(2, "little")) in read_concise_dcf((out / "left_io.bin").read_bytes())
    assert GENERATED not in cmake("--build", str(build), cwd=tmp_path)

    cmake("--install", str(build), cwd=tmp_path)
    names = sorted(p.name for p in installed.iterdir())
    assert names == ["bus.yml", "io_device.eds", "left_io.bin", "master.bin", "master.dcf", "right_io.bin"]
    assert (installed / "bus.yml").read_text() == runtime.replace("500", "250")
