"""`lint` on the project files of the real CANopenNode projects (real_projects.py), judged finding by finding.

Each project file is checked with the installed CLI twice: plainly, and with `--profile canopennode` and the
project's own CO_driver_target.h. Every error either run reported when judged is listed below with its verdict
and the reason: true when the CANopenNode device built from the file, or a peer reading it (python-canopen, lely's
dcf tools, a CiA 302 master), does other than the file says; false when the device and every peer do what the file
says. The errors reported must be exactly the true ones: a new error nobody judged fails, a true one that went
away fails, and a false one (its rule since put right) that comes back fails with the reason it was judged false.
"""

from __future__ import annotations

import json
import subprocess
from dataclasses import dataclass
from pathlib import Path

import mirrors
import pytest
from real_projects import PROJECTS, Project

from support import cli_command


@dataclass(frozen=True)
class Judged:
    code: str
    lines: tuple[int, ...]
    true: bool
    reason: str


IDENTITY = (
    "the device identity the description names differs from 1018h, which the CANopenNode device answers (and its "
    "LSS slave uses): lely's dcfgen takes the description's value for the master's boot-up check (1F85h-1F88h), "
    "which then fails, and an LSS master selecting by it finds no device"
)
IDENTITY_ZERO = (
    "ProductNumber 0 in the description, 53310000h in 1018h sub2: lely's dcf tools take the 0 (and check nothing), "
    "every other reader the 1018h value; CiA 306 makes them one value"
)
PROGRAM_CONTROL = (
    "CiA 302-3 program control sub-indices are UNSIGNED8 and a flash master writes one byte; CANopenNode's SDO "
    "server aborts a one-byte download into this four-byte entry (0607 0013h, validateAndWriteToOD in "
    "CO_SDOserver.c)"
)
TPDO_DUMMY = (
    "CANopenNode maps a dummy entry in a TPDO to OD_read_dummy and sends zeros in its place (301/CO_PDO.c): the "
    "device does what the file says (CiA 301 gives dummy mappings to receivers only, PDO051's word for a device "
    "no stack is named for; these are CANopenEditor files, CANopenNode's by either run)"
)
RPDO_SUB6 = (
    "sub0 says 6 but only sub0-sub2 exist (an RPDO has no sub6 at all): a master reading up to the highest "
    "sub-index is answered 'sub-index does not exist'"
)
PROJECT_LINT: dict[str, tuple[Judged, ...]] = {
    "Apach200/0_F407:CANopenNode_STM32/DS301_profile.xdd": (
        Judged("EDS040", (23,), True, IDENTITY),
        Judged("COB009", (1597, 1633, 1705, 1741, 1777, 1813, 1849, 1885, 1921), True,
               "TPDOs share a CAN-ID: by CiA 306 TPDO2-TPDO4 are all $NODEID+0x280; on CANopenNode (which adds "
               "the node-ID only to a TPDO's own pre-defined base, CO_PDO.c) TPDO2 sends on 280h+node and TPDO3 to "
               "TPDO12 all on 280h, every one valid with mapped objects"),
        Judged("PDO051", (2011,), False, TPDO_DUMMY),
    ),
    "EvgenyDD/sh_gateway:app/profile.xdd": (Judged("STD003", (2995,), True, PROGRAM_CONTROL),),
    "EvgenyDD/sh_node:app/profile.xdd": (Judged("STD003", (2573,), True, PROGRAM_CONTROL),),
    "EvgenyDD/sh_node:ldr/profile.xdd": (Judged("STD003", (2371,), True, PROGRAM_CONTROL),),
    "Inviz/stm32app:src/configs/Base.xdd": (
        Judged("EDS040", (21, 23), True, IDENTITY),
        Judged("EDS035", (3021,), True,
               "4000h sub5's default 12 is below its own allowed range 33-600; lely's dcfchk reports "
               "'DefaultValue underflow in [4000sub5]'"),
    ),
    "MEIKO-T-ED/CANopenNode:IO_Board_sim.xdd": (
        Judged("EDS040", (21,), True, IDENTITY),
        Judged("EDS040", (23,), True, IDENTITY_ZERO),
    ),
    "lv-atomi/canopen-site-firmware:user/canopen/application/DS301_profile3.xdd": (
        Judged("EDS040", (21, 23), True, IDENTITY),
    ),
    "samkwok-hkclr/packaging_machine:CANopenNode_STM32/packaging_machine.xpd": (
        Judged("EDS040", (21, 23), True, IDENTITY),
    ),
    "sudriabotik/carte_lidar_stm32:CANopenNode_STM32/DS301_profile.eds": (
        Judged("DIA019", (17, 19), True, "empty VendorNumber and ProductNumber: python-canopen's import_od raises "
               "ValueError, the file cannot be loaded"),
        Judged("PDO010", (654,), True, RPDO_SUB6),
        Judged("EDS033", (450, 588, 597), True,
               "0x80+$NODEID, 0x600+$NODEID, 0x580+$NODEID: CiA 306 writes $NODEID first; lely's dcfchk rejects the "
               "value and dcfgen's Device.from_dcf refuses the file, so a lely master cannot take this EDS"),
        Judged("PDO044", (696, 705, 714, 723), True,
               "RPDO1 writes 2200h-2203h, AccessType=ro: CiA 301 lets an RPDO write writable entries only, and the "
               "OD gen makes gives them ODA_TPDO (CNO010), so the stack refuses RPDO1's mapping (ODR_NO_MAP); only "
               "CANopenEditor's ODA_TRPDO for every PDOMapping=1 makes it work. The author means rww"),
    ),
    "sicrisembay/CANopenNode_C2000_bootloader:c2000_bootloader.xdd": (
        Judged("STD003", (271,), True, PROGRAM_CONTROL),
    ),
    "thaanstad/ESP32_CanOpenNode:src/DS301_profile.xpd": (
        Judged("PDO051", (1466, 1481, 1496), False, TPDO_DUMMY + " (and TPDO2-TPDO4 are disabled, bit 31)"),
    ),
    "catompiler/slcan_canopen:OD.xdd": (Judged("EDS040", (21, 23), True, IDENTITY),),
    "x893/CANopenNode-VG015:OD/CANbp.xdd": (Judged("EDS040", (23,), True, IDENTITY),),
    "zylos146/CANFuck:linmot.xdd": (Judged("PDO010", (751, 771, 791, 811), True, RPDO_SUB6),),
    "twhitford27/FinalMEng:CANopenNode_STM32/DS301_profile.xpd": (
        Judged("COB004", (843,), True,
               "1800h sub1 is 0x180 as written: CANopenNode sends on 180h + node-ID, python-canopen and lely read "
               "the restricted CAN-ID 180h, so a master configured from the file listens on another ID"),
        Judged("PDO042", (883,), True,
               "TPDO1 maps 6000h, which is not in the OD (only 6001h is): CANopenNode reports CO_EM_PDO_WRONG_MAPPING "
               "and TPDO1, with nothing mapped, never sends"),
    ),
    "skpang/ESP32S3_CANOpenNode_trainer:ESP32S3_CO_trainer_OD/ESP32S3_CO_trainer_OD.xdd": (
        Judged("EDS040", (21, 23), True, IDENTITY),
        Judged("PDO051", (1128, 1133, 1138), False, TPDO_DUMMY),
    ),
    "dmBots/dm_canopen:eds/dm4310_master.xdd": (
        Judged("EDS026", (824,), True,
               "1016h sub0 is 2 while sub-indices 1-9 are described (and stored: OD.c's array has 9): the device "
               "answers 2 to a master that reads how many heartbeat consumers it has, and serves 9"),
        Judged("COB009", (1597,), True,
               "TPDO2 and TPDO3 both store 0x301, which is neither one's pre-defined base, so CANopenNode sends both "
               "on 301h as written (CO_PDO.c adds the node-ID to a base COB-ID only): two PDOs on one CAN-ID"),
    ),
}  # fmt: skip


