"""Impact classification: whether a change of access, range, type or capability narrows what worked before."""

from __future__ import annotations

import math

from ..canopennode.info import DISABLED_PROPERTY
from ..canopennode.profile import COUNT_PREFIX
from ..model import AccessType, DataType, NodeIdExpr, RawValue, Value, ValueKind
from ..model.cia301.objects import (
    COB_ID_EMCY,
    COB_ID_SYNC,
    COB_ID_TIME,
    DEVICE_TYPE,
    IDENTITY,
    IDENTITY_PRODUCT_CODE,
    IDENTITY_VENDOR_ID,
    SDO_CLIENTS,
    SDO_SERVERS,
)
from .records import Impact

# What each access type lets a user of the device do. `const` reads like `ro`: a constant is still read.
_CAPABILITIES: dict[AccessType, frozenset[str]] = {
    AccessType.RO: frozenset({"read"}),
    AccessType.CONST: frozenset({"read"}),
    AccessType.WO: frozenset({"write"}),
    AccessType.RW: frozenset({"read", "write"}),
    AccessType.RWR: frozenset({"read", "write"}),
    AccessType.RWW: frozenset({"read", "write"}),
}

_ABLE = {"read": "readable", "write": "writable"}


def access_impact(
    old: AccessType | None, new: AccessType | None, old_none: bool = False, new_none: bool = False
) -> tuple[Impact, str]:
    """Narrowed (a read or write lost) is breaking, widened compatible, the same abilities cosmetic.

    `old_none`/`new_none`: the side is an XDD's noAccess (no SDO reaches the entry).
    """
    before = frozenset[str]() if old_none else _CAPABILITIES[old] if old is not None else None
    after = frozenset[str]() if new_none else _CAPABILITIES[new] if new is not None else None
    if before is None or after is None:
        return Impact.VALUE, "access type given on one side only"
    lost, gained = before - after, after - before
    if lost:
        return Impact.BREAKING, "no longer " + " or ".join(_ABLE[ability] for ability in sorted(lost))
    if gained:
        return Impact.COMPATIBLE, "now " + " and ".join(_ABLE[ability] for ability in sorted(gained))
    return Impact.COSMETIC, "same read/write abilities"


def data_type_impact(old: DataType | None, new: DataType | None) -> tuple[Impact, str]:
    """Any change of the type generated code and a master use is breaking; an alias of the same type is not."""
    if old is not None and new is not None and old == new:
        return Impact.COSMETIC, f"both are {old.name}"
    if old is None or new is None:
        return Impact.BREAKING, "type changed"
    notes = []
    if old.bits != new.bits:
        notes.append(f"width {_bits(old)} → {_bits(new)}")
    if {old.kind, new.kind} == {ValueKind.SIGNED, ValueKind.UNSIGNED}:
        notes.append("signedness changed")
    elif old.kind != new.kind:
        notes.append(f"{old.kind.value} → {new.kind.value}")
    return Impact.BREAKING, ", ".join(notes) or "type changed"


def _bits(dtype: DataType) -> str:
    return f"{dtype.bits} bits" if dtype.bits is not None else "variable"


def flag_impact(old: bool | None, new: bool | None, what: str) -> tuple[Impact, str]:
    """A capability flag (PDO mapping, LSS, boot-up...): taken away is breaking, given compatible."""
    if bool(old) and not new:
        return Impact.BREAKING, f"no longer {what}"
    if bool(new) and not old:
        return Impact.COMPATIBLE, f"now {what}"
    return Impact.COSMETIC, "unset reads as no"


# The PDOs an XDD's PDOmapping word lets an entry be mapped into (CiA 311).
_PDO_DIRECTIONS = {"no": frozenset(), "TPDO": frozenset({"TPDO"}), "RPDO": frozenset({"RPDO"})}
_BOTH_DIRECTIONS = frozenset({"TPDO", "RPDO"})  # optional, default


def _directions(word: str, access: AccessType | None) -> frozenset[str]:
    """The PDOs the entry can be mapped into: what the word allows and the access permits (a TPDO reads the
    entry, an RPDO writes it)."""
    allowed = _PDO_DIRECTIONS.get(word, _BOTH_DIRECTIONS)
    if access is None:
        return allowed
    abilities = _CAPABILITIES[access]
    return allowed & frozenset(d for d, need in (("TPDO", "read"), ("RPDO", "write")) if need in abilities)


def pdo_direction_impact(
    old: str, new: str, old_access: AccessType | None, new_access: AccessType | None
) -> tuple[Impact, str]:
    """A PDO direction taken away breaks a master that maps the entry there; one given is compatible."""
    before, after = _directions(old, old_access), _directions(new, new_access)
    lost, gained = before - after, after - before
    if lost:
        return Impact.BREAKING, "no longer mappable into " + " or ".join(sorted(f"a {d}" for d in lost))
    if gained:
        return Impact.COMPATIBLE, "now mappable into " + " and ".join(sorted(f"a {d}" for d in gained))
    return Impact.COSMETIC, "the same PDOs, as its access allows"


