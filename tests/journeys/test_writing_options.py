"""Every command and every path it takes, found from the command line's own definition (the click group), run
with that path pointed where no write may go (docs/outputs.md): at the command's input, at a read-only file, at a
hand-written file where a generated one would go. A writing option added without the write path fails here: an
`Output` that bypasses it replaces the input or the read-only file; a writing option declared as a plain path
changes the copy of its file this test points it at; a new command that takes paths has no recipe here.

In-process (click's runner), as the fuzz test runs: some 50 runs in a few seconds."""

from __future__ import annotations

import contextlib
import shutil
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import click
import pytest
from click.testing import CliRunner
from writekit import HAND_WRITTEN, changed, project, state

from cantools_od.cli import main
from cantools_od.cli.common import Output, Rewritten

# A run of each command that takes a path, which succeeds in the project (tests/journeys/writekit.py) and passes
# every path option the command has. Commands without a path (rules, cmake-dir, lsp) need none.
RECIPES: dict[str, list[str]] = {
    "gen": ["gen", "drive.eds", "-t", "c", "-t", "dbc", "--node-id", "2", "-o", "out", "--depfile", "deps.d",
            "--pins", "drive.ids.toml", "--stack-config", "stack.h"],
    "ids": ["ids", "drive.eds", "--pins", "drive.ids.toml", "-o", "pins.toml"],
    "convert": ["convert", "drive.eds", "-o", "drive.xdd"],
    "network": ["network", "bus.yml", "-o", "net", "--dcf-dir", "nodes", "--dbc", "bus.dbc", "--svg", "bus.svg",
                "--write-bus", "installed/bus.yml"],
    "import-table": ["import-table", "table.csv", "-o", "imported.eds", "--overrides", "overrides.toml",
                     "--report", "report.md"],
    "fmt": ["fmt", "unformatted.eds", "--config", "cantools-od.toml"],
    "lint": ["lint", "--select", "EDS033", "--fix", "--unsafe-fixes", "emcy.eds", "--stack-config", "stack.h",
             "--config", "cantools-od.toml"],
    "dump": ["dump", "drive.eds"],
    "pdo": ["pdo", "drive.eds", "--pins", "drive.ids.toml", "--format", "svg", "-o", "pictures"],
    "diff": ["diff", "drive.eds", "io.eds", "--old-pins", "drive.ids.toml", "--new-pins", "drive.ids.toml"],
}  # fmt: skip
# Commands that need a live node on a CAN bus, which a run in this process cannot have: tests/test_live_cli.py
# points `probe -o` at its input and at a read-only file on a bus between processes.
LIVE = {"probe", "simulate"}
BY_DESIGN = {"ids": {"drive.ids.toml"}}  # `ids -o` updates the pin file it reads: its pins are kept
WRITING_WORDS = {"output", "out", "outdir", "dbc", "svg", "depfile", "report", "dest", "destination", "save", "write"}


def commands() -> dict[str, click.Command]:
    with click.Context(main) as ctx:
        found = {name: main.get_command(ctx, name) for name in main.list_commands(ctx)}
    return {name: command for name, command in found.items() if command is not None}


def path_params(command: click.Command) -> list[click.Parameter]:
    return [param for param in command.params if isinstance(param.type, click.Path | click.File)]


@dataclass(frozen=True)
class Slot:
    """Where a path goes in a recipe: the index of its value."""

    command: str
    param: click.Parameter
    at: int

    @property
    def value(self) -> str:
        return RECIPES[self.command][self.at]

    def args(self, value: str) -> list[str]:
        args = list(RECIPES[self.command])
        args[self.at] = value
        return args

    def __str__(self) -> str:
        return f"{self.command} {self.param.opts[0] if isinstance(self.param, click.Option) else self.param.name}"


def slots() -> list[Slot]:
    """Every path parameter of every command, placed in its recipe."""
    found = []
    for name, command in commands().items():
        if name in LIVE:
            continue
        for param in path_params(command):
            if name not in RECIPES:
                found.append(Slot(name, param, -1))  # test_every_path_is_in_a_recipe says so
                continue
            found.append(Slot(name, param, _index(RECIPES[name], param)))
    return found


