"""Generated PDO pack/unpack functions, run in C: round trips of random values, and the bytes
equal python-canopen's encoding of the same values (a bit-level reference where it has none)."""

from __future__ import annotations

import random
import struct
from dataclasses import dataclass
from pathlib import Path

import canopen
import pytest
from ckit import C_FLAGS, EXAMPLES, corpus_file, run, tool, view_of, write, write_odd_eds

from cantools_od.model import ValueKind
from cantools_od.render.c import render
from cantools_od.render.c_pdo import member_names
from cantools_od.render.c_types import real_literal, scalar_type, typed_integer
from cantools_od.views.codegen import DeviceView, PdoEntryView, PdoView

CASES_PER_PDO = 24
SEED = 20250115
NODE_ID = 5


@dataclass(frozen=True)
class Field:
    member: str
    entry: PdoEntryView

    @property
    def kind(self) -> ValueKind:
        assert self.entry.data_type is not None
        return self.entry.data_type.kind

    @property
    def bits(self) -> int:
        return self.entry.bit_length

    @property
    def ctype(self) -> str:
        return scalar_type(self.entry.data_type) or "?"

    def c_value(self, value: object) -> str:
        if self.kind is ValueKind.BOOL:
            return "true" if value else "false"
        if self.kind is ValueKind.REAL:
            assert isinstance(value, float)
            text = real_literal(value, self.bits)
            assert text is not None
            return text
        assert isinstance(value, int)
        return typed_integer(value, self.ctype)

    def raw(self, value: object) -> int:
        """The field's bits in the payload."""
        if self.kind is ValueKind.REAL:
            assert isinstance(value, float)
            return int.from_bytes(struct.pack("<f" if self.bits == 32 else "<d", value), "little")
        assert isinstance(value, (bool, int))
        return int(value) & ((1 << self.bits) - 1)

    def decode(self, raw: int) -> object:
        raw &= (1 << self.bits) - 1
        if self.kind is ValueKind.BOOL:
            return bool(raw)
        if self.kind is ValueKind.REAL:
            return raw  # compared as IEEE bits: NaN payloads and -0.0 included
        if self.kind is ValueKind.SIGNED and raw >> (self.bits - 1):
            return raw - (1 << self.bits)
        return raw

    def printed(self, text: str) -> object:
        if self.kind is ValueKind.BOOL:
            return text == "1"
        if self.kind is ValueKind.REAL:
            return int(text, 16)
        return int(text)

    def random(self, rng: random.Random, case: int) -> object:
        if self.kind is ValueKind.BOOL:
            return bool(case % 2) if case < 2 else rng.random() < 0.5
        if self.kind is ValueKind.REAL:
            fmt, size = ("<f", 4) if self.bits == 32 else ("<d", 8)
            extremes = [
                0.0,
                -0.0,
                1.0,
                -1.5,
                struct.unpack(fmt, b"\xff\xff\x7f\x7f" if size == 4 else bytes(6) + b"\xef\x7f")[0],
            ]
            if case < len(extremes):
                return float(extremes[case])
            while True:
                value: float = struct.unpack(fmt, rng.randbytes(size))[0]
                if value == value and abs(value) != float("inf") and real_literal(value, self.bits) is not None:
                    return value
        assert self.entry.data_type is not None
        low, high = self.entry.data_type.int_range() or (0, 0)
        extremes_int = [low, high, 0, min(high, 1), max(low, -1)]
        return extremes_int[case] if case < len(extremes_int) else rng.randint(low, high)


def fields_of(pdo: PdoView) -> list[Field]:
    return [Field(member, entry) for member, entry in zip(member_names(pdo), pdo.fields, strict=True)]


def reference_pack(pdo: PdoView, values: list[object]) -> bytes:
    payload = 0
    for field, value in zip(fields_of(pdo), values, strict=True):
        payload |= field.raw(value) << field.entry.bit_offset
    return payload.to_bytes(pdo.byte_length, "little")


def canopen_supported(field: Field) -> bool:
    """python-canopen encodes a value that is byte-aligned, or (unsigned, boolean) fits in its type's bytes."""
    entry = field.entry
    if entry.bit_offset % 8 == 0 and entry.bit_length % 8 == 0:
        return True
    window = 8 if field.kind is ValueKind.BOOL else entry.bit_length
    return field.kind in (ValueKind.BOOL, ValueKind.UNSIGNED) and entry.bit_offset % 8 + entry.bit_length <= window


