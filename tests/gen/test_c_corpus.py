"""Every file of the real-world corpus: either `gen -t c` writes C that compiles as C99 and whose header
compiles as C++11 (warnings as errors), or it refuses with exit 1 and a GEN001 diagnostic, never a traceback.

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

DIAGNOSTIC = re.compile(r"^.+:\d+:\d+: error: .+ \[GEN001\]$", re.MULTILINE)


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


def generate_all(files: list[Path], tmp_path: Path) -> tuple[list[Outcome], list[str]]:
    outcomes, failures = [], []
    cli = runner()
    for number, path in enumerate(files):
        folder = tmp_path / f"{number:03d}"
        name = default_name(str(path))
        result = cli.invoke(main, ["gen", str(path), "-t", "c", "-o", str(folder)])
        if result.exception is not None and not isinstance(result.exception, SystemExit):
            failures.append(f"{path.name}: {type(result.exception).__name__}: {result.exception}")
            continue
        generated = (folder / f"{name}.h").is_file() and (folder / f"{name}.c").is_file()
        outcomes.append(Outcome(path, folder, name, result.exit_code, result.stderr, generated))
    return outcomes, failures


def check_refusal(outcome: Outcome) -> list[str]:
    problems = []
    if outcome.exit_code != 1:
        problems.append(f"exit code {outcome.exit_code}")
    if not DIAGNOSTIC.search(outcome.stderr):
        problems.append("no file:line:col: error: ... [GEN001] diagnostic")
    if "Traceback" in outcome.stderr:
        problems.append("a traceback")
    if outcome.folder.exists() and any(outcome.folder.iterdir()):
        problems.append("files written")
    return [f"{outcome.path.name}: refused, but {p}:\n{outcome.stderr}" for p in problems]


def test_every_corpus_file_compiles_or_is_refused(tmp_path: Path, record_property: pytest.RecordProperty) -> None:
    files = corpus_files()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    tool("gcc")
    tool("g++")
    outcomes, failures = generate_all(files, tmp_path)
    generated = [o for o in outcomes if o.generated]
    refused = [o for o in outcomes if not o.generated]
    for outcome in refused:
        failures += check_refusal(outcome)
    for outcome in generated:
        if outcome.exit_code not in (0, 1) or "GEN001" in outcome.stderr or "Traceback" in outcome.stderr:
            failures.append(f"{outcome.path.name}: generated with exit {outcome.exit_code}:\n{outcome.stderr}")
    with ThreadPoolExecutor(max_workers=2) as pool:
        results = pool.map(lambda o: (o, compile_checks(o.folder, o.name)), generated)
        failures += [f"{o.path.name}: {p}" for o, problems in results for p in problems]
    summary = (
        f"{len(files)} corpus files: {len(generated)} generated C that compiles, "
        f"{len(refused)} refused with GEN001 ({', '.join(o.path.name for o in refused)})"
    )
    record_property("c_corpus_sweep", summary)
    print(summary)
    assert not failures, "\n".join(failures)
    assert len(generated) + len(refused) == len(files)
