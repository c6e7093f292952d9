"""The pieces of the Rust target: names, literals and rustfmt's layout, checked by rustc, clippy and rustfmt
on many generated cases (far more than the example files hold)."""

from __future__ import annotations

import math
import random
import struct
from pathlib import Path

import pytest
from rustkit import find_tool, require, run, rustfmt_check

from cantools_od.model import STANDARD_TYPES, ValueKind
from cantools_od.render import rust_layout as layout
from cantools_od.render.rust_names import TypeNames, camel, unique_fields
from cantools_od.render.rust_types import byte_string, float_literal, int_literal, node_expr, rust_type

INTEGER_TYPES = [t for t in STANDARD_TYPES.values() if t.is_integer]


def test_camel_case_and_unique_type_names() -> None:
    assert camel("read_input_8_bit") == "ReadInput8Bit"
    assert camel("foo_1_2") == "Foo1_2" and camel("foo_12") == "Foo12" and camel("type_") == "Type"
    names = TypeNames(["Tpdo1"])
    claimed = [
        names.claim(i, index) for index, i in enumerate(["tpdo1", "result", "self_", "foo1_2", "foo_1_2"], 0x2000)
    ]
    assert claimed == ["Tpdo1At2000", "ResultAt2001", "SelfAt2002", "Foo1_2", "Foo1_2At2004"]


def test_pdo_field_names_are_unique() -> None:
    assert unique_fields(["a", "b", "a", "a_2", "a"]) == ["a", "b", "a_3", "a_2", "a_4"]
    assert unique_fields(["type_", "type_"]) == ["type_", "type_2"]


def test_literals() -> None:
    u8, i8, i24, u32, u64 = (STANDARD_TYPES[i] for i in (0x05, 0x02, 0x10, 0x07, 0x1B))
    assert [int_literal(v, u8) for v in (0, 255, 256, -1)] == ["0", "255", None, None]
    assert [int_literal(v, i8) for v in (-128, 127, -129)] == ["i8::MIN", "127", None]
    assert int_literal(-(1 << 23), i24) == "-8388608"  # an INTEGER24 lives in an i32: not i32::MIN
    assert int_literal(0x180, u32) == "0x00000180" and int_literal(1 << 64, u64) is None
    assert float_literal(1.0, 32) == "1.0_f32" and float_literal(0.1, 32) == "0.1_f32"
    assert float_literal(1e20, 64) == "1.0e20_f64" and float_literal(-2.5e-7, 64) == "-2.5e-7_f64"
    assert float_literal(1e40, 32) == "f32::INFINITY" and float_literal(-math.inf, 64) == "f64::NEG_INFINITY"
    assert float_literal(math.nan, 32) == "f32::NAN" and float_literal(-0.0, 32) == "-0.0_f32"
    assert float_literal(3.14159265, 32) == "f32::from_bits(0x40490FDB)"  # clippy::approx_constant
    assert byte_string(b'a"\\\x00\xff') == 'b"a\\"\\\\\\x00\\xFF"'
    assert node_expr("u8", 0x40) == "node_id + 0x40" and node_expr("u32", 0) == "node_id as u32"
    assert node_expr("u16", 0xFFF0) == "(node_id as u16).wrapping_add(0xFFF0)"


