"""The pre-commit hooks, run for real by `pre-commit` in a user's repository, against this checkout.

This checkout (with its uncommitted changes to tracked files as one more commit, as `pre-commit try-repo`
takes them) is published once as `main` of a bare repository; every test's repository uses it from there
with one PRE_COMMIT_HOME, so pre-commit installs the hooks' environment once per `rev` it is given, not
once per call (each `try-repo` call installs anew: about 17 s of CPU).
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest

from support import EXAMPLES, ROOT

# Its tests share module fixtures: under pytest-xdist they run on one worker, which makes them once.
pytestmark = pytest.mark.xdist_group("precommit")

BAD = """[1000]
ParameterName=Device type
DataType=0x0007
AccessType=ro
DefaultValue=0x00000000

[2000]
ParameterName=Speed
DataType=0x0006
AccessType=rw
DefaultValue=fast
"""


BAD_XDD = """<?xml version="1.0" encoding="utf-8"?>
<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1">
  <ISO15745Profile><ProfileBody><ApplicationLayers><CANopenObjectList>
    <CANopenObject index="2000" name="Speed" objectType="7" dataType="0006" accessType="rw" defaultValue="fast" />
  </CANopenObjectList></ApplicationLayers></ProfileBody></ISO15745Profile>
</ISO15745ProfileContainer>
"""


def pre_commit() -> str:
    found = shutil.which("pre-commit", path=str(Path(sys.executable).parent)) or shutil.which("pre-commit")
    if found is None:
        pytest.skip("pre-commit is not installed")
    if not (ROOT / ".git").exists():
        pytest.skip("publishing this checkout needs it to be a git repository")
    return found


def git(repo: Path, *args: str) -> None:
    subprocess.run(["git", *args], cwd=repo, check=True, capture_output=True)


@dataclass(frozen=True)
class Published:
    url: str  # a bare repository whose `main` is this checkout
    commit: str  # the commit `main` points at: HEAD, or one more holding the uncommitted changes
    home: Path  # the PRE_COMMIT_HOME every test uses


@pytest.fixture(scope="module")
def published(tmp_path_factory: pytest.TempPathFactory) -> Published:
    pre_commit()
    folder = tmp_path_factory.mktemp("published")
    bare, shadow = folder / "published.git", folder / "shadow"
    head = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True, check=True)
    git(folder, "clone", "-q", "--shared", "--no-checkout", str(ROOT), str(shadow))
    git(shadow, "checkout", "-q", head.stdout.strip())
    changes = subprocess.run(["git", "diff", "HEAD", "--binary"], cwd=ROOT, capture_output=True, check=True).stdout
    if changes:
        subprocess.run(["git", "apply", "--binary", "--index"], cwd=shadow, input=changes, check=True)
        git(shadow, "-c", "user.name=Test", "-c", "user.email=test@example.com", "commit", "-q", "-m", "uncommitted")
    git(folder, "init", "-q", "--bare", str(bare))
    git(shadow, "push", "-q", str(bare), "HEAD:refs/heads/main")
    git(bare, "symbolic-ref", "HEAD", "refs/heads/main")
    commit = subprocess.run(["git", "rev-parse", "main"], cwd=bare, capture_output=True, text=True, check=True)
    return Published(str(bare), commit.stdout.strip(), tmp_path_factory.mktemp("pre-commit-home"))


def environment(published: Published) -> dict[str, str]:
    return dict(os.environ, PRE_COMMIT_HOME=str(published.home), PRE_COMMIT_COLOR="never")


HOOKS_CONFIG = """repos:
  - repo: {url}
    rev: main
    hooks:
      - id: cantools-od-lint
      - id: cantools-od-fmt
"""


@pytest.fixture(scope="module")
def workspace(tmp_path_factory: pytest.TempPathFactory, published: Published) -> tuple[Path, dict[str, str]]:
    repo = tmp_path_factory.mktemp("user-repo")
    git(repo, "init", "-q")
    git(repo, "config", "user.email", "test@example.com")
    git(repo, "config", "user.name", "Test")
    (repo / ".pre-commit-config.yaml").write_text(HOOKS_CONFIG.format(url=published.url), encoding="utf-8")
    shutil.copy(EXAMPLES / "io_device.eds", repo / "good.eds")
    (repo / "bad.eds").write_text(BAD)
    (repo / "messy.eds").write_bytes(b"[2000]\r\nParameterName=X\r\nAccessType=RO\r\nDataType=5\r\n")
    (repo / "bad.xdd").write_text(BAD_XDD)
    git(repo, "add", ".")
    return repo, environment(published)


def try_repo(workspace: tuple[Path, dict[str, str]], hook: str, *files: str) -> subprocess.CompletedProcess[str]:
    """`pre-commit run HOOK --files FILES...` in the user's repository."""
    repo, env = workspace
    return subprocess.run(
        [pre_commit(), "run", hook, "--files", *files],
        cwd=repo, env=env, capture_output=True, text=True, timeout=900,
    )  # fmt: skip


