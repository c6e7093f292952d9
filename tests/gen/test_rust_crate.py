"""The generated Rust in a cargo crate: `#![no_std]` build, Rust tests of pack/unpack and of the constants,
clippy and rustfmt. PDO bytes are python-canopen's encoding of the same values wherever python-canopen can
encode the layout (byte-aligned values and BOOLEANs), else the bit rule of pdo-rules.md §6."""

from __future__ import annotations

import random
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from rustkit import (
    EXAMPLES,
    Record,
    canopen_pack,
    cargo,
    eds_text,
    pdo_cases,
    reference_pack,
    render_rust,
    require,
    rust_pdo_test,
    rustfmt_check,
    var,
    write_crate,
)

from cantools_od.render.rust import module as rust_module

from support import CORPUS

# Its tests share one module fixture: under pytest-xdist they run on one worker, which makes it once.
pytestmark = pytest.mark.xdist_group("rust_crate")

NODE_ID = 5
SEED = 20250115
CASES = 16

# Bit-wise layouts: odd offsets, 1-bit BOOLEANs, 24/40/48/56-bit types, REALs, a twice-mapped object, dummies.
ODD_OBJECTS = {
    0x2001: var("Flag A", 0x0001, "1"),
    0x2002: var("Int24 value", 0x0010, "-5"),
    0x2003: var("Uns40 value", 0x0018, "0x123456789A"),
    0x2004: var("Int48 value", 0x0013, "-140737488355328"),
    0x2005: var("Real32 value", 0x0008, "1.5", LowLimit="-2.5", HighLimit="100.25"),
    0x2006: var("Flag B", 0x0001, "0"),
    0x2007: var("Int8 value", 0x0002, "-128"),
    0x2008: var("Uns24 value", 0x0016, "0xABCDEF"),
    0x2009: var("Int40 value", 0x0012, "-1"),
    0x200A: var("Uns48 value", 0x0019, "0"),
    0x200B: var("Int56 value", 0x0014, "36028797018963967"),
    0x200C: var("Uns56 value", 0x001A, "0xFFFFFFFFFFFFFF"),
    0x200D: var("Real64 value", 0x0011, "-0.1"),
    0x200E: var("Int64 value", 0x0015, "-9223372036854775808"),
    0x200F: var("Uns64 value", 0x001B, "0xFFFFFFFFFFFFFFFF"),
    0x2010: var("Uns16 value", 0x0006, "0"),
    0x2011: var("Limited int16", 0x0003, "0", LowLimit="-100", HighLimit="100"),
    0x2012: var("Uns8 value", 0x0005, "7"),
}
FLAGS = [(0x2001, 0, 1), (0x2006, 0, 1)]
ODD_PDOS = {
    ("rx", 1): [(0x2001, 0, 1), (0x2002, 0, 24), (0x2006, 0, 1), (0x2003, 0, 40)],
    ("rx", 2): [(0x2001, 0, 1), (0x2004, 0, 48), (0x0005, 0, 8), (0x2007, 0, 8)],
    ("rx", 3): [(0x2006, 0, 1), (0x2005, 0, 32), (0x2001, 0, 1), (0x2006, 0, 1), (0x2008, 0, 24)],
    ("rx", 4): [],
    ("rx", 5): [(0x0005, 0, 8), (0x0006, 0, 16)],
    ("tx", 1): [(0x2002, 0, 24), (0x2003, 0, 40)],
    ("tx", 2): [(0x2004, 0, 48), (0x2010, 0, 16)],
    ("tx", 3): [*FLAGS * 4, (0x2012, 0, 8), (0x2011, 0, 16), (0x2005, 0, 32)],
    ("tx", 4): [(0x2009, 0, 40), (0x2012, 0, 8), (0x2002, 0, 24)],
    ("tx", 5): [(0x200B, 0, 56), (0x2001, 0, 1), (0x200C, 0, 56)],
    ("tx", 6): [(0x200D, 0, 64), (0x200E, 0, 64), (0x200F, 0, 64), (0x200A, 0, 48)],
    ("tx", 7): [(0x2001, 0, 1), (0x200E, 0, 64), (0x200D, 0, 64)],
    ("tx", 8): [(0x2011, 0, 16), (0x2009, 0, 40), (0x2006, 0, 1), (0x200A, 0, 48)],
}

