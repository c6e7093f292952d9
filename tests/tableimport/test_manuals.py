"""The four vendor manuals of ../shared/seeds: counts, sample objects field by field, conflicts.

Coverage and correctness are measured against independent counts (tests/manualkit.py): every
(index, sub-index) pair the manual documents, and the access and data type it states where it
states exactly one. The tests skip when ../shared is absent."""

from __future__ import annotations

from functools import cache
from pathlib import Path

import pytest
from manualkit import COUNTERS, MANUALS, SEEDS, score

from cantools_od.api import save
from cantools_od.model import AccessType, NodeIdExpr, ObjectKind
from cantools_od.tableimport import ImportResult, import_tables
from cantools_od.tableimport.merge import Conflict

# Its tests share the imports `imported` caches: under pytest-xdist they run on one worker, which makes each once.
pytestmark = pytest.mark.xdist_group("manuals")


def seed(prefix: str) -> Path:
    path = SEEDS / MANUALS[prefix]
    if not path.is_file():
        pytest.skip(f"../shared/seeds/{MANUALS[prefix]} is absent")
    return path


@cache
def imported(*prefixes: str) -> ImportResult:
    return import_tables([seed(p) for p in prefixes])


# documented pairs, imported pairs, pairs with one stated access and type, of which right
EXPECTED = {
    "000": (474, 474, 395, 395),
    "002": (458, 458, 430, 430),
    "003": (258, 258, 244, 244),
    "004": (193, 193, 165, 165),
}
# objects, sub-objects in the EDS of a plain `import-table <manual> -o out.eds` (000: with 1600h-1603h sub 2-8,
# which "Up to 8 objects can be mapped to a single RPDO" states)
SIZES = {"000": (71, 462), "001": (44, 0), "002": (215, 315), "003": (106, 181), "004": (65, 168)}


@pytest.mark.parametrize("prefix", sorted(EXPECTED))
def test_coverage_and_correctness(prefix: str, tmp_path: Path) -> None:
    result = imported(prefix)
    out = tmp_path / "out.eds"
    save(result.device, out, style="canonical")
    pairs = COUNTERS[prefix]()
    assert pairs is not None
    got = score(pairs, out)
    assert (got.documented, got.imported, got.unambiguous, got.correct) == EXPECTED[prefix], (got.missing, got.wrong)
    assert got.coverage >= 0.95 and got.correctness >= 0.95


@pytest.mark.parametrize("prefix", sorted(SIZES))
def test_object_and_sub_object_counts(prefix: str) -> None:
    device = imported(prefix).device
    assert (len(device.objects), sum(len(o.subs) for o in device.objects.values())) == SIZES[prefix]


def conflict(result: ImportResult, index: int, sub: int | None, field: str) -> Conflict:
    for found in result.merged.conflicts:
        entries = [(found.index, found.sub), *found.also]
        if found.field == field and (index, sub) in entries:
            return found
    raise AssertionError(f"no {field} conflict for {index:04X}h sub {sub}")


def lines(found: Conflict) -> set[int]:
    return {s.line for c in found.candidates for s in c.sources}


# --------------------------------------------------------------------------- 000 Elmo


def test_elmo_samples() -> None:
    device = imported("000").device
    dt = device.objects[0x1000]
    assert (dt.name, dt.kind, dt.data_type, dt.access, dt.pdo_mapping, dt.default) == (
        "Device type",
        ObjectKind.VAR,
        0x07,
        AccessType.RO,
        False,
        0x191,
    )  # 000:1507-1518
    identity = device.objects[0x1018]
    assert identity.kind is ObjectKind.RECORD and sorted(identity.subs) == [0, 1, 2, 3, 4]
    assert (identity.subs[1].name, identity.subs[1].data_type, identity.subs[1].access) == ("Vendor ID", 7, "ro")
    tpdo_map = device.objects[0x1A02]  # `1A00h - 1A03h`, `Sub-index 1 - 8` (000:2378, 2394)
    assert sorted(tpdo_map.subs) == list(range(9))
    assert tpdo_map.subs[5].access is AccessType.RW and tpdo_map.subs[5].data_type == 0x07
    user = device.objects[0x2F00]  # ARRAY of Integer32, `1-24` decimal (000:3084-3106)
    assert user.kind is ObjectKind.ARRAY and len(user.subs) == 25
    assert (user.subs[24].data_type, user.subs[24].access, user.subs[24].pdo_mapping) == (0x04, AccessType.RW, True)
    assert (user.subs[24].low_limit, user.subs[24].high_limit) == (-(2**30) + 1, 2**30 - 1)
    assert device.objects[0x2F01].subs[3].data_type == 0x08  # Floating Point (Float)
    recorder = device.objects[0x2030]  # hex sub-indices without suffix: 0A ... 10 (000:2656-2704)
    assert sorted(recorder.subs) == list(range(17)) and recorder.subs[0x10].name == "Speed command"
    assert len(device.objects[0x2F02].subs) == 255  # `1-255`; FFh cannot be written
    emcy = device.objects[0x1014]  # 0x81 is the COB-ID for node 1
    assert emcy.default == NodeIdExpr(offset=0x80)
    assert device.objects[0x1200].subs[1].default == NodeIdExpr(offset=0x600)
    assert device.objects[0x1800].subs[1].default == NodeIdExpr(offset=0x40000180)  # 0x400001FF, node 127
    origin = dt.origin
    assert origin is not None and origin.file.endswith("000_3cb15f7fa7effd3d.txt")
    assert origin.keys["DefaultValue"][0] == 1518 and origin.keys["AccessType"][0] == 1515


