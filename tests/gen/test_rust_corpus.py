"""Every real EDS/DCF of ../shared/eds-corpus: `cantools-od gen -t rust --keep-going` either writes a module
that compiles without warnings (all modules in one crate, compiled once), is clippy- and rustfmt-clean, or,
for a file that is no device description, refuses with exit code 2 (EDS000). Never a traceback.

The crate (about a million lines) is compiled once, by clippy-driver: it is rustc with clippy's lints added
(the toolchain's own compiler, front end and code generation alike), so one run shows both what rustc
reports and what clippy adds. Lints are capped at warnings so that the run goes to the end and every
diagnostic is seen; a test fails on any it is about, as `-D warnings` would. Without clippy, rustc alone
compiles it."""

from __future__ import annotations

import json
import re
import time
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from click.testing import CliRunner
from rustkit import find_tool, has_tool, require, run, rustfmt_check

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


@dataclass
class Compiled:
    tool: str  # "clippy-driver" or "rustc"
    returncode: int
    library: bool  # the .rlib was written
    diagnostics: list[dict[str, object]]  # rustc's JSON diagnostics, the end-of-run counts left out


_COUNT = re.compile(r"(\d+ warnings? emitted|aborting due to .*)")


@pytest.fixture(scope="module")
def compiled(sweep: Sweep) -> Compiled:
    """The crate compiled once: by clippy-driver when installed (the two tests below read its one run), else rustc."""
    tool = next((name for name in ("clippy-driver", "rustc") if has_tool(name)), None)
    if tool is None:
        pytest.skip("neither clippy-driver nor rustc is installed")
    command = [find_tool(tool) or tool, "--edition", "2021", "--crate-type", "lib", "--cap-lints", "warn"]
    result = run([*command, "--error-format", "json", "--out-dir", "out", "src/lib.rs"], sweep.folder)
    diagnostics = [json.loads(line) for line in result.stderr.splitlines() if line.startswith("{")]
    kept = [d for d in diagnostics if not _COUNT.fullmatch(str(d.get("message", "")))]
    library = any((sweep.folder / "out").glob("*.rlib"))
    return Compiled(tool, result.returncode, library, kept)


def _clippy(diagnostic: dict[str, object]) -> bool:
    code = diagnostic.get("code")
    return isinstance(code, dict) and str(code.get("code", "")).startswith("clippy::")


def _shown(diagnostics: list[dict[str, object]]) -> str:
    return "".join(str(d.get("rendered") or d.get("message")) for d in diagnostics)[-8000:]


def test_corpus_compiles_without_warnings(compiled: Compiled) -> None:
    """As `rustc -D warnings` would: no error, no warning of rustc's own, and the library is written."""
    require("rustc")
    found = [d for d in compiled.diagnostics if d.get("level") in ("error", "warning") and not _clippy(d)]
    assert not found, _shown(found)
    assert compiled.returncode == 0 and compiled.library, _shown(compiled.diagnostics)


def test_corpus_is_clippy_clean(compiled: Compiled) -> None:
    """As `clippy-driver -D warnings` would: no diagnostic at all, clippy's lints included."""
    require("clippy-driver")
    assert compiled.tool == "clippy-driver"
    found = [d for d in compiled.diagnostics if d.get("level") in ("error", "warning")]
    assert not found, _shown(found)
    assert compiled.returncode == 0


def test_corpus_is_rustfmt_clean(sweep: Sweep) -> None:
    require("rustfmt")
    result = rustfmt_check([sweep.folder / "src" / f"{module}.rs" for module in sorted(sweep.generated)])
    assert result.returncode == 0, result.stdout[-8000:]
