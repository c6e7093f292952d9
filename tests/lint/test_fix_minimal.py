"""`lint --fix` changes only the lines its fixes name: empty keys stay, repeated list numbers move
into free numbers, and a second `lint` shows the fixed findings gone and no new ones."""

from __future__ import annotations

import bisect
import difflib
import re
import shutil
import subprocess
from collections import Counter
from pathlib import Path

import pytest

from cantools_od import dumps, load, loads
from cantools_od.lint import Finding, lint

from support import cli_command, corpus_file, corpus_params


def _anchors(old: list[str], new: list[str]) -> list[tuple[int, int]]:
    """Lines that occur once in each text, in an order both agree on (patience diff's anchors)."""
    once_old, once_new = _unique(old), _unique(new)
    pairs = sorted((i, once_new[line]) for line, i in once_old.items() if line in once_new)
    # longest increasing run of new positions (patience sorting)
    tails: list[int] = []
    links: list[int | None] = [None] * len(pairs)
    tops: list[int] = []
    for n, (_, j) in enumerate(pairs):
        at = bisect.bisect_left(tails, j)
        if at == len(tails):
            tails.append(j)
            tops.append(n)
        else:
            tails[at], tops[at] = j, n
        links[n] = tops[at - 1] if at else None
    chain: list[tuple[int, int]] = []
    k: int | None = tops[-1] if tops else None
    while k is not None:
        chain.append(pairs[k])
        k = links[k]
    return chain[::-1]


def _unique(lines: list[str]) -> dict[str, int]:
    counts = Counter(lines)
    return {line: n for n, line in enumerate(lines) if counts[line] == 1}


def changed_lines(before: bytes, after: bytes) -> list[int]:
    """Lines of `before` (from 1) that `after` rewrites or drops; added lines are not counted.

    A patience diff: unique lines anchor the texts, the short stretches between anchors are compared
    line by line (a plain SequenceMatcher is quadratic on files of thousands of like lines)."""
    old = before.decode("latin-1").splitlines()
    new = after.decode("latin-1").splitlines()
    changed: list[int] = []
    start_old = start_new = 0
    for i, j in [*_anchors(old, new), (len(old), len(new))]:
        matcher = difflib.SequenceMatcher(None, old[start_old:i], new[start_new:j], autojunk=False)
        for tag, i1, i2, _, _ in matcher.get_opcodes():
            if tag in ("replace", "delete"):
                changed.extend(range(start_old + i1 + 1, start_old + i2 + 1))
        start_old, start_new = i + 1, j + 1
    return changed


def named_lines(applied: list[Finding]) -> set[int]:
    return {f.location.line for f in applied} | {line for f in applied if f.fix for line in f.fix.lines}


def fix_with_cli(tmp_path: Path, source: Path, *options: str) -> tuple[bytes, bytes]:
    copy = tmp_path / source.name
    shutil.copyfile(source, copy)
    command = [*cli_command(), "lint", "--fix", *options, copy.name]
    subprocess.run(command, cwd=tmp_path, capture_output=True, timeout=120)
    return source.read_bytes(), copy.read_bytes()


def test_fix_keeps_the_empty_keys_of_the_section_it_edits(tmp_path: Path) -> None:
    text = (
        "[2135]\nParameterName=Limits\nObjectType=0x8\nSubNumber=4\n\n"
        "[2135sub0]\nParameterName=Number of entries\nDataType=0x0005\nAccessType=ro\nLowLimit=\nHighLimit=\n"
        "ObjFlags=\nDefaultValue=2\n\n"
        + "".join(
            f"[2135sub{n}]\nParameterName=Limit {n}\nDataType=0x0006\nAccessType=rw\nDefaultValue=0\n\n"
            for n in (1, 2, 3)
        )
    )
    source = tmp_path / "in" / "t.eds"
    source.parent.mkdir()
    source.write_text(text)
    _, after = fix_with_cli(tmp_path, source, "--select", "EDS026", "--unsafe-fixes")
    assert after.decode() == text.replace("DefaultValue=2", "DefaultValue=3")