def _random_float(rng: random.Random, bits: int) -> float:
    fmt = "<f" if bits == 32 else "<d"
    if rng.random() < 0.5:
        return float(struct.unpack(fmt, rng.randbytes(bits // 8))[0])
    return rng.choice([1, -1]) * rng.random() * 10.0 ** rng.randint(-40, 40)


def literal_crate(rng: random.Random) -> str:
    """Constants of every literal kind with `const` assertions that they hold the exact value."""
    lines = ["#![no_std]", ""]
    constants = [math.e, 1 / math.pi, math.sqrt(0.5), math.pi / 2, math.log(2), math.log10(math.e), math.pi, math.tau]
    floats = [(round(c, digits), bits) for c in constants for digits in range(1, 12) for bits in (32, 64)]
    floats += [(_random_float(rng, bits), bits) for _ in range(600) for bits in (32, 64)]
    for k, (value, bits) in enumerate(floats):
        if not math.isfinite(value):
            continue
        text = float_literal(value, bits)
        try:
            raw = struct.pack("<f" if bits == 32 else "<d", value)
        except OverflowError:
            raw = struct.pack("<f", math.copysign(math.inf, value))
        lines.append(f"pub const F{k}: f{bits} = {text};")
        lines.append(f"const _: () = assert!(F{k}.to_bits() == 0x{int.from_bytes(raw, 'little'):X});")
    for k, dtype in enumerate(INTEGER_TYPES * 40):
        low, high = dtype.int_range() or (0, 0)
        value = [low, high, 0][k // len(INTEGER_TYPES)] if k < 3 * len(INTEGER_TYPES) else rng.randint(low, high)
        ty = rust_type(dtype)
        lines.append(f"pub const I{k}: {ty} = {int_literal(value, dtype)};")
        lines.append(f"const _: () = assert!(I{k} as i128 == {value});")
    offsets = (0, 1, 0x40, 0x7F, 0x80, 0xFFF0, -5, 0x80000180, -(1 << 40))
    types = ("u8", "u16", "u32", "u64", "i8", "i16", "i32", "i64")
    for k, (ty, offset) in enumerate((t, o) for t in types for o in offsets):
        bits = int(ty[1:])
        lines.append(f"pub const fn n{k}(node_id: u8) -> {ty} {{\n    {node_expr(ty, offset)}\n}}")
        for node in (1, 127):
            wrapped = (node + offset) % (1 << bits)
            if ty.startswith("i") and wrapped >= 1 << (bits - 1):
                wrapped -= 1 << bits
            lines.append(f"const _: () = assert!(n{k}({node}) as i128 == {wrapped});")
    return "\n".join(lines) + "\n"


def test_literals_compile_exactly_and_clippy_clean(tmp_path: Path) -> None:
    require("rustc")
    (tmp_path / "literals.rs").write_text(literal_crate(random.Random(4242)), encoding="utf-8")
    driver = "clippy-driver" if find_tool("clippy-driver") else "rustc"
    require(driver)
    command = [find_tool(driver) or driver, "--edition", "2021", "--crate-type", "lib", "-D", "warnings"]
    result = run([*command, "--emit", "metadata", "literals.rs"], tmp_path)
    assert result.returncode == 0, result.stderr[-6000:]


def layout_cases() -> str:
    """Every construct `rust_layout` lays out, with names from 1 to 170 characters."""
    cases = []
    for n in range(1, 171):
        name, field = "A" * n, "f" * n
        for ty, rhs in (("u8", "0"), ("DataType", "DataType::UNSIGNED32"), ("&str", '"text"'), ("&[u8]", 'b"\\x01"')):
            cases.append(layout.item("", "pub const", f"{name}_X", ty, rhs))
        block = "\n    let mut value = [0; 4];\n    value[1] = 5;\n    value\n};"
        cases.append(layout.item("", "pub const", name, "T" + "t" * (n // 2), "{") + block)
        cases.append(
            layout.fn_head("", "pub fn", f"{field}_is_in_range", ["value: u32"], "bool") + "\n    value > 1\n}"
        )
        call = layout.call("        ", "put", ["dst", "16", "32", f"self.{field}"])
        cases.append(f"fn g() {{\n    {{\n{call}\n    }}\n}}")
        inits = [
            layout.field_init("        ", field, '"text"'),
            layout.field_call("        ", field, "get", ["src", "0", "8"]),
        ]
        cases.append("fn h() -> X {\n    X {\n" + "\n".join(inits) + "\n    }\n}")
        cases.append(layout.struct_open("S" + "s" * n) + "\n" + layout.field_decl("    ", field, "[u8; 10]") + "\n}")
        cases.append(layout.impl_open("S" + "s" * n) + "\n    pub const A: u8 = 0;\n}")
        cases.append(
            layout.impl_open("S" + "s" * n, "Default") + "\n    fn default() -> Self {\n        Self::A\n    }\n}"
        )
        cases.append(layout.type_alias("T" + "t" * n, "[u32; 4]"))
    return "\n\n".join(cases) + "\n"


def test_layout_is_rustfmts(tmp_path: Path) -> None:
    require("rustfmt")
    path = tmp_path / "layout.rs"
    path.write_text(layout_cases(), encoding="utf-8")
    result = rustfmt_check([path])
    assert result.returncode == 0, result.stdout[-6000:]


@pytest.mark.parametrize("kind", [ValueKind.UNSIGNED, ValueKind.SIGNED])
def test_integer_types_have_rust_types(kind: ValueKind) -> None:
    types = {t.name: rust_type(t) for t in INTEGER_TYPES if t.kind is kind}
    prefix = "u" if kind is ValueKind.UNSIGNED else "i"
    names = "UNSIGNED" if kind is ValueKind.UNSIGNED else "INTEGER"
    assert types == {
        f"{names}{b}": f"{prefix}{c}"
        for b, c in ((8, 8), (16, 16), (24, 32), (32, 32), (40, 64), (48, 64), (56, 64), (64, 64))
    }
