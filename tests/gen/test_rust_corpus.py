"""Every real EDS/DCF of ../shared/eds-corpus: `cantools-od gen -t rust --keep-going` either writes a module
that compiles with `rustc -D warnings` (all modules in one crate, compiled once), is clippy- and
rustfmt-clean, or, for a file that is no device description, refuses with exit code 2 (EDS000). Never a
traceback."""

from __future__ import annotations

import time
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from click.testing import CliRunner
from rustkit import find_tool, require, run, rustfmt_check

from cantools_od.cli.gen import command, default_name

from support import corpus_files

# Its tests share one module fixture: under pytest-xdist they run on one worker, which makes it once.
pytestmark = pytest.mark.xdist_group("rust_corpus")


@dataclass
class Sweep:
    folder: Path
    generated: dict[str, Path] = field(default_factory=dict)  # module → input file
    refused: list[Path] = field(default_factory=list)
    failures: list[str] = field(default_factory=list)
    slowest: tuple[float, str] = (0.0, "")


@pytest.fixture(scope="module")
def sweep(tmp_path_factory: pytest.TempPathFactory) -> Sweep:
    files = corpus_files()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    result = Sweep(tmp_path_factory.mktemp("rust_corpus"))
    src = result.folder / "src"
    runner = CliRunner()
    for path in files:
        module = default_name(str(path))
        while module in result.generated:
            module += "_2"
        started = time.perf_counter()
        outcome = runner.invoke(command, [str(path), "-t", "rust", "-o", str(src), "--name", module, "--keep-going"])
        elapsed = time.perf_counter() - started
        result.slowest = max(result.slowest, (elapsed, path.name))
        written = (src / f"{module}.rs").is_file()
        if outcome.exception is not None and not isinstance(outcome.exception, SystemExit):
            result.failures.append(f"{path.name}: {outcome.exception!r}")
        elif written:
            result.generated[module] = path
        elif outcome.exit_code == 2 and "[EDS000]" in outcome.stderr:
            result.refused.append(path)
        else:
            result.failures.append(f"{path.name}: exit {outcome.exit_code} without output: {outcome.stderr[-500:]}")
    lib = "#![no_std]\n\n" + "".join(f"pub mod {module};\n" for module in sorted(result.generated))
    (src / "lib.rs").write_text(lib, encoding="utf-8")
    print(
        f"\nRust corpus sweep: {len(files)} files, {len(result.generated)} generated, {len(result.refused)} refused "
        f"(EDS000); slowest {result.slowest[1]} in {result.slowest[0]:.2f} s"
    )
    return result


def test_every_file_is_generated_or_refused(sweep: Sweep) -> None:
    assert not sweep.failures, "\n".join(sweep.failures)
    assert len(sweep.generated) > len(sweep.refused)


def test_corpus_compiles_without_warnings(sweep: Sweep) -> None:
    require("rustc")
    command = [find_tool("rustc") or "rustc", "--edition", "2021", "--crate-type", "lib", "-D", "warnings"]
    result = run([*command, "--out-dir", "out", "src/lib.rs"], sweep.folder)
    assert result.returncode == 0, result.stderr[-8000:]


def test_corpus_is_clippy_clean(sweep: Sweep) -> None:
    require("clippy-driver")
    command = [find_tool("clippy-driver") or "clippy-driver", "--edition", "2021", "--crate-type", "lib"]
    result = run([*command, "-D", "warnings", "--emit", "metadata", "--out-dir", "clippy", "src/lib.rs"], sweep.folder)
    assert result.returncode == 0, result.stderr[-8000:]


def test_corpus_is_rustfmt_clean(sweep: Sweep) -> None:
    require("rustfmt")
    result = rustfmt_check([sweep.folder / "src" / f"{module}.rs" for module in sorted(sweep.generated)])
    assert result.returncode == 0, result.stdout[-8000:]
