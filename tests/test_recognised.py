"""A device description is recognised, not assumed: INI text without a CiA 306 section (setup.cfg, .gitconfig) and
JSON that is no model (`[]`) are refused by every command with one EDS000 line and exit code 2, and left byte for
byte; every real EDS/DCF/XDD/XDC of ../shared, eds/ and examples/ is still read."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from cantools_od.api import load
from cantools_od.sniff import NotADeviceDescription

from support import ROOT, SHARED, cli_command

# Files of other tools, by the name they have there and under a device description's name.
OTHERS = {
    "setup.cfg": b"[metadata]\nname = foo\nversion = 1\n\n[options]\npackages = find:\n",
    ".gitconfig": b"[user]\n\tname = Foo Bar\n\temail = foo@example.com\n[core]\n\tautocrlf = input\n",
    "tox.ini": b"[tox]\nenvlist = py311\n\n[testenv]\ncommands = pytest\n",
    "settings.eds": b"[metadata]\nname = foo\n",
    "list.json": b"[]\n",
    "list.eds": b"[]\n",
    "package.json": b'{"name": "x", "version": "1.0.0"}\n',
}

COMMANDS = {
    "fmt": ["fmt", "{file}"],
    "fmt --check": ["fmt", "--check", "{file}"],
    "lint --fix": ["lint", "--fix", "--unsafe-fixes", "{file}"],
    "dump": ["dump", "{file}"],
    "convert to XDD": ["convert", "{file}", "-o", "out.xdd"],
    "convert to EDS": ["convert", "{file}", "-o", "out.eds"],
}


@pytest.mark.parametrize("command", list(COMMANDS))
@pytest.mark.parametrize("name", list(OTHERS))
def test_a_file_of_another_tool_is_refused_and_left_alone(tmp_path: Path, name: str, command: str) -> None:
    path = tmp_path / name
    path.write_bytes(OTHERS[name])
    path.chmod(0o644)
    if command.startswith("convert") and path.suffix not in (".eds", ".json"):
        pytest.skip("convert refuses an unknown extension before reading (a usage error of its own)")
    args = [part.format(file=name) for part in COMMANDS[command]]
    ran = subprocess.run([*cli_command(), *args], cwd=tmp_path, capture_output=True, text=True, timeout=120)
    said = ran.stdout + ran.stderr
    assert ran.returncode == 2, said
    refusals = [line for line in said.splitlines() if line.endswith("[EDS000]")]
    assert len(refusals) == 1 and name in refusals[0], said
    assert "reformatted" not in said and "Traceback" not in said, said
    assert path.read_bytes() == OTHERS[name]
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]  # nothing written beside it either


def _descriptions() -> list[Path]:
    roots = [SHARED, ROOT / "eds", ROOT / "examples"]
    suffixes = (".eds", ".dcf", ".xdd", ".xdc", ".xpd")
    return sorted(p for root in roots if root.is_dir() for p in root.rglob("*") if p.suffix.lower() in suffixes)


def test_every_real_device_description_is_recognised() -> None:
    """The sweep: no EDS, DCF, XDD or XDC of real projects is taken for another tool's file; the only ones refused
    hold nothing at all."""
    files = _descriptions()
    if not SHARED.is_dir():
        pytest.skip("../shared is absent")
    refused = []
    for path in files:
        try:
            load(path)
        except NotADeviceDescription as refusal:
            if path.read_bytes().strip():
                refused.append(f"{path}: {refusal}")
    assert len(files) > 250
    assert refused == []
