"""python-canopen interoperability: a loaded model as a `canopen.ObjectDictionary`.

`od_objects` lists what python-canopen's object dictionary holds, computed from the model; both
`to_canopen` and the generated Python module's `object_dictionary()` are built from it, so the two
agree. python-canopen is imported only when `to_canopen` runs.

The entries follow python-canopen's own EDS import (`canopen.import_od`):

- a VAR or DOMAIN object is an `ODVariable`, an ARRAY an `ODArray`, a RECORD (or DEFSTRUCT) an `ODRecord`;
- `data_type` is the CiA 301 type (a DEFTYPE alias resolved), DOMAIN when unknown or not a basic type;
- `access_type` is the access type in lower case, "rw" when the file gives none (python-canopen's default);
- `default` is DefaultValue and `value` ParameterValue: int for integers and BOOLEAN, float for REAL,
  str for strings, bytes for OCTET_STRING and DOMAIN, and the 6 little-endian bytes of a TIME value;
  `$NODEID+n` sets `relative` and becomes node-ID + n, or None when no node-ID is known;
- `min`/`max` are LowLimit/HighLimit. Unlike python-canopen's reader, limits of REAL and of 24/40/48/56-bit
  types are kept, and values it cannot read (kept verbatim in the model) are None.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Literal

from .model import Device, NodeIdExpr, Object, ObjectKind, RawValue, TimeValue, Value, ValueKind, Variable
from .model.datatypes import BASIC_TYPE_RANGE, DOMAIN

if TYPE_CHECKING:
    import canopen

__all__ = ["OdObject", "OdValue", "OdVariable", "od_object", "od_objects", "time_bytes", "to_canopen"]

DOMAIN_TYPE = DOMAIN.index
LAST_BASIC_TYPE = BASIC_TYPE_RANGE[-1]

OdValue = int | float | str | bytes | NodeIdExpr | None
"""A value as python-canopen holds it; `NodeIdExpr` until a node-ID resolves it."""


@dataclass(frozen=True)
class OdVariable:
    index: int
    subindex: int
    name: str
    data_type: int
    access: str
    pdo_mappable: bool
    default: OdValue
    value: OdValue
    low: int | float | None
    high: int | float | None


@dataclass(frozen=True)
class OdObject:
    index: int
    name: str
    kind: Literal["var", "array", "record"]
    variables: tuple[OdVariable, ...]  # a VAR's one variable, or the sub-objects in sub-index order


def time_bytes(value: TimeValue) -> bytes:
    """TIME_OF_DAY / TIME_DIFFERENCE as sent: milliseconds (28 bits, 4 reserved), then days, little-endian."""
    return ((value.days & 0xFFFF) << 32 | (value.ms & 0x0FFFFFFF)).to_bytes(6, "little")


def _value(value: Value | None, kind: ValueKind | None) -> OdValue:
    if value is None or isinstance(value, RawValue):
        return None
    if isinstance(value, TimeValue):
        return time_bytes(value)
    if isinstance(value, NodeIdExpr):
        return value
    if isinstance(value, bool):
        return int(value)
    if kind is ValueKind.REAL and isinstance(value, int):
        return float(value)
    return value


def _limit(value: Value | None, node_id: int | None) -> int | float | None:
    if isinstance(value, NodeIdExpr):
        return value.resolve(node_id) if node_id is not None else None
    if isinstance(value, bool):
        return int(value)
    return value if isinstance(value, (int, float)) else None


def _variable(device: Device, owner: Object, var: Variable, index: int, subindex: int) -> OdVariable:
    dtype = device.entry_type(var, owner)
    basic = dtype is not None and dtype.index <= LAST_BASIC_TYPE and dtype.kind is not ValueKind.COMPLEX
    kind = dtype.kind if dtype is not None else None
    return OdVariable(
        index=index,
        subindex=subindex,
        name=var.name,
        data_type=dtype.index if basic and dtype is not None else DOMAIN_TYPE,
        access=var.access.value if var.access is not None else "rw",
        pdo_mappable=bool(var.pdo_mapping),
        default=_value(var.default, kind),
        value=_value(var.parameter_value, kind),
        low=_limit(var.low_limit, device.node_id),
        high=_limit(var.high_limit, device.node_id),
    )


def od_objects(device: Device) -> list[OdObject]:
    """The objects python-canopen's dictionary holds for `device`, in index order (no NULL or DEFTYPE)."""
    found = (od_object(device, index) for index in sorted(device.objects))
    return [obj for obj in found if obj is not None]


