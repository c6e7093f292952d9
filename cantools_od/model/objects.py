"""Objects and sub-objects of an object dictionary."""

from __future__ import annotations

from enum import IntEnum, StrEnum

from pydantic import BaseModel, ConfigDict, PrivateAttr

from ..canopennode.info import CanopenNodeInfo
from .datatypes import DataType, standard_type
from .source import Origin
from .values import NodeIdExpr, Value


class ObjectKind(IntEnum):
    """ObjectType codes of CiA 301."""

    NULL = 0x0
    DOMAIN = 0x2
    DEFTYPE = 0x5
    DEFSTRUCT = 0x6
    VAR = 0x7
    ARRAY = 0x8
    RECORD = 0x9


class AccessType(StrEnum):
    RO = "ro"
    WO = "wo"
    RW = "rw"
    RWR = "rwr"
    RWW = "rww"
    CONST = "const"

    @property
    def readable(self) -> bool:
        return self is not AccessType.WO

    @property
    def writable(self) -> bool:
        return self in (AccessType.WO, AccessType.RW, AccessType.RWR, AccessType.RWW)


NO_ACCESS = "noAccess"
"""CiA 311's access of an entry no SDO reaches; an EDS has no AccessType for it. Kept as the XDD's `access`."""


class Section(BaseModel):
    """What every section-backed part of the model keeps beside its data.

    `extra` holds keys this model has no field for, and known keys whose value
    could not be read, verbatim and in file order, so nothing is lost.
    `comments` maps a canonical key name (or "" for the section header) to the
    comment lines written directly above it.
    """

    # Schemas are built on first validation or dump: reading and linting need neither.
    model_config = ConfigDict(defer_build=True)

    extra: dict[str, str] = {}
    comments: dict[str, list[str]] = {}
    origin: Origin | None = None


class Variable(Section):
    """The entries a VAR, a sub-object or a CompactSubObj parent can carry."""

    name: str = ""
    data_type: int | None = None
    access: AccessType | None = None
    pdo_mapping: bool | None = None
    default: Value | None = None
    low_limit: Value | None = None
    high_limit: Value | None = None
    obj_flags: int | None = None
    # DCF entries
    parameter_value: Value | None = None
    denotation: str | None = None
    param_refd: str | None = None
    upload_file: str | None = None
    download_file: str | None = None
    # CANopenNode stack metadata (XDD properties, EDS ;StorageLocation=), None when the source has none
    canopennode: CanopenNodeInfo | None = None
    # An XDD's PDOmapping word, which `pdo_mapping` and `access` alone may not give (TPDO on an rw entry).
    _pdo_stated: str | None = PrivateAttr(default=None)

    def pdo_mapping_kind(self) -> str | None:
        """The CiA 311 PDOmapping word: no, default, optional, TPDO or RPDO (None when the file says nothing).

        The XDD's own word where it stated one; otherwise the direction the access allows
        (ro/const/rwr TPDO, wo/rww RPDO, rw optional), as an EDS's PDOMapping=1 means.
        """
        stated = self.stated_pdo_mapping
        if stated is not None:
            return stated
        if self.pdo_mapping is None:
            return None
        if not self.pdo_mapping:
            return "no"
        if self.access in (AccessType.RO, AccessType.CONST, AccessType.RWR):
            return "TPDO"
        if self.access in (AccessType.WO, AccessType.RWW):
            return "RPDO"
        return "optional"

    def state_pdo_mapping(self, word: str) -> None:
        """Keep the PDOmapping word an XDD states (no, default, optional, TPDO, RPDO)."""
        if self.__pydantic_private__ is None:  # built by model_construct, which sets up no private state
            self.__pydantic_private__ = {}
        self._pdo_stated = word

    @property
    def stated_pdo_mapping(self) -> str | None:
        """The PDOmapping word the file stated (an XDD); None where it said only 'mappable' or not (an EDS), or
        where `pdo_mapping` was edited to disagree with it."""
        private = self.__pydantic_private__
        stated = private.get("_pdo_stated") if private is not None else None
        if stated is None or self.pdo_mapping is None or (stated != "no") != self.pdo_mapping:
            return None  # not stated, or `pdo_mapping` was changed since: the word no longer holds
        return str(stated)

    @property
    def no_access(self) -> bool:
        """The file (an XDD) says access="noAccess": the entry is in the device but no SDO reads or writes it.
        CANopenEditor writes it for an entry whose access type it does not know."""
        return self.access is None and self.extra.get("access") == NO_ACCESS

    @property
    def dtype(self) -> DataType | None:
        return standard_type(self.data_type)

    @property
    def mappable(self) -> bool:
        return bool(self.pdo_mapping)

    @property
    def held(self) -> Value | None:
        """The value the device holds, as written: a DCF's ParameterValue (what was configured into the device,
        or uploaded from it), else the DefaultValue. Every check and view of values reads this one."""
        return self.parameter_value if self.parameter_value is not None else self.default

    @property
    def held_key(self) -> str:
        """The key that writes `held`: ParameterValue or DefaultValue."""
        return "ParameterValue" if self.parameter_value is not None else "DefaultValue"

    def hold(self, value: Value) -> None:
        """Make `value` the one the device holds: written where `held` is (ParameterValue or DefaultValue)."""
        if self.parameter_value is not None:
            self.parameter_value = value
        else:
            self.default = value

    def value(self, node_id: int | None = None) -> Value | None:
        """The value the device holds (`held`), resolved for a node-ID."""
        value = self.held
        if isinstance(value, NodeIdExpr) and node_id is not None:
            return value.resolve(node_id)
        return value


class SubObject(Variable):
    """A sub-index of an ARRAY, RECORD or DEFSTRUCT.

    `implicit` marks sub-objects that the file describes only through
    CompactSubObj or CompactPDO rather than with a section of their own.
    """

    object_type: ObjectKind | None = None
    implicit: bool = False


class Object(Variable):
    """An object at one index.

    `object_type` is None when the file leaves ObjectType out (a VAR). For
    ARRAY/RECORD, `sub_number` is the SubNumber as written and `compact_sub_obj`
    the CompactSubObj count; `subs` always holds every sub-object, expanded.
    """

    index: int
    object_type: ObjectKind | None = None
    sub_number: int | None = None
    compact_sub_obj: int | None = None
    subs: dict[int, SubObject] = {}
    links: list[int] | None = None
    implicit: bool = False

    @property
    def kind(self) -> ObjectKind:
        return ObjectKind.VAR if self.object_type is None else self.object_type

    @property
    def has_subs(self) -> bool:
        return self.kind in (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT)

    @property
    def left_out(self) -> bool:
        """The project keeps the object but the device does not have it: CANopenEditor's `CO_disabled`
        (its EDS export and its OD.c leave such objects out)."""
        return self.canopennode is not None and bool(self.canopennode.disabled)

    def entry(self, subindex: int) -> Variable | None:
        """The VAR itself for sub-index 0 of a VAR, else the sub-object."""
        if not self.has_subs:
            return self if subindex == 0 else None
        return self.subs.get(subindex)
