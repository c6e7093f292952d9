"""What no command writes over (docs/outputs.md), as issue 39 found it done: an input replaced by an output (exit 0),
a hand-written file replaced by a generated one, a read-only file replaced; and the batches that stopped at one
bad argument, and Ctrl-C that exited 1 (the code of findings)."""

from __future__ import annotations

import contextlib
import json
import os
import signal
import subprocess
import time
from collections.abc import Iterator
from pathlib import Path

import pytest
from kit import non_writer, open_folder, run
from writekit import HAND_WRITTEN, UNFORMATTED, project, state

from support import ROOT, cli_command

GEN_C = ["gen", "drive.eds", "-t", "c", "-o", "."]

ON_AN_INPUT = {  # the command, the output it would write, the input that output is
    "ids -o its input": (["ids", "drive.eds", "-o", "drive.eds"], "drive.eds", "drive.eds"),
    "gen --depfile its input": ([*GEN_C, "--depfile", "drive.eds"], "drive.eds", "drive.eds"),
    "gen --depfile its pin file": ([*GEN_C, "--depfile", "drive.ids.toml"], "drive.ids.toml", "drive.ids.toml"),
    "network --dbc its bus": (["network", "bus.yml", "--dbc", "bus.yml"], "bus.yml", "bus.yml"),
    "network --dbc a node's EDS": (["network", "bus.yml", "--dbc", "io.eds"], "io.eds", "io.eds"),
    "network -o over a node's DCF": (["network", "bus.yml", "-o", "."], "drive.dcf", "drive.dcf"),
    "convert -o a link to its input": (["convert", "drive.eds", "-o", "link.eds"], "link.eds", "drive.eds"),
    "convert -o a hard link to its input": (["convert", "drive.eds", "-o", "hard.eds"], "hard.eds", "drive.eds"),
    "import-table --report its source": (
        ["import-table", "table.csv", "-o", "t.eds", "--report", "table.csv"],
        "table.csv",
        "table.csv",
    ),
}


@pytest.mark.parametrize("case", sorted(ON_AN_INPUT))
def test_an_output_on_an_input_is_refused(tmp_path: Path, case: str) -> None:
    """Why: `ids dev.eds -o dev.eds` replaced the EDS with a pin file, `gen --depfile dev.eds` with a make rule,
    `network --dbc bus.yml` the bus description with a DBC, each with exit 0."""
    args, output, read = ON_AN_INPUT[case]
    project(tmp_path)
    (tmp_path / "link.eds").symlink_to("drive.eds")
    os.link(tmp_path / "drive.eds", tmp_path / "hard.eds")
    if case.startswith("network -o"):  # a node file that is a DCF, where network writes the node's DCF
        (tmp_path / "drive.dcf").write_bytes((tmp_path / "drive.eds").read_bytes())
        (tmp_path / "bus.yml").write_text((tmp_path / "bus.yml").read_text().replace("drive.eds", "drive.dcf"))
    before = state(tmp_path)
    ran = run(*args, cwd=tmp_path)
    lines = ran.stderr.splitlines()
    assert ran.returncode == 2 and lines, ran
    assert lines[-1] == f"error: cannot write {output}: it is {read}, which the command reads; nothing written", ran
    assert state(tmp_path) == before


def test_two_outputs_that_are_one_file_are_refused(tmp_path: Path) -> None:
    project(tmp_path)
    before = state(tmp_path)
    ran = run(*GEN_C, "--depfile", "drive.c", cwd=tmp_path)
    assert ran.returncode == 2, ran
    assert (
        ran.stderr == "error: cannot write drive.c: it is the same file as drive.c, another output; nothing written\n"
    ), ran
    assert state(tmp_path) == before and not (tmp_path / "drive.h").exists()


