"""A safe fix never changes what a reader sees: on every corpus file and every XDD, all safe fixes applied,
python-canopen (with and without a node-ID) reads every entry as before, lely's dcfchk accepts what it accepted,
and cantools-od reads the same model; [DeviceInfo] changes only to a DCF's 1018h ParameterValue (see
tests/fixsafety.py). The fix-safety table of docs/commands/lint.md says which fixes `--fix` applies and which only
`--unsafe-fixes`: it matches what the fixes show on the rule examples and the corpus."""

from __future__ import annotations

import os
import re
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

import pytest
from fixsafety import Change, judge_fixes

from cantools_od import loads
from cantools_od.lint import lint
from cantools_od.lint.codes import codes
from cantools_od.lint.ruledocs import run_code_example

from support import CORPUS, ROOT, corpus_devices

XDD = CORPUS.parent / "xdd"

# Both tests read one module fixture (every corpus file fixed and judged): under pytest-xdist they run on one
# worker, which makes it once.
pytestmark = pytest.mark.xdist_group("fix_peers")


def _job(job: tuple[Path, Path]) -> tuple[list[Change], set[tuple[str, bool]]]:
    return judge_fixes(*job)


@pytest.fixture(scope="module")
def judged(tmp_path_factory: pytest.TempPathFactory) -> tuple[list[Change], set[tuple[str, bool]], int]:
    files = corpus_devices() + (sorted(XDD.iterdir()) if XDD.is_dir() else [])
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    folder = tmp_path_factory.mktemp("fixes")
    jobs = [(path, folder / str(n)) for n, path in enumerate(files)]
    with ProcessPoolExecutor(max_workers=os.cpu_count() or 1) as pool:
        results = list(pool.map(_job, jobs))
    changes = [change for found, _ in results for change in found]
    seen = {pair for _, pairs in results for pair in pairs}
    return changes, seen, len(files)


def test_no_safe_fix_changes_what_a_peer_reads(judged: tuple[list[Change], set[tuple[str, bool]], int]) -> None:
    changes, seen, files = judged
    assert files > 100
    assert {code for code, safe in seen if safe} >= {"EDS012", "EDS014", "EDS021", "EDS040"}  # the test tests fixes
    assert [str(change) for change in changes] == []


def _table() -> dict[str, set[bool]]:
    """The fix-safety table of lint's page: code -> the safeties its rows give (`--fix`: True, `--unsafe-fixes`:
    False)."""
    text = (ROOT / "docs" / "commands" / "lint.md").read_text(encoding="utf-8")
    block = text[text.index("| Code | Fix | Applied by |") :].split("\n\n", 1)[0]
    table: dict[str, set[bool]] = {}
    for row in block.splitlines()[2:]:
        cells = [cell.strip() for cell in row.strip("|").split("|")]
        for code in re.findall(r"[A-Z]{3}\d{3}", cells[0]):
            table.setdefault(code, set()).add(cells[2] == "`--fix`")
    return table


# Wrong counts of a CompactSubObj's names and of ObjectLinks: no rule example nor corpus file has them (EDS104's
# example is a section without its object).
COUNTS = (
    "[2000]\nParameterName=A\nObjectType=0x8\nDataType=0x0005\nAccessType=ro\nCompactSubObj=3\n"
    "[2000Name]\nNrOfEntries=5\n1=First\n[2000ObjectLinks]\nObjectLinks=3\n1=0x2000\n"
)


def _example_safeties() -> set[tuple[str, bool]]:
    found = {(f.code, f.fix.safe) for f in lint(loads(COUNTS, source="t.eds")) if f.fix is not None}
    for code in codes().values():
        if not code.rule.example:
            continue
        outcome = run_code_example(code, code.rule.example)
        found |= {(f.code, f.fix.safe) for f, _ in outcome.findings if f.code == code.code and f.fix is not None}
    return found


def test_documented_fix_table_matches_the_fixes(judged: tuple[list[Change], set[tuple[str, bool]], int]) -> None:
    table = _table()
    shown = judged[1] | _example_safeties()
    missing = sorted(f"{code} {'safe' if ok else 'unsafe'}" for code, ok in shown if ok not in table.get(code, ()))
    assert missing == [], "fixes the fix-safety table of docs/commands/lint.md does not list"
    unseen = sorted(code for code in table if not any(seen_code == code for seen_code, _ in shown))
    assert unseen == [], (
        "codes in the fix-safety table of docs/commands/lint.md whose fix no example or corpus file shows"
    )
