"""`fmt`'s integer radix style: `integer-radix` in `[tool.cantools-od]` or `--radix`, run as a user runs it."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest

from support import cli_command

VENDOR_STYLE = (
    "[2000]\n"
    "ParameterName=Heartbeat\n"
    "ObjectType=0x7\n"
    "DataType=0x0006\n"
    "AccessType=rw\n"
    "DefaultValue=1000\n"
    "LowLimit=0x0010\n"
    "HighLimit=60000\n"
    "PDOMapping=0\n"
    "\n"
    "[2001]\n"
    "ParameterName=COB-ID\n"
    "ObjectType=0x7\n"
    "DataType=0x0007\n"
    "AccessType=rw\n"
    "DefaultValue=$NODEID+384\n"
    "PDOMapping=0\n"
)


def fmt(folder: Path, *args: str, config: str | None = None) -> tuple[subprocess.CompletedProcess[str], str]:
    if config is not None:
        (folder / "pyproject.toml").write_text(f"[tool.cantools-od]\n{config}\n")
    target = folder / "vendor.eds"
    target.write_text(VENDOR_STYLE)
    result = subprocess.run(
        [*cli_command(), "fmt", *args, target.name], capture_output=True, text=True, cwd=folder, timeout=120
    )
    return result, target.read_text()


def test_canonical_writes_unsigned_values_in_hex(tmp_path: Path) -> None:
    result, text = fmt(tmp_path)
    assert result.returncode == 0, result.stderr
    assert "DefaultValue=0x03E8\n" in text and "HighLimit=0xEA60\n" in text
    assert "DefaultValue=$NODEID+0x180\n" in text


def test_as_written_changes_no_number_of_a_vendor_file(tmp_path: Path) -> None:
    result, text = fmt(tmp_path, config='integer-radix = "as-written"')
    assert result.returncode == 0, result.stderr
    assert text == VENDOR_STYLE  # already in CiA 306 key order: nothing else to change


def test_radix_by_key(tmp_path: Path) -> None:
    result, text = fmt(tmp_path, config='integer-radix = { DefaultValue = "decimal", "*" = "as-written" }')
    assert result.returncode == 0, result.stderr
    assert "DefaultValue=1000\n" in text and "LowLimit=0x0010\n" in text and "HighLimit=60000\n" in text
    assert "DefaultValue=$NODEID+384\n" in text


def test_command_line_radix_replaces_the_configured_one(tmp_path: Path) -> None:
    result, text = fmt(tmp_path, "--radix", "hex", config='integer-radix = "as-written"')
    assert result.returncode == 0, result.stderr
    assert "HighLimit=0xEA60\n" in text and "DefaultValue=0x03E8\n" in text


@pytest.mark.parametrize(
    ("config", "expected"),
    [
        ('integer-radix = "as-writen"', "did you mean 'as-written'?"),
        ('integer-radix = { DefaultVal = "hex" }', "did you mean 'DefaultValue'?"),
        ("integer-radix = 16", "must be a radix or a table"),
    ],
)
def test_a_wrong_style_is_a_usage_error(tmp_path: Path, config: str, expected: str) -> None:
    result, text = fmt(tmp_path, config=config)
    assert result.returncode == 2
    assert expected in result.stderr and "Traceback" not in result.stderr
    assert text == VENDOR_STYLE
