"""The real XDD/XDC/XPD files of ../shared, and small XDD documents made in tests."""

from __future__ import annotations

from pathlib import Path

import pytest

from support import ROOT, file_params

SHARED = ROOT.parent / "shared"
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
    if not SHARED.is_dir():
        return []
    return sorted(p for p in SHARED.rglob("*") if p.suffix.lower() in (".xdd", ".xdc", ".xpd") and p.is_file())


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
