"""Rule examples as files: a documented example is an EDS fragment; `frame()` makes it a whole EDS.

The rule documentation (`cantools-od rules`, docs/rules.md) and the tests run every example
through `run()`: the failing example must trigger its rule, the fixed one must not.

The frame holds what every EDS needs ([FileInfo], [DeviceInfo], [DummyUsage], the mandatory
objects 1000h, 1001h, 1018h and the three object lists, computed from the objects the file ends
up with), so that an example shows only what its rule is about. A section the fragment gives
replaces the frame's. A comment line `; ^ CODE` marks the line above it as where CODE is reported.
"""

from __future__ import annotations

import re

from ..eds.reader import read_bytes
from .rules import Finding
from .runner import lint

_SECTION = re.compile(r"^\[([^\]]+)\]", re.MULTILINE)
_MARK = re.compile(r"^;\s*\^\s*([A-Z]{3}\d{3})\s*$")
_FRAME = {
    "FileInfo": "FileName=example.eds\nFileVersion=1\nFileRevision=0\nEDSVersion=4.0\nDescription=Rule example\n"
    "CreationTime=12:00PM\nCreationDate=01-01-2025\nCreatedBy=cantools-od\nModificationTime=12:00PM\n"
    "ModificationDate=01-01-2025\nModifiedBy=cantools-od",
    "DeviceInfo": "VendorName=Example\nVendorNumber=0x1\nProductName=Example\nProductNumber=0x2\nRevisionNumber=0x3\n"
    "OrderCode=1\nBaudRate_10=0\nBaudRate_20=0\nBaudRate_50=0\nBaudRate_125=1\nBaudRate_250=1\nBaudRate_500=1\n"
    "BaudRate_800=0\nBaudRate_1000=1\nSimpleBootUpMaster=0\nSimpleBootUpSlave=1\nGranularity=8\n"
    "DynamicChannelsSupported=0\nGroupMessaging=0\nNrOfRXPDO={rx}\nNrOfTXPDO={tx}\nLSS_Supported=0",
    "DummyUsage": "\n".join(f"Dummy000{n}={int(n > 1)}" for n in range(1, 8)),
    "1000": "ParameterName=Device type\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x00000000\n"
    "PDOMapping=0",
    "1001": "ParameterName=Error register\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\nDefaultValue=0\n"
    "PDOMapping=1",
    "1018": "ParameterName=Identity object\nObjectType=0x9\nSubNumber=4",
    "1018sub0": "ParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
    "DefaultValue=3\nPDOMapping=0",
    "1018sub1": "ParameterName=Vendor-ID\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x1\n"
    "PDOMapping=0",
    "1018sub2": "ParameterName=Product code\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x2\n"
    "PDOMapping=0",
    "1018sub3": "ParameterName=Revision number\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue=0x3\n"
    "PDOMapping=0",
}
_LISTS = ("MandatoryObjects", "OptionalObjects", "ManufacturerObjects")


def _listing(name: str, indices: list[int]) -> str:
    lines = [f"SupportedObjects={len(indices)}"] + [f"{n}=0x{index:04X}" for n, index in enumerate(indices, 1)]
    return f"[{name}]\n" + "\n".join(lines) + "\n"


def frame(fragment: str) -> str:
    """The fragment inside a clean EDS."""
    given = {name.lower() for name in _SECTION.findall(fragment)}
    parts = [f"[{name}]\n{body}\n" for name, body in _FRAME.items() if name.lower() not in given]
    text = "\n".join(parts) + "\n" + fragment.strip() + "\n"
    objects = sorted({int(m, 16) for m in re.findall(r"^\[([0-9A-Fa-f]{4})\]", text, re.MULTILINE)})
    rx = sum(1 for i in objects if 0x1400 <= i < 0x1600)
    tx = sum(1 for i in objects if 0x1800 <= i < 0x1A00)
    text = text.replace("NrOfRXPDO={rx}", f"NrOfRXPDO={rx}").replace("NrOfTXPDO={tx}", f"NrOfTXPDO={tx}")
    areas = {
        "MandatoryObjects": [i for i in objects if i in (0x1000, 0x1001, 0x1018)],
        "OptionalObjects": [i for i in objects if i not in (0x1000, 0x1001, 0x1018) and not 0x2000 <= i < 0x6000],
        "ManufacturerObjects": [i for i in objects if 0x2000 <= i < 0x6000],
    }
    lists = [_listing(name, areas[name]) for name in _LISTS if name.lower() not in given]
    return text + "\n" + "\n".join(lists)


def marked_lines(text: str) -> dict[str, set[int]]:
    """CODE -> the lines `; ^ CODE` marks (the line above each mark, 1-based)."""
    found: dict[str, set[int]] = {}
    lines = text.splitlines()
    for number, line in enumerate(lines, 1):
        match = _MARK.match(line.strip())
        if match:
            found.setdefault(match.group(1), set()).add(number - 1)
    return found


def run(fragment: str, name: str = "example.eds") -> tuple[str, list[Finding]]:
    """The framed text and every finding lint reports for it."""
    text = frame(fragment)
    return text, lint(read_bytes(text.encode(), name))


def fragment_line(fragment: str, text: str, line: int) -> int | None:
    """The line of the fragment that line `line` of its framed text is, or None when it is in the frame."""
    start = text.find(fragment.strip())
    if start < 0 or line <= 0:
        return None
    first = text.count("\n", 0, start) + 1
    number = line - first + 1
    return number if 1 <= number <= len(fragment.strip().splitlines()) else None
