"""The code registry (cantools_od/lint/codes.py): one list of every code the tool can print."""

from __future__ import annotations

import re
import subprocess

import pytest
from click.testing import CliRunner

from cantools_od import loads
from cantools_od.cli.rules import command as rules_command
from cantools_od.lint import RULES, Selection, lint
from cantools_od.lint.codes import FAMILIES, NAMES, codes, find, load

from support import ROOT, cli_command

KEBAB = re.compile(r"[a-z0-9]+(?:-[a-z0-9]+)*")
CODE_LITERAL = re.compile(r"""["']([A-Z]{3}\d{3})["']""")


def test_registry_and_declarations_agree() -> None:
    load()
    registered = {code: family for family, names in NAMES.items() for code in names}
    assert sorted(set(RULES) - set(registered)) == [], "declared but not in lint/codes.py"
    assert sorted(set(registered) - set(RULES)) == [], "in lint/codes.py but declared nowhere"
    for code, family in registered.items():
        assert RULES[code].family == family, code
        assert family in FAMILIES, code


def test_every_code_the_package_prints_is_registered() -> None:
    printed = set()
    for path in (ROOT / "cantools_od").rglob("*.py"):
        printed |= set(CODE_LITERAL.findall(path.read_text(encoding="utf-8")))
    assert printed, "the scan found no code at all"
    assert sorted(printed - set(codes())) == []


def test_names_are_kebab_case_and_unique() -> None:
    names = [c.name for c in codes().values()]
    assert all(KEBAB.fullmatch(name) for name in names)
    assert len(set(names)) == len(names)


def test_rules_explains_every_code() -> None:
    runner = CliRunner()
    for code, registered in codes().items():
        result = runner.invoke(rules_command, [code])
        assert result.exit_code == 0, code
        assert result.output.startswith(f"{code} ({registered.name}): {registered.summary}"), code
        assert f"family: {registered.family}" in result.output


@pytest.mark.parametrize("asked", ["GEN001", "imp020", "lnt001", "mapping-length-mismatch"])
def test_rules_command_explains_tool_codes_and_names(asked: str) -> None:
    result = subprocess.run([*cli_command(), "rules", asked], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0, result.stderr
    assert find(asked) is not None and result.stdout.startswith(find(asked).code)  # type: ignore[union-attr]


# 1600h maps 6041h sub 5 (a VAR: PDO052) and its COB-ID is a restricted CAN-ID (COB004); 1400h sub3 is set on
# an RPDO (PDO011, family cobid).
PDO_FILE = """[1400]
ParameterName=RPDO communication parameter 1
ObjectType=0x9
SubNumber=4
[1400sub0]
ParameterName=Highest sub-index supported
DataType=0x0005
AccessType=ro
DefaultValue=3
[1400sub1]
ParameterName=COB-ID
DataType=0x0007
AccessType=rw
DefaultValue=0x601
[1400sub2]
ParameterName=Transmission type
DataType=0x0005
AccessType=rw
DefaultValue=255
[1400sub3]
ParameterName=Inhibit time
DataType=0x0006
AccessType=rw
DefaultValue=10
[1600]
ParameterName=RPDO mapping parameter 1
ObjectType=0x9
SubNumber=2
[1600sub0]
ParameterName=Number of mapped objects
DataType=0x0005
AccessType=rw
DefaultValue=1
[1600sub1]
ParameterName=Mapped object 1
DataType=0x0007
AccessType=rw
DefaultValue=0x60410510
[6041]
ParameterName=Statusword
ObjectType=0x7
DataType=0x0006
AccessType=rw
PDOMapping=1
DefaultValue=0
"""


def selected(*selectors: str, ignore: tuple[str, ...] = ()) -> set[str]:
    device = loads(PDO_FILE.encode(), source="t.eds")
    return {f.code for f in lint(device, selection=Selection(select=selectors, ignore=ignore))}


def test_select_and_ignore_by_family_name() -> None:
    assert {"PDO011", "COB004"} <= selected("cobid")
    assert "PDO052" not in selected("cobid")  # family pdo
    assert all(codes()[code].family == "cobid" for code in selected("cobid"))
    assert {"PDO052", "PDO011"} <= selected("PDO")  # a prefix: every PDO code, whatever its family
    assert "PDO011" not in selected("PDO", ignore=("cobid",))
    assert "PDO052" in selected("PDO", ignore=("cobid",))


def test_select_by_family_from_the_command_line(tmp_path: object) -> None:
    from pathlib import Path

    folder = Path(str(tmp_path))
    (folder / "t.eds").write_text(PDO_FILE, encoding="utf-8")
    result = subprocess.run(
        [*cli_command(), "lint", "t.eds", "--select", "cobid", "--format", "json"],
        capture_output=True,
        text=True,
        cwd=folder,
        timeout=60,
    )
    found = {f["code"] for f in __import__("json").loads(result.stdout)}
    assert {"PDO011", "COB004"} <= found and "PDO052" not in found


def test_the_readme_counts_the_rules_and_codes_there_are() -> None:
    """The README's door names how many rules lint runs and how many codes exist; a new rule updates it."""
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    found = re.search(r"a linter of (\d+) rules \((\d+) codes in all", text)
    assert found, "the README no longer counts the rules"
    every = codes()  # registers every family's rules first
    checks = sum(1 for code in every.values() if code.rule.check is not None)
    assert (int(found[1]), int(found[2])) == (checks, len(every))