def _index(recipe: list[str], param: click.Parameter) -> int:
    if isinstance(param, click.Option):
        spelled = [i for i, word in enumerate(recipe) if word in param.opts]
        return spelled[0] + 1 if spelled else -1
    options = [i for i, word in enumerate(recipe[1:], 1) if word.startswith("-")]
    taken = {i + 1 for i in options if _takes_value(recipe[0], recipe[i])} | set(options)
    positional = [i for i in range(1, len(recipe)) if i not in taken]
    return positional[0] if positional else -1


def _takes_value(command: str, option: str) -> bool:
    found = commands()[command]
    return any(option in p.opts and not p.is_flag for p in found.params if isinstance(p, click.Option))


SLOTS = slots()


def test_every_path_is_in_a_recipe() -> None:
    """A command or path option added without a recipe here would go untested: it fails here instead."""
    missing = [str(slot) for slot in SLOTS if slot.at < 0]
    assert not missing, f"add them to RECIPES: {missing}"


def test_writing_options_are_declared_as_outputs() -> None:
    """An option named as an output is an `Output` (or the in-place `Rewritten`); no option is a click.File, which
    would write past the write path."""
    for name, command in commands().items():
        for param in command.params:
            assert not isinstance(param.type, click.File), f"{name} {param.name}: a click.File writes past files.py"
            flag = isinstance(param, click.Option) and param.is_flag
            if WRITING_WORDS & set((param.name or "").split("_")) and not flag:
                kind = type(param.type).__name__
                assert isinstance(param.type, Output | Rewritten), f"{name} {param.name} is a {kind}, not an Output"


@contextlib.contextmanager
def inside(folder: Path) -> Iterator[None]:
    with contextlib.chdir(folder):
        yield


def invoke(folder: Path, args: list[str]) -> tuple[int, str]:
    """The command in `folder`: its exit code and what it printed to stderr."""
    with inside(folder):
        result = CliRunner().invoke(main, args, catch_exceptions=False)
    return result.exit_code, result.stderr


def make(folder: Path) -> Path:
    project(folder)
    (folder / "stack.h").write_text("/* the project's CANopenNode configuration */\n")
    (folder / "cantools-od.toml").write_text("")
    (folder / "overrides.toml").write_text("")
    (folder / "nodes").mkdir()
    return folder


def outputs_of(command: str, args: list[str]) -> set[str]:
    """What a run may change: its outputs' values, the folders' files, the files it rewrites in place."""
    allowed = set()
    found = commands()[command]
    for param in path_params(found):
        at = _index(args, param)
        if at < 0 or not isinstance(param.type, Output | Rewritten):
            continue
        if isinstance(param.type, Rewritten) and command == "lint" and "--fix" not in args:
            continue
        allowed.add(args[at])
    return allowed


def assert_only_outputs_changed(
    folder: Path, before: dict[str, tuple[str, int]], command: str, args: list[str]
) -> None:
    allowed = outputs_of(command, args)
    moved = {name for name in changed(before, state(folder)) if not any(_under(name, a) for a in allowed)}
    assert not moved, f"{' '.join(args)} changed {sorted(moved)}, which are none of its outputs"


def _under(name: str, output: str) -> bool:
    return name == output or name.startswith(output.rstrip("/") + "/")


def test_every_recipe_runs(tmp_path: Path) -> None:
    for command, args in RECIPES.items():
        folder = make(tmp_path / command)
        before = state(folder)
        code, err = invoke(folder, args)
        assert code == 0 or (command == "diff" and code in (0, 1)), f"{' '.join(args)}: exit {code}\n{err}"
        assert_only_outputs_changed(folder, before, command, args)


def inputs_of(slot: Slot) -> list[str]:
    """The files the recipe reads (every path value that is no output), for an output to be pointed at."""
    recipe = RECIPES[slot.command]
    found = commands()[slot.command]
    values = []
    for param in path_params(found):
        at = _index(recipe, param)
        if at >= 0 and not isinstance(param.type, Output):
            values.append(recipe[at])
    return [value for value in values if "." in value and value not in BY_DESIGN.get(slot.command, ())]


OUTPUTS = [slot for slot in SLOTS if isinstance(slot.param.type, Output)]
OUTPUT_FILES = [slot for slot in OUTPUTS if isinstance(slot.param.type, click.Path) and slot.param.type.file_okay]
OUTPUT_FOLDERS = [slot for slot in OUTPUTS if slot not in OUTPUT_FILES]
REWRITTEN = [slot for slot in SLOTS if isinstance(slot.param.type, Rewritten)]
INPUTS = [slot for slot in SLOTS if slot.at >= 0 and not isinstance(slot.param.type, Output | Rewritten)]