def count_impact(old: int | None, new: int | None, what: str) -> tuple[Impact, str]:
    """A number of supported things (PDOs, channels): fewer is breaking, more compatible."""
    if old is not None and new is not None:
        if new < old:
            return Impact.BREAKING, f"fewer {what}"
        return Impact.COMPATIBLE, f"more {what}"
    return Impact.VALUE, f"{what} given on one side only"


def _number(value: Value | None, node_id: int | None) -> float | None:
    if isinstance(value, NodeIdExpr):
        return None if node_id is None else float(value.resolve(node_id))
    if isinstance(value, (int, float)) and not isinstance(value, bool):
        return None if isinstance(value, float) and math.isnan(value) else float(value)
    return None


def limit_impact(
    old: Value | None,
    new: Value | None,
    low: bool,
    dtype: DataType | None,
    node_id: int | None,
    access: AccessType | None = None,
) -> tuple[Impact, str]:
    """A narrower range breaks a master that writes the entry (values it wrote are now refused); a wider range
    breaks a master that reads it (the device may answer values it did not expect). Otherwise compatible.

    A missing bound is the data type's own (or unbounded); bounds that are not numbers are compared as values.
    An entry of unknown access is taken as read and written.
    """
    unbounded = -math.inf if low else math.inf
    type_range = dtype.int_range() if dtype is not None else None
    default = float(type_range[0 if low else 1]) if type_range is not None else unbounded
    before = default if old is None else _number(old, node_id)
    after = default if new is None else _number(new, node_id)
    if before is None or after is None:
        return Impact.VALUE, "limits that are not numbers"
    if before == after:
        return Impact.COSMETIC, "same bound"
    narrowed = after > before if low else after < before
    abilities = _CAPABILITIES[access] if access is not None else frozenset({"read", "write"})
    if narrowed:
        if "write" in abilities:
            return Impact.BREAKING, "range narrowed, and a master writes it"
        return Impact.COMPATIBLE, "range narrowed, but a master only reads it"
    if "read" in abilities:
        return Impact.BREAKING, "range widened, and a master reads it"
    return Impact.COMPATIBLE, "range widened, and a master only writes it"


# Entries a master or another node relies on as they are on the bus: identity it checks at boot (CiA 302) and
# COB-IDs it sends or listens on. A change of their value (both sides stating one) breaks the bus.
_BOOT_CHECKS = {
    (DEVICE_TYPE, None): "a master checks the device type (1000h) at boot",
    (DEVICE_TYPE, 0): "a master checks the device type (1000h) at boot",
    (IDENTITY, IDENTITY_VENDOR_ID): "a master checks the vendor-ID at boot",
    (IDENTITY, IDENTITY_PRODUCT_CODE): "a master checks the product code at boot",
}
_COB_ID_OBJECTS = {COB_ID_SYNC: "SYNC", COB_ID_TIME: "TIME", COB_ID_EMCY: "EMCY"}
_SDO_COB_ID_SUBS = (1, 2)


def _bus_entry(index: int, subindex: int | None) -> str | None:
    """Why the value of this entry matters on the bus, None when it is an ordinary value."""
    if (index, subindex) in _BOOT_CHECKS:
        return _BOOT_CHECKS[(index, subindex)]
    if index in _COB_ID_OBJECTS and subindex in (None, 0):
        return f"the {_COB_ID_OBJECTS[index]} COB-ID on the bus"
    if (index in SDO_SERVERS or index in SDO_CLIENTS) and subindex in _SDO_COB_ID_SUBS:
        return "an SDO COB-ID on the bus"
    return None


def value_impact(index: int, subindex: int | None, old: Value | None, new: Value | None) -> tuple[Impact, str]:
    """A default or configured value: breaking for the bus where a master relies on it, else a value change."""
    why = _bus_entry(index, subindex)
    if why is not None and not isinstance(old, (RawValue, type(None))) and not isinstance(new, (RawValue, type(None))):
        return Impact.BREAKING, why
    return Impact.VALUE, ""


def canopennode_impact(field: str, old: object, new: object) -> tuple[Impact, str]:
    """CANopenNode properties: the storage group and count label decide generated code; a disabled object is
    left out of the generated OD (and so gone from the bus)."""
    if field == "disabled":
        if bool(old) == bool(new):
            return Impact.COSMETIC, "unset reads as enabled"
        if new:
            return Impact.BREAKING, f"disabled ({DISABLED_PROPERTY}): the OD loses it, and the bus with it"
        return Impact.COMPATIBLE, f"enabled ({DISABLED_PROPERTY} no longer set): the OD gains it"
    if field in ("storage_group", "count_label") and old is not None and new is not None:
        what = "storage group" if field == "storage_group" else f"{COUNT_PREFIX} count"
        return Impact.BREAKING, f"generated code and the stored layout change ({what})"
    if old is None or new is None:
        return Impact.VALUE, "stated on one side only"
    return Impact.VALUE, ""
