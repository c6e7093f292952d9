"""The real XDD/XDC/XPD files of ../shared, and small XDD documents made in tests."""

from __future__ import annotations

import re
from pathlib import Path

import canopen
import pytest

from support import SHARED, file_params, shared_files

XDD_CORPUS = SHARED / "eds-corpus" / "xdd"
DEMO = SHARED / "third_party" / "CANopenDemo-demo"
CANOPENNODE_EXAMPLE = SHARED / "third_party" / "CANopenNode" / "example"


def xdd_files() -> list[Path]:
    """Every corpus XDD/XDC, CANopenDemo's demoDevice.xdd and CANopenNode's DS301_profile.xpd."""
    files = sorted(XDD_CORPUS.iterdir()) if XDD_CORPUS.is_dir() else []
    files += [p for p in (DEMO / "demoDevice.xdd", CANOPENNODE_EXAMPLE / "DS301_profile.xpd") if p.is_file()]
    return files


def xdd_params() -> list[object]:
    return file_params(xdd_files(), "../shared is absent")


def shared_xml_files() -> list[Path]:
    """Every XDD/XDC/XPD anywhere in ../shared: corpus, both sides of the history pairs, third_party."""
    return shared_files((".xdd", ".xdc", ".xpd"))


def shared_xml_params() -> list[object]:
    files = shared_xml_files()
    if not files:
        return file_params([], "../shared is absent")
    return [pytest.param(path, id=str(path.relative_to(SHARED))) for path in files]


def shared_file(path: Path) -> Path:
    if not path.is_file():
        pytest.skip(f"{path} is absent")
    return path


def document(objects: str, parameters: str = "", network: str = "") -> str:
    """A CiA 311 v1.1 XDD with the given CANopenObject elements and ApplicationProcess parameters."""
    return f"""<?xml version="1.0" encoding="utf-8"?>
<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
  <ISO15745Profile>
    <ProfileHeader><ProfileIdentification>CANopen device profile</ProfileIdentification></ProfileHeader>
    <ProfileBody xsi:type="ProfileBody_Device_CANopen" fileName="test.xdd" fileVersion="1">
      <DeviceIdentity>
        <vendorName>Test</vendorName>
        <vendorID>0x00000123</vendorID>
        <productName>Widget</productName>
      </DeviceIdentity>
      <ApplicationProcess>
        <parameterList>
{parameters}
        </parameterList>
      </ApplicationProcess>
    </ProfileBody>
  </ISO15745Profile>
  <ISO15745Profile>
    <ProfileHeader><ProfileIdentification>CANopen communication network profile</ProfileIdentification></ProfileHeader>
    <ProfileBody xsi:type="ProfileBody_CommunicationNetwork_CANopen" fileName="test.xdd" fileVersion="1">
      <ApplicationLayers>
        <CANopenObjectList>
{objects}
        </CANopenObjectList>
      </ApplicationLayers>
{network}
    </ProfileBody>
  </ISO15745Profile>
</ISO15745ProfileContainer>
"""


MANDATORY = """\
          <CANopenObject index="1000" name="Device type" objectType="7"
            dataType="0007" accessType="ro" defaultValue="0x00000000" PDOmapping="no" />
          <CANopenObject index="1001" name="Error register" objectType="7"
            dataType="0005" accessType="ro" PDOmapping="TPDO" />
          <CANopenObject index="1018" name="Identity" objectType="9" subNumber="2">
            <CANopenSubObject subIndex="00" name="Highest sub-index supported" objectType="7"
              dataType="0005" accessType="ro" defaultValue="1" PDOmapping="no" />
            <CANopenSubObject subIndex="01" name="Vendor-ID" objectType="7"
              dataType="0007" accessType="ro" defaultValue="0x00000123" PDOmapping="no" />
          </CANopenObject>"""


PeerEntry = tuple[object, ...]
"""What python-canopen reads of one entry: name, data type, access, default, value, min, max, PDO-mappable."""


def peer_entries(path: Path, folder: Path | None = None) -> dict[tuple[int, int], PeerEntry]:
    """Every entry python-canopen reads, sub-objects it makes up on demand included (1-254 of an array).
    A `[DummyUsage]` python-canopen cannot read (it asks for Dummy0001-0007) is left out of both sides."""
    text = re.sub(r"(?ims)^\[DummyUsage\][^\[]*", "", path.read_text(encoding="latin-1"))
    copy = (folder or path.parent) / ("peer-" + path.name)
    copy.write_text(text, encoding="latin-1")
    found: dict[tuple[int, int], PeerEntry] = {}
    for obj in canopen.import_od(str(copy)).values():
        members = [obj] if isinstance(obj, canopen.objectdictionary.ODVariable) else list(obj.values())
        if isinstance(obj, canopen.objectdictionary.ODArray) and 1 in obj.subindices:
            members += [obj[n] for n in range(2, 255) if n not in obj.subindices]
        for var in members:
            found[(var.index, var.subindex)] = (
                var.name, var.data_type, var.access_type, var.default, var.value, var.min, var.max, var.pdo_mappable
            )  # fmt: skip
    return found


def _misread_before(old: PeerEntry | None, new: PeerEntry | None) -> bool:
    """Whether `new` differs from `old` only where python-canopen misread the original: a value it could not
    read (a REAL ParameterValue written as an IEEE bit pattern) or a string it read with the quotes that delimit
    it in lely's dialect, each read right from the output."""
    if old is None or new is None:
        return False
    return all(a == b or a is None or (isinstance(a, str) and a == f'"{b}"') for a, b in zip(old, new, strict=True))


def peer_differences(before: Path, after: Path, misread_before: bool = False) -> list[str]:
    """Entries python-canopen reads differently from `after` than from `before`; with `misread_before`, an entry
    it misread in `before` and reads right from `after` is no difference."""
    old, new = peer_entries(before), peer_entries(after)
    pairs = [(key, old.get(key), new.get(key)) for key in sorted(old.keys() | new.keys())]
    excused = _misread_before if misread_before else lambda a, b: False
    return [f"{i:04X}sub{s}: {a} -> {b}" for (i, s), a, b in pairs if a != b and not excused(a, b)]