def test_fix_keeps_empty_parameter_values_of_a_real_dcf(tmp_path: Path) -> None:
    before, after = fix_with_cli(tmp_path, corpus_file("oresat__c3.dcf"), "--unsafe-fixes")
    assert after != before  # the file has fixes ($NODEID spellings, mapping lengths: both unsafe)
    empty = before.count(b"\nParameterValue=\n") + before.count(b"\nParameterValue=\r\n")
    assert empty and after.count(b"\nParameterValue=\n") + after.count(b"\nParameterValue=\r\n") == empty


def test_fix_keeps_the_limits_of_roboteq_2135sub0(tmp_path: Path) -> None:
    source = corpus_file("roboteq__roboteq_motor_controllers_v2.0-30-01-2019.eds")
    before, after = fix_with_cli(tmp_path, source, "--unsafe-fixes")
    section = re.compile(rb"\[2135sub0\][^\[]*")
    old, new = section.search(before), section.search(after)
    assert old is not None and new is not None
    assert b"LowLimit=" in old.group() and b"HighLimit=" in old.group()
    old_lines, new_lines = old.group().splitlines(), new.group().splitlines()
    assert [(a, b) for a, b in zip(old_lines, new_lines, strict=True) if a != b] == [
        (b"DefaultValue=0x2", b"DefaultValue=0x03")
    ]


def test_repeated_list_number_moves_to_the_free_number(tmp_path: Path) -> None:
    source = corpus_file("infranor__Easy-ak_v1.30.eds")
    before, after = fix_with_cli(tmp_path, source)
    old, new = before.decode("latin-1").splitlines(), after.decode("latin-1").splitlines()
    assert len(old) == len(new)
    diff = [(n, a, b) for n, (a, b) in enumerate(zip(old, new, strict=True), 1) if a != b]
    assert [(a, b) for _, a, b in diff] == [("12=0x3079", "13=0x3079")]
    codes = {f.code for f in lint(loads(after, source=source.name))}
    assert not codes & {"EDS002", "EDS012", "EDS014", "EDS015"}


def test_repeated_number_fix_in_a_small_list() -> None:
    text = (
        "[OptionalObjects]\nSupportedObjects=4\n1=0x1008\n2=0x1009\n2=0x100A\n2=0x1017\n\n"
        "[1008]\nParameterName=Name\nDataType=0x0009\nAccessType=const\n\n"
        "[1009]\nParameterName=HW\nDataType=0x0009\nAccessType=const\n\n"
        "[100A]\nParameterName=SW\nDataType=0x0009\nAccessType=const\n\n"
        "[1017]\nParameterName=Heartbeat\nDataType=0x0006\nAccessType=rw\n"
    )
    device = loads(text, source="t.eds")
    found = [f for f in lint(device) if f.code == "EDS015"]
    assert [f.location.line for f in found] == [5, 6]
    for finding in found:
        assert finding.fix is not None and finding.fix.safe
        finding.fix.apply(device)
    fixed = dumps(device).decode()
    assert fixed == text.replace("2=0x100A", "3=0x100A").replace("2=0x1017", "4=0x1017")
    assert not [f for f in lint(loads(fixed, source="t.eds")) if f.code in ("EDS002", "EDS014", "EDS015")]


def _same(finding: Finding) -> tuple[str, str]:
    """A finding as a second run reports it, whatever lines were added above it."""
    return finding.code, re.sub(r"line \d+", "line N", finding.message)


@pytest.mark.parametrize("path", corpus_params())
def test_fix_on_corpus_is_minimal_and_final(path: Path) -> None:
    device = load(path)
    findings = lint(device)
    applied = [f for f in findings if f.fix is not None and f.fix.safe]
    if not applied:
        return
    for finding in applied:
        assert finding.fix is not None
        finding.fix.apply(device)
    before = path.read_bytes()
    after = dumps(device, "dcf" if device.is_dcf else "eds")
    unnamed = sorted(set(changed_lines(before, after)) - named_lines(applied))
    assert unnamed == [], f"lines no applied fix names: {unnamed[:10]}"
    again = {_same(f) for f in lint(loads(after, fmt="dcf" if device.is_dcf else "eds", source=str(path)))}
    fixed = {_same(f) for f in applied}
    assert not again & fixed, f"fixed findings remain: {sorted(again & fixed)[:5]}"
    assert not again - {_same(f) for f in findings}, f"new findings: {sorted(again - {_same(f) for f in findings})[:5]}"
