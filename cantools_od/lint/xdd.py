"""Codes the XDD/XDC reader reports while it reads a CiA 311 file (see cantools_od/xdd)."""

from __future__ import annotations

from ..model import Severity
from .rules import declare

E, W = Severity.ERROR, Severity.WARNING
_FAMILY = "xdd"

declare(
    "XDD001",
    E,
    "Not well-formed XML",
    """
The file breaks the XML syntax (an unclosed tag, a stray `&`, bytes that are not in its encoding), so no
tool can read it as a CiA 311 device description. Nothing after the error is read. Not fixable
automatically.""",
    '<CANopenObject index="1000" name="Device type">\n</ISO15745ProfileContainer>',
    family=_FAMILY,
)
declare(
    "XDD002",
    E,
    "Entity declarations or external references",
    """
CiA 311 files need no DTD entities. An entity declaration can expand to gigabytes ("billion laughs"),
and an external entity can make a reader disclose local files (XXE); both are refused, and the file is
not read. Remove the DOCTYPE. Not fixable automatically.""",
    '<!DOCTYPE x [<!ENTITY e SYSTEM "file:///etc/passwd">]>\n<ISO15745ProfileContainer>&e;</ISO15745ProfileContainer>',
    family=_FAMILY,
)
declare(
    "XDD003",
    E,
    "XML too large or too deeply nested",
    """
Device descriptions are at most a few megabytes. A file larger than 32 MiB, with more than 500 000
elements or nested deeper than 64 levels is refused unread, so hostile input costs bounded time and
memory. Not fixable automatically.""",
    family=_FAMILY,
)
declare(
    "XDD004",
    E,
    "Not a CiA 311 document",
    """
The root element of an XDD/XDC is `ISO15745ProfileContainer` (CiA 311, after ISO 15745). Another root
means the file is some other XML; it is read as far as its elements match.""",
    '<DeviceDescription>...</DeviceDescription>\n\nfixed:\n<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1">',
    family=_FAMILY,
)
declare(
    "XDD005",
    W,
    "Missing or unknown CiA 311 namespace",
    """
CiA 311 elements live in the namespace `http://www.canopen.org/xml/1.1` (or `.../1.0`). Without it,
schema-validating tools (CANopenEditor's serializer among them) find no CiA 311 element at all. This reader
matches elements by local name either way.""",
    '<ISO15745ProfileContainer>\n\nfixed:\n<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1">',
    family=_FAMILY,
)
declare(
    "XDD006",
    E,
    "Missing required attribute",
    """
`CANopenObject` needs `index` and `name`, `CANopenSubObject` needs `subIndex` and `name` (CiA 311). An
object or sub-object without its index cannot be placed and is left out; one without a name is kept
unnamed.""",
    '<CANopenObject name="Device type" objectType="7"/>\n\n'
    'fixed:\n<CANopenObject index="1000" name="Device type" objectType="7"/>',
    family=_FAMILY,
)
declare(
    "XDD007",
    W,
    "Attribute or element value cannot be read",
    """
A value is outside what CiA 311 allows for it: an index that is not hex, an `objectType` or `accessType`
that CiA 301 does not define, a `PDOmapping` other than no/default/optional/TPDO/RPDO, a CANopenNode
property with a value the stack does not know. The text is kept as it is.""",
    '<CANopenObject index="1000" name="Device type" objectType="7" accessType="read"/>\n\n'
    'fixed:\n<CANopenObject index="1000" name="Device type" objectType="7" accessType="ro"/>',
    family=_FAMILY,
)
declare(
    "XDD008",
    E,
    "Duplicate index, sub-index or uniqueID",
    """
An object index, a sub-index within its object, or a parameter `uniqueID` appears twice. Tools disagree
on which copy counts; this reader keeps the first and ignores the later one.""",
    '<CANopenObject index="2000" name="A"/>\n<CANopenObject index="2000" name="B"/>',
    family=_FAMILY,
)
declare(
    "XDD009",
    W,
    "uniqueIDRef names no parameter",
    """
A `CANopenObject`/`CANopenSubObject` refers by `uniqueIDRef` to a `parameter` of the ApplicationProcess
that does not exist, so the entry's data type, access and default value stated there are missing.""",
    '<CANopenObject index="2000" name="A" objectType="7" uniqueIDRef="UID_OBJ_2000"/>  (no such parameter)',
    family=_FAMILY,
)
declare(
    "XDD010",
    W,
    "Unknown element",
    """
An element that CiA 311 does not define where it stands. It is kept (and written back) but has no
meaning for any tool; check its spelling.""",
    '<CANopenObject index="2000" name="A"><comment>x</comment></CANopenObject>',
    family=_FAMILY,
)
declare(
    "XDD011",
    W,
    "Unknown attribute",
    """
An attribute of `CANopenObject`/`CANopenSubObject` that CiA 311 does not define. It is kept (and written
back) but has no meaning for any tool; check its spelling (attribute names are case-sensitive).""",
    '<CANopenObject index="2000" name="A" AccessType="rw"/>\n\n'
    'fixed:\n<CANopenObject index="2000" name="A" accessType="rw"/>',
    family=_FAMILY,
)
