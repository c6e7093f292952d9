"""`gen -t canopennode` as a user runs it: names, --explain, overrides, refusals, depfile, determinism."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

from cnokit import DEMO, WARNINGS, gen, includes, run, stack

from support import cli_command


def demo_copy(tmp_path: Path) -> Path:
    stack()
    source = tmp_path / "demoDevice.eds"
    shutil.copyfile(DEMO / "demoDevice.eds", source)
    return source


def test_default_name_explain_and_byte_identical_reruns(tmp_path: Path) -> None:
    source = demo_copy(tmp_path)
    result = gen(source, tmp_path / "out", "--explain")
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["OD.c", "OD.h"]
    assert "inferred: 1017h: count label HB_PROD inferred from the index (OD_CNT_HB_PROD)" in result.stderr
    assert "inferred: 1200sub1: default $NODEID+0x600 stored as 0x600" in result.stderr
    first = {p.name: p.read_bytes() for p in (tmp_path / "out").iterdir()}
    mtimes = {p.name: p.stat().st_mtime_ns for p in (tmp_path / "out").iterdir()}
    assert gen(source, tmp_path / "out").returncode == 0
    assert {p.name: p.read_bytes() for p in (tmp_path / "out").iterdir()} == first
    assert {p.name: p.stat().st_mtime_ns for p in (tmp_path / "out").iterdir()} == mtimes  # not rewritten
    assert b"201" not in first["OD.h"].split(b"*/")[0]  # no date in the banner


def test_override_file_sets_string_capacity_and_is_a_dependency(tmp_path: Path) -> None:
    source = demo_copy(tmp_path)
    (tmp_path / "demoDevice.canopennode.toml").write_text(
        "[2121sub2]\nstring_length_min = 1000\n[2122]\ndisabled = true\n"
    )
    result = gen(source, tmp_path / "out", "--name", "OD1", "--depfile", str(tmp_path / "od.d"), "--explain")
    assert result.returncode == 0, result.stderr
    header = (tmp_path / "out" / "OD1.h").read_text()
    assert "char stringLong[1001];" in header and "#define OD1_CNT_NMT 1" in header
    assert "H2122" not in header
    assert "set: 2121sub2: string_length_min = 1000" in result.stderr
    assert "demoDevice.canopennode.toml" in (tmp_path / "od.d").read_text()
    run(["gcc", *WARNINGS, *includes(tmp_path / "out"), "-c", "OD1.c", "-o", "od1.o"], cwd=tmp_path / "out")


def test_refusals_write_nothing(tmp_path: Path) -> None:
    source = demo_copy(tmp_path)
    (tmp_path / "demoDevice.canopennode.toml").write_text("[2121sub2]\nstring_length_min = 'long'\n")
    bad = gen(source, tmp_path / "out")
    assert bad.returncode == 2 and "string_length_min: expected an integer" in bad.stderr
    (tmp_path / "demoDevice.canopennode.toml").write_text("[1017]\ndisabled = true\n")
    refused = gen(source, tmp_path / "out")
    assert refused.returncode == 1
    assert "CNO005" in refused.stderr and "nothing generated" in refused.stderr
    assert not (tmp_path / "out").exists()


def test_objects_of_switched_functions_follow_the_declared_stack_configuration(tmp_path: Path) -> None:
    source = demo_copy(tmp_path)
    settings = tmp_path / "demoDevice.canopennode.toml"
    settings.write_text("[1003]\ndisabled = true\n[1016]\ndisabled = true\n")
    # Nothing declared: the stack's defaults would need 1003h and 1016h; warnings name the switches, and it generates.
    unknown = gen(source, tmp_path / "out", cwd=tmp_path)
    assert unknown.returncode == 0, unknown.stderr
    assert (
        "warning: 1001h counts as EM, so CANopen.c also uses 1003h when built with CO_CONFIG_EM & "
        "CO_CONFIG_EM_HISTORY" in unknown.stderr
    )
    assert "OD_CNT_HB_CONS when built with CO_CONFIG_HB_CONS & CO_CONFIG_HB_CONS_ENABLE" in unknown.stderr
    assert "#define OD_ENTRY_H1003 " not in (tmp_path / "out" / "OD.h").read_text()
    # The project's own CO_driver_target.h turns both functions off: nothing to say.
    target = tmp_path / "CO_driver_target.h"
    target.write_text("#define CO_CONFIG_EM (CO_CONFIG_EM_PRODUCER | \\\n    CO_CONFIG_GLOBAL_FLAG_TIMERNEXT)\n"
                      "#define CO_CONFIG_HB_CONS 0\n")  # fmt: skip
    off = gen(source, tmp_path / "off", "--stack-config", str(target), "--depfile", str(tmp_path / "od.d"))
    assert off.returncode == 0 and "CNO005" not in off.stderr, off.stderr
    assert str(target) in (tmp_path / "od.d").read_text()
    # A [stack] table that keeps the history on makes the missing 1003h an error: the stack would not start.
    settings.write_text(
        settings.read_text() + '[stack]\nCO_CONFIG_EM = "CO_CONFIG_EM_PRODUCER | CO_CONFIG_EM_HISTORY"\n'
    )
    refused = gen(source, tmp_path / "on", "--stack-config", str(target))
    assert refused.returncode == 1 and "error: 1001h counts as EM, so CANopen.c also uses 1003h" in refused.stderr
    assert "CO_CONFIG_EM & CO_CONFIG_EM_HISTORY" in refused.stderr and "CNO005" in refused.stderr
    assert "HB_CONS" not in refused.stderr and not (tmp_path / "on").exists()
    # [tool.cantools-od] ignore still applies.
    (tmp_path / "pyproject.toml").write_text('[tool.cantools-od]\nignore = ["CNO005"]\n')
    assert gen(source, tmp_path / "on", "--stack-config", str(target), cwd=tmp_path).returncode == 0


def test_unreadable_stack_configuration_is_a_usage_error(tmp_path: Path) -> None:
    source = demo_copy(tmp_path)
    target = tmp_path / "CO_driver_target.h"
    target.write_text("#define CO_CONFIG_HB_CONS (CO_CONFIG_HB_CONS_ENABLE |)\n")
    bad = gen(source, tmp_path / "out", "--stack-config", str(target))
    assert bad.returncode == 2 and "CO_CONFIG_HB_CONS" in bad.stderr and not (tmp_path / "out").exists()
    missing = gen(source, tmp_path / "out", "--stack-config", str(tmp_path / "absent.h"))
    assert missing.returncode == 2 and "absent.h" in missing.stderr
    (tmp_path / "demoDevice.canopennode.toml").write_text("[stack]\nCO_CONFIG_HB_CONS = true\n")
    assert gen(source, tmp_path / "out").returncode == 2
    (tmp_path / "demoDevice.canopennode.toml").write_text('[stack]\npdo_attributes = "lely"\n')
    wrong = gen(source, tmp_path / "out")
    assert wrong.returncode == 2 and "pdo_attributes" in wrong.stderr


def test_one_name_for_the_c_and_canopennode_targets_is_refused(tmp_path: Path) -> None:
    source = demo_copy(tmp_path)
    both = gen(source, tmp_path / "out", "-t", "c", "--name", "drive")
    assert both.returncode == 2 and "would both write NAME.h/NAME.c" in both.stderr
    assert not (tmp_path / "out").exists()
    assert gen(source, tmp_path / "out", "-t", "c").returncode == 0  # default names differ: OD.* and demo_device.*
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["OD.c", "OD.h", "demo_device.c", "demo_device.h"]


def test_lint_profile_follows_the_declared_stack_configuration(tmp_path: Path) -> None:
    stack()
    text = (DEMO / "demoDevice.eds").read_text(encoding="utf-8")
    # The same device without its heartbeat consumer (1016h and its two sub-objects).
    kept = [s for s in re.split(r"(?m)^(?=\[)", text) if not s.startswith(("[1016]", "[1016sub"))]
    source = tmp_path / "device.eds"
    source.write_text("".join(kept), encoding="utf-8")
    before = source.read_bytes()

    def lint(*args: str) -> subprocess.CompletedProcess[str]:
        command = [*cli_command(), "lint", "--profile", "canopennode", "--select", "CNO005", str(source), *args]
        return subprocess.run(command, capture_output=True, text=True)

    unknown = lint()
    assert unknown.returncode == 0 and "warning" in unknown.stdout and "CO_CONFIG_HB_CONS_ENABLE" in unknown.stdout
    (tmp_path / "on.h").write_text("#define CO_CONFIG_HB_CONS CO_CONFIG_HB_CONS_ENABLE\n")
    needed = lint("--stack-config", str(tmp_path / "on.h"))
    assert needed.returncode == 1 and "error: no object counts as HB_CONS" in needed.stdout
    (tmp_path / "off.h").write_text("#define CO_CONFIG_HB_CONS (0)\n")
    assert "HB_CONS" not in lint("--stack-config", str(tmp_path / "off.h")).stdout
    (tmp_path / "device.canopennode.toml").write_text("[stack]\nCO_CONFIG_HB_CONS = 0\n")
    assert "HB_CONS" not in lint("--stack-config", str(tmp_path / "on.h")).stdout  # the table wins
    assert source.read_bytes() == before