def test_gen_replaces_only_what_it_generated(tmp_path: Path) -> None:
    """Why: `gen -o .` replaced a hand-written dev.c it never generated."""
    project(tmp_path)
    (tmp_path / "drive.c").write_bytes(HAND_WRITTEN)
    before = state(tmp_path)
    refused = run(*GEN_C, cwd=tmp_path)
    assert refused.returncode == 2, refused
    assert refused.stderr == (
        "error: cannot write drive.c: it is not a file cantools-od generated (it has no generated-file banner);"
        " --force replaces it\n"
    )
    assert state(tmp_path) == before and not (tmp_path / "drive.h").exists()
    assert run(*GEN_C, "--force", cwd=tmp_path).returncode == 0
    generated = (tmp_path / "drive.c").read_bytes()
    assert generated != HAND_WRITTEN
    (tmp_path / "drive.c").write_bytes(generated + b"/* an edit of the generated file */\n")  # still ours
    assert run(*GEN_C, cwd=tmp_path).returncode == 0 and (tmp_path / "drive.c").read_bytes() == generated


def test_read_only_outputs_that_would_not_change_are_left_alone(tmp_path: Path) -> None:
    """A generated folder checked in read-only (as Perforce keeps files until opened for edit) regenerates without
    a word when nothing changed: only a file whose content changes is refused for its mode."""
    project(tmp_path)
    assert run(*GEN_C, cwd=tmp_path).returncode == 0
    for name in ("drive.c", "drive.h"):
        (tmp_path / name).chmod(0o444)
    before = state(tmp_path)
    ran = run(*GEN_C, cwd=tmp_path)
    assert (ran.returncode, ran.stderr) == (0, ""), ran
    assert state(tmp_path) == before


def test_every_generated_text_file_carries_the_banner(tmp_path: Path) -> None:
    """What gen writes into a folder, a later run recognises as its own: regenerating needs no --force."""
    project(tmp_path)
    targets = ["-t", "c", "-t", "rust", "-t", "python", "-t", "markdown", "-t", "dbc", "--node-id", "2"]
    for _ in range(2):
        ran = run("gen", "drive.eds", *targets, "-o", "out", cwd=tmp_path)
        assert ran.returncode == 0, ran
    ran = run("gen", "drive.eds", "-t", "canopennode", "-o", "out", "--keep-going", cwd=tmp_path)
    assert ran.returncode == 0, ran
    for path in (tmp_path / "out").iterdir():
        assert b"generated by cantools-od" in path.read_bytes()[:4096].lower(), path.name
    first = (tmp_path / "out" / "drive.dbc").read_text().splitlines()[0]
    assert first == 'VERSION "generated by cantools-od; do not edit"'


def test_network_replaces_only_configuration_files(tmp_path: Path) -> None:
    project(tmp_path)
    out = tmp_path / "out"
    assert run("network", "bus.yml", "-o", "out", cwd=tmp_path).returncode == 0
    assert run("network", "bus.yml", "-o", "out", cwd=tmp_path).returncode == 0  # its own files, replaced
    (out / "master.dcf").write_bytes(HAND_WRITTEN)
    (out / "io.dcf").unlink()
    before = state(tmp_path)
    ran = run("network", "bus.yml", "-o", "out", cwd=tmp_path)
    assert ran.returncode == 2 and "cannot write out/master.dcf: it is not a file cantools-od generated" in ran.stderr
    assert state(tmp_path) == before and not (out / "io.dcf").exists()
    assert run("network", "bus.yml", "-o", "out", "--force", cwd=tmp_path).returncode == 0
    assert (out / "master.dcf").read_bytes() != HAND_WRITTEN


@pytest.mark.parametrize(
    "args",
    [["fmt", "ro.eds"], ["lint", "--fix", "ro.eds"], ["convert", "unformatted.eds", "-o", "ro.eds"]],
    ids=["fmt", "lint --fix", "convert -o"],
)
def test_a_read_only_file_is_not_replaced(tmp_path: Path, args: list[str]) -> None:
    """Why: fmt, lint --fix and convert -o replaced a file of mode 0444 (the rename ignores the mode; tests run as
    root, whom no permission stops). As ruff and black: one line, exit 2."""
    project(tmp_path)
    source = tmp_path / "ro.eds"
    held = {"fmt": "unformatted.eds", "lint": "emcy.eds", "convert": "drive.eds"}[args[0]]  # what would change
    source.write_bytes((tmp_path / held).read_bytes())
    source.chmod(0o444)
    before = state(tmp_path)
    ran = run(*args, cwd=tmp_path)
    assert ran.returncode == 2, ran
    assert ran.stderr.splitlines()[-1] == (
        "error: cannot write ro.eds: Permission denied (its mode 0444 forbids writing it); nothing written"
    ), ran
    assert state(tmp_path) == before


