"""Helpers of the C target's tests: generating in-process, compiling, a crafted EDS with odd PDO layouts."""

from __future__ import annotations

import re
import shutil
import subprocess
from collections import Counter
from collections.abc import Sequence
from pathlib import Path

import pytest

from cantools_od.api import load
from cantools_od.identifiers import assign
from cantools_od.render.c import render
from cantools_od.views.codegen import DeviceView, build_view

import support

GOLDEN = Path(__file__).resolve().parent / "golden" / "c"
C_FLAGS = ["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"]
CXX_FLAGS = ["-std=c++11", "-Wall", "-Wextra", "-Werror", "-pedantic"]

ROOT = support.ROOT
EXAMPLES = support.EXAMPLES
cli_command = support.cli_command
corpus_file = support.corpus_file
corpus_files = support.corpus_files


def tool(name: str) -> str:
    """The path of a build tool; the test is skipped when it is not installed."""
    found = shutil.which(name)
    if found is None:
        pytest.skip(f"{name} is not installed")
    return found


def view_of(path: Path, name: str, node_id: int | None = None, can_fd: bool = False) -> DeviceView:
    device = load(path, node_id=node_id)
    return build_view(device, name, node_id, assign(device), max_pdo_bits=512 if can_fd else 64)


def generate(path: Path, name: str, node_id: int | None = None, can_fd: bool = False) -> dict[str, str]:
    """NAME.h and NAME.c for `path`, rendered in-process."""
    view = view_of(path, name, node_id, can_fd)
    assert not view.problems, [p.format() for p in view.problems]
    return render(view)


def write(folder: Path, files: dict[str, str]) -> None:
    folder.mkdir(parents=True, exist_ok=True)
    for filename, text in files.items():
        (folder / filename).write_text(text, encoding="utf-8")


def run(command: Sequence[str], cwd: Path, timeout: float = 300) -> subprocess.CompletedProcess[str]:
    return subprocess.run(list(command), cwd=cwd, capture_output=True, text=True, timeout=timeout)


def compile_checks(folder: Path, name: str) -> list[str]:
    """Compile NAME.c as C99 and NAME.h from C++11, warnings as errors; the complaints (and macros defined twice)."""
    (folder / f"{name}_cxx.cpp").write_text(f'#include "{name}.h"\n', encoding="utf-8")
    macros = re.findall(r"^#define (\w+)", (folder / f"{name}.h").read_text("utf-8"), re.MULTILINE)
    twice = sorted(m for m, n in Counter(macros).items() if n > 1)
    problems = [f"{name}.h defines {', '.join(twice)} more than once"] if twice else []
    for command in (
        ["gcc", *C_FLAGS, "-c", f"{name}.c", "-o", f"{name}.o"],
        ["g++", *CXX_FLAGS, "-c", f"{name}_cxx.cpp", "-o", f"{name}_cxx.o"],
    ):
        result = run(command, folder)
        if result.returncode != 0:
            problems.append(f"{' '.join(command)}:\n{result.stderr[:3000]}")
    return problems


# A crafted EDS with what the real files rarely have: bit-wise mappings at odd offsets, 24/40/48/56-bit
# types, REAL32/64, an object mapped twice, dummy entries, a CAN FD PDO, limits, strings and names that
# try to break out of comments and string literals.

# index: (ParameterName, DataType, DefaultValue, extra keys)
ODD_VARS: dict[int, tuple[str, int, str, dict[str, str]]] = {
    0x2001: ("Flag A", 0x0001, "1", {}),
    0x2002: ("Int24 value", 0x0010, "-5", {}),
    0x2003: ("Uns40 value", 0x0018, "0x123456789A", {}),
    0x2004: ("Int48 value", 0x0013, "-140737488355328", {}),
    0x2005: ("Real32 value", 0x0008, "1.5", {"LowLimit": "-2.5", "HighLimit": "100.25"}),
    0x2006: ("Int8 value", 0x0002, "-128", {}),
    0x2007: ("Uns56 value", 0x001A, "0xFFFFFFFFFFFFFF", {}),
    0x2008: ("Real64 value", 0x0011, "-0.1", {}),
    0x2009: ("Int64 value", 0x0015, "-9223372036854775808", {}),
    0x200A: ("Uns64 value", 0x001B, "0xFFFFFFFFFFFFFFFF", {}),
    0x200B: ("Uns24 value", 0x0016, "0xABCDEF", {}),
    0x200C: ("Int40 value", 0x0012, "-1", {}),
    0x200D: ("Uns48 value", 0x0019, "0", {}),
    0x200E: ("Limited int16", 0x0003, "0", {"LowLimit": "-100", "HighLimit": "100"}),
    0x200F: ("Limited uns8", 0x0005, "1", {"LowLimit": "1", "HighLimit": "200"}),
    0x2010: ("Int56 value", 0x0014, "36028797018963967", {}),
    0x2011: ("Flag B", 0x0001, "0", {}),
    0x2012: ("Int32 value", 0x0004, "-2147483648", {"LowLimit": "-2147483648", "HighLimit": "2147483647"}),
    0x2013: ("Backwards limits", 0x0005, "5", {"LowLimit": "10", "HighLimit": "5"}),
    0x2014: ("Uns32 value", 0x0007, "$NODEID+0x40", {}),
    0x2015: ("Int16 value", 0x0003, "-32768", {}),
    # not mappable, for the object part of the header
    0x2100: ('Name */ with "quotes" \\ and ??= trigraph /* x', 0x0009, 'He said "hi" */ \\ ??= \t', {}),
    0x2101: ("Octets", 0x000A, "00FF10", {}),
    0x2102: ("Unicode text", 0x000B, "A\u00e9\u20ac", {}),
    0x2103: ("A domain", 0x000F, "", {}),
    0x2104: ("Time of day", 0x000C, "0", {}),
    0x2105: ("Huge real64", 0x0011, "1e300", {}),
    0x2107: ("Not a number", 0x0008, "nan", {}),
    0x2106: ("Empty string", 0x0009, "", {}),
}

