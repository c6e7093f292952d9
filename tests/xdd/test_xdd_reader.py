"""The XDD/XDC reader: real files, the model it builds, where it says things are."""

from __future__ import annotations

import subprocess
from pathlib import Path

import pytest
from xddkit import DEMO, MANDATORY, XDD_CORPUS, document, shared_file, xdd_params

from cantools_od import api
from cantools_od.model import AccessType, ObjectKind, SrdoAccess

from support import cli_command


@pytest.mark.parametrize("path", xdd_params())
def test_every_real_file_loads(path: Path) -> None:
    device = api.load(path)
    assert device.file_format == "xdd"
    assert device.objects, "no object read"
    refused = [d for d in device.diagnostics if d.code in ("XDD001", "XDD002", "XDD003", "XDD004")]
    assert refused == []
    for obj in device.objects.values():
        assert obj.origin is not None and obj.origin.line > 0
        assert obj.name, f"{obj.index:04X} has no name"


def test_demo_device_model() -> None:
    device = api.load(shared_file(DEMO / "demoDevice.xdd"))
    identity = device.objects[0x1018]
    assert identity.kind is ObjectKind.RECORD and identity.sub_number == 5
    assert identity.subs[1].name == "Vendor-ID" and identity.subs[1].data_type == 0x0007
    assert device.objects[0x1000].default == 0x000F0191
    assert device.objects[0x1001].pdo_mapping is True
    assert device.objects[0x1200].subs[1].default.canonical() == "$NODEID+0x600"  # type: ignore[union-attr]
    assert device.objects[0x1003].subs[0].access is AccessType.RW
    assert device.objects[0x1003].subs[1].access is AccessType.RO  # CiA 311's default access is read
    assert device.device_info.baud_rates == dict.fromkeys((10, 20, 50, 125, 250, 500, 800, 1000), True)
    assert device.device_info.lss_supported is True and device.device_info.nr_of_rx_pdo == 4
    assert device.dummy_usage is not None and device.dummy_usage.enabled[1] is False
    assert device.dummy_usage.enabled[7] is True
    assert device.file_info.created_by == "Janez Paternoster"


def test_canopennode_properties_land_in_typed_fields() -> None:
    device = api.load(shared_file(DEMO / "demoDevice.xdd"))
    info = device.objects[0x1000].canopennode
    assert info is not None and info.count_label == "NMT" and info.storage_group == "PERSIST_COMM"
    disabled = device.objects[0x1280].canopennode
    assert disabled is not None and disabled.disabled is True
    flagged = [o.index for o in device.objects.values() if o.canopennode and o.canopennode.flags_pdo]
    assert len(flagged) == 3
    lengths = [
        s.canopennode.string_length_min
        for o in device.objects.values()
        for s in [o, *o.subs.values()]
        if s.canopennode and s.canopennode.string_length_min is not None
    ]
    assert len(lengths) == 2 and all(n > 0 for n in lengths)
    assert not any("property" in key for o in device.objects.values() for key in o.extra)


def test_srdo_access_and_unknown_property_are_read() -> None:
    parameters = """
          <parameter uniqueID="P2000" access="readWriteOutput">
            <UINT />
            <defaultValue value="7" />
            <allowedValues><range><minValue value="1" /><maxValue value="9" /></range></allowedValues>
            <property name="CO_accessSRDO" value="rx" />
            <property name="vendorThing" value="42" />
          </parameter>"""
    objects = MANDATORY + '\n<CANopenObject index="2000" name="Speed" PDOmapping="RPDO" uniqueIDRef="P2000" />'
    device = api.loads(document(objects, parameters))
    var = device.objects[0x2000]
    assert (var.data_type, var.access, var.pdo_mapping, var.default) == (0x0006, AccessType.RWW, True, 7)
    assert (var.low_limit, var.high_limit) == (1, 9)
    assert var.canopennode is not None and var.canopennode.access_srdo is SrdoAccess.RX
    assert var.extra["property.vendorThing"] == "42"


def test_xdc_actual_values_and_commissioning() -> None:
    device = api.load(shared_file(XDD_CORPUS / "eds-dcf-net__minimal.xdc"))
    assert device.is_dcf and device.node_id == 5
    assert device.commissioning is not None and device.commissioning.baudrate == 500
    assert device.commissioning.node_name == "MinimalDevice"
    assert device.objects[0x1000].parameter_value == 0x191
    assert device.device_info.simple_boot_up_slave is True


