"""Rule documentation as a product: docs/rules.md is generated and current, every rule example runs.

A rule's failing example (cantools_od/lint/exampleset.py: an EDS or XDD fragment framed into a minimal
valid file, other files, or the command line that reports the code) must report exactly its code, and
the companions it names with `; also:`, at a line of the example; its fixed example reports nothing
(but those companions).
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

from cantools_od.lint.codes import Code, codes
from cantools_od.lint.exampleset import default_name, parse
from cantools_od.lint.ruledocs import explain, markdown, run_code_example

from support import ROOT

SHARED_DOCS = re.compile(r"\b(?:cia306|pdo-rules|vendor-manuals|peers)\.md\b")
PRINTED_CODE = re.compile(r"\[([A-Z]{3}\d{3})\]")
# Codes no file or command line can make the tool print: they stand for a bug of the tool itself.
NO_EXAMPLE = {
    "LNT001": "a rule that raises; the linter's own tests inject one (tests/test_lint_framework.py)",
}
# Codes whose failing example has no corrected form: a file refused unread, or a bug of the tool.
NO_FIXED = {"LNT001", "XDD003"}

ALL = sorted(codes())
WITH_EXAMPLE = [c for c in ALL if c not in NO_EXAMPLE]


def test_rules_md_is_current() -> None:
    written = (ROOT / "docs" / "rules.md").read_text(encoding="utf-8")
    assert written == markdown(), "docs/rules.md is stale: python -m cantools_od.lint.ruledocs > docs/rules.md"


def test_rule_texts_cite_standards_not_our_notes() -> None:
    for code, found in codes().items():
        rule = found.rule
        text = "\n".join((rule.summary, rule.description, rule.example, rule.fixed, rule.fix_safety, rule.refs))
        assert not SHARED_DOCS.search(text), f"{code} cites a document users do not have"


@pytest.mark.parametrize("code", ALL)
def test_every_code_is_documented_in_full(code: str) -> None:
    """Why, a failing example, a fixed one, what --fix does, and the standard's sections it rests on."""
    found = codes()[code]
    text = explain(found)
    assert found.rule.description, f"{code} says not why"
    assert code in NO_EXAMPLE or "Example:" in text, f"{code} has no example"
    assert code in NO_FIXED or found.rule.fixed, f"{code} has no fixed example"
    assert "\nFix: " in "\n" + text, f"{code} does not say what --fix does"
    references = next((line for line in text.splitlines() if line.startswith("References: ")), "")
    assert re.search(r"CiA \d{3}", references), f"{code} cites no section of a CiA standard"


def _run_commands(text: str, default: str, folder: Path) -> tuple[set[str], int]:
    """Write the example's files into `folder`, run its command lines there with the installed
    cantools-od first on PATH: the codes printed, and the last command's exit code."""
    folder.mkdir()
    example = parse(text, default)
    for file in example.files:
        data, _ = file.content()
        (folder / file.name).write_bytes(data)
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ.get('PATH', '')}"}
    printed, status = "", 0
    for command in example.commands:
        result = subprocess.run(
            ["bash", "-c", command], cwd=folder, env=env, capture_output=True, text=True, timeout=120
        )
        printed += result.stdout + result.stderr
        status = result.returncode
    assert "Traceback" not in printed, printed
    return set(PRINTED_CODE.findall(printed)), status


def _reported(found: Code, text: str, folder: Path) -> tuple[set[str], list[int | None]]:
    """The codes an example reports, and the example lines its own code is reported at (none for commands)."""
    if parse(text).commands:
        return _run_commands(text, default_name(found.family), folder)[0], []
    outcome = run_code_example(found, text)
    return outcome.codes(), outcome.lines(found.code)


@pytest.mark.parametrize("code", WITH_EXAMPLE)
def test_failing_example_reports_exactly_its_code(code: str, tmp_path: Path) -> None:
    found = codes()[code]
    reported, lines = _reported(found, found.rule.example, tmp_path / "failing")
    assert code in reported, f"{code}: its example does not report it"
    assert reported == {code, *parse(found.rule.example).also}, f"{code}: its example reports {sorted(reported)}"
    assert None not in lines, f"{code}: reported at a line the frame added, outside the example"


@pytest.mark.parametrize("code", [c for c in ALL if codes()[c].rule.fixed])
def test_fixed_example_is_clean(code: str, tmp_path: Path) -> None:
    found = codes()[code]
    reported, _ = _reported(found, found.rule.fixed, tmp_path / "fixed")
    assert reported <= set(parse(found.rule.fixed).also), f"{code}: its fixed example reports {sorted(reported)}"
