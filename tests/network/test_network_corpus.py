"""Every corpus device as the one slave of a network, generated here and by lely's dcfgen: where dcfgen
works, both concise DCFs decode to the same writes; where it crashes, ours works or refuses in one line
for a reason of the device's own (a fixed mapping, a COB-ID entry of the wrong type, an empty file).
Both run in this process (the command through click's runner, dcfgen through its own classes) to keep
the sweep quick; the ros2_canopen test runs both as programs.

Each network remaps the device's first TPDO that maps something with the mapping it has, sets
`cob_id: auto` and transmission type 1: the whole dcfgen PDO sequence (disable, settings, remap, enable).
"""

from __future__ import annotations

import argparse
import os
import warnings
from pathlib import Path

import pytest
import yaml
from click.testing import CliRunner

from cantools_od.api import load
from cantools_od.cli import main
from cantools_od.model.cia301.master import read_concise_dcf
from cantools_od.model.cia301.pdo import TX, pdos

from support import CORPUS, file_params

FILES = sorted(CORPUS.glob("*.[de][dc][sf]")) if CORPUS.is_dir() else []
# A device's own reasons for a network to be refused (each one line).
PRINCIPLED = (
    "the master cannot write it",  # a fixed (ro/const) PDO record: the device would refuse the remap at boot
    "is out of its range",  # a COB-ID entry typed too small for a COB-ID
    "no such object",  # a mapping entry naming an object the device does not have
    "not an EDS/DCF file",  # an empty file
)


def bus_for(device_file: Path) -> str:
    device = load(device_file)
    node_id = device.node_id if device.is_dcf and device.node_id and 1 <= device.node_id <= 127 else 2
    text = f"master:\n  node_id: {3 if node_id == 1 else 1}\n  sync_period: 10000\nslave:\n"
    text += f"  dcf: {device_file.name}\n  node_id: {node_id}\n"
    sending = [pdo for pdo in pdos(device) if pdo.direction == TX and pdo.mapped()]
    if sending:
        pdo = sending[0]
        text += f"  tpdo:\n    {pdo.number}:\n      cob_id: auto\n      transmission: 1\n      mapping:\n"
        text += "".join(f"        - {{index: {e.index}, sub_index: {e.subindex}}}\n" for e in pdo.mapped())
    return text


def dcfgen_writes(bus: Path) -> dict[str, list[tuple[int, int, bytes]]]:
    """What dcfgen writes into each .bin for `bus` (its classes, as its main() uses them)."""
    dcfgen = pytest.importorskip("dcfgen.cli")
    cfg = yaml.safe_load(bus.read_text())
    options = {"cob_id": 0x680, "dcf_path": "", "heartbeat_multiplier": 3.0, "retry_factor": 3}
    args = argparse.Namespace(no_strict=True)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        slaves = {}
        for name in cfg:
            if name not in ("master", "options"):
                slave = dcfgen.Slave.from_config(name, cfg[name], options, args)
                if slave.node_id != 255:
                    slaves[name] = slave
        master = dcfgen.Master.from_config(cfg["master"], options, slaves)
    found = {f"{name}.bin": slave.sdo for name, slave in slaves.items() if slave.sdo}
    if master.sdo:
        found["master.bin"] = master.sdo
    return {name: read_concise_dcf(len(sdo).to_bytes(4, "little") + b"".join(sdo)) for name, sdo in found.items()}


@pytest.mark.parametrize("device_file", file_params(FILES, "no corpus"))
def test_corpus_device_as_a_slave(device_file: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    try:
        (tmp_path / "bus.yml").write_text(bus_for(device_file))
    except ValueError:  # no device description at all: the network command says so in one line
        (tmp_path / "bus.yml").write_text(f"master:\n  node_id: 1\nslave:\n  dcf: {device_file.name}\n  node_id: 2\n")
    folder = ["--dcf-dir", str(device_file.parent)]
    args = ["network", "bus.yml", "-o", "ours", "--no-parameter-values", "--no-check", "--keep-going", *folder]
    ours = CliRunner().invoke(main, args)
    if ours.exit_code != 0:
        last = ours.stderr.splitlines()[-1]
        assert (ours.exit_code == 2 and ours.exception is None) or isinstance(ours.exception, SystemExit), ours.stderr
        assert any(reason in last for reason in PRINCIPLED), last
        assert not (tmp_path / "ours").exists()
        return
    flat = (tmp_path / "bus.yml").read_text().replace(f"dcf: {device_file.name}", f"dcf: {device_file}")
    (tmp_path / "flat.yml").write_text(flat)
    try:
        theirs = dcfgen_writes(tmp_path / "flat.yml")
    except Exception as error:  # dcfgen's crashes are what this records
        print(f"dcfgen crashes on {device_file.name} ({type(error).__name__}: {error}); cantools-od generates it")
        return
    mine = {p.name: read_concise_dcf(p.read_bytes()) for p in (tmp_path / "ours").glob("*.bin")}
    assert mine == theirs
    assert os.path.isfile(tmp_path / "ours" / "master.dcf")
