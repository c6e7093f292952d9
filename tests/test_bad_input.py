"""Bad input never ends in a traceback: every command answers with diagnostics and an exit code."""

from __future__ import annotations

from pathlib import Path

import pytest
from click.testing import CliRunner

from cantools_od.cli import main

from support import EXAMPLES

GOOD = (EXAMPLES / "io_device.eds").read_bytes()
BAD_INPUTS = {
    "empty.eds": b"",
    "binary.eds": bytes(range(256)) * 4,
    "truncated.eds": GOOD[: len(GOOD) // 2],
    "headerless.eds": b"ParameterName=x\nDataType=zz\n",
    "broken-json.json": b'{"objects": {"x": 1}}',
    "not-json.json": b"{ this is not json",
    "mapping-to-nothing.eds": GOOD.replace(b"DefaultValue=0x62000108", b"DefaultValue=0x7FFF0108"),
    "nodeid-everywhere.eds": GOOD.replace(b"DataType=0x0005", b"DataType=$NODEID"),
    "cp1252.eds": b"[2000]\nParameterName=\x94\x81\nDataType=0x0009\nDefaultValue=\xff\n",
}
COMMANDS = [
    ["dump"],
    ["dump", "--format", "json"],
    ["pdo"],
    ["pdo", "--format", "json", "--node-id", "3"],
    ["lint"],
    ["lint", "--fix"],
    ["lint", "--format", "sarif"],
    ["lint", "--network"],
    ["fmt", "--check"],
    ["ids"],
    ["gen", "-t", "c", "-t", "rust", "-t", "python", "-t", "markdown", "-o", "out"],
    ["convert", "-o", "out.json"],
    ["convert", "-o", "out.dcf", "--node-id", "4"],
    ["import-table", "-o", "imported.eds"],
]


@pytest.mark.parametrize("name", sorted(BAD_INPUTS))
@pytest.mark.parametrize("args", COMMANDS, ids=lambda a: " ".join(a))
def test_no_traceback(tmp_path: Path, name: str, args: list[str], monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / name).write_bytes(BAD_INPUTS[name])
    result = CliRunner().invoke(main, [args[0], name, *args[1:]], catch_exceptions=True)
    assert result.exception is None or isinstance(result.exception, SystemExit), result.output
    assert result.exit_code in (0, 1, 2), result.output
    assert "Traceback" not in result.output


def test_gen_writes_nothing_when_it_refuses(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.chdir(tmp_path)
    (tmp_path / "bad.eds").write_bytes(BAD_INPUTS["mapping-to-nothing.eds"])
    result = CliRunner().invoke(main, ["gen", "bad.eds", "-t", "c", "-o", "out"])
    assert result.exit_code == 1 and "[GEN001]" in result.output
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize("args", [["lint"], ["lint", "--fix"], ["dump"], ["fmt"], ["convert", "-o", "out.eds"]])
def test_json_that_is_no_model_is_refused_with_one_line(
    tmp_path: Path, args: list[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """JSN001: a .json file that `dump --format json` did not write is refused, exit 2, and never rewritten."""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "device.json").write_bytes(BAD_INPUTS["broken-json.json"])
    result = CliRunner().invoke(main, [args[0], "device.json", *args[1:]])
    assert result.exit_code == 2, result.output
    lines = [line for line in result.output.splitlines() if line.strip()]
    if args[0] == "lint":  # lint reports it in its report, which ends with its count of files
        assert lines[1:] == ["1 file checked: 1 error"], result.output
        lines = lines[:1]
    assert len(lines) == 1 and lines[0].endswith("[JSN001]"), result.output
    assert (tmp_path / "device.json").read_bytes() == BAD_INPUTS["broken-json.json"]
    assert not (tmp_path / "out.eds").exists()