def canopen_pack(eds: Path, pdos: list[PdoView], values: dict[str, list[list[object]]]) -> dict[tuple[str, int], bytes]:
    """python-canopen's payload for (struct, case), for the PDOs whose layout it supports."""
    node = canopen.RemoteNode(NODE_ID, canopen.import_od(str(eds), NODE_ID))
    canopen.Network().add_node(node)  # PDO maps subscribe to a network; no bus is needed
    theirs: dict[int, canopen.pdo.base.PdoMap] = {}
    for maps in (node.rpdo, node.tpdo):
        maps.read(from_od=True)
        theirs.update({m.map_array.od.index: m for m in maps.map.values()})
    out: dict[tuple[str, int], bytes] = {}
    for pdo in pdos:
        if not all(canopen_supported(f) for f in fields_of(pdo)):
            continue
        their = theirs[pdo.pdo.map_index]
        variables = [v for v in their.map if v.index >= 0x1000]
        assert [(v.index, v.subindex, v.offset) for v in variables] == [
            (f.entry.entry.index, f.entry.entry.subindex, f.entry.bit_offset) for f in fields_of(pdo) if f.entry.entry
        ]
        for case, row in enumerate(values[pdo.struct_name]):
            their.data = bytearray(pdo.byte_length)
            for variable, value in zip(variables, row, strict=True):
                variable.raw = value
            out[(pdo.struct_name, case)] = bytes(their.data)
    return out


def harness(view: DeviceView, values: dict[str, list[list[object]]], frames: dict[str, list[bytes]]) -> str:
    name = view.name
    lines = [
        "#include <inttypes.h>",
        "#include <stdio.h>",
        "#include <string.h>",
        f'#include "{name}.h"',
        "",
        'void put_bytes(const uint8_t *b, int n) { int i; for (i = 0; i < n; ++i) printf("%02x", b[i]); }',
        'void put_f32(float v) { uint32_t b; memcpy(&b, &v, sizeof b); printf(" %08" PRIx32, b); }',
        'void put_f64(double v) { uint64_t b; memcpy(&b, &v, sizeof b); printf(" %016" PRIx64, b); }',
        "",
        "int main(void)",
        "{",
        "    uint8_t buf[80];",
        "    int n;",
    ]
    for pdo in view.pdos:
        fields = fields_of(pdo)
        if not fields:
            continue
        struct_ = f"{name}_{pdo.struct_name}"

        def show(var: str, fields: list[Field] = fields) -> list[str]:
            out = []
            for f in fields:
                if f.kind is ValueKind.BOOL:
                    out.append(f'        printf(" %d", {var}.{f.member} ? 1 : 0);')
                elif f.kind is ValueKind.REAL:
                    out.append(f"        put_f{f.bits}({var}.{f.member});")
                elif f.kind is ValueKind.SIGNED:
                    out.append(f'        printf(" %" PRId64, (int64_t){var}.{f.member});')
                else:
                    out.append(f'        printf(" %" PRIu64, (uint64_t){var}.{f.member});')
            return out

        rows = ",\n".join("        {" + ", ".join(f.c_value(v) for f, v in zip(fields, row, strict=True)) + "}"
                          for row in values[pdo.struct_name])  # fmt: skip
        frame_rows = ",\n".join("        {" + ", ".join(f"0x{b:02X}u" for b in frame) + "}"
                                for frame in frames[pdo.struct_name])  # fmt: skip
        lines += [
            "    {",
            f"        static const struct {struct_} in[] = {{\n{rows}\n        }};",
            f"        static const uint8_t frames[][{pdo.byte_length}] = {{\n{frame_rows}\n        }};",
            f"        struct {struct_} out;",
            "        size_t k;",
            "        for (k = 0; k < sizeof in / sizeof in[0]; ++k) {",
            "            memset(buf, 0xFF, sizeof buf);",
            f"            n = {struct_}_pack(buf, &in[k], sizeof buf);",
            f'            printf("P {pdo.struct_name} %d ", n);',
            "            put_bytes(buf, n);",
            f"            n = {struct_}_unpack(&out, buf, (size_t)n);",
            '            printf(" %d", n);',
            *["    " + line for line in show("out")],
            '            printf("\\n");',
            f"            {struct_}_unpack(&out, frames[k], sizeof frames[k]);",
            f'            printf("U {pdo.struct_name}");',
            *["    " + line for line in show("out")],
            '            printf("\\n");',
            "        }",
            f'        printf("E {pdo.struct_name} %d %d %d %d\\n",',
            f"               {struct_}_pack(buf, &in[0], sizeof frames[0] - 1),",
            f"               {struct_}_unpack(&out, frames[0], sizeof frames[0] - 1),",
            f"               {struct_}_pack(NULL, &in[0], 8u), {struct_}_unpack(NULL, frames[0], sizeof frames[0]));",
            "    }",
        ]
    lines += ["    return 0;", "}", ""]
    return "\n".join(lines)


