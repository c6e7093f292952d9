"""Where each command is written down, and that it says what the command does. The README's table has one row
per command, a line each, linking the command's page; docs/commands/<name>.md gives the full synopsis and the
rules. The help texts must say the same: every option of a command is named in its page's synopsis and again in
the page's text, and the help names every file format and target the row and the page name. A help text, a row
or a page that drifts fails here; so does a command line the README or a command page shows that does not run."""

from __future__ import annotations

import os
import re
import shlex
import subprocess
from pathlib import Path

import click
import pytest
from docpages import PAGES, page_synopsis

from cantools_od.cli import COMMANDS, main

from support import EXAMPLES, ROOT, SHARED, cli_command

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


def test_every_command_has_a_row_and_a_page() -> None:
    assert set(COMMANDS) <= set(ROWS), sorted(set(COMMANDS) - set(ROWS))
    assert set(ROWS) - {"--version"} <= set(COMMANDS)
    lacking = [name for name in COMMANDS if f"(docs/commands/{name}.md)" not in ROWS[name]]
    assert not lacking, f"README rows that do not link their page: {lacking}"
    assert {page.stem for page in PAGES.glob("*.md")} == set(COMMANDS), "docs/commands/ has a page per command"


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_every_option_is_on_its_page(name: str) -> None:
    """Named in the synopsis, and again in the page's text, where what it does is said."""
    written, summary, rest = page_synopsis(name)
    spelled = options(command(name))
    missing = [spellings for spellings in spelled if not any(said(written, o) for o in spellings)]
    assert not missing, f"the synopsis of docs/commands/{name}.md lacks {missing}"
    unexplained = [spellings for spellings in spelled if not any(said(f"{summary}\n{rest}", o) for o in spellings)]
    assert not unexplained, f"docs/commands/{name}.md names {unexplained} only in its synopsis"


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_help_names_the_formats_its_row_and_page_name(name: str) -> None:
    """Both the command's --help and the line `cantools-od --help` gives it, when that names formats."""
    summary = page_synopsis(name)[1]
    named = [word for word in FORMATS if re.search(rf"\b{word}\b", f"{what_it_does(ROWS[name])} {summary}")]
    cmd = command(name)
    help_text = cmd.help or ""
    assert all(word in help_text for word in named), f"{name} --help names not all of {named}:\n{help_text}"
    line = COMMANDS[name][1]
    if any(re.search(rf"\b{word}\b", line) for word in FORMATS):
        assert all(word in line for word in named), f"`cantools-od --help` on {name} names not all of {named}: {line}"


@pytest.mark.parametrize("name", sorted(COMMANDS))
def test_help_and_page_name_every_choice(name: str) -> None:
    """Targets (gen -t), output formats, profiles: a page's synopsis and summary that list choices list all of
    them; gen's targets are in its help line too."""
    written, summary, _ = page_synopsis(name)
    for param in command(name).params:
        if isinstance(param, click.Option) and isinstance(param.type, click.Choice):
            choices = [str(choice) for choice in param.type.choices]
            listed = [choice for choice in choices if said(f"{written} {summary}", choice)]
            assert not listed or listed == choices, (name, param.opts, choices)
            if param.name == "targets":
                top = COMMANDS[name][1].replace("OD.h/OD.c", "")
                assert all(said(top, choice) for choice in choices), (top, choices)


# Every command line the README and the command pages show runs as written ---------------------------------------

PLACEHOLDERS = {
    "FILE...": "device.eds",
    "FILE": "device.eds",
    "IN": "device.eds",
    "OUT": "out.json",
    "OUTDIR": "out",
    "OLD": "device.eds",
    "NEW": "new.eds",
    "N": "5",
    "BUS.yml": "bus.yml",
    "SOURCE...": "table.csv",
    "OUT.eds": "imported.eds",
}
BUS = 'master:\n  node_id: 1\ndevice:\n  node_id: 5\n  dcf: "device.eds"\n'
ROBOT = 'options:\n  dcf_path: "@BUS_CONFIG_PATH@"\n' + BUS  # ros2_canopen's installed layout, under $PREFIX
TABLE = "Index,Sub-index,Name,Data type,Access,Default\n0x1000,0,Device type,UNSIGNED32,ro,0\n"


def synopsis(written: str) -> str:
    """A synopsis as a user types it with nothing optional: `[...]` left out, placeholders filled in."""
    text = written.removeprefix("cantools-od ")
    while re.search(r"\[[^][]*\]", text):
        text = re.sub(r"\s*\[[^][]*\]", "", text)
    return " ".join(PLACEHOLDERS.get(word, word) for word in text.split())


def row_synopsis(row: str) -> str:
    written = re.match(r"\| `(cantools-od [^`]*)`", row)
    assert written is not None, row
    return synopsis(written.group(1).replace("\\|", "|"))