@pytest.mark.parametrize("slot", OUTPUT_FILES, ids=str)
def test_an_output_file_never_lands_on_an_input(tmp_path: Path, slot: Slot) -> None:
    for number, read in enumerate(inputs_of(slot)):
        folder = make(tmp_path / str(number))
        before = state(folder)
        code, err = invoke(folder, slot.args(read))
        assert code == 2 and err.splitlines() and read in err.splitlines()[-1], f"{slot} {read}: exit {code}\n{err}"
        assert state(folder) == before, f"{slot} pointed at {read} changed the project"


@pytest.mark.parametrize("slot", OUTPUT_FILES, ids=str)
def test_an_output_file_that_is_read_only_is_kept(tmp_path: Path, slot: Slot) -> None:
    folder = make(tmp_path)
    locked = folder / f"locked{Path(slot.value).suffix}"
    locked.write_bytes(HAND_WRITTEN)
    locked.chmod(0o444)
    before = state(folder)
    code, err = invoke(folder, slot.args(locked.name))
    assert code == 2 and "Permission denied (its mode 0444 forbids writing it)" in err, f"{slot}: exit {code}\n{err}"
    assert state(folder) == before


@pytest.mark.parametrize("slot", OUTPUT_FOLDERS, ids=str)
def test_an_output_folder_keeps_what_it_did_not_generate(tmp_path: Path, slot: Slot) -> None:
    """Hand-written files where the command writes its own are refused; read-only ones of its own too; --force
    takes the hand-written ones over."""
    first = make(tmp_path / "first")
    assert invoke(first, slot.args(slot.value))[0] == 0
    made = sorted(p.relative_to(first / slot.value) for p in (first / slot.value).rglob("*") if p.is_file())
    assert made, f"{slot} made nothing"
    for kind in ("hand-written", "read-only", "forced"):
        folder = make(tmp_path / kind)
        for name in made:
            target = folder / slot.value / name
            target.parent.mkdir(parents=True, exist_ok=True)
            if kind == "read-only":  # its own, an earlier version
                target.write_bytes((first / slot.value / name).read_bytes() + b"\n")
                target.chmod(0o444)
            else:
                target.write_bytes(HAND_WRITTEN)
        before = state(folder)
        args = slot.args(slot.value) + (["--force"] if kind == "forced" else [])
        code, err = invoke(folder, args)
        if kind == "forced":
            assert code == 0, f"{slot} --force: exit {code}\n{err}"
            assert all((folder / slot.value / name).read_bytes() != HAND_WRITTEN for name in made)
            continue
        reason = "Permission denied" if kind == "read-only" else "it is not a file cantools-od generated"
        assert code == 2 and reason in err and len(err.splitlines()) >= 1, f"{slot} {kind}: exit {code}\n{err}"
        assert state(folder) == before, f"{slot}: {kind} files changed"


@pytest.mark.parametrize("slot", REWRITTEN, ids=str)
def test_a_file_rewritten_in_place_is_kept_when_read_only(tmp_path: Path, slot: Slot) -> None:
    folder = make(tmp_path)
    (folder / slot.value).chmod(0o444)
    before = state(folder)
    code, err = invoke(folder, RECIPES[slot.command])
    assert code == 2 and "Permission denied (its mode 0444 forbids writing it)" in err, f"{slot}: exit {code}\n{err}"
    assert state(folder) == before


@pytest.mark.parametrize("slot", INPUTS, ids=str)
def test_a_path_that_is_read_is_not_written(tmp_path: Path, slot: Slot) -> None:
    """Each path the command only reads, pointed at a copy of its file: the copy stays as it was (a path option that
    writes without being an `Output` changes it), and nothing but the declared outputs changes."""
    folder = make(tmp_path)
    original = folder / slot.value
    copy = original.with_name(f"copy-{original.name}")
    if original.is_dir():
        shutil.copytree(original, copy)
        (copy / "hand-written.txt").write_bytes(HAND_WRITTEN)
    else:
        shutil.copy2(original, copy)
        copy.chmod(0o640)
    args = slot.args(copy.relative_to(folder).as_posix())
    before = state(folder)
    code, err = invoke(folder, args)
    assert code in (0, 1), f"{slot}: exit {code}\n{err}"
    assert_only_outputs_changed(folder, before, slot.command, args)