LONG = "Digital input polarity if set input is active when switch is open i e normally closed digital inputs 9 15"
# Names and values that try to break out of comments and literals, collide with Rust names or are very long.
HOSTILE_OBJECTS: dict[int, dict[str, str] | Record] = {
    0x2001: Record("Data type", [var("Highest sub-index", 0x0005, "1", "ro", False), var("x", 0x0005, "1")]),
    0x2002: Record("Result", [var("Highest sub-index", 0x0005, "1", "ro", False), var("Ok", 0x0001, "1")]),
    0x2003: Record("self", [var("Highest sub-index", 0x0005, "1", "ro", False), var("type", 0x0003, "-1")]),
    0x2004: Record("Foo 1 2", [var("Highest sub-index", 0x0005, "0", "ro", False)]),
    0x2005: Record("Foo 12", [var("Highest sub-index", 0x0005, "0", "ro", False)]),
    0x2006: Record("Foo1 2", [var("Highest sub-index", 0x0005, "0", "ro", False)]),
    0x2007: var('Name */ with "quotes" \\ and ??= trigraph /* x', 0x0009, 'He said "hi" */ \\ ??= {}', mappable=False),
    0x2008: var("Température µs 电机 ", 0x0009, "Grüße µ 电机", mappable=False),
    0x2009: var("Octets", 0x000A, "00FF10", mappable=False),
    0x200A: var("Pi", 0x0008, "3.14159265", LowLimit="3.1416", HighLimit="1e40"),
    0x200B: var("Euler", 0x0011, "2.718281828459045", LowLimit="-1e-300"),
    0x200C: var("Int64 min", 0x0015, "-9223372036854775808", LowLimit="-9223372036854775807"),
    0x200D: var("Uns64 max", 0x001B, "0xFFFFFFFFFFFFFFFF", HighLimit="0xFFFFFFFFFFFFFFFE"),
    0x200E: var("High limit zero", 0x0005, "0", HighLimit="0"),
    0x200F: var("Low limit max", 0x0005, "255", LowLimit="255"),
    0x2010: var("Backwards limits", 0x0005, "5", LowLimit="10", HighLimit="5"),
    0x2011: var("Too big", 0x0005, "300"),
    0x2012: var("Node u8", 0x0005, "$NODEID+0x40"),
    0x2013: var("Node u16 wraps", 0x0006, "$NODEID+0xFFF0"),
    0x2014: var("Node i8 wraps", 0x0002, "$NODEID+0x7F"),
    0x2015: Record(
        "Gains", [var("Count", 0x0005, "3", "ro", False)] + [var(f"Gain {v}", 0x0008, v) for v in "121"], "0x8"
    ),
    0x2016: Record(
        "Nodes",
        [var("Count", 0x0005, "3", "ro", False)] + [var(f"Node {n}", 0x0007, n) for n in ("$NODEID+0x100", "0", "0")],
        "0x8",
    ),
    0x2017: Record(
        "Mixed record",
        [
            var("Highest sub-index", 0x0005, "3", "ro", False),
            var("Label", 0x0009, 'abc\\"def'),
            var("COB", 0x0007, "$NODEID+0x80"),
            var("On", 0x0001, "1"),
        ],
    ),
    0x2018: var(LONG, 0x0007, "1", LowLimit="1", HighLimit="9"),
    0x2019: Record(
        LONG,
        [var("Highest sub-index", 0x0005, "2", "ro", False)] + [var(f"{LONG} {k}", 0x0004, str(k)) for k in (1, 2)],
    ),
    0x201A: Record(
        LONG + " array", [var("Count", 0x0005, "2", "ro", False), var("A", 0x0006, "1"), var("B", 0x0006, "2")], "0x8"
    ),
    0x201B: {"ParameterName": "Blob", "ObjectType": "0x2", "AccessType": "rw"},
    0x201C: var("", 0x0005, "1"),
}
CORPUS_LAYOUTS = {
    "sevcon_gen4": "sevcon-gen4__Gen4.eds",  # BOOLEANs mapped bit by bit
    "sd_mav1500": "sd-mav1500__EDS_20014_Standard_CANopen_V212_01.eds",  # 16 one-bit BOOLEANs
    "marathon_test": "marathon__Test.eds",  # REAL32 at bit 8, REAL64
}
HOSTILE_PDOS = {("tx", 1): [(0x2018, 0, 32), (0x2018, 0, 32)], ("rx", 1): [(0x2012, 0, 8), (0x200A, 0, 32)]}


@dataclass
class Crate:
    path: Path
    checked: dict[str, int] = field(default_factory=dict)  # module → PDO cases python-canopen confirmed
    cases: int = 0


