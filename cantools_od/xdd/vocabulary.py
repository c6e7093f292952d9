"""CiA 311 spellings and their model meaning: namespaces, type elements, access and PDO mapping names."""

from __future__ import annotations

from ..model import AccessType

NS_1_0 = "http://www.canopen.org/xml/1.0"
NS_1_1 = "http://www.canopen.org/xml/1.1"
NAMESPACES = (NS_1_0, NS_1_1)
XSI = "http://www.w3.org/2001/XMLSchema-instance"

# CiA 311 (after IEC 61131-3) names the simple types of a parameter by element; CiA 301 index of each.
TYPE_ELEMENTS: dict[str, int] = {
    "BOOL": 0x0001,
    "SINT": 0x0002,
    "CHAR": 0x0002,
    "INT": 0x0003,
    "DINT": 0x0004,
    "USINT": 0x0005,
    "BYTE": 0x0005,
    "UINT": 0x0006,
    "WORD": 0x0006,
    "UDINT": 0x0007,
    "DWORD": 0x0007,
    "REAL": 0x0008,
    "STRING": 0x0009,
    "BITSTRING": 0x000A,
    "WSTRING": 0x000B,
    "LREAL": 0x0011,
    "LINT": 0x0015,
    "ULINT": 0x001B,
    "LWORD": 0x001B,
}
# The element written for each CiA 301 type; types CiA 311 has no element for are written as
# BITSTRING, with the exact type in the CANopenObject's dataType attribute.
ELEMENT_OF_TYPE: dict[int, str] = {
    0x0001: "BOOL",
    0x0002: "SINT",
    0x0003: "INT",
    0x0004: "DINT",
    0x0005: "USINT",
    0x0006: "UINT",
    0x0007: "UDINT",
    0x0008: "REAL",
    0x0009: "STRING",
    0x000B: "WSTRING",
    0x0011: "LREAL",
    0x0015: "LINT",
    0x001B: "ULINT",
}
DOMAIN = 0x000F
OCTET_STRING = 0x000A

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

CANOPENNODE_PROPERTIES = (
    "CO_storageGroup",
    "CO_countLabel",
    "CO_disabled",
    "CO_flagsPDO",
    "CO_accessSRDO",
    "CO_stringLengthMin",
)

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
