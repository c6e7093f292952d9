"""Codes the XDD/XDC reader reports while it reads a CiA 311 file (see cantools_od/xdd)."""

from __future__ import annotations

from ..model import Severity
from .rules import Clause, Placement, declare

E, W = Severity.ERROR, Severity.WARNING
_FAMILY = "xdd"
# The object of the examples: a framed XDD holds it besides the mandatory objects.
_SETTING = (
    '<CANopenObject index="2000" name="Setting" objectType="7" dataType="0007" accessType="rw" defaultValue="0" '
    'PDOmapping="no"'
)

declare(
    "XDD001",
    E,
    "Not well-formed XML",
    """
The file breaks the XML syntax (an unclosed tag, a stray `&`, bytes that are not in its encoding), so no
tool can read it as a CiA 311 device description. Nothing after the error is read.""",
    _SETTING + ">\n</CANopenObjectList>",
    fixed=_SETTING + "/>",
    fix_safety="No automatic fix: only the author knows what the broken markup meant.",
    family=_FAMILY,
    placed=Placement(Clause.PEER_CANNOT_LOAD, "no XML parser reads past the error"),
)
declare(
    "XDD002",
    E,
    "Entity declarations or external references",
    """
CiA 311 files need no DTD entities. An entity declaration can expand to gigabytes ("billion laughs"),
and an external entity can make a reader disclose local files (XXE); both are refused, and the file is
not read. Remove the DOCTYPE.""",
    '; whole file: device.xdd\n<?xml version="1.0"?>\n<!DOCTYPE x [<!ENTITY e SYSTEM "file:///etc/passwd">]>\n'
    '<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1">&e;</ISO15745ProfileContainer>',
    fixed="; file: device.xdd\n" + _SETTING + "/>",
    fix_safety="No automatic fix: the file is not read, so nothing is written back.",
    family=_FAMILY,
    placed=Placement(Clause.NOT_DONE, "refused unread, against entity expansion and XXE"),
)
declare(
    "XDD003",
    E,
    "XML too large or too deeply nested",
    """
Device descriptions are at most a few megabytes. A file larger than 32 MiB, with more than 500 000
elements or nested deeper than 64 levels is refused unread, so hostile input costs bounded time and
memory.""",
    "; $ python3 -c \"print('<a>' * 65 + '</a>' * 65)\" > deep.xdd\n; $ cantools-od lint deep.xdd",
    fix_safety="No automatic fix: the file is not read.",
    family=_FAMILY,
    placed=Placement(Clause.NOT_DONE, "refused unread, to bound time and memory"),
)
declare(
    "XDD004",
    E,
    "Not a CiA 311 document",
    """
The root element of an XDD/XDC is `ISO15745ProfileContainer` (CiA 311, after ISO 15745). Another root
means the file is some other XML; it is read as far as its elements match.""",
    '; whole file: device.xdd\n<?xml version="1.0"?>\n<DeviceDescription xmlns="http://www.canopen.org/xml/1.1">\n'
    "</DeviceDescription>",
    fixed="; file: device.xdd\n" + _SETTING + "/>",
    fix_safety="No automatic fix: the file is not read as a CiA 311 document.",
    family=_FAMILY,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "not a CiA 311 document: CiA 311 tools find no device in it"),
)
declare(
    "XDD005",
    W,
    "Missing or unknown CiA 311 namespace",
    """
CiA 311 elements live in the namespace `http://www.canopen.org/xml/1.1` (or `.../1.0`). Without it,
schema-validating tools (CANopenEditor's serializer among them) find no CiA 311 element at all. This reader
matches elements by local name either way.""",
    '<ISO15745ProfileContainer xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">',
    fixed='<ISO15745ProfileContainer xmlns="http://www.canopen.org/xml/1.1" xmlns:xsi="http://www.w3.org/2001/XMLSchema-instance">',
    fix_safety='No automatic fix: add `xmlns="http://www.canopen.org/xml/1.1"` to the root element.',
    family=_FAMILY,
    placed=Placement(
        Clause.BEYOND_THE_PEERS,
        "schema-validating tools (CANopenEditor's serializer) find no element; namespace-blind readers read it",
    ),
)
declare(
    "XDD006",
    E,
    "Missing required attribute",
    """
`CANopenObject` needs `index` and `name`, `CANopenSubObject` needs `subIndex` and `name` (CiA 311). An
object or sub-object without its index cannot be placed and is left out; one without a name is kept
unnamed.""",
    _SETTING.replace(' index="2000"', "") + "/>",
    fixed=_SETTING + "/>",
    fix_safety="No automatic fix: only the author knows the index or name meant.",
    family=_FAMILY,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "an object without its index cannot be placed: it is left out"),
)
declare(
    "XDD007",
    W,
    "Attribute or element value cannot be read",
    """
A value is outside what CiA 311 allows for it: an index that is not hex, an `objectType` or `accessType`
that CiA 301 does not define, a `PDOmapping` other than no/default/optional/TPDO/RPDO, a CANopenNode
property with a value the stack does not know. The text is kept as it is.""",
    _SETTING.replace("rw", "read") + "/>",
    fixed=_SETTING + "/>",
    fix_safety="No automatic fix: the text is kept as written.",
    family=_FAMILY,
    placed=Placement(
        Clause.PORTABILITY, "a value outside CiA 311's words; the text is kept, tools may read it otherwise"
    ),
)
declare(
    "XDD008",
    E,
    "Duplicate index, sub-index or uniqueID",
    """
An object index, a sub-index within its object, or a parameter `uniqueID` appears twice. Tools disagree
on which copy counts; this reader keeps the first and ignores the later one.""",
    _SETTING + "/>\n" + _SETTING.replace("Setting", "Other setting") + "/>",
    fixed=_SETTING + "/>\n" + _SETTING.replace("2000", "2001").replace("Setting", "Other setting") + "/>",
    fix_safety="No automatic fix: which copy is meant is the author's decision.",
    family=_FAMILY,
    placed=Placement(Clause.PEER_READS_OTHERWISE, "tools disagree on which copy counts"),
)
declare(
    "XDD009",
    W,
    "uniqueIDRef names no parameter",
    """
A `CANopenObject`/`CANopenSubObject` refers by `uniqueIDRef` to a `parameter` of the ApplicationProcess
that does not exist, so the entry's data type, access and default value stated there are missing.""",
    _SETTING + ' uniqueIDRef="UID_OBJ_2000"/>',
    fixed=_SETTING + "/>",
    fix_safety="No automatic fix: add the parameter, or state the attributes on the object itself.",
    family=_FAMILY,
    placed=Placement(
        Clause.STYLE,
        "every reader finds the entry without its parameter's type, access and default; usually a mistyped ID",
    ),
)
declare(
    "XDD010",
    W,
    "Unknown element",
    """
An element that CiA 311 does not define where it stands. It is kept (and written back) but has no
meaning for any tool; check its spelling.""",
    _SETTING + "><comment>speed set-point</comment></CANopenObject>",
    fixed=_SETTING + "/>",
    fix_safety="No automatic fix: the element is kept as written.",
    family=_FAMILY,
    placed=Placement(Clause.STYLE, "an element nobody gives a meaning; usually a typo"),
)
declare(
    "XDD011",
    W,
    "Unknown attribute",
    """
An attribute of `CANopenObject`/`CANopenSubObject` that CiA 311 does not define. It is kept (and written
back) but has no meaning for any tool; check its spelling (attribute names are case-sensitive).""",
    _SETTING + ' lowlimit="0"/>',
    fixed=_SETTING + ' lowLimit="0"/>',
    fix_safety="No automatic fix: the attribute is kept as written.",
    family=_FAMILY,
    placed=Placement(Clause.STYLE, "an attribute nobody gives a meaning; usually a typo"),
)