# (direction, number) → [(index, sub-index, bits)], packed in this order
ODD_PDOS: dict[tuple[str, int], list[tuple[int, int, int]]] = {
    ("tx", 1): [(0x2001, 0, 1), (0x2004, 0, 48), (0x2006, 0, 8), (0x2001, 0, 1)],
    ("tx", 2): [(0x2002, 0, 24), (0x2003, 0, 40)],
    ("tx", 3): [(0x2011, 0, 1), (0x2005, 0, 32), (0x200B, 0, 24), (0x2001, 0, 1)],
    ("tx", 4): [(0x2008, 0, 64)],
    ("tx", 5): [(0x200E, 0, 16), (0x200F, 0, 8), (0x2012, 0, 32), (0x2013, 0, 8)],
    ("rx", 1): [(0x2001, 0, 1), (0x0001, 0, 1), (0x2011, 0, 1), (0x200C, 0, 40), (0x0005, 0, 8), (0x2006, 0, 8)],
    ("rx", 2): [(0x2009, 0, 64)],
    ("rx", 3): [(0x2007, 0, 56), (0x2006, 0, 8)],
    ("rx", 4): [(0x2011, 0, 1), (0x2001, 0, 1), (0x2011, 0, 1), (0x200D, 0, 48), (0x2014, 0, 32), (0x2015, 0, 16)],
    ("rx", 5): [(0x200A, 0, 64), (0x2010, 0, 56), (0x2005, 0, 32), (0x2002, 0, 24), (0x2008, 0, 64)],
}
CAN_FD_PDOS = {("rx", 4), ("rx", 5)}  # longer than 64 bits


def _section(name: str, keys: dict[str, str]) -> str:
    return f"[{name}]\n" + "".join(f"{key}={value}\n" for key, value in keys.items()) + "\n"


def _var(name: str, dtype: int, default: str, access: str = "rw", mappable: bool = False) -> dict[str, str]:
    keys = {"ParameterName": name, "ObjectType": "0x7", "DataType": f"0x{dtype:04X}", "AccessType": access}
    if default != "" or dtype in (0x0009, 0x000A):
        keys["DefaultValue"] = default
    keys["PDOMapping"] = "1" if mappable else "0"
    return keys


def odd_eds() -> str:
    """The crafted EDS (see ODD_VARS and ODD_PDOS)."""
    out = ["[FileInfo]\nFileName=odd_bits.eds\nFileVersion=1\nFileRevision=0\nEDSVersion=4.0\n\n"]
    out.append(
        "[DeviceInfo]\nVendorName=cantools-od tests\nProductName=Odd bits */ device\nGranularity=1\n"
        f"NrOfRXPDO={sum(d == 'rx' for d, _ in ODD_PDOS)}\nNrOfTXPDO={sum(d == 'tx' for d, _ in ODD_PDOS)}\n\n"
    )
    out.append(_section("DummyUsage", {f"Dummy000{i}": "1" for i in range(1, 8)}))
    out.append(_section("1000", _var("Device type", 0x0007, "0", "ro")))
    out.append(_section("1001", _var("Error register", 0x0005, "0", "ro")))
    for (direction, number), entries in sorted(ODD_PDOS.items()):
        comm = (0x1400 if direction == "rx" else 0x1800) + number - 1
        cob = {"rx": 0x200, "tx": 0x180}[direction] + 0x100 * ((number - 1) % 4)
        out.append(_section(f"{comm:04X}", {"ParameterName": f"{direction} comm {number}", "ObjectType": "0x9"}))
        out.append(_section(f"{comm:04X}sub0", _var("Highest sub-index", 0x0005, "2", "ro")))
        cob_text = f"$NODEID+0x{cob:X}" if number <= 4 else f"0x{0x80000000 | (0x480 + number):X}"
        out.append(_section(f"{comm:04X}sub1", _var("COB-ID", 0x0007, cob_text)))
        out.append(_section(f"{comm:04X}sub2", _var("Transmission type", 0x0005, "255")))
        mapping = comm + 0x200
        out.append(_section(f"{mapping:04X}", {"ParameterName": f"{direction} map {number}", "ObjectType": "0x9"}))
        out.append(_section(f"{mapping:04X}sub0", _var("Number of entries", 0x0005, str(len(entries)))))
        for sub, (index, subindex, bits) in enumerate(entries, 1):
            value = f"0x{index:04X}{subindex:02X}{bits:02X}"
            out.append(_section(f"{mapping:04X}sub{sub:X}", _var(f"Entry {sub}", 0x0007, value)))
    for index, (name, dtype, default, extra) in sorted(ODD_VARS.items()):
        keys = _var(name, dtype, default, mappable=index < 0x2100)
        out.append(_section(f"{index:04X}", keys | extra))
    return "".join(out)


def write_odd_eds(folder: Path) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / "odd_bits.eds"
    path.write_text(odd_eds(), encoding="utf-8")
    return path
