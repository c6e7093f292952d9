"""`cantools-od diff` as users run it: formats, exit codes, hostile inputs, and inside git."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest
from diffkit import BASE, drop_section, set_key

from cantools_od.changes.jsonout import DiffReport, schema_text
from cantools_od.resources import resource_dir

from support import cli_command


def run(
    *args: str | Path, cwd: Path | None = None, env: dict[str, str] | None = None
) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*cli_command(), *map(str, args)], capture_output=True, text=True, cwd=cwd, timeout=120, env=env
    )


@pytest.fixture
def pair(tmp_path: Path) -> tuple[Path, Path]:
    """An example and a release of it that drops an object and changes a default."""
    old, new = tmp_path / "old.eds", tmp_path / "new.eds"
    old.write_text(BASE)
    new.write_text(set_key(drop_section(BASE, "1017"), "2000sub2", "DefaultValue", "20"))
    return old, new


def test_text_report_is_plain_when_piped(pair: tuple[Path, Path]) -> None:
    before = [(p.read_bytes(), p.stat().st_mode) for p in pair]
    result = run("diff", *pair)
    assert result.returncode == 0, result.stderr
    assert "\x1b[" not in result.stdout
    assert "1 breaking (1 wire, 1 code), 0 compatible, 1 value, 0 cosmetic" in result.stdout
    assert "0x1017 Producer heartbeat time" in result.stdout and "removed" in result.stdout
    assert [(p.read_bytes(), p.stat().st_mode) for p in pair] == before, "inputs must stay untouched"
    coloured = run("diff", "--color", *pair)
    assert "\x1b[31m" in coloured.stdout  # breaking in red


def test_fail_on(pair: tuple[Path, Path], tmp_path: Path) -> None:
    old, new = pair
    assert run("diff", old, new, "--fail-on", "breaking").returncode == 1
    assert run("diff", old, new, "--fail-on", "any").returncode == 1
    assert run("diff", old, old, "--fail-on", "any").returncode == 0
    value_only = tmp_path / "value.eds"
    value_only.write_text(set_key(BASE, "2000sub2", "DefaultValue", "20"))
    assert run("diff", old, value_only, "--fail-on", "breaking").returncode == 0
    assert run("diff", old, value_only, "--fail-on", "any").returncode == 1


def test_json_report_follows_its_schema(pair: tuple[Path, Path]) -> None:
    result = run("diff", *pair, "--format", "json")
    assert result.returncode == 0, result.stderr
    data = json.loads(result.stdout)
    report = DiffReport.model_validate(data)
    assert report.summary.breaking == 1 and report.summary.value == 1
    schema = json.loads(schema_text())
    assert set(data) == set(schema["properties"])
    change = report.objects[0].changes[0]  # objects in index order: 0x1017, then 0x2000
    assert (change.kind.value, change.impact.value, change.index) == ("object-removed", "breaking", 0x1017)


def test_checked_in_diff_schema_has_not_drifted() -> None:
    checked_in = (resource_dir("schemas") / "diff.schema.json").read_text()
    assert checked_in == schema_text(), "regenerate: python -m cantools_od.changes.jsonout > schemas/diff.schema.json"


def test_markdown_report(pair: tuple[Path, Path]) -> None:
    from markdown_it import MarkdownIt

    result = run("diff", *pair, "--format", "markdown")
    assert result.returncode == 0, result.stderr
    text = result.stdout
    assert text.startswith("## Object dictionary changes: `old.eds` → `new.eds`")
    assert "### Breaking changes (1)" in text and "### Changed values (1)" in text
    html = MarkdownIt("commonmark").enable("table").render(text)
    assert "<h3>Breaking changes (1)</h3>" in html and "<strong>Producer heartbeat time</strong>" in html


def test_markdown_pdo_table(tmp_path: Path) -> None:
    old, new = tmp_path / "old.eds", tmp_path / "new.eds"
    old.write_text(BASE)
    new.write_text(set_key(BASE, "1A00sub0", "DefaultValue", "2"))
    text = run("diff", old, new, "--format", "markdown").stdout
    assert "#### TPDO1" in text and "| Bits | Before | After |" in text
    assert "| 24-39 | `0x6401:02` `read_analog_input_16_bit_analog_input_2` INTEGER16 |  |" in text


@pytest.mark.parametrize(
    "content",
    [b"", b"\x00\x01binary\xff", b'{"not": "a model"}', b"[2000]\nDataType=zz\n"],
    ids=["empty", "binary", "foreign-json", "broken"],
)
def test_hostile_inputs_never_traceback(tmp_path: Path, content: bytes) -> None:
    bad, good = tmp_path / "bad.eds", tmp_path / "good.eds"
    bad.write_bytes(content)
    good.write_text(BASE)
    result = run("diff", bad, good)
    assert result.returncode in (0, 2), result.stderr
    assert "Traceback" not in result.stderr
    assert len(result.stderr.strip().splitlines()) <= 1
    assert bad.read_bytes() == content


def test_usage_errors_exit_2(tmp_path: Path) -> None:
    missing = run("diff", tmp_path / "nope.eds", tmp_path / "nope2.eds")
    assert missing.returncode == 2 and "cannot read" in missing.stderr and "Traceback" not in missing.stderr
    assert run("diff", tmp_path / "one.eds").returncode == 2
    assert run("diff", "--format", "yaml", "a", "b").returncode == 2


def test_pins_make_a_rename_cosmetic(tmp_path: Path) -> None:
    old, new = tmp_path / "old.eds", tmp_path / "new.eds"
    old.write_text(BASE)
    new.write_text(set_key(BASE, "1017", "ParameterName", "Heartbeat"))
    assert run("diff", old, new, "--fail-on", "breaking").returncode == 1
    pins = tmp_path / "pins.toml"
    pins.write_text('[identifiers]\n"1017" = "producer_heartbeat_time"\n')
    result = run("diff", old, new, "--old-pins", pins, "--new-pins", pins, "--fail-on", "breaking")
    assert result.returncode == 0 and "cosmetic" in result.stdout
    shutil.copy(pins, tmp_path / "new.ids.toml")  # found beside the file, as `gen` finds it
    shutil.copy(pins, tmp_path / "old.ids.toml")
    assert run("diff", old, new, "--fail-on", "breaking").returncode == 0


def _git(repo: Path, *args: str, env: dict[str, str] | None = None) -> subprocess.CompletedProcess[str]:
    return subprocess.run(["git", *args], cwd=repo, capture_output=True, text=True, check=True, env=env)


@pytest.fixture
def repo(tmp_path: Path) -> Path:
    if shutil.which("git") is None:
        pytest.skip("git is not installed")
    repo = tmp_path / "repo"
    (repo / "od").mkdir(parents=True)
    _git(repo, "init", "-q")
    _git(repo, "config", "user.email", "dev@example.com")
    _git(repo, "config", "user.name", "dev")
    (repo / "od" / "device.eds").write_text(BASE)
    _git(repo, "add", ".")
    _git(repo, "commit", "-qm", "v1")
    (repo / "od" / "device.eds").write_text(set_key(BASE, "1017", "AccessType", "ro"))
    _git(repo, "commit", "-qam", "v2")
    return repo


def test_git_revisions(repo: Path) -> None:
    result = run("diff", "--git", "HEAD~1", "HEAD", "od/device.eds", cwd=repo)
    assert result.returncode == 0, result.stderr
    assert "--- HEAD~1:od/device.eds" in result.stdout
    assert "access: rw → ro (no longer writable)" in result.stdout
    (repo / "od" / "device.eds").write_text(BASE)  # the work tree against a revision
    result = run("diff", "--git", "HEAD", "od/device.eds", "--fail-on", "any", cwd=repo)
    assert result.returncode == 1 and "now writable" in result.stdout
    bad = run("diff", "--git", "no-such-rev", "HEAD", "od/device.eds", cwd=repo)
    assert bad.returncode == 2 and len(bad.stderr.strip().splitlines()) == 1


def _script_dir() -> str:
    return str(Path(cli_command()[0]).parent) if len(cli_command()) == 1 else ""


def test_git_external_diff_driver(repo: Path) -> None:
    """The .gitattributes + git config recipe of docs/diff.md, and GIT_EXTERNAL_DIFF."""
    env = {**os.environ, "PATH": os.pathsep.join(filter(None, [_script_dir(), os.environ.get("PATH", "")]))}
    command = " ".join(cli_command()) + " diff"
    (repo / ".gitattributes").write_text("*.eds diff=cantools-od\n")
    _git(repo, "config", "diff.cantools-od.command", command)
    shown = _git(repo, "diff", "HEAD~1", "HEAD", "--", "od/device.eds", env=env).stdout
    assert "--- a/od/device.eds" in shown and "access: rw → ro" in shown
    log = _git(repo, "log", "-p", "--ext-diff", "-1", "--", "od/device.eds", env=env).stdout
    assert "access: rw → ro" in log
    (repo / ".gitattributes").unlink()
    env["GIT_EXTERNAL_DIFF"] = command
    (repo / "od" / "new.eds").write_text(BASE)
    _git(repo, "add", "od/new.eds")
    added = _git(repo, "diff", "--cached", env=env).stdout  # a new file: git passes /dev/null as the old side
    assert "object-added" not in added and "added" in added and "0x1017 Producer heartbeat time" in added
    _git(repo, "commit", "-qm", "v3")
    _git(repo, "mv", "od/new.eds", "od/renamed.eds")
    (repo / "od" / "renamed.eds").write_text(set_key(BASE, "1017", "DefaultValue", "500"))
    (repo / "NOTES.txt").write_text("not a device description\n")
    _git(repo, "add", "-A")
    shown = _git(repo, "diff", "--cached", "-M", env=env).stdout  # a rename: git passes 9 arguments
    assert "--- a/od/new.eds\n+++ b/od/renamed.eds" in shown and "default: 1000 ms → 500 ms" in shown
    assert "+not a device description" in shown  # GIT_EXTERNAL_DIFF sends every file: others as a text diff


def test_git_revisions_use_the_pin_file_of_each_revision(repo: Path) -> None:
    (repo / "od" / "device.ids.toml").write_text('[identifiers]\n"1017" = "producer_heartbeat_time"\n')
    _git(repo, "add", "od/device.ids.toml")
    _git(repo, "commit", "-qm", "pin")
    (repo / "od" / "device.eds").write_text(set_key(BASE, "1017", "ParameterName", "Heartbeat"))
    _git(repo, "commit", "-qam", "rename")
    result = run("diff", "--git", "HEAD~1", "HEAD", "od/device.eds", "--fail-on", "breaking", cwd=repo)
    assert result.returncode == 0, result.stdout + result.stderr
    words = " ".join(result.stdout.split())  # long lines wrap at 100 columns
    assert "cosmetic" in words and "identifier producer_heartbeat_time stays" in words
    (repo / "od" / "device.ids.toml").unlink()
    _git(repo, "commit", "-qam", "unpin")
    unpinned = run("diff", "--git", "HEAD~3", "HEAD", "od/device.eds", "--fail-on", "breaking", cwd=repo)
    assert unpinned.returncode == 1 and "identifier producer_heartbeat_time → heartbeat" in " ".join(
        unpinned.stdout.split()
    )


def _invoke(*args: str | Path) -> tuple[int, str, str]:
    """The command in-process: exit code, stdout, stderr."""
    from click.testing import CliRunner

    from cantools_od.cli import main

    result = CliRunner().invoke(main, ["diff", *map(str, args)], catch_exceptions=False)
    return result.exit_code, result.stdout, result.stderr


@pytest.mark.parametrize(
    ("edit", "codes"),
    [
        # (fail-on wire, code, breaking, any, never)
        (lambda t: set_key(t, "2000sub2", "ParameterName", "Filter time"), (0, 1, 1, 1, 0)),  # a rename: code only
        (lambda t: set_key(t, "2000sub2", "AccessType", "ro"), (1, 0, 1, 1, 0)),  # a write lost: wire only
        (lambda t: set_key(t, "2000sub2", "DataType", "0x0007"), (1, 1, 1, 1, 0)),  # a type: both
        (lambda t: set_key(t, "2000sub2", "DefaultValue", "20"), (0, 0, 0, 1, 0)),  # a value
        (lambda t: t, (0, 0, 0, 0, 0)),
    ],
)
def test_fail_on_selects_who_is_hurt(tmp_path: Path, edit: object, codes: tuple[int, ...]) -> None:
    old, new = tmp_path / "old.eds", tmp_path / "new.eds"
    old.write_text(BASE)
    assert callable(edit)
    new.write_text(edit(BASE))
    found = tuple(_invoke(old, new, "--fail-on", level)[0] for level in ("wire", "code", "breaking", "any", "never"))
    assert found == codes


def test_a_new_file_passes_fail_on_breaking(tmp_path: Path) -> None:
    """git shows an added file as /dev/null → file: every object is added, nothing breaks."""
    new = tmp_path / "new.eds"
    new.write_text(BASE)
    code, out, _ = _invoke("/dev/null", new, "--fail-on", "breaking")
    assert code == 0, out
    assert _invoke(new, "/dev/null", "--fail-on", "code")[0] == 1  # a deleted file breaks generated code


def test_an_internal_failure_is_one_line_and_exit_2(pair: tuple[Path, Path], monkeypatch: pytest.MonkeyPatch) -> None:
    import cantools_od.changes

    def broken(*args: object, **kwargs: object) -> None:
        raise KeyError((4099, 0))

    monkeypatch.setattr(cantools_od.changes, "compare", broken)
    code, out, err = _invoke(*pair, "--fail-on", "any")
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and err.startswith("error: internal error: KeyError: (4099, 0)"), err


def test_unreadable_input_is_one_line_and_exit_2(pair: tuple[Path, Path], tmp_path: Path) -> None:
    old, _ = pair
    for bad in (tmp_path / "missing.eds", tmp_path):
        code, out, err = _invoke(old, bad, "--fail-on", "any")
        assert code == 2 and out == "" and err.count("\n") == 1, err


def test_a_refused_xdd_is_one_line_and_exit_2(tmp_path: Path) -> None:
    """XML that is not well-formed has no model: compared, every object would show as removed."""
    from cantools_od import dumps, loads

    whole = dumps(loads(BASE.encode(), source="device.eds"), fmt="xdd")
    good, cut = tmp_path / "old" / "device.xdd", tmp_path / "new" / "device.xdd"
    for path, data in ((good, whole), (cut, whole[: len(whole) // 2])):
        path.parent.mkdir()
        path.write_bytes(data)
    (tmp_path / "old" / "io.eds").write_text(BASE)
    (tmp_path / "new" / "io.eds").write_text(set_key(BASE, "2000sub2", "DefaultValue", "20"))
    single = run("diff", good, cut)
    assert single.returncode == 2 and single.stdout == "", single
    assert single.stderr.count("\n") == 1 and "error: not well-formed XML" in single.stderr, single.stderr
    assert single.stderr.startswith(f"{cut}:") and single.stderr.endswith("[XDD001]; nothing compared\n")
    folders = run("diff", "old", "new", "--jobs", "1", cwd=tmp_path)  # every other pair is still reported
    assert folders.returncode == 2 and "io.eds" in folders.stdout and "device.xdd" not in folders.stdout, folders
    assert folders.stderr.startswith("new/device.xdd:") and folders.stderr.count("\n") == 1, folders.stderr
