"""What a check holds and costs beyond the device: what rules share (`Context.once`, lint/rules.py) lives only as
long as the family that made it, since each walk holds an item per entry of the device and holding every family's
walks at once was the peak memory of checking a large file (bench/bench_scale.py measures it); and no collector pass
runs while the rules do (cantools_od/collector.py)."""

from __future__ import annotations

import gc
from pathlib import Path

import pytest

from cantools_od import load
from cantools_od.lint import lint, runner
from cantools_od.lint.config import Selection
from cantools_od.lint.objlists import _missing
from cantools_od.lint.rules import Context, Finding, Rule

from support import corpus_file

EXAMPLES = Path(__file__).resolve().parents[2] / "eds"


def test_a_family_starts_without_the_walks_of_the_families_before_it(monkeypatch: pytest.MonkeyPatch) -> None:
    seen: list[tuple[str, set[str]]] = []
    run = runner._run

    def recording(rule: Rule, context: Context, selection: Selection) -> tuple[list[Finding], bool]:
        if not seen or seen[-1][0] != rule.family:
            seen.append((rule.family, set(context.memo)))
        return run(rule, context, selection)

    monkeypatch.setattr(runner, "_run", recording)
    device = load(EXAMPLES / "cia402_drive.eds")
    findings = lint(device)
    families = [family for family, _ in seen]
    assert {"objects", "dcf", "objlists", "values", "portability"} <= set(families)
    assert all(not held for _, held in seen), [(family, held) for family, held in seen if held]
    monkeypatch.undo()
    assert findings == lint(load(EXAMPLES / "cia402_drive.eds")), "forgetting changes no finding"


@pytest.mark.parametrize(
    ("positions", "missing"),
    [([], []), ([1, 2, 3], []), ([2, 5], [1, 3, 4]), ([1, 4, 5, 9], [2, 3, 6, 7, 8]), ([3], [1, 2])],
)
def test_the_numbers_missing_from_an_object_list(positions: list[int], missing: list[int]) -> None:
    assert list(_missing(positions)) == missing


def test_a_check_makes_no_collector_pass() -> None:
    """The collector is paused while rules run (cantools_od/collector.py): on a 16 MB file its full passes over the
    model took a fifth of `lint`'s time, and the pauses between them grow with the device."""
    device = load(corpus_file("sevcon__Nano_pc0x04013019_rev0x0001000b.eds"))  # the largest file: 17,000 sections
    passes: list[int] = []

    def count(phase: str, info: dict[str, int]) -> None:
        if phase == "start":
            passes.append(info["generation"])

    gc.callbacks.append(count)
    try:
        lint(device)
    finally:
        gc.callbacks.remove(count)
    assert passes == [], f"collector passes during the check, generations {passes}"
    assert gc.isenabled(), "the collector runs again after the check"