def shown_lines() -> list[str]:
    """The `cantools-od ...` lines of the sh blocks of the README and the command pages, comments left out."""
    lines, inside = [], False
    for page in [ROOT / "README.md", *sorted(PAGES.glob("*.md"))]:
        for line in page.read_text(encoding="utf-8").splitlines():
            if line.startswith("```"):
                inside = line == "```sh"
            elif inside and line.startswith("cantools-od "):
                lines.append(" ".join(line.split(" #")[0].split()[1:]))
    return lines


def scratch(folder: Path) -> Path:
    """The files the README's lines name, in a folder of their own."""
    drive = (EXAMPLES / "cia402_drive.eds").read_bytes()
    names = ["device.eds", "new.eds", "old.eds", "a.dcf", "b.dcf", "c.dcf", "eds/cia402_drive.eds", "od/device.eds"]
    names += ["old/device.eds", "new/device.eds", "release-1.2/device.eds", "release-1.3/device.eds"]
    names += ["config/robot/device.eds", "share/robot/config/robot/device.eds", "build/config/robot/.keep"]
    for name in names:
        (folder / name).parent.mkdir(parents=True, exist_ok=True)
        (folder / name).write_bytes(drive)
    for number, name in enumerate(("a.dcf", "b.dcf", "c.dcf"), 2):
        text = (folder / name).read_text(encoding="utf-8").replace("[DeviceInfo]", "[DeviceComissioning]\nNodeID=")
        (folder / name).write_text(text.replace("NodeID=\n", f"NodeID={number}\n", 1), encoding="utf-8")
    (folder / "bus.yml").write_text(BUS, encoding="utf-8")
    (folder / "config" / "robot" / "bus.yml").write_text(ROBOT, encoding="utf-8")
    (folder / "table.csv").write_text(TABLE, encoding="utf-8")
    header = SHARED / "third_party" / "CANopenNode" / "example" / "CO_driver_target.h"
    if header.is_file():
        (folder / "src").mkdir()
        (folder / "src" / "CO_driver_target.h").write_bytes(header.read_bytes())
    ran = subprocess.run([*cli_command(), "convert", "device.eds", "-o", "device.xdd"], cwd=folder, capture_output=True)
    assert ran.returncode == 0, ran.stderr
    _history(folder)
    return folder


def _history(folder: Path) -> None:
    """od/device.eds in a git repository: tagged v1.2.0 (also origin/main), then changed in HEAD."""
    git = ["git", "-c", "user.name=t", "-c", "user.email=t@t", "-c", "commit.gpgsign=false"]
    steps = [["init", "-q"], ["add", "od"], ["commit", "-qm", "v1.2.0"], ["tag", "v1.2.0"]]
    steps += [["update-ref", "refs/remotes/origin/main", "HEAD"]]
    for step in steps:
        subprocess.run([*git, *step], cwd=folder, check=True, capture_output=True)
    drive = folder / "od" / "device.eds"
    drive.write_bytes(drive.read_bytes().replace(b"DataType=0x0006", b"DataType=0x0007", 1))
    subprocess.run([*git, "commit", "-qam", "change"], cwd=folder, check=True, capture_output=True)


LIVE = ("probe", "simulate")  # commands that need a CAN bus with a device on it


def lines_to_run() -> list[str]:
    """Each line once: the README's rows, the pages' synopses, the lines shown in sh blocks."""
    lines = [row_synopsis(row) for row in ROWS.values()] + [synopsis(page_synopsis(name)[0]) for name in COMMANDS]
    return list(dict.fromkeys(lines + shown_lines()))


@pytest.mark.parametrize("line", lines_to_run())
def test_documented_command_lines_run_as_written(line: str, tmp_path: Path) -> None:
    """Why: the table's `gen` line failed as written (`-t dbc` without `--node-id`), and so did `network BUS.yml`.
    Each line, run by the shell in a folder holding the files it names, exits 0, or 1 for findings: never 2, a
    usage error."""
    if line.split()[0] in LIVE:
        pytest.skip("talks to a device on a CAN adapter; tests/test_live_cli.py runs it on a bus between processes")
    folder = scratch(tmp_path)
    if "CO_driver_target.h" in line and not (folder / "src").is_dir():
        pytest.skip("../shared/third_party is absent")
    command = f"{shlex.join(cli_command())} {line}"
    env = {**os.environ, "PREFIX": str(folder)}
    ran = subprocess.run(
        command, shell=True, cwd=folder, env=env, capture_output=True, text=True, stdin=subprocess.DEVNULL
    )
    assert ran.returncode in (0, 1), f"cantools-od {line}: exit {ran.returncode}\n{ran.stderr}"
    assert "Traceback" not in ran.stderr
