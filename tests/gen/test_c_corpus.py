"""Every file of the real-world corpus: `gen -t c --keep-going` writes C that compiles as C99 and whose
header compiles as C++11 (warnings as errors), leaving out only what errors in the file touch, or the file
is no device description at all (exit 2, EDS000); never a traceback. Without --keep-going, a file whose
errors touch generated code is refused: exit 1, an error diagnostic, and nothing written.

`gen` runs in-process (click's test runner) and the compilers run two at a time, to keep the sweep short.
"""

from __future__ import annotations

import re
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import click.testing
import pytest
from ckit import compile_checks, corpus_files, tool

from cantools_od.cli import main
from cantools_od.cli.gen import default_name

DIAGNOSTIC = re.compile(r"^.+:\d+:\d+: error: .+ \[[A-Z]{3}\d{3}\]$", re.MULTILINE)
NOT_A_DEVICE = re.compile(r"^.+: error: not an EDS/DCF file: .+ \[EDS000\]$", re.MULTILINE)


@dataclass
class Outcome:
    path: Path
    folder: Path
    name: str
    exit_code: int
    stderr: str
    generated: bool


def runner() -> click.testing.CliRunner:
    try:
        return click.testing.CliRunner(mix_stderr=False)  # type: ignore[call-arg]  # click < 8.2
    except TypeError:
        return click.testing.CliRunner()  # click >= 8.2 keeps stderr apart


def generate_all(files: list[Path], tmp_path: Path, *options: str) -> tuple[list[Outcome], list[str]]:
    outcomes, failures = [], []
    cli = runner()
    for number, path in enumerate(files):
        folder = tmp_path / f"{number:03d}"
        name = default_name(str(path))
        result = cli.invoke(main, ["gen", str(path), "-t", "c", "-o", str(folder), *options])
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            failures.append(f"{path.name}: {type(result.exception).__name__}: {result.exception}")
            continue
        generated = (folder / f"{name}.h").is_file() and (folder / f"{name}.c").is_file()
        outcomes.append(Outcome(path, folder, name, result.exit_code, result.stderr, generated))
    return outcomes, failures


def check_refusal(outcome: Outcome) -> list[str]:
    problems = []
    if outcome.exit_code == 2 and NOT_A_DEVICE.search(outcome.stderr):
        pass  # no device description at all: nothing to generate from
    elif outcome.exit_code != 1:
        problems.append(f"exit code {outcome.exit_code}")
    elif not DIAGNOSTIC.search(outcome.stderr) or "error: nothing generated" not in outcome.stderr:
        problems.append("no file:line:col: error: ... [CODE] diagnostic and 'nothing generated'")
    if "Traceback" in outcome.stderr:
        problems.append("a traceback")
    if outcome.folder.exists() and any(outcome.folder.iterdir()):
        problems.append("files written")
    return [f"{outcome.path.name}: refused, but {p}:\n{outcome.stderr}" for p in problems]


def test_every_corpus_file_compiles_with_keep_going(tmp_path: Path, record_property: pytest.RecordProperty) -> None:
    files = corpus_files()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    tool("gcc")
    tool("g++")
    outcomes, failures = generate_all(files, tmp_path, "--keep-going")
    generated = [o for o in outcomes if o.generated]
    refused = [o for o in outcomes if not o.generated]
    for outcome in refused:
        if not (outcome.exit_code == 2 and NOT_A_DEVICE.search(outcome.stderr)):
            failures.append(f"{outcome.path.name}: nothing generated with --keep-going:\n{outcome.stderr}")
    partial = [o for o in generated if "left out of the generated files" in o.stderr]
    for outcome in generated:
        if outcome.exit_code != 0 or "Traceback" in outcome.stderr:
            failures.append(f"{outcome.path.name}: generated with exit {outcome.exit_code}:\n{outcome.stderr}")
        note = "cantools-od gen --keep-going left out" in (outcome.folder / f"{outcome.name}.h").read_text("utf-8")
        if note != (outcome in partial):
            failures.append(f"{outcome.path.name}: the header's note does not match stderr:\n{outcome.stderr}")
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = pool.map(lambda o: (o, compile_checks(o.folder, o.name)), generated)
        failures += [f"{o.path.name}: {p}" for o, problems in results for p in problems]
    summary = (
        f"{len(files)} corpus files: {len(generated)} generated C that compiles with --keep-going "
        f"({len(partial)} leaving something out: {', '.join(o.path.name for o in partial)}); "
        f"{len(refused)} no device description ({', '.join(o.path.name for o in refused)})"
    )
    record_property("c_corpus_sweep", summary)
    print(summary)
    assert not failures, "\n".join(failures)
    assert len(generated) + len(refused) == len(files)


def test_without_keep_going_errors_refuse_and_write_nothing(tmp_path: Path) -> None:
    """The files --keep-going generated only in part are refused outright without it."""
    files = corpus_files()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    outcomes, failures = generate_all(files, tmp_path)
    refused = [o for o in outcomes if not o.generated]
    for outcome in refused:
        failures += check_refusal(outcome)
    for outcome in outcomes:
        if outcome.generated and (outcome.exit_code != 0 or "nothing generated" in outcome.stderr):
            failures.append(f"{outcome.path.name}: generated with exit {outcome.exit_code}:\n{outcome.stderr}")
    print(f"{len(files)} corpus files: {len(refused)} refused without --keep-going")
    assert not failures, "\n".join(failures)
    assert refused, "no corpus file has errors that touch generated code: the sweep proves nothing"
