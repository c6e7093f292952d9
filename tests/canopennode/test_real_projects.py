"""Public CANopenNode v4 projects (real_projects.py): ours against the OD.c CANopenEditor generated for them.

For each project the project file is generated with default options (`gen -t canopennode`, exit 0),
and again with the project's own CO_driver_target.h (`--stack-config`); ours is compiled with the
stack's CO_ODinterface.c and walked (od_walk.c); their OD.c/OD.h are read as text (editor_od.py,
never built) into the same shape. Every object, sub-entry count and type, every sub-entry's attribute,
length, storage group and default bytes, and every name of OD.h (OD_ENTRY_H..., x<index>_...) must
agree, except the differences the manifest documents with their reason.
"""

from __future__ import annotations

import re
from pathlib import Path

import mirrors
import pytest
from cnokit import Entry, gen, stack, walk
from editor_od import EditorOD
from real_projects import PROJECTS, Project


def names(header: str) -> set[str]:
    return set(re.findall(r"#define (OD_ENTRY_H\w+)", header)) | set(re.findall(r"\bx[0-9A-F]{4}_\w+", header))


def compare(ours: dict[int, Entry], theirs: dict[int, Entry]) -> tuple[int, dict[tuple[int, int], str]]:
    """The number of sub-entries compared, and where ours and theirs differ (object-level differences at sub -1)."""
    found: dict[tuple[int, int], str] = {}
    for index in sorted(set(ours) ^ set(theirs)):
        found[index, -1] = "only in ours" if index in ours else "only in CANopenEditor's"
    compared = 0
    for index in sorted(set(ours) & set(theirs)):
        mine, seen = ours[index], theirs[index]
        if (mine.sub_count, mine.kind) != (seen.sub_count, seen.kind):
            found[index, -1] = (
                f"ours {mine.sub_count} sub-entries type {mine.kind}, theirs {seen.sub_count} {seen.kind}"
            )
        for sub in sorted(set(mine.subs) | set(seen.subs)):
            compared += 1
            if mine.subs.get(sub) != seen.subs.get(sub):
                found[index, sub] = f"ours {mine.subs.get(sub)}, CANopenEditor's {seen.subs.get(sub)}"
    return compared, found


@pytest.mark.parametrize("project", PROJECTS, ids=[p.key for p in PROJECTS])
def test_real_project_agrees_with_canopeneditor_entry_for_entry(project: Project, tmp_path: Path) -> None:
    stack()
    mirrors.require(project.repo)
    paths = [project.source, *project.stack_config]
    mirrors.materialize(project.repo, project.commit, paths, tmp_path / "project")
    source = tmp_path / "project" / project.source
    plain = gen(source, tmp_path / "plain")
    assert plain.returncode == 0, plain.stderr
    if project.settings:
        source.with_suffix(".canopennode.toml").write_text(project.settings, encoding="utf-8")
    configured = gen(source, tmp_path / "ours", *(f"--stack-config={tmp_path / 'project' / p}" for p in paths[1:]))
    assert configured.returncode == 0, configured.stderr
    assert "error" not in configured.stderr, configured.stderr
    their_c = mirrors.show(project.repo, project.commit, project.od_file("OD.c")).decode("utf-8", "replace")
    their_h = mirrors.show(project.repo, project.commit, project.od_file("OD.h")).decode("utf-8", "replace")
    theirs = EditorOD(their_c, their_h).entries()
    ours = walk(tmp_path / "ours", tmp_path / "walk")
    compared, found = compare(ours, theirs)
    undocumented = {k: v for k, v in found.items() if k not in project.documented}
    print(f"\n{project.key}: {compared - len(found)} of {compared} sub-entries agree; documented: {len(found)}")
    assert undocumented == {}
    assert found.keys() == project.documented.keys()  # a documented difference that went away is stale
    their_names = names(their_h)
    if project.digit_names:  # v4.0's moduleTimer_1 is v4.1's (and our) moduleTimer1
        their_names = {re.sub(r"(?<=[A-Za-z])_(?=\d)", "", name) for name in their_names}
    assert names((tmp_path / "ours" / "OD.h").read_text(encoding="utf-8")) == their_names