def od_object(device: Device, index: int) -> OdObject | None:
    """The object at `index` as python-canopen's dictionary holds it; None for NULL, DEFTYPE or no object."""
    obj = device.objects.get(index)
    if obj is None or obj.kind in (ObjectKind.NULL, ObjectKind.DEFTYPE):
        return None
    if not obj.has_subs:
        return OdObject(index, obj.name, "var", (_variable(device, obj, obj, index, 0),))
    variables = tuple(_variable(device, obj, obj.subs[sub], index, sub) for sub in sorted(obj.subs))
    return OdObject(index, obj.name, "array" if obj.kind is ObjectKind.ARRAY else "record", variables)


def resolve(value: OdValue, node_id: int | None) -> int | float | str | bytes | None:
    """A value with `$NODEID` resolved, or None when it cannot be."""
    if isinstance(value, NodeIdExpr):
        return value.resolve(node_id) if node_id is not None else None
    return value


def to_canopen(device: Device, node_id: int | None = None) -> canopen.ObjectDictionary:
    """`device` as a python-canopen object dictionary; `$NODEID` stands for `node_id`, else the device's."""
    from canopen import objectdictionary as cod

    nid = node_id if node_id is not None else device.node_id
    od = cod.import_od(None)  # an empty dictionary; ObjectDictionary() is not annotated
    od.node_id = nid
    _device_information(device, od)
    for obj in od_objects(device):
        group: cod.ODArray | cod.ODRecord | None = None
        if obj.kind == "array":
            group = cod.ODArray(obj.name, obj.index)
        elif obj.kind == "record":
            group = cod.ODRecord(obj.name, obj.index)
        for row in obj.variables:
            var = cod.ODVariable(row.name, row.index, row.subindex)
            var.data_type = row.data_type
            var.access_type = row.access
            var.pdo_mappable = row.pdo_mappable
            var.relative = isinstance(row.default, NodeIdExpr)
            # python-canopen annotates these as int but holds floats, strings and bytes as well.
            vars(var).update(
                default=resolve(row.default, nid), value=resolve(row.value, nid), min=row.low, max=row.high
            )
            if group is None:
                od.add_object(var)
            else:
                group.add_member(var)
        if group is not None:
            od.add_object(group)
    return od


def _device_information(device: Device, od: canopen.ObjectDictionary) -> None:
    info = device.device_info
    if device.comments is not None:
        od.comments = "\n".join(device.comments.lines[n] for n in sorted(device.comments.lines))
    if device.commissioning is not None and device.commissioning.baudrate:
        od.bitrate = device.commissioning.baudrate * 1000
    target = od.device_information
    target.allowed_baudrates = {rate * 1000 for rate, supported in info.baud_rates.items() if supported}
    vars(target).update(
        vendor_name=info.vendor_name,
        vendor_number=info.vendor_number,
        product_name=info.product_name,
        product_number=info.product_number,
        revision_number=info.revision_number,
        order_code=info.order_code,
        simple_boot_up_master=info.simple_boot_up_master,
        simple_boot_up_slave=info.simple_boot_up_slave,
        granularity=info.granularity,
        dynamic_channels_supported=info.dynamic_channels_supported,
        group_messaging=info.group_messaging,
        nr_of_RXPDO=info.nr_of_rx_pdo,
        nr_of_TXPDO=info.nr_of_tx_pdo,
        LSS_supported=info.lss_supported,
    )