def pdo_tests(module: str, eds: Path, can_fd: bool, reference: bool) -> tuple[str, str, int, int]:
    """The module's text and Rust PDO tests; how many cases there are and how many python-canopen encoded."""
    view, text = render_rust(eds, module, can_fd=can_fd)
    rng = random.Random(f"{SEED}-{module}")
    tests, total, confirmed = [], 0, 0
    for pdo in rust_module(view).pdos:
        rows, frames = pdo_cases(pdo, rng, CASES if pdo.fields else 1)
        packed = [reference_pack(pdo, row) for row in rows]
        theirs = canopen_pack(eds, NODE_ID, pdo, rows) if pdo.fields and reference else None
        if theirs is not None:
            assert theirs == packed, f"{module} {pdo.label}: python-canopen disagrees with pdo-rules.md §6"
            confirmed += len(rows)
        total += len(rows)
        tests.append(rust_pdo_test(module, pdo, rows, theirs or packed, frames))
    return text, "\n".join(tests), total, confirmed


API_TESTS = """
use rust_target_tests::{cia402_drive as drive, io_device as io, io_device_node5 as io5};

#[test]
fn constants() {
    assert_eq!(io::IDENTITY_OBJECT_INDEX, 0x1018);
    assert_eq!(io::IDENTITY_OBJECT_VENDOR_ID_INDEX, 0x1018);
    assert_eq!(io::IDENTITY_OBJECT_VENDOR_ID_SUBINDEX, 1);
    assert_eq!(io::IDENTITY_OBJECT_VENDOR_ID_DEFAULT, 0xCA7);
    assert_eq!(io::IDENTITY_OBJECT_VENDOR_ID_DATA_TYPE, io::DataType::UNSIGNED32);
    assert_eq!(io::IDENTITY_OBJECT_VENDOR_ID_ACCESS, io::Access::Ro);
    assert_eq!(u8::from(io::ERROR_REGISTER_PDO_MAPPABLE), 1);
    assert_eq!(io::DEVICE_SETTINGS_LOCATION_TAG_DEFAULT, "unassigned");
    assert_eq!(io::DEVICE_SETTINGS_LOCATION_TAG_LEN, 10);
    assert_eq!(io::DEVICE_SETTINGS_ANALOG_SCALING_FACTOR_DEFAULT.to_bits(), 1.0f32.to_bits());
    assert_eq!(drive::TARGET_TORQUE_LOW_LIMIT, -3000);
    assert_eq!(drive::TARGET_TORQUE_HIGH_LIMIT, 3000);
    assert!(drive::target_torque_is_in_range(-3000));
    assert!(!drive::target_torque_is_in_range(3001));
    assert!(!io::read_analog_input_16_bit_analog_input_1_is_in_range(10001));
    assert!(io::Access::Rw.writable() && io::Access::Ro.readable() && !io::Access::Ro.writable());
}

#[test]
fn node_id() {
    assert_eq!(io::cob_id_emcy_default(5), 0x85);
    assert_eq!(io::cob_id_tpdo1(5), 0x185);
    assert_eq!(io::cob_id_rpdo1(127), 0x27F);
    assert_eq!(io5::NODE_ID, 5);
    assert_eq!(io5::COB_ID_TPDO2, 0x285);
    assert_eq!(io5::COB_ID_EMCY_DEFAULT, 0x85);
    assert_eq!(io::SdoServerParameter::defaults(5).cob_id_client_to_server, 0x605);
    assert_eq!(io5::SdoServerParameter::DEFAULT.cob_id_server_to_client, 0x585);
}

#[test]
fn records_and_arrays() {
    let identity = io::IdentityObject::default();
    assert_eq!((identity.highest_sub_index_supported, identity.product_code), (4, 0x401));
    assert_eq!(&io::DeviceSettings::DEFAULT.location_tag, b"unassigned");
    assert_eq!(io::DeviceSettings::DEFAULT.input_filter_time, 10);
    let errors: io::PreDefinedErrorField = io::PRE_DEFINED_ERROR_FIELD_DEFAULT;
    assert_eq!(errors, [0; 4]);
    let limits: drive::SoftwarePositionLimit = drive::SOFTWARE_POSITION_LIMIT_DEFAULT;
    assert_eq!(limits, [-1_000_000_000, 1_000_000_000]);
}

#[test]
fn table() {
    let objects = io::OBJECTS;
    assert!(objects.windows(2).all(|w| (w[0].index, w[0].subindex) < (w[1].index, w[1].subindex)));
    assert_eq!(io5::OBJECTS.len(), objects.len());
    assert_eq!(io::OBJECTS.len(), IO_ENTRIES);
    assert_eq!(drive::OBJECTS.len(), DRIVE_ENTRIES);
    let vendor = io::find(0x1018, 1).unwrap();
    assert_eq!((vendor.name, vendor.size), ("Vendor-ID", 4));
    assert_eq!(vendor.data_type, Some(io::DataType::UNSIGNED32));
    assert_eq!(vendor.access, Some(io::Access::Ro));
    assert_eq!(io::find(0x1008, 0).unwrap().size, 30);
    assert!(io::find(0x1018, 5).is_none());
    assert!(drive::find(0x6040, 0).unwrap().pdo_mappable);
}
"""


