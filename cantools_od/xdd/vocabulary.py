"""CiA 311 spellings and their model meaning: namespaces, type elements, access and PDO mapping names."""

from __future__ import annotations

from ..model import AccessType
from ..model.datatypes import DOMAIN as DOMAIN_TYPE
from ..model.datatypes import INDEX_BY_NAME
from ..model.datatypes import OCTET_STRING as OCTET_STRING_TYPE

NS_1_0 = "http://www.canopen.org/xml/1.0"
NS_1_1 = "http://www.canopen.org/xml/1.1"
NAMESPACES = (NS_1_0, NS_1_1)
XSI = "http://www.w3.org/2001/XMLSchema-instance"

# CiA 311 (after IEC 61131-3) names the simple types of a parameter by element; the CiA 301 type of each.
_TYPE_OF_ELEMENT = {
    "BOOL": "BOOLEAN",
    "SINT": "INTEGER8",
    "CHAR": "INTEGER8",
    "INT": "INTEGER16",
    "DINT": "INTEGER32",
    "USINT": "UNSIGNED8",
    "BYTE": "UNSIGNED8",
    "UINT": "UNSIGNED16",
    "WORD": "UNSIGNED16",
    "UDINT": "UNSIGNED32",
    "DWORD": "UNSIGNED32",
    "REAL": "REAL32",
    "STRING": "VISIBLE_STRING",
    "BITSTRING": "OCTET_STRING",
    "WSTRING": "UNICODE_STRING",
    "LREAL": "REAL64",
    "LINT": "INTEGER64",
    "ULINT": "UNSIGNED64",
    "LWORD": "UNSIGNED64",
}
TYPE_ELEMENTS: dict[str, int] = {element: INDEX_BY_NAME[name] for element, name in _TYPE_OF_ELEMENT.items()}
# The element written for each CiA 301 type; types CiA 311 has no element for are written as
# BITSTRING, with the exact type in the CANopenObject's dataType attribute.
_WRITTEN = (
    "BOOL",
    "SINT",
    "INT",
    "DINT",
    "USINT",
    "UINT",
    "UDINT",
    "REAL",
    "STRING",
    "WSTRING",
    "LREAL",
    "LINT",
    "ULINT",
)
ELEMENT_OF_TYPE: dict[int, str] = dict(sorted((TYPE_ELEMENTS[element], element) for element in _WRITTEN))
DOMAIN = DOMAIN_TYPE.index
OCTET_STRING = OCTET_STRING_TYPE.index

PARAMETER_ACCESS: dict[str, AccessType] = {
    "const": AccessType.CONST,
    "read": AccessType.RO,
    "write": AccessType.WO,
    "readWrite": AccessType.RW,
    "readWriteInput": AccessType.RWR,
    "readWriteOutput": AccessType.RWW,
}
ACCESS_NAME = {access: name for name, access in PARAMETER_ACCESS.items()}

PDO_MAPPINGS = ("no", "default", "optional", "TPDO", "RPDO")

# Attributes of CANopenObject / CANopenSubObject and the EDS key each stands for.
OBJECT_ATTRIBUTES = {
    "index": "",
    "subIndex": "",
    "name": "ParameterName",
    "objectType": "ObjectType",
    "dataType": "DataType",
    "accessType": "AccessType",
    "defaultValue": "DefaultValue",
    "lowLimit": "LowLimit",
    "highLimit": "HighLimit",
    "PDOmapping": "PDOMapping",
    "objFlags": "ObjFlags",
    "subNumber": "SubNumber",
    "actualValue": "ParameterValue",
    "denotation": "Denotation",
    "uniqueIDRef": "",
}

EDS_PROPERTY = "EDS:"
"""Prefix of a `property` name that holds an EDS key CiA 311 has no attribute for (`EDS:Factor`)."""

# Elements of CiA 311 this reader knows; others are reported as unknown (and kept).
KNOWN_ELEMENTS = frozenset(
    [
        "ISO15745ProfileContainer",
        "ISO15745Profile",
        "ProfileHeader",
        "ProfileIdentification",
        "ProfileRevision",
        "ProfileName",
        "ProfileSource",
        "ProfileClassID",
        "ProfileDate",
        "ExternalProfileHandle",
        "ProfileLocation",
        "ISO15745Reference",
        "ISO15745Part",
        "ISO15745Edition",
        "ProfileTechnology",
        "ProfileBody",
        "DeviceIdentity",
        "vendorName",
        "vendorID",
        "vendorText",
        "deviceFamily",
        "productFamily",
        "productName",
        "productID",
        "productText",
        "orderNumber",
        "version",
        "buildDate",
        "specificationRevision",
        "instanceName",
        "label",
        "description",
        "labelRef",
        "DeviceManager",
        "indicatorList",
        "LEDList",
        "LED",
        "LEDstate",
        "connectorList",
        "DeviceFunction",
        "capabilities",
        "characteristicsList",
        "characteristic",
        "characteristicName",
        "characteristicContent",
        "standardComplianceList",
        "compliantWith",
        "picturesList",
        "picture",
        "dictionaryList",
        "dictionary",
        "file",
        "ApplicationProcess",
        "dataTypeList",
        "array",
        "subrange",
        "struct",
        "varDeclaration",
        "enum",
        "enumValue",
        "derived",
        "count",
        "typeRef",
        "functionTypeList",
        "functionType",
        "functionInstanceList",
        "functionInstance",
        "templateList",
        "parameterTemplate",
        "parameterList",
        "parameter",
        "dataTypeIDRef",
        "defaultValue",
        "actualValue",
        "substituteValue",
        "allowedValues",
        "range",
        "minValue",
        "maxValue",
        "step",
        "value",
        "unit",
        "property",
        "denotation",
        "conditionalSupport",
        "variableRef",
        "instanceIDRef",
        "memberRef",
        "parameterGroupList",
        "parameterGroup",
        "parameterRef",
        "ApplicationLayers",
        "identity",
        "CANopenObjectList",
        "CANopenObject",
        "CANopenSubObject",
        "dummyUsage",
        "dummy",
        "dynamicChannels",
        "dynamicChannel",
        "TransportLayers",
        "PhysicalLayer",
        "baudRate",
        "supportedBaudRate",
        "NetworkManagement",
        "CANopenGeneralFeatures",
        "CANopenMasterFeatures",
        "deviceCommissioning",
    ]
) | frozenset(TYPE_ELEMENTS)


def standard_header(kind: str) -> str:
    """The ProfileHeader of a CANopen profile (`Device` or `CommunicationNetwork`), as one line of XML."""
    identification = "CANopen device profile" if kind == "Device" else "CANopen communication network profile"
    return (
        f'<ProfileHeader xmlns=""><ProfileIdentification>{identification}</ProfileIdentification>'
        "<ProfileRevision>1.1</ProfileRevision><ProfileName /><ProfileSource />"
        f"<ProfileClassID>{kind}</ProfileClassID><ISO15745Reference><ISO15745Part>1</ISO15745Part>"
        "<ISO15745Edition>1</ISO15745Edition><ProfileTechnology>CANopen</ProfileTechnology>"
        "</ISO15745Reference></ProfileHeader>"
    )
