"""XDD files as CANopenEditor writes them: CRLF and LF lines mixed, its own `edseditor_extension_*`
attributes, and a deviceCommissioning element in a file named .xdd. Unchanged, such a file is written
back byte for byte in the format its name asks for (as `convert` and `lint --fix` choose it)."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from xddkit import MANDATORY, document, shared_xml_params

from cantools_od import api

from support import cli_command

_EDITOR_OBJECTS = MANDATORY.replace(
    'accessType="ro" defaultValue="0x00000000"',
    'accessType="ro" defaultValue="0x00000000" edseditor_extension_notifyonchange="false"',
) + (
    '\n          <CANopenObject index="2000" name="Speed" objectType="7" dataType="0006" accessType="rw"'
    ' defaultValue="7" actualValue="" denotation="" edseditor_extenstion_storagelocation="RAM"'
    ' edseditor_extension_notifyonchange="true" PDOmapping="optional" />'
)
_COMMISSIONING = """      <NetworkManagement>
        <CANopenGeneralFeatures granularity="8" />
        <deviceCommissioning nodeID="0" actualBaudRate="0" networkNumber="0" CANopenManager="false" />
      </NetworkManagement>"""


def _mixed_endings(text: str) -> bytes:
    """Every third line ends in CRLF, the others in LF (as a file edited on two systems)."""
    lines = text.split("\n")
    return b"\n".join(line.encode() + (b"\r" if n % 3 == 0 and line else b"") for n, line in enumerate(lines))


def _editor_file(vendor: str = "0x00000123") -> bytes:
    text = document(_EDITOR_OBJECTS, network=_COMMISSIONING).replace(
        "<vendorID>0x00000123</vendorID>", f"<vendorID>{vendor}</vendorID>"
    )
    data = _mixed_endings(text)
    assert b"\r\n" in data and b">\n" in data
    return data


def test_unchanged_editor_file_is_the_same_bytes() -> None:
    data = _editor_file()
    device = api.loads(data, source="dev.xdd")
    assert api.dumps(device, "xdd") == data
    assert api.dumps(device, "xdd", style="preserve") == data


def test_convert_to_the_same_format_copies_the_bytes(tmp_path: Path) -> None:
    data = _editor_file()
    source = tmp_path / "dev.xdd"
    source.write_bytes(data)
    source.chmod(0o640)
    result = subprocess.run([*cli_command(), "convert", "dev.xdd", "-o", "copy.xdd"], cwd=tmp_path, capture_output=True)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "copy.xdd").read_bytes() == data
    assert source.read_bytes() == data and source.stat().st_mode & 0o777 == 0o640


def test_fix_changes_only_the_fixed_text(tmp_path: Path) -> None:
    """lint --fix --unsafe-fixes sets vendorID from 1018h sub1: all other bytes (line ends, editor attributes) stay."""
    data = _editor_file(vendor="0x00000999")
    path = tmp_path / "dev.xdd"
    path.write_bytes(data)
    result = subprocess.run(
        [*cli_command(), "lint", "--fix", "--unsafe-fixes", "--select", "EDS040", "dev.xdd"], cwd=tmp_path
    )
    assert result.returncode == 0
    assert path.read_bytes() == data.replace(b"0x00000999", b"0x00000123")


@pytest.mark.parametrize("path", shared_xml_params())
def test_every_shared_xml_file_comes_back_in_the_format_its_name_asks_for(path: Path) -> None:
    device = api.load(path)
    assert api.dumps(device, api.format_for(path), style="preserve") == path.read_bytes()
