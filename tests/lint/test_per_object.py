"""The rules declared `per_object` (lint/rules.py) keep their promise on every real file: judged on the device
cut down to one object (and the data-type definitions), a rule finds on that object's lines exactly what it finds
there on the whole device, and off every object's lines what it finds there on the whole device. The incremental
re-check of the language server (lint/runner.py, `linted(since=...)`) relies on it."""

from __future__ import annotations

from collections import defaultdict
from pathlib import Path

import pytest

from cantools_od import load
from cantools_od.eds.decode import decode_as
from cantools_od.lint import RULES, Finding, LintOptions
from cantools_od.lint.codes import load as load_families
from cantools_od.lint.rules import Context
from cantools_od.lint.runner import _view
from cantools_od.lsp.quick import _Layout

from support import corpus_params


def _object_lines(text: str) -> dict[int, int]:
    """Line (from 1) -> the object whose section holds it."""
    layout = _Layout.of(text)
    total = text.count("\n") + 2
    owner: dict[int, int] = {}
    for at, index in enumerate(layout.objects):
        if index is not None:
            end = layout.lines[at + 1] if at + 1 < len(layout.lines) else total
            owner.update(dict.fromkeys(range(layout.lines[at], end), index))
    return owner


def _by_owner(findings: list[Finding], owner: dict[int, int]) -> dict[int | None, list[str]]:
    found: dict[int | None, list[str]] = defaultdict(list)
    for finding in findings:
        found[owner.get(finding.location.line)].append(finding.format())
    return {key: sorted(value) for key, value in found.items()}


@pytest.mark.parametrize("path", corpus_params())
def test_per_object_rules_judge_one_object_as_the_whole_device_does(path: Path) -> None:
    if path.suffix.lower() not in (".eds", ".dcf"):
        pytest.skip("the incremental re-check is for EDS/DCF text")
    load_families()
    rules = [rule for rule in RULES.values() if rule.per_object and rule.check is not None]
    device, options = load(path), LintOptions()
    owner = _object_lines(decode_as(path.read_bytes())[0])
    whole = Context(device, options)
    expected = {rule.code: _by_owner(list(rule.check(whole)), owner) for rule in rules if rule.check is not None}
    for index in [-1, *device.objects]:
        view = Context(_view(device, index), options)
        for rule in rules:
            assert rule.check is not None
            found = _by_owner(list(rule.check(view)), owner)
            for key in (index, None) if index == -1 else (index,):
                assert found.get(key, []) == expected[rule.code].get(key, []), (rule.code, hex(index))