def test_fmt_goes_on_after_a_read_only_file(tmp_path: Path) -> None:
    project(tmp_path)
    (tmp_path / "ro.eds").write_bytes(UNFORMATTED)
    (tmp_path / "ro.eds").chmod(0o444)
    ran = run("fmt", "ro.eds", "unformatted.eds", cwd=tmp_path)
    assert ran.returncode == 2 and "reformatted unformatted.eds" in ran.stderr, ran
    assert (tmp_path / "ro.eds").read_bytes() == UNFORMATTED
    assert (tmp_path / "unformatted.eds").read_bytes() != UNFORMATTED


# ---- batches: one bad argument does not stop the run ------------------------------------------------------------


def batch(tmp_path: Path) -> list[str]:
    """A folder as `*` expands it: a subfolder, a file nobody may read (as root: none), a file that is gone."""
    project(tmp_path)
    (tmp_path / "old").mkdir()
    return ["drive.eds", "old", "gone.eds", "emcy.eds"]


@pytest.mark.parametrize("fmt", ["text", "json", "sarif", "github"])
def test_lint_reports_what_it_cannot_read_and_checks_the_rest(tmp_path: Path, fmt: str) -> None:
    """Why: `lint *` with a subfolder said "File 'old' is a directory", exit 2, and checked nothing; a missing file
    was counted as checked ("2 files checked: no findings"), `[]` in JSON, and left out of SARIF and GitHub."""
    files = batch(tmp_path)
    before = state(tmp_path)
    ran = run("lint", "--format", fmt, *files, cwd=tmp_path)
    assert ran.returncode == 2 and ran.stderr == "", ran
    reported = _reported(fmt, ran.stdout)
    assert ("old", "EDS000", "cannot read: it is a folder") in reported, ran
    assert ("gone.eds", "EDS000", "cannot read: No such file or directory") in reported, ran
    assert any(file == "emcy.eds" and code != "EDS000" for file, code, _ in reported), ran  # the rest was checked
    if fmt == "text":
        assert ran.stdout.splitlines()[-1].startswith("2 files checked, 2 not read: "), ran
    assert state(tmp_path) == before


def _reported(fmt: str, out: str) -> set[tuple[str, str, str]]:
    """(file, code, message) of each finding, from any format."""
    if fmt == "json":
        return {(f["file"], f["code"], f["message"]) for f in json.loads(out)}
    if fmt == "sarif":
        results = json.loads(out)["runs"][0]["results"]
        return {
            (r["locations"][0]["physicalLocation"]["artifactLocation"]["uri"], r["ruleId"], r["message"]["text"])
            for r in results
        }
    found = set()
    for line in out.splitlines():
        if fmt == "github" and line.startswith("::"):
            head, _, message = line[2:].partition("::")
            fields = dict(part.split("=", 1) for part in head.split(" ", 1)[1].split(","))
            found.add((fields["file"], fields["title"], message))
        elif fmt == "text" and line.endswith("]") and ": error: " in line:
            where, _, rest = line.partition(": error: ")
            message, _, code = rest.rpartition(" [")
            found.add((where.split(":")[0], code[:-1], message))
        elif fmt == "text" and line.endswith("]"):
            found.add((line.split(":")[0], line.rpartition(" [")[2][:-1], ""))
    return found


def test_an_unreadable_file_does_not_stop_the_batch() -> None:
    """Why: a file the user may not read stopped `lint *` and `fmt --check *` as a usage error, nothing checked."""
    user = non_writer()
    with open_folder() as folder:
        project(folder)
        (folder / "secret.eds").write_bytes(UNFORMATTED)
        (folder / "secret.eds").chmod(0o600 if user else 0o000)  # root's file: nobody else may read it
        linted = run("lint", "secret.eds", "emcy.eds", cwd=folder, user=user)
        assert linted.returncode == 2 and linted.stderr == "", linted
        assert "secret.eds:1:1: error: cannot read: Permission denied [EDS000]" in linted.stdout.splitlines(), linted
        assert "emcy.eds:" in linted.stdout and linted.stdout.splitlines()[-1].startswith("1 file checked, 1 not read")
        checked = run("fmt", "--check", "secret.eds", "unformatted.eds", cwd=folder, user=user)
        assert checked.returncode == 2, checked
        assert checked.stderr.splitlines() == [
            "secret.eds: error: cannot read: Permission denied",
            "would reformat unformatted.eds",
        ], checked


