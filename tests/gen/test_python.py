"""`cantools-od gen -t python`: golden files, PDO bytes against python-canopen, SDO over a virtual CAN bus,
`object_dictionary()` and `to_canopen` against python-canopen's own EDS import, mypy --strict."""

from __future__ import annotations

import dataclasses
import logging
import math
import random
import shutil
import subprocess
import sys
import uuid
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType
from typing import Any

import canopen
import pytest
from pykit import (
    ODD_PDOS,
    assert_example_golden,
    canopen_bytes,
    canopen_pdos,
    generate,
    generated_module,
    import_file,
    odd_bits_eds,
    random_value,
    run_gen,
    virtual_network,
)

from cantools_od import load, to_canopen

from support import EXAMPLES, corpus_files

EXAMPLE_FILES = ["io_device.eds", "cia402_drive.eds"]


@pytest.fixture(autouse=True)
def quiet_canopen() -> Iterator[None]:
    """python-canopen logs a warning for every value beyond LowLimit/HighLimit it packs; the tests pack many."""
    logger = logging.getLogger("canopen")
    level = logger.level
    logger.setLevel(logging.ERROR)
    yield
    logger.setLevel(level)


@pytest.fixture
def odd_eds(tmp_path: Path) -> Path:
    path = tmp_path / "odd_bits.eds"
    path.write_text(odd_bits_eds(), encoding="ascii")
    return path


@pytest.fixture
def io_module(tmp_path: Path) -> ModuleType:
    return generated_module(EXAMPLES / "io_device.eds", tmp_path, "io_device")


# --- golden files ------------------------------------------------------------------------------------------


@pytest.mark.parametrize("name", EXAMPLE_FILES)
def test_python_golden(name: str, tmp_path: Path) -> None:
    assert_example_golden(name, "python", ".py", tmp_path)


def test_python_cli_writes_module(tmp_path: Path) -> None:
    result = run_gen(EXAMPLES / "cia402_drive.eds", "-t", "python", "-o", tmp_path, "--name", "drive")
    assert result.exit_code == 0, result.output
    module = import_file(tmp_path / "drive.py")
    assert module.INDEX_STATUSWORD == 0x6041
    assert module.Rpdo2.COB_ID is None and module.Rpdo2.COB_ID_NODEID_OFFSET == 0x300
    with_node = run_gen(EXAMPLES / "cia402_drive.eds", "-t", "python", "-o", tmp_path / "n", "--node-id", "5")
    assert with_node.exit_code == 0, with_node.output
    numeric = import_file(tmp_path / "n" / "cia402_drive.py")
    assert numeric.Rpdo2.COB_ID == 0x305 and numeric.NODE_ID == 5
    assert numeric.object_dictionary()[0x1400][1].default == 0x205