def test_lint_hook_passes_a_good_file(workspace: tuple[Path, dict[str, str]]) -> None:
    result = try_repo(workspace, "cantools-od-lint", "good.eds")
    assert result.returncode == 0, result.stdout + result.stderr
    assert "Passed" in result.stdout


def test_lint_hook_fails_a_bad_file_with_its_diagnostic(workspace: tuple[Path, dict[str, str]]) -> None:
    result = try_repo(workspace, "cantools-od-lint", "bad.eds")
    assert result.returncode == 1, result.stdout + result.stderr
    assert "Failed" in result.stdout
    assert "bad.eds:11:14: error:" in result.stdout and "[EDS030]" in result.stdout


def test_fmt_hook_rewrites_and_then_passes(workspace: tuple[Path, dict[str, str]]) -> None:
    repo, _ = workspace
    first = try_repo(workspace, "cantools-od-fmt", "messy.eds")
    assert first.returncode == 1 and "files were modified by this hook" in first.stdout
    assert (repo / "messy.eds").read_bytes() == b"[2000]\nParameterName=X\nDataType=0x0005\nAccessType=ro\n"
    second = try_repo(workspace, "cantools-od-fmt", "messy.eds")
    assert second.returncode == 0, second.stdout


def test_lint_hook_checks_xdd_files_at_their_xml_line(workspace: tuple[Path, dict[str, str]]) -> None:
    result = try_repo(workspace, "cantools-od-lint", "bad.xdd")
    assert result.returncode == 1, result.stdout + result.stderr
    assert "bad.xdd:4:107: error:" in result.stdout and "[EDS030]" in result.stdout


def readme_snippet() -> str:
    """The .pre-commit-config.yaml docs/pre-commit.md (which the README links) tells users to write."""
    section = (ROOT / "docs" / "pre-commit.md").read_text("utf-8")
    start = section.index("```yaml\n") + len("```yaml\n")
    return section[start : section.index("```", start)]


def test_readme_snippet_in_a_fresh_repository(tmp_path: Path, published: Published) -> None:
    """The documented snippet as written (only the URL is the user's to fill in), against this checkout
    published as `main`; then `pre-commit autoupdate --freeze` pins it to a commit that exists."""
    tool = pre_commit()
    repo = tmp_path / "user-repo"
    repo.mkdir()
    git(repo, "init", "-q")
    snippet = readme_snippet()
    url = next(line.split()[2] for line in snippet.splitlines() if line.strip().startswith("- repo:"))
    (repo / ".pre-commit-config.yaml").write_text(snippet.replace(url, published.url), encoding="utf-8")
    shutil.copy(EXAMPLES / "io_device.eds", repo / "good.eds")
    (repo / "bad.eds").write_text(BAD)
    git(repo, "add", ".")
    env = environment(published)

    def run(*args: str) -> subprocess.CompletedProcess[str]:
        return subprocess.run([tool, *args], cwd=repo, env=env, capture_output=True, text=True, timeout=900)

    first = run("run", "--all-files")
    assert first.returncode == 1, first.stdout + first.stderr  # bad.eds fails the lint hook
    assert "bad.eds:11:14: error:" in first.stdout and "[EDS030]" in first.stdout
    frozen = run("autoupdate", "--freeze")
    assert frozen.returncode == 0, frozen.stdout + frozen.stderr
    config = (repo / ".pre-commit-config.yaml").read_text("utf-8")
    assert f"rev: {published.commit}" in config, config
    (repo / "bad.eds").unlink()
    git(repo, "add", "-A")
    second = run("run", "--all-files")
    lint_line = next(line for line in second.stdout.splitlines() if line.startswith("cantools-od lint"))
    assert lint_line.endswith("Passed"), second.stdout