def test_fmt_check_reports_what_it_cannot_read_and_checks_the_rest(tmp_path: Path) -> None:
    files = batch(tmp_path)
    ran = run("fmt", "--check", *files, "unformatted.eds", cwd=tmp_path)
    assert ran.returncode == 2, ran
    assert "old: error: cannot read: it is a folder" in ran.stderr.splitlines(), ran
    assert "gone.eds: error: cannot read: No such file or directory" in ran.stderr.splitlines(), ran
    assert "would reformat unformatted.eds" in ran.stderr.splitlines(), ran


# ---- Ctrl-C --------------------------------------------------------------------------------------------------------

INTERRUPTED = {
    "dump": ["dump", "fifo.eds"],
    "lint": ["lint", "fifo.eds"],
    "lint --jobs 2": ["lint", "--jobs", "2", "drive.eds", "fifo.eds", "io.eds"],
    "fmt": ["fmt", "fifo.eds"],
    "convert": ["convert", "fifo.eds", "-o", "out.json"],
    "gen": ["gen", "fifo.eds", "-t", "c", "-o", "out"],
    "pdo": ["pdo", "fifo.eds"],
    "ids": ["ids", "fifo.eds"],
    "diff": ["diff", "drive.eds", "fifo.eds"],
    "network": ["network", "fifo.yml", "--load"],
    "import-table": ["import-table", "fifo.csv", "-o", "out.eds"],
    "lsp": ["lsp", "--stdio"],
}


@contextlib.contextmanager
def _waiting_reader(fifo: Path | None) -> Iterator[None]:
    """Returns once the command has the pipe open for reading (it then waits for data), and keeps the pipe's
    writing end open meanwhile (its closing would end the command's wait); without a pipe (lsp reads stdin), after
    a while."""
    if fifo is None:
        time.sleep(3)
        yield
        return
    deadline = time.monotonic() + 60
    while True:
        try:
            writer = os.open(fifo, os.O_WRONLY | os.O_NONBLOCK)  # ENXIO while nobody reads it
            break
        except OSError:
            assert time.monotonic() < deadline, f"nothing opened {fifo.name} to read it"
            time.sleep(0.05)
    try:
        time.sleep(0.2)  # from opening to reading
        yield
    finally:
        os.close(writer)


@pytest.mark.parametrize("command", sorted(INTERRUPTED))
def test_ctrl_c_exits_130_in_one_line(tmp_path: Path, command: str) -> None:
    """Why: Ctrl-C printed "Aborted!" and exited 1, the code of findings: a CI step or a script took an
    interrupted check for one that found errors. Each command here waits on a pipe nobody writes to."""
    project(tmp_path)
    for name in ("fifo.eds", "fifo.yml", "fifo.csv"):
        os.mkfifo(tmp_path / name)
    started = subprocess.Popen(
        [*cli_command(), *INTERRUPTED[command]],
        cwd=tmp_path,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        start_new_session=True,  # its own process group: Ctrl-C reaches it and its workers, as in a terminal
        text=True,
    )
    fifo = next((tmp_path / arg for arg in INTERRUPTED[command] if arg.startswith("fifo.")), None)
    with _waiting_reader(fifo):
        os.killpg(started.pid, signal.SIGINT)
    _, err = started.communicate(timeout=60)
    assert (started.returncode, err) == (130, "cantools-od: interrupted\n")
    assert not list(tmp_path.glob("**/*.tmp"))


def test_help_and_docs_give_the_interrupted_code(tmp_path: Path) -> None:
    """`cantools-od --help`, the README's line of exit codes and the exit-code table of docs/cli.md."""
    assert "130 interrupted (Ctrl-C)" in " ".join(run("--help", cwd=tmp_path).stdout.split())
    assert "`130` interrupted" in " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    assert "| `130` | interrupted (Ctrl-C: one line, `cantools-od: interrupted`) |" in (
        ROOT / "docs" / "cli.md"
    ).read_text(encoding="utf-8")