def check_pdos(tmp_path: Path, eds: Path, name: str, can_fd: bool = False) -> int:
    """Compile the generated code with a harness and compare its output; the number of PDO cases checked."""
    tool("gcc")
    view = view_of(eds, name, NODE_ID, can_fd)
    assert not view.problems
    write(tmp_path, render(view))
    rng = random.Random(SEED)
    values: dict[str, list[list[object]]] = {}
    frames: dict[str, list[bytes]] = {}
    pdos = [p for p in view.pdos if p.fields]
    for pdo in pdos:
        fields = fields_of(pdo)
        values[pdo.struct_name] = [[f.random(rng, case) for f in fields] for case in range(CASES_PER_PDO)]
        frames[pdo.struct_name] = [rng.randbytes(pdo.byte_length) for _ in range(CASES_PER_PDO)]
    (tmp_path / "harness.c").write_text(harness(view, values, frames), encoding="utf-8")
    built = run(["gcc", *C_FLAGS, "-o", "harness", "harness.c", f"{name}.c"], tmp_path)
    assert built.returncode == 0, built.stderr
    result = run([str(tmp_path / "harness")], tmp_path)
    assert result.returncode == 0, result.stderr
    theirs = canopen_pack(eds, pdos, values)
    lines = iter(result.stdout.splitlines())
    by_name = {p.struct_name: p for p in pdos}
    checked = 0
    for pdo in pdos:
        fields = fields_of(pdo)
        for case in range(CASES_PER_PDO):
            row = values[pdo.struct_name][case]
            tag, struct_name, count, data, back, *printed = next(lines).split()
            assert (tag, by_name[struct_name]) == ("P", pdo)
            assert int(count) == int(back) == pdo.byte_length
            packed = bytes.fromhex(data)
            assert packed == reference_pack(pdo, row), (pdo.pdo.name, case, row)
            if (pdo.struct_name, case) in theirs:
                assert packed == theirs[(pdo.struct_name, case)], (pdo.pdo.name, case, row)
            expected = [f.decode(f.raw(v)) for f, v in zip(fields, row, strict=True)]
            assert [f.printed(t) for f, t in zip(fields, printed, strict=True)] == expected, (pdo.pdo.name, case)
            tag, struct_name, *printed = next(lines).split()
            payload = int.from_bytes(frames[pdo.struct_name][case], "little")
            expected = [f.decode(payload >> f.entry.bit_offset) for f in fields]
            assert [f.printed(t) for f, t in zip(fields, printed, strict=True)] == expected, (pdo.pdo.name, case)
            checked += 1
        assert next(lines).split() == ["E", pdo.struct_name, "-2", "-2", "-1", "-1"]
    return checked


@pytest.mark.parametrize("stem", ["cia402_drive", "io_device"])
def test_examples_round_trip_and_match_python_canopen(tmp_path: Path, stem: str) -> None:
    assert check_pdos(tmp_path, EXAMPLES / f"{stem}.eds", stem) > 0


@pytest.mark.parametrize(
    "name",
    [
        "sevcon-gen4__Gen4.eds",  # BOOLEANs mapped bit by bit
        "sd-mav1500__EDS_20014_Standard_CANopen_V212_01.eds",  # 16 one-bit BOOLEANs
        "marathon__Test.eds",  # REAL32 at bit 8, REAL64
    ],
)
def test_corpus_bitwise_layouts(tmp_path: Path, name: str) -> None:
    assert check_pdos(tmp_path, corpus_file(name), "device") > 0


def test_odd_layouts(tmp_path: Path) -> None:
    """1-bit BOOLEANs, INTEGER48 at bit 1, 24/40/56-bit types, REAL32 at bit 1, a CAN FD PDO, dummies."""
    eds = write_odd_eds(tmp_path / "eds")
    assert check_pdos(tmp_path, eds, "odd_bits", can_fd=True) == 10 * CASES_PER_PDO
