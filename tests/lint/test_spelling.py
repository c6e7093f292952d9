"""EDS091 and DIA018: key and section names peers do not find, and the fix that respells only the name."""

from __future__ import annotations

from pathlib import Path

from cantools_od import dumps, loads
from cantools_od.lint import lint

from support import corpus_file

LIST = "[MandatoryObjects]\nSupported Objects=1\n1=0x1000\n\n[1000]\nParameterName=Device type\nDataType=0x0007\n"
DCF = "[DeviceCommissioning]\nNodeId=5\nBaudrate=500\n\n[DeviceInfo]\nVendorName=x\n"


def found(text: str, code: str, source: str = "t.eds") -> list[tuple[int, int, str]]:
    return [(f.location.line, f.location.column, f.message) for f in lint(loads(text, source=source)) if f.code == code]


def fixed(text: str, code: str, source: str = "t.eds", safe: bool = True) -> str:
    """The text with the code's fixes applied; each must be safe (a name python-canopen does not look up) or, with
    `safe=False`, unsafe (one it does: it then reads what it did not read before)."""
    device = loads(text, source=source)
    for finding in lint(device):
        if finding.code == code:
            assert finding.fix is not None and finding.fix.safe is safe
            finding.fix.apply(device)
    return dumps(device, "dcf" if source.endswith(".dcf") else "eds").decode()


def test_key_with_a_blank_is_an_error_and_respelled() -> None:
    assert found(LIST, "EDS091") == [
        (2, 1, "Supported Objects: CiA 306 spells this key SupportedObjects; lely and python-canopen miss it")
    ]
    assert found(LIST, "DIA018") == []
    assert fixed(LIST, "EDS091") == LIST.replace("Supported Objects=", "SupportedObjects=")
    assert found(fixed(LIST, "EDS091"), "EDS091") == []


def test_commissioning_section_with_two_m_is_an_error_and_respelled() -> None:
    assert found(DCF, "EDS091", "t.dcf") == [
        (1, 2, "DeviceCommissioning: CiA 306 spells this section DeviceComissioning; lely and python-canopen miss it")
    ]
    assert fixed(DCF, "EDS091", "t.dcf", safe=False) == DCF.replace("[DeviceCommissioning]", "[DeviceComissioning]")
    assert found(DCF.replace("Commissioning", "Comissioning"), "EDS091", "t.dcf") == []


def test_case_only_is_dia018_with_the_same_fix() -> None:
    assert [where[:2] for where in found(DCF, "DIA018", "t.dcf")] == [(2, 1)]
    assert fixed(DCF, "DIA018", "t.dcf", safe=False) == DCF.replace("NodeId=", "NodeID=")
    text = "[deviceinfo]\nVendorName=x\n"
    assert found(text, "DIA018") == [
        (1, 2, "deviceinfo: CiA 306 spells it DeviceInfo; python-canopen reads section names case-sensitively")
    ]
    assert fixed(text, "DIA018", safe=False) == "[DeviceInfo]\nVendorName=x\n"
    text = "[FileInfo]\nFileName=t.eds\nfileversion=1\n"  # python-canopen does not look the key up: safe
    assert fixed(text, "DIA018") == "[FileInfo]\nFileName=t.eds\nFileVersion=1\n"


def test_header_respelled_inside_blanks() -> None:
    text = "[ DeviceCommissioning ]\nNodeID=5\n"
    assert fixed(text, "EDS091", "t.dcf", safe=False) == "[ DeviceComissioning ]\nNodeID=5\n"


def test_real_files() -> None:
    maxon = Path(corpus_file("maxon__maxon-70_10.eds"))
    assert [line for line, _, _ in found(maxon.read_text("latin-1"), "EDS091")] == [57, 139, 2083]
    for name in ("oresat__c3.dcf", "technosoft__ISD860.dcf"):
        text = Path(corpus_file(name)).read_text("latin-1")
        assert [(line, column) for line, column, _ in found(text, "EDS091", name)] == [(51, 2)]
