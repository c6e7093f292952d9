"""Fuzzing every command, in-process (tests/fuzzkit.py): 2,100 randomly damaged corpus files with a
fixed seed, so that a run is the same on every machine; bench/fuzz.py runs as many as asked.

Below them, what earlier runs found, each as a fixed example of its own.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest
from click.testing import CliRunner
from fuzzkit import COMMANDS, XDD_CORPUS, cases, run, sources

from cantools_od import loads
from cantools_od.cli import main

from support import CORPUS, EXAMPLES

SEED = 27
CHUNKS = 14
PER_CHUNK = 150  # 2,100 cases in all: every command on about 140 inputs


@pytest.fixture(scope="module")
def originals() -> dict[str, bytes]:
    return sources()


@pytest.mark.parametrize("chunk", range(CHUNKS))
def test_every_command_on_damaged_files(
    chunk: int, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, originals: dict[str, bytes]
) -> None:
    monkeypatch.chdir(tmp_path)
    failures = []
    for number, (case, data) in enumerate(cases(SEED + chunk, PER_CHUNK, [])):
        problems = run(case, data, originals[case.source], tmp_path / str(number))
        failures += [f"{case}: {problem}" for problem in problems]
    assert not failures, "\n".join(failures[:10])


def test_the_cases_cover_every_command_and_source(originals: dict[str, bytes]) -> None:
    every = [pair for chunk in range(CHUNKS) for pair in cases(SEED + chunk, PER_CHUNK, [])]
    commands = Counter(case.command for case, _ in every)
    assert set(commands) == set(COMMANDS) and min(commands.values()) >= 100, commands
    chosen = cases(SEED, PER_CHUNK, [])
    assert {case.source for case, _ in chosen} == set(originals)
    assert len({data for _, data in chosen}) > PER_CHUNK * 0.9  # mutated, and each differently


# --- found by fuzzing -----------------------------------------------------------------------------


def invoke(tmp_path: Path, monkeypatch: pytest.MonkeyPatch, *args: str) -> str:
    monkeypatch.chdir(tmp_path)
    result = CliRunner().invoke(main, list(args))
    assert result.exception is None or isinstance(result.exception, SystemExit), repr(result.exception)
    assert result.exit_code in (0, 1, 2)
    return result.output


def test_diff_json_with_nodeid_cob_ids(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """`diff --format json` re-validated its records from plain dicts: `$NODEID+0x200` did not survive."""
    old = (EXAMPLES / "io_device.eds").read_bytes()
    (tmp_path / "old.eds").write_bytes(old)
    (tmp_path / "new.eds").write_bytes(old.replace(b"DefaultValue=$NODEID+0x200", b"DefaultValue=$NODEID+0x300", 1))
    output = invoke(tmp_path, monkeypatch, "diff", "old.eds", "new.eds", "--format", "json")
    assert '"nodeid": 768' in output and '"nodeid": 512' in output


def test_diff_sub_objects_under_a_var(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Sub-object sections under an object that lost its ObjectType (a VAR then): identifiers had no entry."""
    old = EXAMPLES / "io_device.eds"
    data = old.read_bytes()
    start = data.index(b"[1400]")
    (tmp_path / "new.eds").write_bytes(data[:start] + data[start:].replace(b"ObjectType=0x9\n", b"", 1))
    (tmp_path / "renamed.eds").write_bytes(
        (tmp_path / "new.eds").read_bytes().replace(b"ParameterName=Transmission type", b"ParameterName=Kind", 1)
    )
    output = invoke(tmp_path, monkeypatch, "diff", "new.eds", "renamed.eds")
    assert "Kind" not in output  # sub-objects of a VAR are no part of its dictionary: nothing to compare


def corpus_bytes(folder: Path, name: str) -> bytes:
    path = folder / name
    if not path.is_file():
        pytest.skip(f"{name} is not in ../shared")
    return path.read_bytes()


def test_xdd_baud_rate_of_thousands_of_digits() -> None:
    data = corpus_bytes(XDD_CORPUS, "eds-dcf-net__minimal.xdc")
    device = loads(data.replace(b'value="250 Kbps"', b'value="' + b"9" * 5000 + b' Kbps"'), source="x.xdc")
    assert 250 not in device.device_info.baud_rates


def test_module_count_of_thousands_of_digits(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    data = corpus_bytes(CORPUS, "eds-dcf-net__modular_device.dcf")
    (tmp_path / "m.dcf").write_bytes(data.replace(b"NrOfEntries=2", b"NrOfEntries=0x" + b"F" * 5000, 1))
    output = invoke(tmp_path, monkeypatch, "lint", "m.dcf")
    assert "[LNT001]" not in output and "set_int_max_str_digits" not in output


def test_fmt_keeps_an_unreadable_xdd_attribute_once(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """An unreadable nrOfTxPDO was written twice (its default and the text kept): XML that no reader takes."""
    data = corpus_bytes(XDD_CORPUS, "eds-dcf-net__sample_device.xdd")
    (tmp_path / "d.xdd").write_bytes(data.replace(b'nrOfTxPDO="4"', 'nrOfTxPDO="½"'.encode(), 1))
    invoke(tmp_path, monkeypatch, "fmt", "d.xdd")
    written = (tmp_path / "d.xdd").read_bytes()
    assert written.count(b"nrOfTxPDO=") == 1
    loads(written, source="d.xdd")
