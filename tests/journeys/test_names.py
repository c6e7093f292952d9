"""Unknown names are errors: a misspelt rule code, format, extension or configuration key is
refused with exit 2 in one line naming the closest valid names, never silently ignored."""

from __future__ import annotations

from pathlib import Path

import pytest
from kit import GOOD, assert_failed_cleanly, run, snapshot


@pytest.fixture
def project(tmp_path: Path) -> Path:
    (tmp_path / "io.eds").write_bytes(GOOD)
    return tmp_path


def refused(ran_args: list[str], folder: Path, *expected: str) -> None:
    before = snapshot(folder)
    ran = run(*ran_args, cwd=folder)
    assert_failed_cleanly(ran)
    assert ran.returncode == 2, ran
    for text in expected:
        assert text in ran.stderr, ran
    assert snapshot(folder) == before


@pytest.mark.parametrize(
    ("option", "code", "expected"),
    [
        ("--select", "NOPE", "unknown rule code 'NOPE'; a rule code"),
        ("--select", "EDS0300", "unknown rule code 'EDS0300'; did you mean EDS030"),
        ("--ignore", "PDO,XYZ001", "unknown rule code 'XYZ001'"),
        ("--select", "line-to-long", "unknown rule code 'line-to-long'; did you mean line-too-long"),
        ("--ignore", "EDS,objlist", "unknown rule code 'objlist'; did you mean objlists"),
    ],
)
def test_unknown_rule_codes_on_the_command_line(project: Path, option: str, code: str, expected: str) -> None:
    """Why: `lint --select NOPE` exited 0 with "no findings"."""
    refused(["lint", option, code, "io.eds"], project, expected)


def test_codes_and_prefixes_are_accepted(project: Path) -> None:
    for selection in ("EDS030", "EDS", "PDO0", "eds030", "line-too-long", "Line-Too-Long", "objlists"):
        ran = run("lint", "--select", selection, "io.eds", cwd=project)
        assert ran.returncode == 0, ran


@pytest.mark.parametrize(
    ("table", "expected"),
    [
        ('selct = ["EDS"]', "unknown key in [tool.cantools-od] 'selct'; did you mean select"),
        ('select = ["NOPE1"]', "[tool.cantools-od] select: unknown rule code 'NOPE1'"),
        ('ignore = ["EDS9999"]', "unknown rule code 'EDS9999'"),
        ('per-file-ignores = { "*.eds" = ["COB0O6"] }', "unknown rule code 'COB0O6'; did you mean COB006"),
        ('ignore = ["line-to-lng"]', "ignore: unknown rule code 'line-to-lng'; did you mean line-too-long"),
    ],
)
def test_unknown_names_in_the_configuration(project: Path, table: str, expected: str) -> None:
    (project / "pyproject.toml").write_text(f"[tool.cantools-od]\n{table}\n")
    refused(["lint", "io.eds"], project, expected)


@pytest.mark.parametrize(
    "args",
    [
        ["lint", "--format", "jsn", "io.eds"],
        ["dump", "--format", "yaml", "io.eds"],
        ["pdo", "--format", "csv", "io.eds"],
        ["gen", "io.eds", "-t", "rusty", "-o", "out"],
    ],
)
def test_unknown_output_formats(project: Path, args: list[str]) -> None:
    refused(args, project, "is not one of")


@pytest.mark.parametrize(
    ("args", "expected"),
    [
        (["convert", "io.eds", "-o", "io.ed"], "io.ed: error: output: unknown file extension '.ed'; did you mean .eds"),
        (["convert", "io.eds", "-o", "io.txt"], "unknown file extension '.txt'"),
        (["gen", "io.txt", "-t", "c", "-o", "out"], "io.txt: error: input: unknown file extension '.txt'"),
        (["convert", "io.txt", "-o", "io.json"], "io.txt: error: input: unknown file extension '.txt'"),
    ],
)
def test_unknown_file_extensions(project: Path, args: list[str], expected: str) -> None:
    (project / "io.txt").write_bytes(GOOD)
    refused(args, project, expected)


def test_convert_never_writes_eds_under_an_xml_name(project: Path) -> None:
    """Why: `convert a.eds -o a.xdd` wrote EDS bytes under an XML name and exited 0. Either the
    extension is refused and nothing is written, or what is written is XML."""
    ran = run("convert", "io.eds", "-o", "io.xdd", cwd=project)
    if ran.returncode == 0:
        assert (project / "io.xdd").read_bytes().lstrip().startswith(b"<"), "EDS bytes under an XML name"
    else:
        assert_failed_cleanly(ran)
        assert ran.returncode == 2 and "'.xdd'" in ran.stderr, ran
        assert not (project / "io.xdd").exists()


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("line-to-long", "error: no rule line-to-long; did you mean line-too-long"),
        ("EDS0300", "error: no rule EDS0300; did you mean EDS030"),
        ("zzzzzzzz", "error: no rule zzzzzzzz; `cantools-od rules` lists them"),
    ],
)
def test_rules_names_the_closest_rule(project: Path, name: str, expected: str) -> None:
    """Why: `rules line-to-long` said only "no rule"; a misspelt name is met with the closest, in one line."""
    refused(["rules", name], project, expected)
    assert len(run("rules", name, cwd=project).stderr.splitlines()) == 1
