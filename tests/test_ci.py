"""`.ci/run`, the CI entry point: it refuses to run the suite without ../shared instead of letting sweeps skip."""

from __future__ import annotations

import shutil
import subprocess
from pathlib import Path

from support import ROOT


def test_ci_run_fails_in_one_line_without_shared(tmp_path: Path) -> None:
    project = tmp_path / "checkout"
    (project / ".ci").mkdir(parents=True)
    shutil.copy2(ROOT / ".ci" / "run", project / ".ci" / "run")
    (project / "Makefile").write_text("test:\n\t@echo ran-the-suite\n", encoding="utf-8")
    result = subprocess.run(["bash", str(project / ".ci" / "run")], capture_output=True, text=True, timeout=60)
    assert result.returncode != 0
    assert "ran-the-suite" not in result.stdout
    assert len(result.stderr.strip().splitlines()) == 1
    assert "../shared/" in result.stderr and "missing" in result.stderr


def test_ci_run_runs_the_suite_with_shared(tmp_path: Path) -> None:
    project = tmp_path / "checkout"
    (project / ".ci").mkdir(parents=True)
    shutil.copy2(ROOT / ".ci" / "run", project / ".ci" / "run")
    (project / "Makefile").write_text("test:\n\t@echo ran-the-suite\n", encoding="utf-8")
    for needed in ("eds-corpus/eds", "seeds", "third_party"):
        (tmp_path / "shared" / needed).mkdir(parents=True)
    result = subprocess.run(["bash", str(project / ".ci" / "run")], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert "ran-the-suite" in result.stdout
