"""The typed object-dictionary model: CANopen, independent of any file format."""

from ..canopennode.info import CanopenNodeInfo, SrdoAccess
from .datatypes import STANDARD_TYPES, DataType, ValueKind, standard_type, type_by_name
from .device import (
    Comments,
    Commissioning,
    Device,
    DeviceInfo,
    Dialect,
    DummyUsage,
    FileInfo,
    ObjectList,
    RawSection,
)
from .objects import AccessType, Object, ObjectKind, Section, SubObject, Variable
from .source import Diagnostic, Location, Origin, Severity
from .values import NodeIdExpr, RawValue, TimeValue, Value

__all__ = [
    "STANDARD_TYPES",
    "AccessType",
    "CanopenNodeInfo",
    "Comments",
    "Commissioning",
    "DataType",
    "Device",
    "DeviceInfo",
    "Diagnostic",
    "Dialect",
    "DummyUsage",
    "FileInfo",
    "Location",
    "NodeIdExpr",
    "Object",
    "ObjectKind",
    "ObjectList",
    "Origin",
    "RawSection",
    "RawValue",
    "Section",
    "Severity",
    "SrdoAccess",
    "SubObject",
    "TimeValue",
    "Value",
    "ValueKind",
    "Variable",
    "standard_type",
    "type_by_name",
]