def test_python_module_imports_without_cantools_od(tmp_path: Path) -> None:
    (tmp_path / "io_device.py").write_text(generate(EXAMPLES / "io_device.eds", "python", "io_device"))
    code = (
        "import sys\n"
        "class Block:\n"
        "    def find_spec(self, name, path=None, target=None):\n"
        "        if name.split('.')[0] == 'cantools_od': raise ImportError('blocked')\n"
        "sys.meta_path.insert(0, Block())\n"
        "import io_device\n"
        "assert io_device.Tpdo1(1, -2, 3).pack() == bytes([1, 0xFE, 0xFF, 3, 0])\n"
        "assert len(io_device.object_dictionary()) == 22\n"
        "assert 'cantools_od' not in sys.modules\n"
    )
    result = subprocess.run([sys.executable, "-c", code], cwd=tmp_path, capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr


def test_constants(io_module: ModuleType) -> None:
    assert io_module.INDEX_IDENTITY_OBJECT == 0x1018
    assert io_module.SUBINDEX_IDENTITY_OBJECT_VENDOR_ID == 1
    assert io_module.INDEX_PRODUCER_HEARTBEAT_TIME == 0x1017
    assert io_module.SUBINDEX_DEVICE_SETTINGS_LOCATION_TAG == 4
    assert io_module.SOURCE == "io_device.eds" and io_module.NODE_ID is None


def test_any_text_makes_valid_source(tmp_path: Path) -> None:
    from pykit import eds_text, var

    names = ['"""', "'''", "a\\", "\\x00 \\N{x}", "é ü €", "\u202e evil", "# comment", "{x} %s", '"; import os; "']
    objects = [var(0x2000 + n, name, 0x0009, "rw", name) for n, name in enumerate(names)]
    path = tmp_path / "text.eds"
    path.write_text(eds_text(objects).replace("ProductName=Crafted", 'ProductName="""\\'), encoding="utf-8")
    module = generated_module(path, tmp_path, "text")
    rows = {row.idx: row for row in module._VARIABLES}
    for number, name in enumerate(names):
        assert rows[0x2000 + number].name == name and rows[0x2000 + number].default == name
    assert module.object_dictionary()[0x2000].name == '"""'
    assert '"""\\' in (module.__doc__ or "")
    assert '"""' in (module.Device.object_2000.__doc__ or "")


# --- PDOs -------------------------------------------------------------------------------------------------


def _pdo_classes(module: ModuleType) -> dict[str, type]:
    return {name: cls for name, cls in vars(module).items() if name[:4] in ("Rpdo", "Tpdo") and name[4:].isdigit()}


def _same(a: tuple[Any, ...], b: tuple[Any, ...]) -> bool:
    return all(x == y or (isinstance(x, float) and math.isnan(x) and math.isnan(y)) for x, y in zip(a, b, strict=True))


@pytest.mark.parametrize("name", [*EXAMPLE_FILES, "odd_bits.eds"])
def test_pdo_bytes_match_python_canopen(name: str, tmp_path: Path, odd_eds: Path) -> None:
    path = odd_eds if name == "odd_bits.eds" else EXAMPLES / name
    module = generated_module(path, tmp_path, Path(name).stem)
    classes = _pdo_classes(module)
    maps = canopen_pdos(path, node_id=5)
    assert set(classes) == set(maps) and classes
    rng = random.Random(f"{name}-pdo")
    for class_name, cls in classes.items():
        layout = cls._LAYOUT  # type: ignore[attr-defined]
        assert [f.name for f in dataclasses.fields(cls)] == [f.name for f in layout]
        for _ in range(200):
            values = [random_value(rng, f.kind, f.bits) for f in layout]
            packed = cls(*values).pack()
            assert packed == canopen_bytes(maps[class_name], values), (class_name, values)
            assert len(packed) == cls.SIZE  # type: ignore[attr-defined]
            assert _same(dataclasses.astuple(cls.unpack(packed)), tuple(values))  # type: ignore[attr-defined]


def test_odd_bits_layout(tmp_path: Path, odd_eds: Path) -> None:
    module = generated_module(odd_eds, tmp_path, "odd_bits")
    fields = [f.name for f in dataclasses.fields(module.Tpdo1)]
    assert fields == [
        "odd_values_flag_a",
        "odd_values_int48",
        "odd_values_flag_b",
        "odd_values_flag_a_2",
        "odd_values_flag_b_2",
        "odd_values_flag_a_3",
        "odd_values_flag_b_3",
        "odd_values_flag_a_4",
        "odd_values_flag_b_4",
        "odd_values_byte",
    ]
    assert len(ODD_PDOS[("tx", 1)]) == len(fields)
    # INTEGER48 at bit 1: -1 fills bits 1..48; the flags and the byte keep their own bits
    pdo = module.Tpdo1(odd_values_int48=-1, odd_values_byte=0xA5)
    assert pdo.pack() == bytes([0xFE, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0x01, 0xA5])
    assert module.Tpdo1.unpack(pdo.pack()).odd_values_int48 == -1
    low = module.Tpdo1(odd_values_flag_a=True, odd_values_int48=-(1 << 47)).pack()
    assert low == bytes([0x01, 0, 0, 0, 0, 0, 0x01, 0])  # sign bit at bit 48
    assert module.Tpdo1.unpack(low).odd_values_int48 == -(1 << 47)
    # dummy entries are zero and are not fields
    rpdo2 = module.Rpdo2(odd_values_int16=-1, odd_values_byte=7)
    assert rpdo2.pack() == bytes([0xFF, 0xFF, 0, 7, 0, 0, 0, 0])
    assert module.Rpdo2.unpack(bytes([1, 0, 0xFF, 2, 0xFF, 0xFF, 0xFF, 0xFF])) == module.Rpdo2(1, 2)


def test_pdo_values_are_checked(tmp_path: Path, odd_eds: Path) -> None:
    module = generated_module(odd_eds, tmp_path, "odd_bits")
    with pytest.raises(ValueError, match=r"Tpdo2\.odd_values_int24: 8388608 is above 8388607"):
        module.Tpdo2(odd_values_int24=1 << 23).pack()
    with pytest.raises(ValueError, match="odd_values_uint40: -1 is below 0"):
        module.Tpdo2(odd_values_uint40=-1).pack()
    with pytest.raises(ValueError, match="outside the range of REAL32"):
        module.Tpdo3(odd_values_real=1e39).pack()
    with pytest.raises(TypeError, match="takes an int"):
        module.Tpdo2(odd_values_int24="1").pack()
    with pytest.raises(ValueError, match="Tpdo2 has 8 bytes, not 7"):
        module.Tpdo2.unpack(bytes(7))
    assert module.Tpdo2.unpack(bytes(12)) == module.Tpdo2()  # a longer (CAN FD) frame is fine


def test_field_names_avoid_methods(tmp_path: Path) -> None:
    from pykit import eds_text, pdo, record

    objects = [record(0x2000, "Data", [("Pack", 0x5, "rw", "0"), ("Unpack", 0x5, "rw", "0")])]
    objects.append(pdo("tx", 1, [(0x2000, 1, 8), (0x2000, 2, 8), (0x2000, 1, 8)]))
    path = tmp_path / "clash.eds"
    path.write_text(eds_text(objects).replace("ParameterName=Data", "ParameterName=P"))
    module = generated_module(path, tmp_path, "clash")
    assert [f.name for f in dataclasses.fields(module.Tpdo1)] == ["p_pack", "p_unpack", "p_pack_2"]


# --- SDO over a virtual bus ------------------------------------------------------------------------------


@pytest.fixture
def bus(tmp_path: Path) -> Iterator[tuple[ModuleType, Any, canopen.LocalNode, list[Any]]]:
    """(generated module, Device on a RemoteNode, the LocalNode serving it, frames the client sent)."""
    path = EXAMPLES / "io_device.eds"
    module = generated_module(path, tmp_path, "io_device")
    channel = f"cantools-od-{uuid.uuid4().hex}"
    with virtual_network(channel) as server_net, virtual_network(channel) as client_net:
        local = canopen.LocalNode(5, canopen.import_od(str(path), 5))
        server_net.add_node(local)
        remote = canopen.RemoteNode(5, canopen.import_od(str(path), 5))
        remote.sdo.RESPONSE_TIMEOUT = 5.0  # a busy CI machine must not turn a slow answer into a failure
        client_net.add_node(remote)
        sent: list[Any] = []
        send = client_net.send_message

        def spy(can_id: int, data: bytes, remote: bool = False) -> None:
            sent.append((can_id, bytes(data)))
            send(can_id, data, remote)

        client_net.send_message = spy  # type: ignore[method-assign]
        yield module, module.Device(remote), local, sent
        local.nmt.stop_heartbeat()


def test_sdo_read_and_write(bus: tuple[ModuleType, Any, canopen.LocalNode, list[Any]]) -> None:
    _, device, local, sent = bus
    assert device.producer_heartbeat_time == 1000
    device.producer_heartbeat_time = 500
    assert local.sdo[0x1017].raw == 500 and sent
    assert device.producer_heartbeat_time == 500
    assert device.identity_object.vendor_id == 0x0CA7
    assert device.manufacturer_device_name == "cantools-od example I/O module"  # segmented upload
    assert device.cob_id_emcy == 0x85  # $NODEID+0x80 for node 5
    settings = device.device_settings
    settings.input_filter_enable = False
    assert local.sdo[0x2000][1].raw is False and settings.input_filter_enable is False
    settings.analog_scaling_factor = 2.5
    assert local.sdo[0x2000][3].raw == 2.5 and settings.analog_scaling_factor == 2.5
    settings.location_tag = "rack 7, slot 3"  # segmented download
    assert local.sdo[0x2000][4].raw == "rack 7, slot 3" and settings.location_tag == "rack 7, slot 3"
    device.write_output_8_bit.digital_outputs_1_to_8 = 0xA5
    assert local.sdo[0x6200][1].raw == 0xA5
    local.sdo[0x6401][2].raw = -1234
    assert device.read_analog_input_16_bit.analog_input_2 == -1234


def test_limits_are_checked_before_sending(bus: tuple[ModuleType, Any, canopen.LocalNode, list[Any]]) -> None:
    _, device, local, sent = bus
    with pytest.raises(ValueError, match=r"0x2000:02 'Input filter time': 5000 is above 1000, HighLimit"):
        device.device_settings.input_filter_time = 5000
    with pytest.raises(ValueError, match=r"0 is below 1, LowLimit \(limits 1\.\.1000\)"):
        device.device_settings.input_filter_time = 0
    with pytest.raises(ValueError, match=r"0x1017:00 'Producer heartbeat time': 65536 is above 65535"):
        device.producer_heartbeat_time = 65536
    with pytest.raises(ValueError, match="-1 is below 0"):
        device.producer_heartbeat_time = -1
    with pytest.raises(TypeError, match="takes an int, not str"):
        device.producer_heartbeat_time = "500"
    with pytest.raises(ValueError, match="ASCII only"):
        device.device_settings.location_tag = "Ä"
    with pytest.raises(ValueError, match="outside the range of REAL32"):
        device.device_settings.analog_scaling_factor = 1e40
    assert sent == []  # nothing went on the bus
    assert local.sdo[0x2000][2].raw == 10 and local.sdo[0x1017].raw == 1000
    device.device_settings.input_filter_time = 1000  # the limit itself is allowed
    assert local.sdo[0x2000][2].raw == 1000


def test_read_only_objects_have_no_setter(bus: tuple[ModuleType, Any, canopen.LocalNode, list[Any]]) -> None:
    module, device, local, sent = bus
    with pytest.raises(AttributeError):
        device.device_type = 1
    with pytest.raises(AttributeError):
        device.identity_object.vendor_id = 1
    with pytest.raises(AttributeError):
        device.identity_object = None
    assert module.Device.device_type.fset is None
    assert module.Device.producer_heartbeat_time.fset is not None
    assert sent == [] and local.sdo[0x1018][1].raw == 0x0CA7


def test_device_on_a_local_node(tmp_path: Path) -> None:
    path = EXAMPLES / "cia402_drive.eds"
    module = generated_module(path, tmp_path, "cia402_drive")
    local = canopen.LocalNode(3, canopen.import_od(str(path), 3))
    for device in (module.Device(local), module.Device(local.sdo)):
        device.target_torque = -3000
        assert local.sdo[0x6071].raw == -3000 and device.target_torque == -3000
        with pytest.raises(ValueError, match="-3001 is below -3000, LowLimit"):
            device.target_torque = -3001
        device.target_position = -1_000_000_000
        assert device.target_position == -1_000_000_000
    assert local.sdo[0x6071].raw == -3000


def test_real_boolean_and_wide_values_on_a_local_node(tmp_path: Path) -> None:
    from pykit import eds_text, var

    objects = [
        var(0x2000, "Gain", 0x8, "rw", "1.0", LowLimit="-1.5", HighLimit="2.5"),
        var(0x2001, "Enable", 0x1, "rw", "1"),
        var(0x2002, "Wide", 0x13, "rw", "-5"),  # INTEGER48
        var(0x2003, "Command", 0x7, "wo", "0"),
        var(0x2004, "Blob", 0xA, "rw", "0102"),
    ]
    path = tmp_path / "values.eds"
    path.write_text(eds_text(objects))
    module = generated_module(path, tmp_path, "values")
    local = canopen.LocalNode(1, canopen.import_od(str(path), 1))
    device = module.Device(local)
    assert device.gain == 1.0 and device.enable is True and device.wide == -5 and device.blob == b"\x01\x02"
    device.gain, device.enable, device.wide, device.blob = -1.5, False, -(1 << 47), b"\xff"
    assert (local.sdo[0x2000].raw, local.sdo[0x2001].raw, local.sdo[0x2002].raw) == (-1.5, False, -(1 << 47))
    assert local.sdo[0x2004].raw == b"\xff"
    for bad in (2.75, float("nan"), float("inf")):
        with pytest.raises(ValueError, match=r"0x2000:00 'Gain'"):
            device.gain = bad
    with pytest.raises(ValueError, match="above 140737488355327"):
        device.wide = 1 << 47
    with pytest.raises(TypeError, match="takes a bool"):
        device.enable = 2
    device.command = 7
    assert local.sdo[0x2003].raw == 7
    with pytest.raises(AttributeError, match="write-only"):
        device.command  # noqa: B018
    assert local.sdo[0x2000].raw == -1.5


# --- the object dictionary ------------------------------------------------------------------------------


def _entries(od: canopen.ObjectDictionary) -> dict[tuple[int, int], dict[str, Any]]:
    found: dict[tuple[int, int], dict[str, Any]] = {}
    for index in od:
        obj = od[index]
        if isinstance(obj, canopen.objectdictionary.ODVariable):
            variables, kind = [obj], "var"
        else:
            variables = [obj[sub] for sub in obj]
            kind = type(obj).__name__
        for var in variables:
            found[index, var.subindex] = {
                "kind": kind,
                "group": obj.name,
                **{key: getattr(var, key) for key in ("name", "data_type", "access_type", "pdo_mappable")},
                **{key: getattr(var, key) for key in ("default", "value", "relative", "min", "max")},
            }
    return found


def _canopen_comparable(entries: dict[tuple[int, int], dict[str, Any]]) -> dict[tuple[int, int], dict[str, Any]]:
    """Without what python-canopen's reader drops: limits it cannot read, and dummy-usage variables."""
    return {
        key: {k: v for k, v in entry.items() if k not in ("min", "max") or v is not None}
        for key, entry in entries.items()
        if key[0] >= 0x1000
    }


@pytest.mark.parametrize("node_id", [None, 5])
@pytest.mark.parametrize("name", [*EXAMPLE_FILES, "odd_bits.eds"])
def test_object_dictionary_matches_python_canopen(
    name: str, node_id: int | None, tmp_path: Path, odd_eds: Path
) -> None:
    path = odd_eds if name == "odd_bits.eds" else EXAMPLES / name
    module = generated_module(path, tmp_path, Path(name).stem)
    generated = _entries(module.object_dictionary(node_id))
    assert generated == _entries(to_canopen(load(path), node_id))
    theirs = _canopen_comparable(_entries(canopen.import_od(str(path), node_id)))
    ours = _canopen_comparable(generated)
    assert {k: {f: v for f, v in e.items() if f in theirs[k]} for k, e in ours.items()} == theirs
    od = module.object_dictionary(node_id)
    assert od.node_id == node_id
    assert od.device_information.vendor_name == load(path).device_info.vendor_name


def test_to_canopen_serves_a_local_node() -> None:
    device = load(EXAMPLES / "io_device.eds")
    od = to_canopen(device, 7)
    assert od[0x1800][1].default == 0x187 and od[0x1800][1].relative
    assert od[0x2000][2].min == 1 and od[0x2000][2].max == 1000
    local = canopen.LocalNode(7, od)
    assert local.sdo[0x1018][1].raw == 0x0CA7
    assert local.sdo[0x2000][3].raw == 1.0


def test_to_canopen_is_lazy() -> None:
    code = "import cantools_od, sys; cantools_od.to_canopen; assert 'canopen' not in sys.modules, 'canopen imported'"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr


# --- mypy --strict --------------------------------------------------------------------------------------------

MYPY_CONFIG = """\
[mypy]
strict = True
python_version = 3.11

[mypy-canopen.*]
ignore_missing_imports = True
"""


def test_generated_modules_pass_mypy_strict(tmp_path: Path, odd_eds: Path) -> None:
    mypy = shutil.which("mypy", path=str(Path(sys.executable).parent)) or shutil.which("mypy")
    if mypy is None:
        pytest.skip("mypy is not installed")
    folder = tmp_path / "generated"
    folder.mkdir()
    sources = [EXAMPLES / name for name in EXAMPLE_FILES] + [odd_eds]
    corpus = corpus_files()
    sources += corpus[:: max(1, len(corpus) // 6)][:6]
    written = 0
    for number, path in enumerate(sources):
        result = run_gen(path, "-t", "python", "-o", folder, "--name", f"module_{number}")
        if (folder / f"module_{number}.py").exists():
            written += 1
        else:
            assert result.exit_code == 1 and "GEN001" in result.output, result.output
    assert written >= 3
    user = folder / "use.py"  # the generated API used as a typed program would
    user.write_text(
        "import canopen\n"
        "from module_0 import Device, Tpdo1, object_dictionary\n\n\n"
        "def main(node: canopen.RemoteNode, local: canopen.LocalNode) -> None:\n"
        "    device = Device(node)\n"
        "    device.producer_heartbeat_time = device.producer_heartbeat_time + 1\n"
        "    vendor: int = device.identity_object.vendor_id\n"
        "    tag: str = Device(local).device_settings.location_tag\n"
        "    pdo: Tpdo1 = Tpdo1.unpack(Tpdo1(1, 2, 3).pack())\n"
        "    od: canopen.ObjectDictionary = object_dictionary()\n"
        "    print(vendor, tag, pdo, od)\n"
    )
    config = tmp_path / "mypy.ini"
    config.write_text(MYPY_CONFIG)
    command = [mypy, "--config-file", str(config), "--cache-dir", str(tmp_path / "cache"), str(folder)]
    result = subprocess.run(command, cwd=folder, capture_output=True, text=True, timeout=900)
    assert result.returncode == 0, result.stdout + result.stderr
    assert f"no issues found in {written + 1} source files" in result.stdout
