"""The error-precision sweep's files and how `lint` is run on them (issue #41): every EDS/DCF/XDD/XDC/XPD of
../shared and the project file of each CANopenNode project in tests/canopennode/real_projects.py, read from this
machine's snapshots (tests/mirrors.py).

A file is named by its key: its path relative to ../shared, or `mirror:owner/name:path` for a snapshot's file.
CANopenNode/CANopenEditor files (an EDS with CANopenEditor's `;StorageLocation=` comments, an XDD/XPD with its
`CO_*` properties, every project of the manifest) are checked with `--profile canopennode`, as their users
would; a project's own CO_driver_target.h and settings go with it. Used by tests/lint/test_error_precision.py
and bench/bench_error_sweep.py.
"""

from __future__ import annotations

import json
import subprocess
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

import mirrors
from canopennode.real_projects import PROJECTS, Project

from support import SHARED, cli_command, shared_files

SUFFIXES = (".eds", ".dcf", ".xdd", ".xdc", ".xpd")
MIRROR = "mirror:"
_EDITOR_MARKS = (b";StorageLocation=", b'name="CO_storageGroup"', b'name="CO_disabled"', b'name="CO_countLabel"')


@dataclass(frozen=True)
class Finding:
    key: str
    code: str
    line: int
    message: str
    severity: str


def shared_keys() -> list[str]:
    """Every device file of ../shared by key ([] when ../shared is absent)."""
    return [path.relative_to(SHARED).as_posix() for path in shared_files(SUFFIXES)]


def mirror_key(project: Project) -> str:
    return f"{MIRROR}{project.repo}:{project.source}"


def project_of(key: str) -> Project | None:
    return next((p for p in PROJECTS if mirror_key(p) == key), None)


def mirror_keys() -> list[str]:
    """The manifest's project files whose snapshot is on this machine."""
    return [mirror_key(p) for p in PROJECTS if mirrors.git_dir(p.repo) is not None]


def is_canopennode(path: Path) -> bool:
    data = path.read_bytes()
    return any(mark in data for mark in _EDITOR_MARKS)


def _place_project(project: Project, into: Path) -> tuple[Path, list[Path]]:
    """The project file and its stack configuration headers, written under `into` as the repository lays them."""
    folder = into / project.repo.replace("/", "+")
    wanted = [project.source, *project.stack_config]
    source, *headers = mirrors.materialize(project.repo, project.commit, wanted, folder)
    if project.settings:
        source.with_suffix(".canopennode.toml").write_text(project.settings, encoding="utf-8")
    return source, headers


def _lint(paths: list[Path], options: list[str]) -> list[dict[str, object]]:
    command = [*cli_command(), "lint", "--format", "json", "--jobs", "1", *options, *map(str, paths)]
    done = subprocess.run(command, capture_output=True, text=True, check=False)
    # 2: a file could not be read (the corpus holds an empty one); every other file is still reported
    if done.returncode not in (0, 1, 2) or not done.stdout.strip():
        raise RuntimeError(f"lint exited {done.returncode}: {done.stderr.strip()}")
    found: list[dict[str, object]] = json.loads(done.stdout)
    return found


def _findings(found: list[dict[str, object]], key_of: dict[str, str]) -> list[Finding]:
    return [
        Finding(key_of[str(f["file"])], str(f["code"]), int(str(f["line"])), str(f["message"]), str(f["severity"]))
        for f in found
    ]


def findings(keys: Iterable[str], scratch: Path) -> list[Finding]:
    """Every finding `lint` reports on the files `keys` name: one CLI call for the plain files of ../shared, one
    for its CANopenNode files and one per snapshot project (its own stack configuration); snapshots are written
    under `scratch`."""
    plain: list[Path] = []
    editor: list[Path] = []
    projects: list[Project] = []
    for key in sorted(set(keys)):
        project = project_of(key)
        if project is not None:
            projects.append(project)
            continue
        path = SHARED / key
        (editor if is_canopennode(path) else plain).append(path)
    found: list[Finding] = []
    for batch, options in ((plain, []), (editor, ["--profile", "canopennode"])):
        if batch:
            found += _findings(_lint(batch, options), {str(p): p.relative_to(SHARED).as_posix() for p in batch})
    for project in projects:
        source, headers = _place_project(project, scratch)
        options = ["--profile", "canopennode", *(f"--stack-config={h}" for h in headers)]
        found += _findings(_lint([source], options), {str(source): mirror_key(project)})
    return sorted(found, key=lambda f: (f.key, f.line, f.code, f.message))


def errors(keys: Iterable[str], scratch: Path) -> list[Finding]:
    """The findings of `findings` that are errors."""
    return [f for f in findings(keys, scratch) if f.severity == "error"]


def read_lines(key: str) -> list[str]:
    """The file's text by lines (for reading a finding in context)."""
    project = project_of(key)
    data = mirrors.show(project.repo, project.commit, project.source) if project else (SHARED / key).read_bytes()
    return data.decode("utf-8", errors="replace").splitlines()