def _errors(project: Project, folder: Path, profile: bool) -> set[tuple[str, int]]:
    paths = [project.source, *project.stack_config]
    mirrors.materialize(project.repo, project.commit, paths, folder)
    source = folder / project.source
    before = source.read_bytes()
    extra = ["--profile", "canopennode", *(f"--stack-config={folder / p}" for p in paths[1:])] if profile else []
    result = subprocess.run(
        [*cli_command(), "lint", "--format", "json", *extra, str(source)], capture_output=True, text=True, check=False
    )
    assert result.returncode in (0, 1), result.stderr
    assert source.read_bytes() == before
    findings = json.loads(result.stdout)
    errors = {(f["code"], f["line"]) for f in findings if f["severity"] == "error"}
    assert (result.returncode == 1) == bool(errors)
    return errors


def test_every_judged_project_is_in_the_manifest() -> None:
    assert set(PROJECT_LINT) <= {p.key for p in PROJECTS}


@pytest.mark.parametrize("profile", [False, True], ids=["plain", "canopennode"])
@pytest.mark.parametrize("project", PROJECTS, ids=[p.key for p in PROJECTS])
def test_lint_reports_the_judged_errors_of_a_real_project(project: Project, profile: bool, tmp_path: Path) -> None:
    mirrors.require(project.repo)
    found = _errors(project, tmp_path / "project", profile)
    judged = {(j.code, line): j for j in PROJECT_LINT.get(project.key, ()) for line in j.lines}
    assert found - judged.keys() == set(), "errors nobody judged"
    true = {key for key, j in judged.items() if j.true}
    assert true - found == set(), "true errors no longer reported"
    false = {f"{code} at line {line}: {judged[code, line].reason}" for code, line in found - true}
    assert sorted(false) == [], "errors judged false"
