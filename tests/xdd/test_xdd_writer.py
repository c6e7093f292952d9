"""XDD/XDC writers: byte-identical preserve, minimal edits, idempotent canonical, conversion both ways."""

from __future__ import annotations

import difflib
import subprocess
from pathlib import Path
from typing import Any

import pytest
from hypothesis import given, settings
from test_properties import devices
from xddkit import MANDATORY, document, xdd_params

from cantools_od import api
from cantools_od.model import AccessType, Device, ObjectKind
from cantools_od.xdd.eds_form import eds_form

from support import cli_command


def _fmt(device: Device) -> Any:
    return "xdc" if device.is_dcf else "xdd"


@pytest.mark.parametrize("path", xdd_params())
def test_preserve_gives_the_original_bytes(path: Path) -> None:
    device = api.load(path)
    assert api.dumps(device, _fmt(device)) == path.read_bytes()


@pytest.mark.parametrize("path", xdd_params())
def test_canonical_is_idempotent_and_keeps_the_model(path: Path) -> None:
    device = api.load(path)
    first = api.dumps(device, _fmt(device), style="canonical")
    again = api.loads(first, source="canonical.xdd")
    assert again.diagnostics == [] or all(d.code.startswith(("EDS", "XDD007")) for d in again.diagnostics)
    assert api.dumps(again, _fmt(device), style="canonical") == first
    assert again.content() == device.content()
    assert b'xmlns="http://www.canopen.org/xml/1.1"' in first


def _eds_content(device: Device) -> dict[str, Any]:
    """What an EDS can carry of a device: no XML-only parts, and of the CANopenNode data the storage group."""
    content = eds_form(device).content()
    content["other_sections"] = [s for s in content["other_sections"] if not s["name"].startswith("XDD.")]
    for obj in content["objects"].values():
        for var in (obj, *obj["subs"].values()):
            info = var["canopennode"]
            var["canopennode"] = {"storage_group": info["storage_group"]} if info and info["storage_group"] else None
    return content


@pytest.mark.parametrize("path", xdd_params())
def test_xdd_to_eds_to_xdd_keeps_the_model(path: Path) -> None:
    device = api.load(path)
    eds = api.dumps(device, "dcf" if device.is_dcf else "eds")
    through = api.loads(eds, source="through.eds")
    assert not [d for d in through.diagnostics if d.code == "EDS001"], "an EDS line is too long"
    back = api.loads(api.dumps(through, _fmt(device)), source="back.xdd")
    assert _eds_content(back) == _eds_content(device)
    groups = [o.canopennode.storage_group for o in device.objects.values() if o.canopennode]
    assert eds.count(b";StorageLocation=") == len([g for g in groups if g])


def test_edits_change_only_their_attributes() -> None:
    text = document(MANDATORY + '\n<CANopenObject index="2000" name="Speed" objectType="7" dataType="0006" />')
    device = api.loads(text)
    device.objects[0x1001].pdo_mapping = False
    device.objects[0x1018].subs[1].default = 0x456
    device.objects[0x2000].access = AccessType.RW
    out = api.dumps(device, "xdd").decode()
    changed = [line for line in difflib.ndiff(text.splitlines(), out.splitlines()) if line[:1] in "+-"]
    assert changed == [
        '-             dataType="0005" accessType="ro" PDOmapping="TPDO" />',
        '+             dataType="0005" accessType="ro" PDOmapping="no" />',
        '-               dataType="0007" accessType="ro" defaultValue="0x00000123" PDOmapping="no" />',
        '+               dataType="0007" accessType="ro" defaultValue="0x00000456" PDOmapping="no" />',
        '- <CANopenObject index="2000" name="Speed" objectType="7" dataType="0006" />',
        '+ <CANopenObject index="2000" name="Speed" objectType="7" dataType="0006" accessType="rw" />',
    ]


def test_structural_change_falls_back_to_canonical() -> None:
    device = api.loads(document(MANDATORY))
    device.objects[0x2000] = device.objects[0x1000].model_copy(update={"index": 0x2000, "name": "Copy"})
    out = api.loads(api.dumps(device, "xdd"))
    assert out.objects[0x2000].name == "Copy" and out.objects[0x2000].kind is ObjectKind.VAR


def test_refused_file_is_never_replaced() -> None:
    broken = b"<ISO15745ProfileContainer><oops></ISO15745ProfileContainer>"
    device = api.loads(broken)
    assert api.dumps(device, "xdd", style="canonical") == broken


def test_eds_to_xdd_keeps_the_storage_group_and_values() -> None:
    eds = api.loads(
        "[1000]\nParameterName=Device type\nObjectType=0x7\n;StorageLocation=PERSIST_COMM\nDataType=0x0007\n"
        "AccessType=ro\nDefaultValue=0x191\nPDOMapping=0\nFactor=2\n"
    )
    assert eds.objects[0x1000].canopennode is not None
    assert eds.objects[0x1000].canopennode.storage_group == "PERSIST_COMM"
    xdd = api.loads(api.dumps(eds, "xdd"))
    obj = xdd.objects[0x1000]
    assert (obj.default, obj.access, obj.pdo_mapping, obj.extra) == (0x191, AccessType.RO, False, {"Factor": "2"})
    assert obj.canopennode is not None and obj.canopennode.storage_group == "PERSIST_COMM"


def test_xdc_needs_a_node_id() -> None:
    device = api.loads(document(MANDATORY))
    with pytest.raises(ValueError, match="node-ID"):
        api.dumps(device, "xdc")


@settings(max_examples=100, deadline=None)
@given(devices())
def test_any_device_written_as_xdd_reads_back(device: Device) -> None:
    xml = api.dumps(device, "xdd", "canonical")
    back = api.loads(xml, source="generated.xdd")
    assert back.diagnostics == []
    assert api.dumps(back, "xdd", "canonical") == xml
    assert back.content()["objects"] == device.content()["objects"]


def test_control_characters_in_names_stay_well_formed() -> None:
    device = api.loads("[2000]\nParameterName=Bell\x07Name\nDataType=0x0005\nAccessType=ro\n")
    back = api.loads(api.dumps(device, "xdd"))
    assert back.diagnostics == [] and back.objects[0x2000].name == "Bell\ufffdName"


def test_identity_fix_edits_the_element_text(tmp_path: Path) -> None:
    """lint --fix --unsafe-fixes sets VendorNumber from 1018h sub1 (EDS040; unsafe from a default, which may be a
    template's): only the vendorID element's text changes."""
    text = document(MANDATORY).replace("<vendorID>0x00000123</vendorID>", "<vendorID>0x00000999</vendorID>")
    path = tmp_path / "dev.xdd"
    path.write_text(text)
    command = [*cli_command(), "lint", "--fix", "--select", "EDS040", "dev.xdd"]
    assert subprocess.run(command, cwd=tmp_path).returncode == 1 and path.read_text() == text
    result = subprocess.run([*command, "--unsafe-fixes"], cwd=tmp_path)
    assert result.returncode == 0
    assert path.read_text() == text.replace("0x00000999", "0x00000123")
