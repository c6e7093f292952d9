"""What the Rust target's tests share: generation, crafted EDS files, and cargo, rustc, rustfmt and clippy.

The toolchain is found on PATH (rustup's `~/.cargo/bin` too). Tests skip with the reason when a tool or
component is missing; nothing is downloaded: the test crates have no dependencies and build offline.
"""

from __future__ import annotations

import functools
import math
import os
import random
import shutil
import struct
import subprocess
import tempfile
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path

import canopen
import pytest

from cantools_od.api import load
from cantools_od.render import renderer
from cantools_od.render.rust_pdo import RustPdo
from cantools_od.views.codegen import DeviceView, build_view

from support import EXAMPLES

__all__ = [
    "EXAMPLES",
    "Record",
    "cargo",
    "eds_text",
    "has_tool",
    "render_rust",
    "require",
    "run",
    "rustfmt_check",
    "var",
    "write_crate",
]

# A guard against a hung compiler, not a speed limit: the corpus crate takes about 2 min of CPU, several times
# that on a machine busy with other work (600 s was exceeded at a load of 14).
TIMEOUT = 1800


def _search_path() -> str:
    cargo_bin = Path.home() / ".cargo" / "bin"
    return os.pathsep.join([os.environ.get("PATH", ""), str(cargo_bin)])


@functools.cache
def find_tool(name: str) -> str | None:
    return shutil.which(name, path=_search_path())


@functools.cache
def _works(*command: str) -> bool:
    """Whether `command` (e.g. `cargo clippy --version`) runs: rustup installs components separately."""
    if find_tool(command[0]) is None:
        return False
    try:
        result = subprocess.run(command, capture_output=True, text=True, timeout=60, env=_env())
    except (OSError, subprocess.TimeoutExpired):
        return False
    return result.returncode == 0


_PROBES = {
    "cargo": ("cargo", "--version"),
    "rustc": ("rustc", "--version"),
    "rustfmt": ("rustfmt", "--version"),
    "clippy": ("cargo", "clippy", "--version"),
    "clippy-driver": ("clippy-driver", "--version"),
}


def has_tool(component: str) -> bool:
    """Whether `component` (one of `cargo`, `rustc`, `rustfmt`, `clippy`, `clippy-driver`) is installed and runs."""
    return _works(*_PROBES[component])


def require(*components: str) -> None:
    """Skip the test unless every one of `cargo`, `rustc`, `rustfmt`, `clippy` is installed."""
    for component in components:
        if not has_tool(component):
            pytest.skip(
                f"{component} is not installed (rustup component add {component.split('-')[0]} needs the network)"
            )


def target_dir() -> Path:
    """One CARGO_TARGET_DIR for every test crate, kept between runs so that rebuilds are incremental."""
    configured = os.environ.get("CANTOOLS_OD_CARGO_TARGET")
    user = getattr(os, "getuid", lambda: 0)()
    path = Path(configured) if configured else Path(tempfile.gettempdir()) / f"cantools-od-cargo-{user}"
    path.mkdir(parents=True, exist_ok=True)
    return path


def _env() -> dict[str, str]:
    env = dict(os.environ, PATH=_search_path(), CARGO_TERM_COLOR="never", CARGO_NET_OFFLINE="true")
    env.pop("RUSTFLAGS", None)
    return env


def run(command: Sequence[str], cwd: Path, timeout: float = TIMEOUT) -> subprocess.CompletedProcess[str]:
    return subprocess.run(list(command), cwd=cwd, capture_output=True, text=True, timeout=timeout, env=_env())


# The dev and test profiles as cargo has them (overflow checks and debug assertions on), without debug info and
# incremental state, which no test reads: they cost most of a build of the generated modules' large tables.
_PROFILE = {"CARGO_PROFILE_DEV_DEBUG": "0", "CARGO_PROFILE_TEST_DEBUG": "0", "CARGO_INCREMENTAL": "0"}


