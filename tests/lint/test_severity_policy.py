"""The severity policy of docs/rules.md: error when a peer tool reads the file otherwise than it says (or cannot
load it) or a device built from it misbehaves; warning for portability or style. Built from real files of
../shared read in place through the installed CLI."""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest

from cantools_od.lint.codes import codes
from cantools_od.model import Severity

from support import ROOT, SHARED, cli_command

HISTORY = SHARED / "eds-history"

# What a rule's text says when python-canopen (or lely) cannot load a file that has the finding.
_CANNOT_LOAD = re.compile(r"(cannot|fails? to) load|load nothing|stops it loading|fail on the file", re.IGNORECASE)


def _lint(path: Path, select: str) -> list[tuple[str, str, str]]:
    if not path.is_file():
        pytest.skip(f"{path} is absent")
    done = subprocess.run(
        [*cli_command(), "lint", "-j1", "--format", "json", "--select", select, str(path)],
        capture_output=True,
        text=True,
    )
    assert done.returncode in (0, 1), done.stderr
    return [(f["code"], f["severity"], f["message"]) for f in json.loads(done.stdout)]


def test_every_code_whose_finding_stops_a_peer_loading_the_file_is_an_error() -> None:
    placed = {code.code: code.rule.severity for code in codes().values() if _CANNOT_LOAD.search(code.rule.description)}
    assert {"DIA019", "DIA020", "DIA021"} <= set(placed)
    assert {code: severity for code, severity in placed.items() if severity is not Severity.ERROR} == {}


def test_real_files_python_canopen_cannot_load_fail_lint() -> None:
    import canopen  # the peer: it refuses both files

    empty_number = HISTORY / "lv-atomi__canopen-site-firmware__1" / "old.eds"  # ProductNumber=
    comment_case = HISTORY / "CANopenNode__CANopenSocket__1" / "new.eds"  # line5=
    for path, code in ((empty_number, "DIA019"), (comment_case, "DIA021")):
        with pytest.raises(Exception):  # noqa: B017 - python-canopen raises ValueError or NoOptionError
            canopen.import_od(str(path))
        assert {severity for found, severity, _ in _lint(path, code) if found == code} == {"error"}


def test_a_key_every_peer_passes_over_on_a_record_header_is_a_warning() -> None:
    # bggardner/canopen-rpi: DataType on the 1018h and 1200h RECORD headers; python-canopen reads the sub-objects
    found = _lint(HISTORY / "bggardner__canopen-rpi__1" / "old.eds", "EDS024")
    headers = [(severity, message) for _, severity, message in found if "type RECORD" in message]
    assert ("warning", "[1018]: DataType is not allowed on an object of type RECORD") in headers
    assert {severity for severity, _ in headers} == {"warning"}


def test_rules_md_states_the_policy() -> None:
    text = (ROOT / "docs" / "rules.md").read_text(encoding="utf-8")
    assert "## Severity policy" in text
    assert "a peer tool reads the file otherwise than it says" in text
