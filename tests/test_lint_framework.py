"""The linter's machinery: selection, configuration, suppression, output formats, exit codes."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

from cantools_od import loads
from cantools_od.lint import RULES, Selection, lint, load_selection
from cantools_od.lint.codes import load as load_catalog
from cantools_od.lint.output import github, sarif

from support import ROOT, cli_command

BAD_VALUE = "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\nDefaultValue=fast\n"


def codes_of(text: str, selection: Selection | None = None) -> list[str]:
    return [f.code for f in lint(loads(text.encode(), source="t.eds"), selection=selection)]


def test_reader_findings_are_lint_findings() -> None:
    assert "EDS030" in codes_of(BAD_VALUE)


def test_select_and_ignore_by_code_and_prefix() -> None:
    assert "EDS030" not in codes_of(BAD_VALUE, Selection(ignore=("EDS030",)))
    assert "EDS030" not in codes_of(BAD_VALUE, Selection(ignore=("EDS",)))
    assert set(codes_of(BAD_VALUE, Selection(select=("EDS03",)))) <= {"EDS030", "EDS031", "EDS032", "EDS033"}


def test_suppression_comment_above_key_and_section() -> None:
    above_key = BAD_VALUE.replace("DefaultValue", "; cantools-od: ignore EDS030\nDefaultValue")
    assert "EDS030" not in codes_of(above_key)
    above_section = "; cantools-od: ignore EDS030, EDS999\n" + BAD_VALUE
    assert "EDS030" not in codes_of(above_section)
    elsewhere = BAD_VALUE.replace("DataType", "; cantools-od: ignore EDS030\nDataType")
    assert "EDS030" in codes_of(elsewhere)


def test_pyproject_configuration(tmp_path: Path) -> None:
    (tmp_path / "pyproject.toml").write_text(
        '[tool.cantools-od]\nignore = ["EDS032"]\nper-file-ignores = { "vendor/*.eds" = ["EDS030"] }\n'
    )
    (tmp_path / "vendor").mkdir()
    selection = load_selection(tmp_path / "vendor")
    assert not selection.enabled("EDS032", str(tmp_path / "x.eds"))
    assert not selection.enabled("EDS030", str(tmp_path / "vendor" / "x.eds"))
    assert selection.enabled("EDS030", str(tmp_path / "x.eds"))
    assert selection.merged(("EDS03",), ()).enabled("EDS030", "x.eds")


def run_lint(cwd: Path, *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([*cli_command(), "lint", *args], cwd=cwd, capture_output=True, text=True, timeout=120)


def test_cli_exit_codes_and_text(tmp_path: Path) -> None:
    bad = tmp_path / "bad.eds"
    bad.write_text(BAD_VALUE)
    result = run_lint(tmp_path, "bad.eds")
    assert result.returncode == 1
    assert "bad.eds:5:14: error: " in result.stdout and "[EDS030]" in result.stdout
    assert "1 file checked:" in result.stdout
    assert run_lint(tmp_path, "bad.eds", "--ignore", "EDS030", "--select", "EDS03").returncode == 0
    assert run_lint(tmp_path, "missing.eds").returncode == 2
    assert run_lint(tmp_path, "bad.eds", "--format", "xml").returncode == 2
    (tmp_path / "pyproject.toml").write_text("[tool.cantools-od]\nignore = 3\n")
    broken = run_lint(tmp_path, "bad.eds")
    assert broken.returncode == 2 and "configuration" in broken.stderr


def test_json_output_is_exactly_the_documented_shape(tmp_path: Path) -> None:
    (tmp_path / "bad.eds").write_text(BAD_VALUE)
    data = json.loads(run_lint(tmp_path, "bad.eds", "--format", "json").stdout)
    assert isinstance(data, list) and data
    for item in data:
        assert set(item) - {"fix"} == {"file", "line", "column", "code", "severity", "message"}
        assert item["severity"] in ("error", "warning", "info")
    value = next(item for item in data if item["code"] == "EDS030")
    assert {"file": "bad.eds", "line": 5, "column": 14, "code": "EDS030"}.items() <= value.items()


def test_sarif_and_github_outputs() -> None:
    findings = lint(loads(BAD_VALUE.encode(), source="bad.eds"))
    log = json.loads(sarif(findings))
    assert log["version"] == "2.1.0"
    run = log["runs"][0]
    rule_ids = [rule["id"] for rule in run["tool"]["driver"]["rules"]]
    result = next(r for r in run["results"] if r["ruleId"] == "EDS030")
    assert rule_ids[result["ruleIndex"]] == "EDS030"
    assert result["locations"][0]["physicalLocation"]["region"] == {"startLine": 5, "startColumn": 14}
    assert "::error file=bad.eds,line=5,col=14,title=EDS030::" in github(findings)


def test_every_rule_is_documented_and_tested() -> None:
    load_catalog()
    tests = "".join(p.read_text() for p in (ROOT / "tests").rglob("test_*.py"))
    for code, rule in RULES.items():
        assert rule.summary and len(rule.description) > 40, code
        if rule.family not in ("import", "gen", "lint"):  # the importer's codes are tested by what it reads
            assert code in tests, f"no test mentions {code}"


def test_rules_command_lists_and_explains() -> None:
    listing = subprocess.run([*cli_command(), "rules"], capture_output=True, text=True)
    assert listing.returncode == 0 and "EDS030" in listing.stdout
    one = subprocess.run([*cli_command(), "rules", "eds030"], capture_output=True, text=True)
    assert one.returncode == 0 and "Example:" in one.stdout
    assert subprocess.run([*cli_command(), "rules", "NOPE1"], capture_output=True, text=True).returncode == 2


def test_nodeid_spelling_fix_touches_only_its_line(tmp_path: Path) -> None:
    source = "[1014]\r\nParameterName=COB-ID EMCY\r\nDataType=0x0007\r\nAccessType=ro\r\nDefaultValue=0x80+$nodeid\r\n"
    target = tmp_path / "emcy.eds"
    target.write_bytes(source.encode())
    before = run_lint(tmp_path, "emcy.eds", "--select", "EDS033", "--format", "json")
    findings = json.loads(before.stdout)  # two: $NODEID placed last, and in lower case
    assert len(findings) == 2
    # unsafe: python-canopen reads no default from the old spelling and one from the new
    assert all(f["fix"] == {"message": "write $NODEID+0x80", "safe": False} for f in findings)
    # $NODEID placed last is an error (lely's dcf-tools reject it): left unfixed, lint still fails
    assert run_lint(tmp_path, "emcy.eds", "--select", "EDS033", "--fix").returncode == 1
    assert target.read_bytes() == source.encode()
    assert run_lint(tmp_path, "emcy.eds", "--select", "EDS033", "--fix", "--unsafe-fixes").returncode == 0
    assert target.read_bytes() == source.replace("0x80+$nodeid", "$NODEID+0x80").encode()
    assert json.loads(run_lint(tmp_path, "emcy.eds", "--select", "EDS033", "--format", "json").stdout) == []


def test_count_fix_rewrites_only_the_count_lines(tmp_path: Path) -> None:
    source = (
        "[2000]\r\nParameterName=A\r\nObjectType=0x8\r\nDataType=0x0005\r\nAccessType=ro\r\nCompactSubObj=3\r\n"
        "[2000Name]\r\nNrOfEntries=5\r\n1=First\r\n[2000ObjectLinks]\r\nObjectLinks=3\r\n1=0x2000\r\n"
    )
    target = tmp_path / "counts.eds"
    target.write_bytes(source.encode())
    found = json.loads(run_lint(tmp_path, "counts.eds", "--select", "EDS104", "--format", "json").stdout)
    # NrOfEntries: unsafe, python-canopen reads as many names as it says; no peer reads ObjectLinks
    assert [(f["line"], f["column"], f["fix"]["safe"]) for f in found] == [(8, 1, False), (11, 1, True)]
    assert run_lint(tmp_path, "counts.eds", "--select", "EDS104", "--fix").returncode == 1
    assert target.read_bytes() == source.replace("ObjectLinks=3", "ObjectLinks=1").encode()
    assert run_lint(tmp_path, "counts.eds", "--select", "EDS104", "--fix", "--unsafe-fixes").returncode == 0
    expected = source.replace("NrOfEntries=5", "NrOfEntries=1").replace("ObjectLinks=3", "ObjectLinks=1")
    assert target.read_bytes() == expected.encode()


_EXAMPLES_UNBUILT = """
import sys
from cantools_od.lint import examples
made = []
for name in ("pdo", "record", "var", "section", "identity"):
    setattr(examples, name, lambda *a, _name=name, **k: made.append(_name) or "")
from cantools_od import loads
from cantools_od.lint import RULES, lint
from cantools_od.lint.codes import load
load()
lint(loads(sys.argv[1].encode(), source="t.eds"))
print(len(made), len(RULES))
RULES["PDO001"].example
print(len(made))
"""


def test_lint_does_not_build_rule_examples() -> None:
    # Start-up of every `lint`: the examples made with the builders of `examples` are made when read (`rules`,
    # the documentation), not when the rule modules are imported.
    run = subprocess.run([sys.executable, "-c", _EXAMPLES_UNBUILT, BAD_VALUE], capture_output=True, text=True)
    assert run.returncode == 0, run.stderr
    before, rules, after = (int(n) for n in run.stdout.split())
    assert before == 0 and rules > 100 and after > 0
