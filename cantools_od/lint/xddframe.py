"""The frame of an XDD rule example: a minimal clean CiA 311 XDD that the example's objects go into.

An example for the XDD reader is a few `CANopenObject` elements; the frame adds the document around
them and the mandatory objects 1000h, 1001h and 1018h the example does not give itself.
"""

from __future__ import annotations

import re

_HEAD = """<?xml version="1.0" encoding="utf-8"?>
<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1" \
xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">
  <ISO15745Profile>
    <ProfileHeader><ProfileIdentification>CANopen device profile</ProfileIdentification></ProfileHeader>
    <ProfileBody xsi:type="ProfileBody_Device_CANopen" fileName="example.xdd" fileVersion="1">
      <DeviceIdentity>
        <vendorName>Example</vendorName>
        <vendorID>0x00000001</vendorID>
        <productName>Example</productName>
        <productID>0x00000002</productID>
      </DeviceIdentity>
      <ApplicationProcess><parameterList/></ApplicationProcess>
    </ProfileBody>
  </ISO15745Profile>
  <ISO15745Profile>
    <ProfileHeader><ProfileIdentification>CANopen communication network profile</ProfileIdentification></ProfileHeader>
    <ProfileBody xsi:type="ProfileBody_CommunicationNetwork_CANopen" fileName="example.xdd" fileVersion="1">
      <ApplicationLayers>
        <CANopenObjectList>
"""
_TAIL = """        </CANopenObjectList>
      </ApplicationLayers>
      <TransportLayers>
        <PhysicalLayer>
          <baudRate defaultValue="250 Kbps"><supportedBaudRate value="250 Kbps"/></baudRate>
        </PhysicalLayer>
      </TransportLayers>
    </ProfileBody>
  </ISO15745Profile>
</ISO15745ProfileContainer>
"""
# The frame's objects that CiA 301 makes mandatory (model/cia301/objects.MANDATORY), each known by its index.
_MANDATORY_ELEMENTS = (
    '<CANopenObject index="1000" name="Device type" objectType="7" dataType="0007" accessType="ro" '
    'defaultValue="0x00000000" PDOmapping="no"/>',
    '<CANopenObject index="1001" name="Error register" objectType="7" dataType="0005" accessType="ro" '
    'PDOmapping="TPDO"/>',
    '<CANopenObject index="1018" name="Identity object" objectType="9" subNumber="3">\n'
    '  <CANopenSubObject subIndex="00" name="Highest sub-index supported" objectType="7" dataType="0005" '
    'accessType="ro" defaultValue="2" PDOmapping="no"/>\n'
    '  <CANopenSubObject subIndex="01" name="Vendor-ID" objectType="7" dataType="0007" accessType="ro" '
    'defaultValue="0x00000001" PDOmapping="no"/>\n'
    '  <CANopenSubObject subIndex="02" name="Product code" objectType="7" dataType="0007" accessType="ro" '
    'defaultValue="0x00000002" PDOmapping="no"/>\n'
    "</CANopenObject>",
)
_ROOT = "<ISO15745ProfileContainer"
_INDEX = re.compile(r'<CANopenObject\b[^>]*\bindex="([0-9A-Fa-f]{1,4})"')


def framed_xdd(fragment: list[tuple[str, int]]) -> tuple[str, dict[int, int]]:
    """The whole XDD, and for each of its lines that the fragment gives, the fragment's number.

    A fragment that starts with the root's start tag `<ISO15745ProfileContainer ...>` gives the
    frame's root its own."""
    origin: dict[int, int] = {}
    head = _HEAD
    if fragment and fragment[0][0].startswith(_ROOT):
        lines = head.splitlines(keepends=True)
        root = next(n for n, line in enumerate(lines) if line.startswith(_ROOT))
        lines[root] = fragment[0][0] + "\n"
        head, origin[root + 1] = "".join(lines), fragment[0][1]
        fragment = fragment[1:]
    given = {int(index, 16) for line, _ in fragment for index in _INDEX.findall(line)}
    frame = [element for element in _MANDATORY_ELEMENTS if int(_INDEX.findall(element)[0], 16) not in given]
    head += "".join(line + "\n" for element in frame for line in element.splitlines())
    first = head.count("\n") + 1
    origin.update({first + i: number for i, (_, number) in enumerate(fragment)})
    return head + "".join(line + "\n" for line, _ in fragment) + _TAIL, origin
