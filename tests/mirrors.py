"""Files of public repositories that a session brought onto this machine (its snapshots of them), read in place.

Such repositories are test material we may read but never commit: a test names the repository, commit and
path it needs (a manifest in the test), reads the bytes straight from the snapshot's git directory, and skips
when the snapshot is not on this machine. CANTOOLS_OD_MIRRORS names the folder that holds the snapshots
(`<owner>+<name>/repo`); /work/.mirror by default.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(os.environ.get("CANTOOLS_OD_MIRRORS", "/work/.mirror"))


def git_dir(repo: str) -> Path | None:
    """The git directory of `owner/name`'s snapshot, or None when it is not here."""
    folder = ROOT / repo.replace("/", "+")
    for candidate in (folder / "repo", folder):
        if (candidate / "HEAD").is_file() or (candidate / ".git").exists():
            return candidate
    return None


def require(repo: str) -> Path:
    """The snapshot's git directory; the calling test is skipped when the snapshot is absent."""
    found = git_dir(repo)
    if found is None:
        pytest.skip(f"no snapshot of {repo} under {ROOT}")
    return found


def _git(repo: str, *args: str) -> bytes:
    result = subprocess.run(["git", "--git-dir", str(require(repo)), *args], capture_output=True, check=False)
    if result.returncode != 0:
        pytest.skip(f"{repo}: git {' '.join(args)} failed: {result.stderr.decode(errors='replace').strip()}")
    return result.stdout


def show(repo: str, commit: str, path: str) -> bytes:
    """The bytes of `path` at `commit` (a commit id, or HEAD) in the snapshot of `repo`."""
    return _git(repo, "show", f"{commit}:{path}")


def files(repo: str, commit: str = "HEAD") -> list[str]:
    """Every path in `repo` at `commit`."""
    return _git(repo, "ls-tree", "-r", "--name-only", commit).decode().splitlines()


def materialize(repo: str, commit: str, paths: list[str], into: Path) -> list[Path]:
    """Writes `paths` at `commit` under `into` (keeping their relative folders) and returns where they went."""
    written = []
    for path in paths:
        target = into / path
        target.parent.mkdir(parents=True, exist_ok=True)
        target.write_bytes(show(repo, commit, path))
        written.append(target)
    return written