def test_v1_0_attributes_on_objects() -> None:
    device = api.load(shared_file(XDD_CORPUS / "emec-demaclenko__emecdrv5.xdd"))
    rpdo = device.objects[0x1400].subs[1]
    assert rpdo.default.canonical() == "$NODEID+0x200"  # type: ignore[union-attr]
    assert device.objects[0x1000].access is AccessType.CONST
    assert device.objects[0x1010].subs[1].obj_flags == 1


def _lint(tmp_path: Path, text: str) -> subprocess.CompletedProcess[str]:
    path = tmp_path / "dev.xdd"
    path.write_text(text)
    return subprocess.run([*cli_command(), "lint", str(path)], capture_output=True, text=True, cwd=tmp_path)


def test_lint_points_at_the_xml_attribute(tmp_path: Path) -> None:
    bad = '<CANopenObject index="2000" name="Small" dataType="0005" accessType="rw" defaultValue="300" />'
    text = document(MANDATORY + "\n" + bad)
    line = text.splitlines().index(next(t for t in text.splitlines() if 'index="2000"' in t)) + 1
    column = text.splitlines()[line - 1].index('defaultValue="300"') + len('defaultValue="') + 1
    result = _lint(tmp_path, text)
    findings = [f for f in result.stdout.splitlines() if "EDS030" in f or "2000" in f]
    assert any(f.startswith(f"{tmp_path / 'dev.xdd'}:{line}:{column}:") for f in findings), result.stdout


def test_reader_codes_for_broken_structure(tmp_path: Path) -> None:
    objects = (
        MANDATORY
        + """
          <CANopenObject name="No index" objectType="7" />
          <CANopenObject index="1000" name="Again" objectType="7" />
          <CANopenObject index="2001" name="Odd" uniqueIDRef="NOPE" color="red"><extra /></CANopenObject>"""
    )
    device = api.loads(document(objects), source="dev.xdd")
    codes = sorted(d.code for d in device.diagnostics)
    assert codes == ["XDD006", "XDD008", "XDD009", "XDD010", "XDD011"]
    assert device.objects[0x1000].name == "Device type"  # the first copy counts
    assert device.objects[0x2001].extra["color"] == "red"  # unknown things are kept
    result = _lint(tmp_path, document(objects))
    assert "XDD008" in result.stdout and result.returncode != 0


def test_file_without_namespace_is_read_with_a_warning() -> None:
    text = document(MANDATORY).replace(' xmlns="http://www.canopen.org/xml/1.1"', "")
    device = api.loads(text)
    assert [d.code for d in device.diagnostics] == ["XDD005"]
    assert set(device.objects) == {0x1000, 0x1001, 0x1018}


def test_not_well_formed_reports_where() -> None:
    text = document(MANDATORY).replace("</CANopenObjectList>", "</CANopenObjectLis>")
    device = api.loads(text, source="x.xdd")
    assert [d.code for d in device.diagnostics] == ["XDD001"]
    line = next(n for n, t in enumerate(text.splitlines(), 1) if "</CANopenObjectLis>" in t)
    assert device.diagnostics[0].location.line == line


def test_unreadable_values_are_kept_with_xdd007() -> None:
    parameters = '<parameter uniqueID="P1"><UINT /><property name="CO_disabled" value="yes" /></parameter>'
    objects = (
        MANDATORY
        + '\n<CANopenObject index="2000" name="A" accessType="read" PDOmapping="maybe" />'
        + '\n<CANopenObject index="2001" name="B" objectType="7" uniqueIDRef="P1" />'
    )
    device = api.loads(document(objects, parameters))
    assert [d.code for d in device.diagnostics] == ["XDD007", "XDD007", "XDD007"]
    assert device.objects[0x2000].extra["accessType"] == "read"
    assert device.objects[0x2001].extra["property.CO_disabled"] == "yes"


def test_other_xml_is_xdd004() -> None:
    device = api.loads('<?xml version="1.0"?>\n<DeviceDescription><a/></DeviceDescription>')
    assert [d.code for d in device.diagnostics] == ["XDD004", "XDD005", "XDD010"]
    assert device.objects == {}
