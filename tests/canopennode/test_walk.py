"""The stack's own OD_find/OD_getSub see every entry as the device description says.

For every corpus file the canopennode profile accepts, a C program built with the generated OD
and `301/CO_ODinterface.c` walks the dictionary; its report is compared with expectations this
test derives from the model on its own (types, access, defaults), not from the generator's view.
"""

from __future__ import annotations

import struct
from pathlib import Path

import pytest
from cnokit import DEMO, STACK, Entry, load_accepted, parallel, stack, walk, write_od

from cantools_od.model import AccessType, DataType, Device, NodeIdExpr, Object, ObjectKind, TimeValue, Value, Variable

from support import corpus_files

KIND = {ObjectKind.VAR: 1, ObjectKind.DOMAIN: 1, ObjectKind.ARRAY: 2, ObjectKind.RECORD: 3}
SDO = {AccessType.RO: 1, AccessType.CONST: 1, AccessType.WO: 2}  # others: read and write (3)
PDO = {AccessType.RO: 4, AccessType.CONST: 4, AccessType.RWR: 4, AccessType.WO: 8, AccessType.RWW: 8}  # rw: 12
TEXT = (0x0009, 0x000A, 0x000B)


def expected_length(dtype_index: int, bits: int | None, value: Value | None) -> int:
    if dtype_index == 0x0001:
        return 1
    if bits is not None:
        return bits // 8
    if isinstance(value, str):
        return len(value.encode("utf-16-le" if dtype_index == 0x000B else "utf-8"))
    return len(value) if isinstance(value, bytes) else 0


def expected_bytes(dtype_index: int, kind: str, value: Value | None, length: int) -> bytes | None:
    if isinstance(value, NodeIdExpr):
        value = value.offset  # CANopenNode adds the node-ID at run time
    if isinstance(value, TimeValue):  # ms after midnight (28 bits), then days since 1984-01-01
        return struct.pack("<IH", value.ms & 0x0FFFFFFF, value.days)
    if isinstance(value, str):
        value = value.encode("utf-16-le" if dtype_index == 0x000B else "utf-8")
    if isinstance(value, bytes):
        return value.ljust(length, b"\0")
    if isinstance(value, float) or (kind == "real" and isinstance(value, int)):
        return struct.pack("<f" if length == 4 else "<d", value)
    if isinstance(value, (bool, int)):
        return int(value).to_bytes(length, "little", signed=kind == "signed" and value < 0)
    return None if dtype_index not in TEXT else bytes(length)


def attribute(dtype_index: int, numeric: bool, bits: int | None, var: Variable) -> int:
    bits_set = SDO.get(var.access, 3) if var.access is not None else 0
    if var.pdo_mapping and var.access is not None:
        bits_set |= PDO.get(var.access, 12)
    elif var.access in (AccessType.RWR, AccessType.RWW):  # CANopenEditor: rwr/rww name the direction themselves
        bits_set |= PDO[var.access]
    if numeric and bits in (16, 32, 64):
        bits_set |= 0x40
    if dtype_index in (0x0009, 0x000B):
        bits_set |= 0x80
    return bits_set


def check_object(device: Device, obj: Object, seen: Entry) -> None:
    assert seen.kind == KIND[obj.kind], f"{obj.index:04X}"
    pairs = sorted(obj.subs.items()) if obj.has_subs else [(0, obj)]
    assert seen.sub_count == len(pairs), f"{obj.index:04X}"
    assert sorted(seen.subs) == [sub for sub, _ in pairs], f"{obj.index:04X}"
    element = max(
        (expected_length(v.data_type or 0, _bits(device, obj, v), _value(v)) for s, v in pairs if s > 0), default=0
    )
    for sub, var in pairs:
        dtype = device.entry_type(var, obj)
        assert dtype is not None
        got = seen.subs[sub]
        where = f"{obj.index:04X}sub{sub:X}"
        length = expected_length(dtype.index, dtype.bits, _value(var))
        if obj.kind is ObjectKind.ARRAY and sub > 0:
            length = element
        assert got.length == length, where
        assert got.attribute == attribute(dtype.index, dtype.is_numeric, dtype.bits, var), where
        data = _data(dtype, obj.index, var, length)
        if obj.kind is ObjectKind.ARRAY and sub > 0:  # one C array: memory for all elements or none, as the first
            first = _data(device.entry_type(pairs[1][1], obj), obj.index, pairs[1][1], length)
            data = None if first is None else (data or bytes(length))
        assert got.data == data, where
        stated = obj.canopennode.storage_group if obj.canopennode else None
        if got.data is not None and stated:
            assert got.group == stated, where


# What CO_CANopenInit reads (CANopen.c, CO_config_t): these need memory, 0 without a default.
READ_AT_INIT = {0x1001, 0x1005, 0x1006, 0x1007, 0x100C, 0x100D, 0x1012, 0x1014, 0x1015, 0x1016, 0x1017, 0x1019, 0x1300,
                0x13FE, 0x13FF, *range(0x1200, 0x1300), *range(0x1301, 0x1341), *range(0x1381, 0x13C1),
                *range(0x1400, 0x1C00)}  # fmt: skip


def _data(dtype: DataType | None, index: int, var: Variable, length: int) -> bytes | None:
    assert dtype is not None
    data = expected_bytes(dtype.index, dtype.kind.value, _value(var), length) if length else None
    if data is None and length and index in READ_AT_INIT:
        data = bytes(length)
    return data


def _value(var: Variable) -> Value | None:
    return var.parameter_value if var.parameter_value is not None else var.default


def _bits(device: Device, obj: Object, var: Variable) -> int | None:
    dtype = device.entry_type(var, obj)
    return dtype.bits if dtype else None


def test_the_stack_walks_every_entry_as_the_model_says(tmp_path: Path) -> None:
    stack()
    sources = [DEMO / "demoDevice.eds", STACK / "example" / "DS301_profile.eds", *corpus_files()]
    devices, _ = load_accepted(sources)
    if len(devices) < 3:
        pytest.skip("../shared/eds-corpus is absent")

    def one(job: tuple[int, Device]) -> tuple[Device, dict[int, Entry]]:
        n, device = job
        write_od(device, tmp_path / f"od{n}")
        return device, walk(tmp_path / f"od{n}", tmp_path / f"walk{n}")

    checked = 0
    for device, seen in parallel(one, list(enumerate(devices))):
        objects = [o for o in device.objects.values() if o.kind in KIND]
        assert sorted(seen) == [o.index for o in objects], device.source
        for obj in objects:
            check_object(device, obj, seen[obj.index])
            checked += 1
    print(f"\nwalked {checked} objects of {len(devices)} devices")
    assert checked > 1000
