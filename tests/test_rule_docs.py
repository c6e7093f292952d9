"""Rule documentation as a product: docs/rules.md is generated and current, every rule example runs.

A rule's failing example, framed into a minimal valid EDS (cantools_od/lint/examples.py), must
trigger exactly its rule, at a line of the example; its fixed example must lint clean.
"""

from __future__ import annotations

import re

import pytest

from cantools_od.lint.codes import FAMILIES, codes
from cantools_od.lint.examples import fragment_line, run
from cantools_od.lint.ruledocs import markdown

from support import ROOT

# Families whose examples are no EDS fragment (XML, tables, other commands' inputs): their own tests run them.
TOOL_FAMILIES = tuple(name for name, family in FAMILIES.items() if not family.eds_examples)
SHARED_DOCS = re.compile(r"\b(?:cia306|pdo-rules|vendor-manuals|peers)\.md\b")

RULE_CODES = sorted(code for code, c in codes().items() if c.family not in TOOL_FAMILIES)
# Examples that do not yet trigger exactly their rule inside the frame: a section the frame always adds
# (EDS009, EDS011, EDS019), a code another always accompanies (DIA012 with EDS070, DIA005 with EDS081,
# PDO045/PDO046 with PDO053, DIA008 with DIA005, EDS018 with EDS010, PDO002 with PDO012), a second file (COB011)
# or bytes (EDS100, EDS102), or no EDS at all (EDS000, JSN001), or a 1018h that the frame's own
# 1018h sub-objects join (STD002, STD004). The test below fails as soon as one runs, so that the list only shrinks.
PENDING = {
    *("COB011", "DIA005", "DIA008", "EDS009", "EDS011", "EDS018", "EDS019", "EDS070", "EDS081", "EDS100", "EDS102"),
    *("PDO002", "PDO053", "EDS000", "JSN001", "STD002", "STD004"),
}


def test_rules_md_is_current() -> None:
    written = (ROOT / "docs" / "rules.md").read_text(encoding="utf-8")
    assert written == markdown(), "docs/rules.md is stale: python -m cantools_od.lint.ruledocs > docs/rules.md"


def test_rule_texts_cite_standards_not_our_notes() -> None:
    for code, found in codes().items():
        rule = found.rule
        text = "\n".join((rule.summary, rule.description, rule.example, rule.fixed, rule.fix_safety, rule.refs))
        assert not SHARED_DOCS.search(text), f"{code} cites a document users do not have"


def _triggers_exactly(code: str, example: str) -> bool:
    text, findings = run(example)
    mine = [f for f in findings if f.code == code]
    inside = all(fragment_line(example, text, f.location.line) is not None for f in mine)
    return bool(mine) and inside and all(f.code == code for f in findings)


@pytest.mark.parametrize("code", [c for c in RULE_CODES if c not in PENDING])
def test_failing_example_triggers_exactly_its_rule(code: str) -> None:
    example = codes()[code].rule.example
    assert example, f"{code} has no example"
    text, findings = run(example)
    mine = [f for f in findings if f.code == code]
    assert mine, f"{code}: its example does not trigger it"
    assert all(fragment_line(example, text, f.location.line) is not None for f in mine), "reported outside the example"
    assert [f.format() for f in findings if f.code != code] == []


@pytest.mark.parametrize("code", sorted(PENDING))
def test_pending_examples_are_still_pending(code: str) -> None:
    assert not _triggers_exactly(code, codes()[code].rule.example), f"{code} runs now: remove it from PENDING"


@pytest.mark.parametrize("code", [c for c in RULE_CODES if codes()[c].rule.fixed])
def test_fixed_example_is_clean(code: str) -> None:
    _, findings = run(codes()[code].rule.fixed)
    assert [f.format() for f in findings] == []