@pytest.mark.parametrize(
    ("index", "sub", "field", "expected"),
    [
        (0x1000, 0, "default", {466, 1518}),  # Constant value = 0x12D vs 0x191
        (0x1003, 0, "access", {469, 1599}),
        (0x1012, 0, "access", {480, 1831}),
        (0x1024, 0, "access", {487, 2099}),
        (0x1400, 1, "default", {1016, 2225}),
        (0x1401, 2, "default", {1047, 2233}),
        (0x1600, 0, "data_type", {365, 2282}),  # record 0021h sub 0 U8 vs value range UNSIGNED32
        (0x1600, 1, "default", {1021, 1032, 2291, 2292}),
        (0x1800, 2, "default", {1028, 2337}),
        (0x1A00, 0, "access", {504, 2389}),
        (0x2012, 0, "access", {512, 2538}),
        (0x2013, 0, "access", {513, 2557}),
        (0x20A1, 0, "pdo_mapping", {521, 2938}),
        (0x2F30, 0, "pdo_mapping", {536, 3505}),
        (0x2F31, 0, "pdo_mapping", {537, 3528}),
        (0x2F00, 1, "access", {526, 3103}),
        (0x2F20, 2, "default", {1066, 3276}),
        (0x2F70, 1, "data_type", {3663, 3681}),
        (0x1003, None, "name", {469, 1572, 1589}),
        (0x1018, None, "name", {485, 1972, 1979}),
    ],
)
def test_elmo_conflicts(index: int, sub: int | None, field: str, expected: set[int]) -> None:
    assert expected <= lines(conflict(imported("000"), index, sub, field))


def test_elmo_second_source_agrees() -> None:
    """001 (one cell per line) holds Table 3-1 only; it agrees with 000 on every value."""
    alone = imported("001")
    table = [e for e in alone.reads[0].entries if e.layout == "table"]
    assert len(table) == 67  # the rows of Table 3-1 (000:465-540)
    both = imported("000", "001")
    assert len(both.merged.conflicts) == len(imported("000").merged.conflicts)
    sources = {s.file for s in both.merged.objects[0x2F40].sources}
    assert any(f.endswith("001_6a6bb34a259a2c0a.txt") for f in sources)
    names = {n for n, _ in both.merged.objects[0x2041].aliases} | {both.device.objects[0x2041].name}
    assert "Drive free-running timer" in names


def test_elmo_states_objects_left_out_of_its_own_eds() -> None:
    result = imported("000")
    assert set(result.reads[0].excluded) == {0x2030, 0x2090}
    assert "removed from the EDS" in result.report()


# --------------------------------------------------------------------------- 002 Sanyo


def test_sanyo_samples() -> None:
    device = imported("002").device
    errors = device.objects[0x1003]  # list has 01h only, block `01h...02h` (002:1477, 1650)
    assert sorted(errors.subs) == [0, 1, 2]
    sub0 = errors.subs[0]
    assert (sub0.access, sub0.data_type, sub0.default, sub0.low_limit, sub0.high_limit) == (AccessType.RW, 5, 0, 0, 2)
    motor = device.objects[0x22E0]  # `:` elision rows stand for 03h-35h (002:5260-5263)
    assert sorted(motor.subs) == list(range(0x37))
    assert (motor.subs[0x20].name, motor.subs[0x20].data_type, motor.subs[0x20].access) == (
        "Motor Parameter 32",
        0x06,
        AccessType.RW,
    )
    gain = device.objects[0x2211].subs[2]  # 1LSB 0.1: Min/Max 0.5/1000.0 are engineering values (002:4998)
    assert (gain.low_limit, gain.high_limit) == (5, 10000)
    assert device.objects[0x605E].default == -1  # FFFFh two's complement (002:1966)
    assert device.objects[0x6040].pdo_mapping is True and device.objects[0x603F].pdo_mapping is False
    assert device.objects[0x1400].subs[1].default == NodeIdExpr(offset=0x200)
    assert device.objects[0x1018].subs[1].default == 0x1B9
    assert device.objects[0x2125].kind is ObjectKind.VAR  # an ARRAY holding only the password (002:4951)


