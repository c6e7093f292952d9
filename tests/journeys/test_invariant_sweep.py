"""The invariants of docs/outputs.md over real files: every writing command on a sample of ../shared (every kind:
EDS, DCF, XDD, XDC) and on damaged variants of some (tests/fuzzkit.py), each also with its output pointed at its
input. After each run: an exit code docs/cli.md lists (0, 1, 2), no exception; no file changed in bytes or mode but
the command's outputs, and the input only where the command rewrites it by design (`fmt`, `lint --fix`, with the
mode kept); an output pointed at the input is refused and leaves everything as it was.

In-process (click's runner), as the fuzz test runs; bench/README gives its run time."""

from __future__ import annotations

import contextlib
import random
from dataclasses import dataclass
from pathlib import Path

import pytest
from click.testing import CliRunner
from fuzzkit import mutated
from writekit import changed, state

from cantools_od.cli import main

from support import shared_files

KINDS = (".eds", ".dcf", ".xdd", ".xdc", ".xpd")
SAMPLE = 16  # real files, spread over ../shared in name order
FUZZED = 6  # damaged variants of the first of them
LARGEST = 96 * 1024  # bytes: the sweep stays within seconds


def sample() -> list[tuple[str, bytes]]:
    """(name, bytes) of the files swept: real ones of every kind, then damaged copies of some (fixed seed)."""
    found = [path for path in shared_files(KINDS) if path.stat().st_size <= LARGEST]
    if not found:
        return []
    chosen: list[Path] = []
    for kind in KINDS:  # at least one of each kind present
        chosen += [path for path in found if path.suffix.lower() == kind][:1]
    step = max(1, len(found) // SAMPLE)
    chosen += [path for path in found[::step] if path not in chosen][: SAMPLE - len(chosen)]
    files = [(f"{n:02d}-{path.name}", path.read_bytes()) for n, path in enumerate(chosen)]
    rng = random.Random(39)
    for name, data in files[:FUZZED]:
        files.append((f"fuzzed-{name}", mutated(rng, data)[1]))
    return files


@dataclass(frozen=True)
class Command:
    args: tuple[str, ...]  # "{f}": the input file
    outputs: tuple[str, ...] = ()  # what it may write (a folder: anything under it); "{stem}" the input's stem
    rewrites_input: bool = False  # by design, when it says so on stderr
    onto_input: bool = False  # its output is pointed at its input: refused, nothing changes
    mode: int = 0o640  # the input's mode (0444: read-only, so that nothing may rewrite it)


BUS = "master:\n  node_id: 1\nnode:\n  node_id: 5\n  dcf: {f}\n"
COMMANDS = {
    "fmt": Command(("fmt", "{f}"), rewrites_input=True),
    "fmt read-only": Command(("fmt", "{f}"), mode=0o444),
    "fmt --check": Command(("fmt", "--check", "--diff", "{f}")),
    "lint --fix": Command(("lint", "--fix", "{f}"), rewrites_input=True),
    "lint --fix read-only": Command(("lint", "--fix", "{f}"), mode=0o444),
    "convert": Command(("convert", "{f}", "-o", "out.json"), ("out.json",)),
    "convert onto its input": Command(("convert", "{f}", "-o", "{f}"), onto_input=True),
    "ids": Command(("ids", "{f}", "-o", "pins.toml"), ("pins.toml",)),
    "ids onto its input": Command(("ids", "{f}", "-o", "{f}"), onto_input=True),
    "gen": Command(
        ("gen", "{f}", "-t", "c", "-t", "python", "-o", "out", "--depfile", "out/deps.d", "--keep-going"), ("out",)
    ),
    "gen beside its input": Command(("gen", "{f}", "-t", "markdown", "-o", ".", "--keep-going"), ("{stem}.md",)),
    "gen --depfile onto its input": Command(
        ("gen", "{f}", "-t", "c", "-o", "out", "--depfile", "{f}"), onto_input=True
    ),
    "network": Command(
        ("network", "bus.yml", "-o", "net", "--dbc", "bus.dbc", "--keep-going", "--no-check"), ("net", "bus.dbc")
    ),
    "network --dbc onto a node": Command(("network", "bus.yml", "--dbc", "{f}", "--keep-going"), onto_input=True),
}
FILES = sample()


def sweep(folder: Path, name: str, data: bytes, command: Command) -> list[str]:
    """What is wrong with `command` on the file `name` holding `data`, run in the empty `folder`."""
    folder.mkdir()
    (folder / name).write_bytes(data)
    (folder / name).chmod(command.mode)
    (folder / "bus.yml").write_text(BUS.format(f=name))
    stem = Path(name).stem
    args = [arg.format(f=name) for arg in command.args]
    before = state(folder)
    with contextlib.chdir(folder):
        result = CliRunner().invoke(main, args)
    said = f"{' '.join(args)} -> {result.exit_code}: {result.stderr[-300:]!r}"
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        return [f"{said}: raised {type(result.exception).__name__}: {result.exception}"]
    problems = [] if result.exit_code in (0, 1, 2) else [f"{said}: an exit code docs/cli.md does not list"]
    moved = changed(before, state(folder))
    if command.onto_input:
        if result.exit_code == 0 or moved:
            problems.append(f"{said}: an output onto the input was not refused, or changed {sorted(moved)}")
        return problems
    allowed = {output.format(stem=stem) for output in command.outputs}
    by_design = command.rewrites_input and ("reformatted" in result.stderr or ": fixed " in result.stderr)
    for file in moved:
        if file == name and by_design:
            if before[name][1] != state(folder)[name][1]:
                problems.append(f"{said}: the rewritten input lost its mode")
        elif not any(file == out or file.startswith(out + "/") for out in allowed):
            problems.append(f"{said}: changed {file}, which is none of its outputs")
    return problems


@pytest.mark.skipif(not FILES, reason="../shared is absent")
@pytest.mark.parametrize("command", sorted(COMMANDS))
def test_every_writing_command_keeps_the_invariants(tmp_path: Path, command: str) -> None:
    problems = []
    for number, (name, data) in enumerate(FILES):
        problems += sweep(tmp_path / str(number), name, data, COMMANDS[command])
    assert not problems, "\n".join(problems[:10])


def test_the_sample_covers_every_kind() -> None:
    if not FILES:
        pytest.skip("../shared is absent")
    kinds = {Path(name).suffix.lower() for name, _ in FILES}
    assert {".eds", ".dcf", ".xdd", ".xdc"} <= kinds and len(FILES) == SAMPLE + FUZZED
