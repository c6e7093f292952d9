"""Hostile XML is refused with a diagnostic, in bounded time and memory; mutated XDD never raises."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st
from xddkit import MANDATORY, document

from cantools_od import api
from cantools_od.sniff import NotADeviceDescription

BILLION_LAUGHS = """<?xml version="1.0"?>
<!DOCTYPE lolz [
 <!ENTITY lol "lol">
 <!ENTITY lol2 "&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;&lol;">
 <!ENTITY lol3 "&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;&lol2;">
 <!ENTITY lol4 "&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;&lol3;">
 <!ENTITY lol5 "&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;&lol4;">
 <!ENTITY lol6 "&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;&lol5;">
 <!ENTITY lol7 "&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;&lol6;">
 <!ENTITY lol8 "&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;&lol7;">
 <!ENTITY lol9 "&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;&lol8;">
]>
<ISO15745ProfileContainer><vendorName>&lol9;</vendorName></ISO15745ProfileContainer>
"""

XXE = """<?xml version="1.0"?>
<!DOCTYPE x [<!ENTITY secret SYSTEM "file:///etc/passwd">]>
<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1"><ISO15745Profile><ProfileBody>
<DeviceIdentity><vendorName>&secret;</vendorName></DeviceIdentity></ProfileBody></ISO15745Profile>
</ISO15745ProfileContainer>
"""

PARAMETER_ENTITY = """<?xml version="1.0"?>
<!DOCTYPE x [<!ENTITY % remote SYSTEM "http://127.0.0.1:9/evil.dtd"> %remote;]>
<ISO15745ProfileContainer />
"""


def _run_bounded(tmp_path: Path, name: str, data: bytes) -> subprocess.CompletedProcess[str]:
    """`lint` on the file in a child limited to 1 GiB of address space and 60 s."""
    path = tmp_path / name
    path.write_bytes(data)
    limit = "import resource; resource.setrlimit(resource.RLIMIT_AS, (1 << 30, 1 << 30))"
    command = [sys.executable, "-c", f"{limit}; from cantools_od.cli import main; main()"]
    return subprocess.run([*command, "lint", str(path)], capture_output=True, text=True, timeout=60, cwd=tmp_path)


def test_billion_laughs_is_refused(tmp_path: Path) -> None:
    result = _run_bounded(tmp_path, "lol.xdd", BILLION_LAUGHS.encode())
    assert result.returncode != 0
    assert "XDD002" in result.stdout + result.stderr
    assert "lollol" not in result.stdout


def test_external_entity_is_never_read(tmp_path: Path) -> None:
    device = api.loads(XXE, source="xxe.xdd")
    assert [d.code for d in device.diagnostics] == ["XDD002"]
    assert "root:" not in device.model_dump_json()
    result = _run_bounded(tmp_path, "xxe.xdd", XXE.encode())
    assert result.returncode != 0 and "root:" not in result.stdout + result.stderr


def test_external_parameter_entity_is_not_fetched() -> None:
    device = api.loads(PARAMETER_ENTITY)
    assert [d.code for d in device.diagnostics] == ["XDD002"]


def test_100_mb_file_is_refused_in_bounded_memory(tmp_path: Path) -> None:
    head = document(MANDATORY).encode()
    filler = b"<!-- " + b"x" * (100 * 1024 * 1024) + b" -->\n"
    result = _run_bounded(tmp_path, "huge.xdd", head.replace(b"<ISO15745Profile>", filler + b"<ISO15745Profile>", 1))
    assert result.returncode != 0
    assert "XDD003" in result.stdout + result.stderr


def test_too_many_elements_are_refused() -> None:
    many = "<a/>" * 600_000
    device = api.loads(f"<ISO15745ProfileContainer>{many}</ISO15745ProfileContainer>")
    assert [d.code for d in device.diagnostics] == ["XDD003"]


def test_deep_nesting_is_refused() -> None:
    device = api.loads("<ISO15745ProfileContainer>" + "<a>" * 5000 + "</a>" * 5000 + "</ISO15745ProfileContainer>")
    assert [d.code for d in device.diagnostics] == ["XDD003"]


SAMPLE = document(
    MANDATORY,
    """
          <parameter uniqueID="P1" access="readWrite"><label lang="en">x</label><UINT />
            <defaultValue value="$NODEID+0x80" />
            <property name="CO_storageGroup" value="RAM" /></parameter>""",
).replace('PDOmapping="TPDO" />', 'PDOmapping="TPDO" uniqueIDRef="P1" />')


@settings(max_examples=150, deadline=None)
@given(st.data())
def test_mutated_xdd_never_raises(data: st.DataObject) -> None:
    text = SAMPLE
    for _ in range(data.draw(st.integers(1, 4))):
        at = data.draw(st.integers(0, len(text)))
        cut = data.draw(st.integers(0, 12))
        insert = data.draw(st.sampled_from(["", "<", ">", '"', "&", "=", "x", "<a>", "</b>", '="1"', "0x", "$NODEID"]))
        text = text[:at] + insert + text[at + cut :]
    try:
        device = api.loads(text.encode(), source="m.xdd")
    except NotADeviceDescription:
        return  # mutated until it is no XML (nor anything else) at all: refused in one line
    api.dumps(device, "json")


def test_utf16_file_is_read_and_unknown_encoding_refused() -> None:
    text = document(MANDATORY).replace('encoding="utf-8"', 'encoding="utf-16"')
    device = api.loads(text.encode("utf-16"), source="wide.xdd")
    assert device.diagnostics == [] and set(device.objects) == {0x1000, 0x1001, 0x1018}
    assert device.objects[0x1001].origin is not None and device.objects[0x1001].origin.line > 1
    odd = api.loads(document(MANDATORY).replace('encoding="utf-8"', 'encoding="klingon"'))
    assert [d.code for d in odd.diagnostics] == ["XDD001"]


def test_gen_fails_on_a_refused_xdd_and_writes_nothing(tmp_path: Path) -> None:
    """A build step must not pass on an XDD that could not be read (an empty header would compile)."""
    from support import cli_command

    source = tmp_path / "broken.xdd"
    source.write_bytes(b'<?xml version="1.0"?>\n<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1">\n')
    for extra in ([], ["--keep-going"]):
        out = tmp_path / "out"
        result = subprocess.run(
            [*cli_command(), "gen", str(source), "-t", "c", "-o", str(out), *extra], capture_output=True, text=True
        )
        assert result.returncode == 1, result.stderr
        assert "XDD001" in result.stderr and "Traceback" not in result.stderr
        assert not out.exists()


def test_lint_of_a_refused_xdd_reports_only_why_it_was_refused(tmp_path: Path) -> None:
    """Nothing of a refused file was read: "mandatory object missing" would blame the device for the reader."""
    from support import cli_command

    source = tmp_path / "broken.xdd"
    source.write_bytes(b'<?xml version="1.0"?>\n<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1">\n')
    result = subprocess.run([*cli_command(), "lint", str(source)], capture_output=True, text=True)
    assert result.returncode == 1, result.stderr
    codes = [line.rsplit("[", 1)[-1].rstrip("]") for line in result.stdout.splitlines() if line.endswith("]")]
    assert codes == ["XDD001"], result.stdout
