"""Every finding has a place a user can go to: a line and a column from 1, in every output format, for every
real file of ../shared and for inputs that keep no positions (a model written as JSON by hand) or put a bad
value where the reader once gave the section's line only. A place not known within the file is the file's
start, 1:1, said alike in text, JSON, SARIF and GitHub annotations (#39: `file:0:0`)."""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any

import pytest
from kit import GOOD, run

from support import shared_files

TEXT_POSITION = re.compile(r"^(?P<file>[^\s:][^:]*):(?P<line>\d+):(?P<column>\d+): (error|warning|info): ", re.M)


def _without_positions(value: Any) -> Any:
    """A model as someone writes it by hand or from another tool: no `origin` anywhere."""
    if isinstance(value, dict):
        return {key: _without_positions(item) for key, item in value.items() if key != "origin"}
    if isinstance(value, list):
        return [_without_positions(item) for item in value]
    return value


@pytest.fixture
def inputs(tmp_path: Path) -> list[str]:
    (tmp_path / "io.eds").write_bytes(GOOD)
    assert run("convert", "io.eds", "-o", "model.json", cwd=tmp_path).returncode == 0
    model = json.loads((tmp_path / "model.json").read_text(encoding="utf-8"))
    del model["objects"]["4096"]["data_type"]  # 1000h: an error the JSON cannot place
    (tmp_path / "handmade.json").write_text(json.dumps(_without_positions(model)), encoding="utf-8")
    listed = GOOD.replace(b"[OptionalObjects]\nSupportedObjects=", b"[OptionalObjects]\n99=zz\nSupportedObjects=")
    assert listed != GOOD
    (tmp_path / "list.eds").write_bytes(listed)
    return ["handmade.json", "list.eds"]


def _json_positions(stdout: str) -> list[tuple[str, int, int, str]]:
    return [(f["file"], f["line"], f["column"], f["code"]) for f in json.loads(stdout)]


def test_findings_without_a_place_are_at_the_file_start_in_every_format(tmp_path: Path, inputs: list[str]) -> None:
    text = run("lint", *inputs, cwd=tmp_path)
    shown = [(m["file"], int(m["line"]), int(m["column"])) for m in TEXT_POSITION.finditer(text.stdout)]
    assert shown and all(line >= 1 and column >= 1 for _, line, column in shown), text.stdout
    assert ("handmade.json", 1, 1) in shown and ":0:" not in text.stdout
    found = _json_positions(run("lint", "--format", "json", *inputs, cwd=tmp_path).stdout)
    assert all(line >= 1 and column >= 1 for _, line, column, _ in found), found
    assert ("handmade.json", 1, 1, "EDS020") in found
    sarif = json.loads(run("lint", "--format", "sarif", *inputs, cwd=tmp_path).stdout)
    regions = [r["locations"][0]["physicalLocation"].get("region") for r in sarif["runs"][0]["results"]]
    assert regions and all(r is not None and r["startLine"] >= 1 and r["startColumn"] >= 1 for r in regions)
    github = run("lint", "--format", "github", *inputs, cwd=tmp_path).stdout
    assert github and not re.search(r",(line|col)=0,", github)


def test_a_bad_list_entry_is_found_at_its_value(tmp_path: Path, inputs: list[str]) -> None:
    found = _json_positions(run("lint", "--format", "json", "--select", "EDS030", "list.eds", cwd=tmp_path).stdout)
    line = GOOD.split(b"\n").index(b"[OptionalObjects]") + 2
    assert found == [("list.eds", line, 4, "EDS030")]


def test_every_finding_over_shared_has_a_line_and_column(tmp_path: Path) -> None:
    files = shared_files((".eds", ".dcf", ".xdd", ".xdc"))
    if not files:
        pytest.skip("../shared is absent")
    ran = run("lint", "--format", "json", "--jobs", "2", *files, cwd=tmp_path, timeout=600)
    found = _json_positions(ran.stdout)
    assert len({file for file, *_ in found}) > len(files) // 2
    unplaced = [f for f in found if f[1] < 1 or f[2] < 1]
    assert not unplaced, unplaced[:10]
