"""CiA 402 object conformance, in the rule style of CiA 301's (STD001-STD006): access types of the profile objects
for the first logical drive (1000h names profile 402) and for further ones (their device type at 67FFh + n x 800h).
The wrong accesses are the ones real drives' files have (6040h/6060h `wo`, 6063h/6064h `rw`, 60FDh `rwr`)."""

from __future__ import annotations

import pytest
from lintkit import BASE, replace

from cantools_od import loads
from cantools_od.lint import lint

DRIVE = replace(
    BASE, "DefaultValue=0x00000000\nPDOMapping=0\n\n[1001]", "DefaultValue=0x00020192\nPDOMapping=0\n\n[1001]"
)


def _var(index: int, name: str, data_type: str, access: str) -> str:
    return (
        f"\n[{index:04X}]\nParameterName={name}\nObjectType=0x7\nDataType={data_type}\nAccessType={access}\n"
        "DefaultValue=0\nPDOMapping=1\n"
    )


def _std004(text: str) -> list[str]:
    return [f.message for f in lint(loads(text, source="t.eds")) if f.code == "STD004"]


@pytest.mark.parametrize(
    ("index", "name", "data_type", "wrong", "right", "allowed"),
    [
        (0x6040, "Controlword", "0x0006", "wo", "rw", "rw"),
        (0x6060, "Modes of operation", "0x0002", "wo", "rww", "rw"),
        (0x6041, "Statusword", "0x0006", "rwr", "ro", "const/ro"),
        (0x6064, "Position actual value", "0x0004", "rw", "ro", "const/ro"),
        (0x6077, "Torque actual value", "0x0003", "rwr", "ro", "const/ro"),
        (0x6065, "Following error window", "0x0007", "wo", "ro", "const/ro/rw"),  # a parameter: rw, or fixed
    ],
)
def test_profile_access(index: int, name: str, data_type: str, wrong: str, right: str, allowed: str) -> None:
    assert _std004(DRIVE + _var(index, name, data_type, wrong)) == [
        f"[{index:04X}] AccessType={wrong}: CiA 402-2 gives {index:04X}h {name} access {allowed}"
    ]
    assert _std004(DRIVE + _var(index, name, data_type, right)) == []
    assert _std004(BASE + _var(index, name, data_type, wrong)) == []  # not a drive: a vendor's own object


def test_further_logical_drive_by_its_own_device_type() -> None:
    second = _var(0x6FFF, "Device type", "0x0007", "ro").replace("DefaultValue=0", "DefaultValue=0x00020192")
    statusword = _var(0x6841, "Statusword", "0x0006", "rwr")
    assert _std004(BASE + second + statusword) == [
        "[6841] AccessType=rwr: CiA 402-2 gives 6841h Statusword access const/ro"
    ]
    io_module = second.replace("0x00020192", "0x000F0191")  # sevcon's second logical device: profile 401
    assert _std004(BASE + io_module + statusword) == []
    wrong_type = statusword.replace("DataType=0x0006", "DataType=0x0007")
    assert any(f.code == "STD003" for f in lint(loads(BASE + second + wrong_type, source="t.eds")))