@pytest.mark.parametrize(
    ("index", "sub", "field", "expected"),
    [
        (0x1014, 0, "default", {1892, 2025}),
        (0x607D, 1, "default", {1970, 3411}),
        (0x60C2, 1, "default", {1991, 3957}),
        (0x2106, 0, "default", {1997, 4699}),
        (0x60C2, 2, "access", {1334, 2856, 3960}),
        (0x60C4, None, "object_code", {2860}),
        (0x2125, None, "object_code", {4223, 4951}),
    ],
)
def test_sanyo_conflicts(index: int, sub: int | None, field: str, expected: set[int]) -> None:
    assert expected <= lines(conflict(imported("002"), index, sub, field))


# --------------------------------------------------------------------------- 003 MOONS'


def test_moons_samples() -> None:
    device = imported("003").device
    assert device.objects[0x1018].subs[1].default == 0x2D9  # 003:805
    registers = device.objects[0x4000]  # Array row + `0x0A` sub-table (003:1330-1356)
    assert registers.kind is ObjectKind.ARRAY and len(registers.subs) == 24
    assert (registers.subs[0x0A].name, registers.subs[0x0A].data_type) == ("userRegister10", 0x04)
    assert [device.objects[0x1800 + n].subs[1].default for n in range(4)] == [
        NodeIdExpr(offset=base) for base in (0x180, 0x280, 0x380, 0x480)
    ]  # Note 3, split over 003:1088-1092
    assert device.objects[0x1800].subs[3].default == 100
    notch = [device.objects[i] for i in range(0x5007, 0x500F)]  # `5007h -500Eh` (003:369)
    assert all(o.data_type == 0x03 and o.access is AccessType.RW for o in notch)
    assert device.objects[0x6085].data_type == 0x07  # attribute row starting with a TAB (003:1777)
    assert device.objects[0x1005].default == 0x80  # 7-digit 0x0000080 (003:619)
    assert device.objects[0x1008].default == "AMA CANopen Motor Driver"
    assert device.objects[0x1011].kind is ObjectKind.RECORD  # `Var` with a sub-table (003:732)
    assert device.objects[0x7002].pdo_mapping is True


@pytest.mark.parametrize(
    ("index", "sub", "field", "expected"),
    [
        (0x1010, 0, "access", {328, 696}),
        (0x1011, None, "object_code", {732}),
        (0x6074, 0, "data_type", {391, 1685}),
        (0x6074, 0, "access", {391, 1685}),
        (0x6078, 0, "access", {392, 1696}),
        (0x6099, 0, "access", {404, 1812}),
        (0x7003, 0, "access", {421, 1916}),
        (0x7002, 0, "pdo_mapping", {420, 1903}),
        (0x1401, 1, "default", {960, 976}),
    ],
)
def test_moons_conflicts(index: int, sub: int | None, field: str, expected: set[int]) -> None:
    assert expected <= lines(conflict(imported("003"), index, sub, field))


# --------------------------------------------------------------------------- 004 Nidec


def test_nidec_samples() -> None:
    device = imported("004").device
    rx = [i for i in device.objects if 0x1400 <= i <= 0x15FF]
    tx_maps = [i for i in device.objects if 0x1A00 <= i <= 0x1BFF]
    assert rx == [0x1400, 0x1402, 0x1404, 0x1405] and tx_maps == [0x1A00, 0x1A02, 0x1A04, 0x1A05]
    assert 0x1602 not in device.objects  # implied by the numbering, never described: not invented
    assert device.objects[0x1405].subs[1].default == NodeIdExpr(offset=0x80000500)  # Table 11-9, letter D
    assert device.objects[0x1805].subs[1].default == 0x80000000  # Table 11-15, letter D
    assert device.objects[0x1018].subs[1].default == 0xF9 and device.objects[0x1018].subs[2].default == 448
    ramp = device.objects[0x6046]  # Object Type ARRAY, Elements 2, italic sub names (004:4419-4438)
    assert ramp.kind is ObjectKind.ARRAY and sorted(ramp.subs) == [0, 1, 2]
    assert (ramp.subs[1].name, ramp.subs[1].data_type, ramp.subs[1].pdo_mapping) == ("vl_velocity_min_amount", 7, True)
    assert device.objects[0x2832].data_type == 0x05  # BYTE
    assert device.objects[0x1600].subs[1].default == 0x20062A20 and device.objects[0x1600].subs[1].name
    assert device.objects[0x6502].default == 0xA
    assert device.objects[0x1400].subs[0].name == "Largest sub-index supported"  # name in the key slot
    assert 0x604C not in device.objects  # ARRAY listed without any sub-index (004:4374)


@pytest.mark.parametrize(
    ("index", "sub", "field", "expected"),
    [
        (0x1400, 1, "access", {2575, 2630}),
        (0x6041, 0, "access", {4070, 4154}),
    ],
)
def test_nidec_conflicts(index: int, sub: int | None, field: str, expected: set[int]) -> None:
    assert expected <= lines(conflict(imported("004"), index, sub, field))
