"""The documented ways of using cantools-od outside its own commands, run the way a user runs them:
a pin file made with a shell redirection or with `ids -o`, and the type information the package ships."""

from __future__ import annotations

import shlex
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest
from docpages import PAGES, page_synopsis

from support import ROOT, cli_command

EDS = ROOT / "eds" / "cia402_drive.eds"


def shell(command: str, cwd: Path) -> subprocess.CompletedProcess[str]:
    cli = shlex.join(cli_command())
    return subprocess.run(["sh", "-c", command.replace("cantools-od", cli)], cwd=cwd, capture_output=True, text=True)


def test_ids_redirected_into_the_default_pin_file(tmp_path: Path) -> None:
    """`cantools-od ids FILE > FILE.ids.toml`: the shell empties the pin file before the tool reads it."""
    shutil.copy(EDS, tmp_path / "drive.eds")
    expected = shell("cantools-od ids drive.eds", tmp_path)
    assert expected.returncode == 0 and "[identifiers]" in expected.stdout
    result = shell("cantools-od ids drive.eds > drive.ids.toml", tmp_path)
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    assert (tmp_path / "drive.ids.toml").read_text("utf-8") == expected.stdout
    # The pin file is in force: generating uses it, and the next `ids` reads it back unchanged.
    again = shell("cantools-od ids drive.eds", tmp_path)
    assert again.returncode == 0 and again.stdout == expected.stdout


def test_ids_output_option_keeps_pins_already_made(tmp_path: Path) -> None:
    shutil.copy(EDS, tmp_path / "drive.eds")
    pins = tmp_path / "drive.ids.toml"
    assert shell("cantools-od ids drive.eds -o drive.ids.toml", tmp_path).returncode == 0
    text = pins.read_text("utf-8")
    assert '"6060" = "modes_of_operation"' in text
    pins.write_text(text.replace('"modes_of_operation"', '"op_mode"'), encoding="utf-8")
    result = shell("cantools-od ids drive.eds -o drive.ids.toml", tmp_path)
    assert result.returncode == 0 and result.stdout == "", result.stderr
    assert '"6060" = "op_mode"' in pins.read_text("utf-8")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["drive.eds", "drive.ids.toml"]  # no temp file left


def test_an_empty_pin_file_pins_nothing_but_a_wrong_one_fails(tmp_path: Path) -> None:
    shutil.copy(EDS, tmp_path / "drive.eds")
    (tmp_path / "drive.ids.toml").write_text("# nothing pinned yet\n", encoding="utf-8")
    assert shell("cantools-od gen drive.eds -t c -o out", tmp_path).returncode == 0
    (tmp_path / "drive.ids.toml").write_text("[identifier]\n", encoding="utf-8")
    failed = shell("cantools-od gen drive.eds -t c -o out2", tmp_path)
    assert failed.returncode == 2 and "no [identifiers] table" in failed.stderr


def test_package_ships_py_typed(tmp_path: Path) -> None:
    """PEP 561: users' type checkers read the package's annotations only when it ships py.typed."""
    if not (ROOT / "pyproject.toml").is_file():
        pytest.skip("needs the source checkout to build the wheel")
    build = [sys.executable, "-m", "pip", "wheel", "--no-deps", "--no-build-isolation", "-w", str(tmp_path), str(ROOT)]
    subprocess.run(build, check=True, capture_output=True, timeout=300)
    wheel = next(tmp_path.glob("cantools_od-*.whl"))
    assert "cantools_od/py.typed" in zipfile.ZipFile(wheel).namelist()
    user = tmp_path / "user.py"
    user.write_text("import cantools_od\n\nx: int = cantools_od.load('a.eds')\n", encoding="utf-8")
    checked = subprocess.run(
        [sys.executable, "-m", "mypy", "--no-incremental", "--follow-imports=silent", str(user)],
        capture_output=True, text=True, cwd=tmp_path, timeout=300,
    )  # fmt: skip
    # With py.typed mypy sees the real return type and rejects the assignment (without it: "missing library stubs").
    assert 'Incompatible types in assignment (expression has type "Device"' in checked.stdout, checked.stdout


def test_readme_facts_match_the_code() -> None:
    """The Python version the README asks for is the one pyproject.toml requires, and every option the
    README's command table and the command pages' synopses (docs/commands/) name is one the command's --help
    offers."""
    import tomllib

    readme = (ROOT / "README.md").read_text("utf-8")
    required = tomllib.loads((ROOT / "pyproject.toml").read_text("utf-8"))["project"]["requires-python"]
    assert required.startswith(">=")
    assert f"Python {required[2:]}+" in readme
    rows = [line for line in readme.splitlines() if line.startswith("| `cantools-od ")]
    assert len(rows) >= 10
    synopses = [f"`{page_synopsis(page.stem)[0]}`" for page in sorted(PAGES.glob("*.md"))]
    assert len(synopses) >= 10
    for row in rows + synopses:
        usage = row.split("`")[1]
        command = usage.split()[1]
        if command.startswith("--"):
            continue
        helped = subprocess.run([*cli_command(), command, "--help"], capture_output=True, text=True, timeout=60)
        assert helped.returncode == 0, usage
        for option in {word.strip("[]|.") for word in usage.split() if word.lstrip("[").startswith("-")}:
            assert option in helped.stdout, f"{usage}: {command} --help has no {option}"
