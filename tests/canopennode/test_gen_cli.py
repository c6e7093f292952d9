"""`gen -t canopennode` as a user runs it: names, --explain, overrides, refusals, depfile, determinism."""

from __future__ import annotations

import shutil
from pathlib import Path

from cnokit import DEMO, WARNINGS, gen, includes, run, stack


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


def test_a_project_can_ignore_a_profile_rule_for_a_stack_built_without_that_function(tmp_path: Path) -> None:
    source = demo_copy(tmp_path)
    (tmp_path / "demoDevice.canopennode.toml").write_text("[1003]\ndisabled = true\n")
    refused = gen(source, tmp_path / "out", cwd=tmp_path)
    assert refused.returncode == 1 and "1001h counts as EM, so CANopen.c also uses 1003h [CNO005]" in refused.stderr
    (tmp_path / "pyproject.toml").write_text('[tool.cantools-od]\nignore = ["CNO005"]\n')
    assert gen(source, tmp_path / "out", cwd=tmp_path).returncode == 0
    assert "#define OD_ENTRY_H1003 " not in (tmp_path / "out" / "OD.h").read_text()


def test_one_name_for_the_c_and_canopennode_targets_is_refused(tmp_path: Path) -> None:
    source = demo_copy(tmp_path)
    both = gen(source, tmp_path / "out", "-t", "c", "--name", "drive")
    assert both.returncode == 2 and "would both write NAME.h/NAME.c" in both.stderr
    assert not (tmp_path / "out").exists()
    assert gen(source, tmp_path / "out", "-t", "c").returncode == 0  # default names differ: OD.* and demo_device.*
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == ["OD.c", "OD.h", "demo_device.c", "demo_device.h"]