@pytest.fixture(scope="module")
def crate(tmp_path_factory: pytest.TempPathFactory) -> Crate:
    folder = tmp_path_factory.mktemp("rust_crate")
    eds_dir = folder / "eds"
    eds_dir.mkdir()
    odd = eds_dir / "odd_bits.eds"
    odd.write_text(eds_text("odd_bits.eds", ODD_OBJECTS, ODD_PDOS, "Odd bits */ device"), encoding="utf-8")
    hostile = eds_dir / "hostile.eds"
    hostile.write_text(eds_text("hostile.eds", HOSTILE_OBJECTS, HOSTILE_PDOS, 'Hostile "*/ device'), "utf-8")
    modules: dict[str, str] = {}
    tests: list[str] = []
    result = Crate(folder)
    for module, eds, can_fd, reference in [
        ("io_device", EXAMPLES / "io_device.eds", False, True),
        ("cia402_drive", EXAMPLES / "cia402_drive.eds", False, True),
        ("odd_bits", odd, True, True),
        ("hostile", hostile, False, False),  # python-canopen cannot read a DOMAIN object without DataType
    ]:
        modules[module], test, total, confirmed = pdo_tests(module, eds, can_fd, reference)
        tests.append(test)
        result.checked[module] = confirmed
        result.cases += total
    for module, name in CORPUS_LAYOUTS.items():  # real bit-wise layouts, when ../shared is there
        if (CORPUS / name).is_file():
            modules[module], test, total, confirmed = pdo_tests(module, CORPUS / name, False, True)
            tests.append(test)
            result.checked[module] = confirmed
            result.cases += total
    modules["io_device_node5"] = render_rust(EXAMPLES / "io_device.eds", "io_device_node5", NODE_ID)[1]
    pdo_rs = "#![deny(warnings)]\n\nuse rust_target_tests::*;\n\n" + "\n".join(tests)
    io_entries = len(rust_module(render_rust(EXAMPLES / "io_device.eds", "x")[0]).entries)
    drive_entries = len(rust_module(render_rust(EXAMPLES / "cia402_drive.eds", "x")[0]).entries)
    api_rs = "#![deny(warnings)]\n" + API_TESTS.replace("IO_ENTRIES", str(io_entries))
    api_rs = api_rs.replace("DRIVE_ENTRIES", str(drive_entries))
    write_crate(folder / "crate", "rust_target_tests", modules, {"pdo": pdo_rs, "api": api_rs})
    result.path = folder / "crate"
    return result


def test_python_canopen_encodes_the_same_bytes(crate: Crate) -> None:
    """The fixture checked python-canopen against the bit rule; each file has layouts it could encode."""
    assert crate.checked["io_device"] > 0 and crate.checked["cia402_drive"] > 0 and crate.checked["odd_bits"] > 0


def test_builds_under_no_std(crate: Crate) -> None:
    require("cargo", "rustc")
    result = cargo(crate.path, "build", "--lib")
    assert result.returncode == 0, result.stderr[-6000:]


def test_rust_tests_pass(crate: Crate) -> None:
    require("cargo", "rustc")
    result = cargo(crate.path, "test")
    assert result.returncode == 0, (result.stdout + result.stderr)[-8000:]
    assert "test result: ok" in result.stdout and "FAILED" not in result.stdout


def test_clippy_clean(crate: Crate) -> None:
    require("cargo", "clippy")
    result = cargo(crate.path, "clippy", "--all-targets", "--", "-D", "warnings")
    assert result.returncode == 0, result.stderr[-8000:]


def test_rustfmt_clean(crate: Crate) -> None:
    require("rustfmt")
    generated = [p for p in sorted((crate.path / "src").glob("*.rs")) if p.name != "lib.rs"]
    result = rustfmt_check(generated)
    assert result.returncode == 0, result.stdout[-8000:]
