"""Every command works on XDD as on EDS: gen gives the EDS twin's output, lint --fix, fmt, dump, pdo, convert."""

from __future__ import annotations

import re
import shutil
import subprocess
from pathlib import Path

import pytest
from xddkit import CANOPENNODE_EXAMPLE, DEMO, MANDATORY, document, shared_file

from cantools_od import api

from support import cli_command

TWINS = [
    (DEMO / "demoDevice.xdd", DEMO / "demoDevice.eds"),
    (CANOPENNODE_EXAMPLE / "DS301_profile.xpd", CANOPENNODE_EXAMPLE / "DS301_profile.eds"),
]


def _run(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), *args], capture_output=True, text=True, cwd=cwd)


def _generated(tmp_path: Path, source: Path) -> dict[str, str]:
    tmp_path.mkdir()
    copy = tmp_path / f"device{source.suffix}"  # one stem for both: generated code names its source file
    shutil.copyfile(source, copy)
    targets = ("-t", "c", "-t", "rust", "-t", "python", "-t", "markdown")
    result = _run(tmp_path, "gen", copy.name, *targets, "-o", "out", "--name", "demo")
    assert result.returncode == 0, result.stderr
    return {path.name: path.read_text() for path in sorted((tmp_path / "out").iterdir())}


def _same_device(text: str) -> str:
    """The output without what names the source format (legitimately different between twins).

    - the source file's name (also as FileName) and line numbers (Markdown's `file:line` references);
    - the device rows from CiA 306-only keys: RevisionNumber (CANopenEditor writes 0 into
      the EDS where its XDD has none), FileRevision and EDSVersion.
    """
    text = re.sub(r"\w+(\\)?\.(xdd|xpd|eds)(\\:\d+)?", "SOURCE", text)
    text = re.sub(r"\| (Revision number|File version|EDS version) \|[^\n]*", "", text)
    return re.sub(r"revision_number=(None|0),", "", text)


@pytest.mark.parametrize(("xdd", "eds"), [pytest.param(x, e, id=x.name) for x, e in TWINS])
def test_gen_from_xdd_equals_gen_from_its_eds(tmp_path: Path, xdd: Path, eds: Path) -> None:
    from_xdd = _generated(tmp_path / "x", shared_file(xdd))
    from_eds = _generated(tmp_path / "e", shared_file(eds))
    assert sorted(from_xdd) == sorted(from_eds)
    code = sorted(name for name in from_xdd if not name.endswith(".svg"))  # beside the page: its PDO pictures
    assert code == ["demo.c", "demo.h", "demo.md", "demo.py", "demo.rs"]
    for name in from_xdd:
        if name == "demo.md" or name == "demo.py":
            assert _same_device(from_xdd[name]) == _same_device(from_eds[name]), name
        else:
            assert from_xdd[name].splitlines()[1:] == from_eds[name].splitlines()[1:], name


def test_lint_fix_edits_the_xml_minimally(tmp_path: Path) -> None:
    wrong = (
        '<CANopenObject index="1014" name="COB-ID EMCY" dataType="0007" accessType="rw" defaultValue="0x80+$nodeid" />'
    )
    text = document(MANDATORY + "\n" + wrong)
    path = tmp_path / "dev.xdd"
    path.write_text(text)
    before = _run(tmp_path, "lint", "dev.xdd", "--select", "EDS033")
    assert "EDS033" in before.stdout
    line = next(n for n, t in enumerate(text.splitlines(), 1) if "0x80+$nodeid" in t)
    assert f"dev.xdd:{line}:" in before.stdout
    # unsafe (a peer reads a value from the new spelling it did not read from the old): --unsafe-fixes applies it
    assert _run(tmp_path, "lint", "dev.xdd", "--select", "EDS033", "--fix").returncode == 0
    assert path.read_text() == text
    assert _run(tmp_path, "lint", "dev.xdd", "--select", "EDS033", "--fix", "--unsafe-fixes").returncode == 0
    assert path.read_text() == text.replace("0x80+$nodeid", "$NODEID+0x80")


def test_fmt_dump_pdo_and_convert_on_xdd(tmp_path: Path) -> None:
    source = shared_file(DEMO / "demoDevice.xdd")
    path = tmp_path / "demo.xdd"
    shutil.copyfile(source, path)
    shutil.copyfile(shared_file(DEMO / "demoDevice.eds"), tmp_path / "demo.eds")
    assert _run(tmp_path, "dump", "demo.xdd").returncode == 0
    pdo = _run(tmp_path, "pdo", "demo.xdd", "--node-id", "5")
    assert pdo.returncode == 0 and "RPDO1 (1400/1600)  COB-ID 0x205" in pdo.stdout
    assert pdo.stdout == _run(tmp_path, "pdo", "demo.eds", "--node-id", "5").stdout
    assert _run(tmp_path, "fmt", "--check", "demo.xdd").returncode == 1  # CANopenEditor's layout is not ours
    assert _run(tmp_path, "fmt", "demo.xdd").returncode == 0
    assert _run(tmp_path, "fmt", "--check", "demo.xdd").returncode == 0
    formatted = api.load(path)
    assert formatted.content() == api.load(source).content()
    assert _run(tmp_path, "convert", "demo.xdd", "-o", "out.eds").returncode == 0
    assert b";StorageLocation=PERSIST_COMM" in (tmp_path / "out.eds").read_bytes()
    assert _run(tmp_path, "convert", "out.eds", "-o", "again.xpd").returncode == 0
    again = api.load(tmp_path / "again.xpd")
    assert again.objects[0x1000].canopennode is not None
    assert again.objects[0x1000].canopennode.storage_group == "PERSIST_COMM"
    assert _run(tmp_path, "convert", "demo.xdd", "-o", "node.xdc").returncode != 0  # an XDC is for one node
    assert _run(tmp_path, "convert", "demo.xdd", "-o", "node.xdc", "--node-id", "5").returncode == 0
    node = api.load(tmp_path / "node.xdc")
    assert node.is_dcf and node.node_id == 5
