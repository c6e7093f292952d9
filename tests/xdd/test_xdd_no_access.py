"""What the canonical XDD writer (`fmt`, `dumps(..., style="canonical")`) must not lose: an entry
CiA 311 declares `access="noAccess"` (in the OD, reached by no SDO; CANopenEditor writes its "no" SDO
access so), and the deviceCommissioning a file named .xdd states (CANopenEditor's files do). Both
shapes are those of real files in ../shared/eds-history."""

from __future__ import annotations

import subprocess
from pathlib import Path

from xddkit import MANDATORY, document

from cantools_od import api
from cantools_od.changes import compare

from support import cli_command


def _parameter(sub: int, access: str, label: str, body: str) -> str:
    label_element = f'<label lang="en">{label}</label>'
    return f'<parameter uniqueID="UID_SUB_2000{sub:02X}" access="{access}">{label_element}{body}</parameter>'


_PARAMETERS = "\n".join(
    (
        '<parameter uniqueID="UID_OBJ_2000"><label lang="en">Storage</label>'
        '<dataTypeIDRef uniqueIDRef="UID_REC_2000" /></parameter>',
        _parameter(0, "read", "Highest sub-index", '<USINT /><defaultValue value="0x02" />'),
        _parameter(1, "noAccess", "Page Size", '<UINT /><defaultValue value="0" />'),
        _parameter(2, "readWrite", "Pages", '<UINT /><defaultValue value="4" />'),
    )
)
_OBJECTS = MANDATORY + (
    '\n          <CANopenObject index="2000" name="Storage" objectType="9" uniqueIDRef="UID_OBJ_2000" subNumber="3">'
    '\n            <CANopenSubObject subIndex="00" name="Highest sub-index" objectType="7" PDOmapping="no"'
    ' uniqueIDRef="UID_SUB_200000" />'
    '\n            <CANopenSubObject subIndex="01" name="Page Size" objectType="7" PDOmapping="no"'
    ' uniqueIDRef="UID_SUB_200001" />'
    '\n            <CANopenSubObject subIndex="02" name="Pages" objectType="7" PDOmapping="no"'
    ' uniqueIDRef="UID_SUB_200002" />'
    "\n          </CANopenObject>"
)
_FEATURES = """      <NetworkManagement>
        <CANopenGeneralFeatures granularity="8" />
      </NetworkManagement>"""
_COMMISSIONING = _FEATURES.replace(
    "/>\n",
    '/>\n        <deviceCommissioning nodeID="0" actualBaudRate="0" networkNumber="0" CANopenManager="false" />\n',
)


def _changes(before: api.Device, after: api.Device) -> list[tuple[str, object, object, str]]:
    return [(c.kind.value, c.index, c.subindex, c.field) for c in compare(before, after).changes()]


def test_no_access_entry_reads_back_from_the_canonical_xdd() -> None:
    device = api.loads(document(_OBJECTS, _PARAMETERS, network=_FEATURES), source="dev.xdd")
    entry = device.objects[0x2000].subs[1]
    assert entry.access is None and entry.extra["access"] == "noAccess"
    again = api.loads(api.dumps(device, "xdd", style="canonical"), source="canonical.xdd")
    assert again.objects[0x2000].subs[1].extra.get("access") == "noAccess"
    assert again.objects[0x2000].subs[1].access is None  # never a read-only entry
    assert _changes(device, again) == []


def test_device_commissioning_of_an_xdd_reads_back_from_the_canonical_xdd() -> None:
    device = api.loads(document(_OBJECTS, _PARAMETERS, network=_COMMISSIONING), source="dev.xdd")
    assert device.commissioning is not None
    text = api.dumps(device, "xdd", style="canonical")
    again = api.loads(text, source="canonical.xdd")
    assert again.commissioning is not None and again.commissioning.node_id == 0
    assert _changes(device, again) == []


def test_fmt_convert_and_fix_keep_no_access_and_commissioning(tmp_path: Path) -> None:
    source = document(_OBJECTS, _PARAMETERS, network=_COMMISSIONING).encode()
    path = tmp_path / "dev.xdd"
    path.write_bytes(source)
    original = api.load(path)
    for args, out in (
        (["fmt", "dev.xdd"], "dev.xdd"),
        (["convert", "dev.xdd", "-o", "copy.xdc"], "copy.xdc"),
        (["lint", "--fix", "dev.xdd"], "dev.xdd"),
    ):
        result = subprocess.run([*cli_command(), *args], cwd=tmp_path, capture_output=True, text=True)
        assert result.returncode in (0, 1), result.stderr  # lint may report findings it cannot fix
        written = api.load(tmp_path / out)
        assert written.objects[0x2000].subs[1].extra.get("access") == "noAccess", args
        assert written.commissioning is not None, args
    assert b'access="noAccess"' in path.read_bytes()
    assert _changes(original, api.load(path)) == []
