"""The README's command table is the one list of what each command takes and reads; the help texts
must say the same: every command has a row, every option of a command is in its row, and the help
names every file format and target its row names. A help text or a row that drifts fails here."""

from __future__ import annotations

import re

import click
import pytest

from cantools_od.cli import COMMANDS, main

from support import ROOT

FORMATS = ("EDS", "DCF", "XDD", "XDC", "JSON")


def readme_rows() -> dict[str, str]:
    """Command name → its README table row."""
    rows = {}
    for line in (ROOT / "README.md").read_text(encoding="utf-8").splitlines():
        found = re.match(r"\| `cantools-od ([a-z-]+)", line)
        if found is not None:
            rows[found.group(1)] = line
    return rows


ROWS = readme_rows()


def command(name: str) -> click.Command:
    with click.Context(main) as ctx:
        found = main.get_command(ctx, name)
    assert found is not None
    return found


def options(cmd: click.Command) -> list[list[str]]:
    """Each option's spellings (`-o`, `--output`; `--color`, `--no-color`)."""
    return [[*param.opts, *param.secondary_opts] for param in cmd.params if isinstance(param, click.Option)]


def what_it_does(row: str) -> str:
    """The row's second cell (its first holds escaped `\\|`)."""
    return re.split(r"(?<!\\)\|", row)[2]


def said(text: str, word: str) -> bool:
    return re.search(rf"(?<![\w-]){re.escape(word)}(?![\w-])", text, re.IGNORECASE) is not None


def test_every_command_has_a_row() -> None:
    assert set(COMMANDS) <= set(ROWS), sorted(set(COMMANDS) - set(ROWS))
    assert set(ROWS) - {"--version"} <= set(COMMANDS)


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_every_option_is_in_the_readme(name: str) -> None:
    missing = [spellings for spellings in options(command(name)) if not any(said(ROWS[name], o) for o in spellings)]
    assert not missing, f"README row of {name} lacks {missing}"


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_help_names_the_formats_its_row_names(name: str) -> None:
    """Both the command's --help and the line `cantools-od --help` gives it, when that names formats."""
    named = [word for word in FORMATS if re.search(rf"\b{word}\b", what_it_does(ROWS[name]))]
    cmd = command(name)
    help_text = cmd.help or ""
    assert all(word in help_text for word in named), f"{name} --help names not all of {named}:\n{help_text}"
    line = COMMANDS[name][1]
    if any(re.search(rf"\b{word}\b", line) for word in FORMATS):
        assert all(word in line for word in named), f"`cantools-od --help` on {name} names not all of {named}: {line}"


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_help_and_row_name_every_choice(name: str) -> None:
    """Targets (gen -t), output formats, profiles: a row that lists choices lists all of them (one that
    lists none points to the docs); gen's targets are in its help line too."""
    for param in command(name).params:
        if isinstance(param, click.Option) and isinstance(param.type, click.Choice):
            choices = [str(choice) for choice in param.type.choices]
            listed = [choice for choice in choices if said(ROWS[name], choice)]
            assert not listed or listed == choices, (name, param.opts, choices)
            if param.name == "targets":
                top = COMMANDS[name][1].replace("OD.h/OD.c", "")
                assert all(said(top, choice) for choice in choices), (top, choices)