def cargo(crate: Path, *args: str, env: Mapping[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    env = _env() | _PROFILE | {"CARGO_TARGET_DIR": str(target_dir())} | dict(env or {})
    command = [find_tool("cargo") or "cargo", "--offline", *args]
    return subprocess.run(command, cwd=crate, capture_output=True, text=True, timeout=TIMEOUT, env=env)


def rustfmt_check(files: Sequence[Path]) -> subprocess.CompletedProcess[str]:
    command = [find_tool("rustfmt") or "rustfmt", "--edition", "2021", "--check", *map(str, files)]
    return run(command, Path(files[0]).parent)


def render_rust(eds: Path, name: str, node_id: int | None = None, can_fd: bool = False) -> tuple[DeviceView, str]:
    """The view and the generated module of `eds`, as `cantools-od gen -t rust` makes them."""
    view = build_view(load(str(eds), node_id=node_id), name, node_id, max_pdo_bits=512 if can_fd else 64)
    assert not view.problems, [p.message for p in view.problems]
    files = renderer("rust")(view)
    assert list(files) == [f"{name}.rs"]
    return view, files[f"{name}.rs"]


def write_crate(folder: Path, name: str, modules: Mapping[str, str], tests: Mapping[str, str]) -> Path:
    """A library crate: `#![no_std]` lib.rs with a `pub mod` per module, integration tests in tests/."""
    (folder / "src").mkdir(parents=True, exist_ok=True)
    (folder / "tests").mkdir(exist_ok=True)
    manifest = f'[package]\nname = "{name}"\nversion = "0.1.0"\nedition = "2021"\npublish = false\n\n[dependencies]\n'
    (folder / "Cargo.toml").write_text(manifest, encoding="utf-8")
    lib = "#![no_std]\n#![deny(warnings)]\n\n" + "".join(f"pub mod {module};\n" for module in sorted(modules))
    (folder / "src" / "lib.rs").write_text(lib, encoding="utf-8")
    for module, text in modules.items():
        (folder / "src" / f"{module}.rs").write_text(text, encoding="utf-8")
    for test, text in tests.items():
        (folder / "tests" / f"{test}.rs").write_text(text, encoding="utf-8")
    return folder


# --- crafted EDS files -------------------------------------------------------------------------------

Keys = dict[str, str]


@dataclass(frozen=True)
class Record:
    """A RECORD (or ARRAY with kind "0x8"): its sub-objects from sub-index 0."""

    name: str
    subs: list[Keys]
    kind: str = "0x9"


def var(
    name: str, data_type: int, default: str | None, access: str = "rw", mappable: bool = True, **extra: str
) -> Keys:
    keys = {"ParameterName": name, "ObjectType": "0x7", "DataType": f"0x{data_type:04X}", "AccessType": access}
    if default is not None:
        keys["DefaultValue"] = default
    return keys | {"PDOMapping": "1" if mappable else "0"} | extra


PdoLayout = Mapping[tuple[str, int], Sequence[tuple[int, int, int]]]


def eds_text(file_name: str, objects: Mapping[int, Keys | Record], pdos: PdoLayout, product: str) -> str:
    """An EDS with `objects` and PDOs: ("rx"/"tx", number) → (index, sub-index, bits) entries, COB-IDs `$NODEID+...`."""
    sections: dict[str, Keys] = {
        "FileInfo": {"FileName": file_name, "FileVersion": "1", "FileRevision": "0", "EDSVersion": "4.0"},
        "DeviceInfo": {
            "VendorName": "cantools-od tests",
            "ProductName": product,
            "Granularity": "1",
            "NrOfRXPDO": str(sum(d == "rx" for d, _ in pdos)),
            "NrOfTXPDO": str(sum(d == "tx" for d, _ in pdos)),
        },
        "DummyUsage": {f"Dummy000{i}": "1" for i in range(1, 8)},
        "1000": var("Device type", 0x0007, "0", "ro", False),
        "1001": var("Error register", 0x0005, "0", "ro", False),
    }
    records: dict[int, Keys | Record] = {}
    for (direction, number), entries in pdos.items():
        comm = (0x1400 if direction == "rx" else 0x1800) + number - 1
        cob = (0x200 if direction == "rx" else 0x180) + 0x100 * ((number - 1) % 4)
        records[comm] = Record(
            f"{direction} comm {number}",
            [
                var("Highest sub-index", 0x0005, "2", "ro", False),
                var("COB-ID", 0x0007, f"$NODEID+0x{cob:X}", mappable=False),
                var("Transmission type", 0x0005, "255", mappable=False),
            ],
        )
        subs = [var("Number of entries", 0x0005, str(len(entries)), mappable=False)]
        subs += [
            var(f"Entry {k}", 0x0007, f"0x{i:04X}{s:02X}{b:02X}", mappable=False)
            for k, (i, s, b) in enumerate(entries, 1)
        ]
        records[comm + 0x200] = Record(f"{direction} map {number}", subs)
    for index, keys in sorted((records | dict(objects)).items()):
        if isinstance(keys, dict):
            sections[f"{index:04X}"] = keys
            continue
        sections[f"{index:04X}"] = {
            "ParameterName": keys.name,
            "ObjectType": keys.kind,
            "SubNumber": str(len(keys.subs)),
        }
        for sub, sub_keys in enumerate(keys.subs):
            sections[f"{index:04X}sub{sub:X}"] = sub_keys
    return "".join(
        f"[{title}]\n" + "".join(f"{k}={v}\n" for k, v in keys.items()) + "\n" for title, keys in sections.items()
    )


# --- PDO cases: values, reference bytes, python-canopen's bytes, and Rust tests that check them ----------


@dataclass(frozen=True)
class Field:
    name: str  # the Rust struct field
    ty: str  # bool, u8..u64, i8..i64, f32, f64
    offset: int
    bits: int
    index: int
    subindex: int

    @property
    def signed(self) -> bool:
        return self.ty.startswith("i")

    def raw(self, value: object) -> int:
        """The field's bits in the payload."""
        if self.ty.startswith("f"):
            assert isinstance(value, float)
            return int.from_bytes(struct.pack("<f" if self.ty == "f32" else "<d", value), "little")
        assert isinstance(value, (bool, int))
        return int(value) & ((1 << self.bits) - 1)

    def decode(self, payload: int) -> object:
        raw = (payload >> self.offset) & ((1 << self.bits) - 1)
        if self.ty == "bool":
            return bool(raw)
        if self.ty.startswith("f"):
            return struct.unpack("<f" if self.ty == "f32" else "<d", raw.to_bytes(self.bits // 8, "little"))[0]
        return raw - (1 << self.bits) if self.signed and raw >> (self.bits - 1) else raw

    def random(self, rng: random.Random, case: int) -> object:
        if self.ty == "bool":
            return case % 2 == 1 if case < 2 else rng.random() < 0.5
        if self.ty.startswith("f"):
            fmt = "<f" if self.ty == "f32" else "<d"
            largest = struct.unpack(fmt, b"\xff\xff\x7f\x7f" if fmt == "<f" else b"\xff" * 6 + b"\xef\x7f")[0]
            extremes = [0.0, -0.0, 1.0, -1.5, largest, math.inf, -math.inf, 5e-324 if fmt == "<d" else 1e-45]
            if case < len(extremes):
                return float(extremes[case])
            while True:  # any finite value, NaN excepted: the struct's PartialEq compares the round trip
                value: float = struct.unpack(fmt, rng.randbytes(self.bits // 8))[0]
                if math.isfinite(value):
                    return value
        low, high = (-(1 << (self.bits - 1)), (1 << (self.bits - 1)) - 1) if self.signed else (0, (1 << self.bits) - 1)
        extremes_int = [low, high, 0, 1, -1 if self.signed else high - 1]
        return extremes_int[case] if case < len(extremes_int) else rng.randint(low, high)

    def rust(self, value: object) -> str:
        if self.ty == "bool":
            return "true" if value else "false"
        if self.ty.startswith("f"):
            return f"{self.ty}::from_bits(0x{self.raw(value):X})"
        assert isinstance(value, int)
        container = int(self.ty[1:])
        return f"{self.ty}::MIN" if self.signed and value == -(1 << (container - 1)) else str(value)


def fields(pdo: RustPdo) -> list[Field]:
    return [Field(f.name, f.ty, f.offset, f.bits, f.index, f.subindex) for f in pdo.fields]


def reference_pack(pdo: RustPdo, row: Sequence[object]) -> bytes:
    """The payload by the rule of pdo-rules.md §6: LSB first from bit 0, each value little-endian."""
    payload = 0
    for field, value in zip(fields(pdo), row, strict=True):
        payload |= field.raw(value) << field.offset
    return payload.to_bytes(pdo.length, "little")


def canopen_handles(field: Field) -> bool:
    """python-canopen encodes byte-aligned values, and BOOLEANs anywhere; other bit offsets it truncates."""
    return field.ty == "bool" or (field.offset % 8 == 0 and field.bits % 8 == 0)


def canopen_pack(eds: Path, node_id: int, pdo: RustPdo, rows: Sequence[Sequence[object]]) -> list[bytes] | None:
    """python-canopen's payloads of `rows`; None when it cannot encode every field of the PDO."""
    if not all(canopen_handles(f) for f in fields(pdo)):
        return None
    node = canopen.RemoteNode(node_id, canopen.import_od(str(eds), node_id))
    canopen.Network().add_node(node)  # PDO maps subscribe to a network; no bus is needed
    maps = node.rpdo if pdo.view.pdo.direction == "rx" else node.tpdo
    maps.read(from_od=True)
    (their,) = [m for m in maps.map.values() if m.map_array.od.index == pdo.view.pdo.map_index]
    variables = [v for v in their.map if v.index >= 0x1000]
    assert [(v.index, v.subindex, v.offset) for v in variables] == [
        (f.index, f.subindex, f.offset) for f in fields(pdo)
    ]
    out = []
    for row in rows:
        their.data = bytearray(pdo.length)
        for variable, value in zip(variables, row, strict=True):
            variable.raw = value
        out.append(bytes(their.data))
    return out


def _bytes(data: bytes) -> str:
    return "[" + ", ".join(f"0x{b:02X}" for b in data) + "]"


def rust_pdo_test(
    module: str, pdo: RustPdo, rows: Sequence[Sequence[object]], packed: Sequence[bytes], frames: Sequence[bytes]
) -> str:
    """A `#[test]` that packs `rows` into the bytes `packed`, unpacks them back, and unpacks `frames`."""
    struct_, length, fs = f"{module}::{pdo.name}", pdo.length, fields(pdo)

    def literal(row: Sequence[object]) -> str:
        return struct_ + " {" + ", ".join(f"{f.name}: {f.rust(v)}" for f, v in zip(fs, row, strict=True)) + "}"

    cases = ",\n".join(f"        ({literal(row)}, {_bytes(data)})" for row, data in zip(rows, packed, strict=True))
    decoded = [[f.decode(int.from_bytes(frame, "little")) for f in fs] for frame in frames]
    expected = ",\n".join(
        f"        ({_bytes(frame)}, {literal(row)})" for frame, row in zip(frames, decoded, strict=True)
    )
    compare = [f"assert_eq!(got.{f.name}{'.to_bits()' * f.ty.startswith('f')}, "
               f"want.{f.name}{'.to_bits()' * f.ty.startswith('f')});" for f in fs]  # fmt: skip
    lines = [
        "#[test]",
        f"fn {module}_{pdo.func}() {{",
        f"    let cases: [({struct_}, [u8; {length}]); {len(rows)}] = [\n{cases}\n    ];",
        "    for (value, bytes) in cases {",
        f"        let mut buf = [0xA5u8; {length + 2}];",
        f"        assert_eq!(value.pack(&mut buf), Ok({length}));",
        f"        assert_eq!(buf[..{length}], bytes);",
        f"        assert_eq!(buf[{length}..], [0xA5, 0xA5]);",
        f"        assert_eq!({struct_}::unpack(&buf), Ok(value));",
        "    }",
        f"    let frames: [([u8; {length}], {struct_}); {len(frames)}] = [\n{expected}\n    ];",
        f"    for (bytes, {'want' if fs else '_'}) in frames {{",
        f"        let {'got' if fs else '_'} = {struct_}::unpack(&bytes).unwrap();",
        *[f"        {line}" for line in compare],
        "    }",
    ]
    if length:
        error = f"{module}::PdoError"
        lines += [
            f"    let short = [0u8; {length - 1}];",
            f"    assert_eq!({struct_}::default().pack(&mut [0u8; {length - 1}]), "
            f"Err({error}::BufferTooSmall {{ needed: {length}, len: {length - 1} }}));",
            f"    assert_eq!({struct_}::unpack(&short), "
            f"Err({error}::TooShort {{ needed: {length}, len: {length - 1} }}));",
        ]
    return "\n".join([*lines, "}", ""])


def pdo_cases(pdo: RustPdo, rng: random.Random, count: int) -> tuple[list[list[object]], list[bytes]]:
    """`count` rows of values (extremes first) and `count` random frames."""
    fs = fields(pdo)
    rows = [[f.random(rng, case) for f in fs] for case in range(count)]
    return rows, [rng.randbytes(pdo.length) for _ in range(count)]
