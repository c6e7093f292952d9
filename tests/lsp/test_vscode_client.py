"""The VS Code client in editors/vscode: its manifest, its EDS/DCF grammar on real lines, and its build."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest

from support import EXAMPLES, ROOT, corpus_devices

VSCODE = ROOT / "editors" / "vscode"


def _grammar() -> dict[str, dict[str, object]]:
    grammar = json.loads((VSCODE / "syntaxes" / "eds.tmLanguage.json").read_text())
    assert grammar["scopeName"] == "source.canopen-eds"
    repository: dict[str, dict[str, object]] = grammar["repository"]
    return repository


def _rule(name: str, key: str = "match") -> re.Pattern[str]:
    return re.compile(str(_grammar()[name][key]))


def test_the_manifest_associates_every_format_with_the_server_and_a_grammar() -> None:
    manifest = json.loads((VSCODE / "package.json").read_text())
    extensions = {e for language in manifest["contributes"]["languages"] for e in language["extensions"]}
    assert extensions == {".eds", ".dcf", ".xdd", ".xdc", ".xpd"}
    for grammar in manifest["contributes"]["grammars"]:
        assert json.loads((VSCODE / grammar["path"]).read_text())["scopeName"] == grammar["scopeName"]
    assert manifest["scripts"]["compile"] and (VSCODE / "package-lock.json").is_file()
    ignored = (VSCODE / ".gitignore").read_text().split()
    assert "node_modules/" in ignored and "out/" in ignored


def test_the_grammar_scopes_sections_keys_and_values() -> None:
    section, entry = _rule("section"), _rule("entry", "begin")
    sub = section.match("[1A00sub1]")
    assert sub is not None and (sub.group(2), sub.group(3), sub.group(4)) == ("1A00", "sub", "1")
    named = section.match("[FileInfo]")
    assert named is not None and named.group(6) == "FileInfo"
    compact = section.match("[1003Value]")
    assert compact is not None and compact.group(5) == "Value"
    key = entry.match("DefaultValue=$NODEID+0x180")
    assert key is not None and key.group(1) == "DefaultValue"
    assert _rule("comment").match("; cantools-od: ignore PDO001") and not _rule("comment").match("Key=1 ; x")
    values = [re.compile(str(p["match"])) for p in _grammar()["entry"]["patterns"]]  # type: ignore[index, union-attr]
    rest = "$NODEID+0x180"
    found = {p.pattern: [m.group(0) for m in p.finditer(rest)] for p in values}
    assert ["$NODEID"] in found.values() and ["0x180"] in found.values()


@pytest.mark.parametrize("path", [EXAMPLES / "cia402_drive.eds", *corpus_devices()[:20]], ids=lambda p: p.name)
def test_every_line_of_a_real_file_is_a_comment_a_section_or_an_entry(path: Path) -> None:
    rules = [_rule("comment"), _rule("section"), _rule("entry", "begin")]
    text = path.read_bytes().decode("utf-8", "replace")
    strays = [line for line in text.splitlines() if line.strip() and not any(r.match(line) for r in rules)]
    assert not strays, strays[:3]


@pytest.mark.skipif(shutil.which("npm") is None, reason="npm is not on this machine")
def test_the_client_builds_with_npm_ci(tmp_path: Path) -> None:
    copy = tmp_path / "vscode"
    shutil.copytree(VSCODE, copy, ignore=shutil.ignore_patterns("node_modules", "out"))
    for step in (["npm", "ci", "--no-audit", "--no-fund"], ["npm", "run", "compile"]):
        result = subprocess.run(step, cwd=copy, capture_output=True, text=True, timeout=600)
        assert result.returncode == 0, result.stdout[-2000:] + result.stderr[-2000:]
    assert (copy / "out" / "extension.js").is_file()
