"""Severities decided case by case: what every tool reads as intended is a warning, not an error."""

from __future__ import annotations

from cantools_od import loads
from cantools_od.lint import lint
from cantools_od.model import Severity


def severities(text: str, code: str, source: str = "t.eds") -> list[tuple[int, Severity]]:
    return [(f.location.line, f.severity) for f in lint(loads(text, source=source)) if f.code == code]


W, E = Severity.WARNING, Severity.ERROR


def test_subnumber_zero_on_a_var_is_a_warning() -> None:
    text = "[2000]\nParameterName=A\nDataType=0x0006\nAccessType=rw\nSubNumber={}\n"
    assert severities(text.format(0), "EDS024") == [(5, W)]
    assert severities(text.format(2), "EDS024") == [(5, E)]


def test_subnumber_zero_on_a_sub_object_is_a_warning() -> None:
    text = (
        "[2000]\nParameterName=A\nObjectType=0x8\nSubNumber=2\n\n[2000sub0]\nParameterName=N\nDataType=0x0005\n"
        "AccessType=ro\nDefaultValue=1\nSubNumber=0\n\n[2000sub1]\nParameterName=B\nDataType=0x0005\nAccessType=ro\n"
    )
    assert severities(text, "EDS024") == [(11, W)]


def test_pdomapping_zero_on_a_domain_is_a_warning() -> None:
    text = "[2000]\nParameterName=Blob\nObjectType=0x2\nDataType=0x000F\nAccessType=rw\nPDOMapping={}\n"
    assert severities(text.format(0), "EDS024") == [(6, W)]
    assert severities(text.format(1), "EDS024") == [(6, E)]


def test_default_zero_on_a_domain_is_a_warning() -> None:
    text = "[2000]\nParameterName=Blob\nObjectType=0x2\nDataType=0x000F\nAccessType=rw\nDefaultValue={}\n"
    assert severities(text.format("0"), "EDS030") == [(6, W)]
    assert severities(text.format("0x123"), "EDS030") == [(6, E)]


def test_other_object_in_the_mandatory_list_is_a_warning() -> None:
    text = "[MandatoryObjects]\nSupportedObjects=2\n1=0x1000\n2=0x1017\n\n"
    text += "[OptionalObjects]\nSupportedObjects=1\n1=0x1001\n"
    assert severities(text, "EDS013") == [(4, W), (8, E)]


def test_lss_serial_number_compared_with_the_parameter_value() -> None:
    text = (
        "[DeviceComissioning]\nNodeID=5\nLSS_SerialNumber=0x00000017\n\n[1018]\nParameterName=Identity\n"
        "ObjectType=0x9\nSubNumber=5\n\n[1018sub4]\nParameterName=Serial number\nDataType=0x0007\nAccessType=ro\n"
        "DefaultValue=0x00000018\n"
    )
    assert severities(text, "EDS045", "t.dcf") == []  # the EDS default says nothing of this device
    configured = text + "ParameterValue=0x00000018\n"
    assert severities(configured, "EDS045", "t.dcf") == [(3, E)]
    assert severities(configured.replace("ParameterValue=0x00000018", "ParameterValue=0x17"), "EDS045", "t.dcf") == []
