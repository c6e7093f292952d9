"""The target-neutral view that every code and document generator renders.

Everything a template needs is computed here: identifiers, resolved types and
values, PDO layouts. Templates only lay it out. Values stay Python values;
each target's renderer spells them in its own language.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ..identifiers import Identifiers, assign
from ..model import (
    AccessType,
    DataType,
    Device,
    Diagnostic,
    Location,
    NodeIdExpr,
    Object,
    ObjectKind,
    Origin,
    RawValue,
    Severity,
    TimeValue,
    Value,
    ValueKind,
    Variable,
)
from ..model.cia301.pdo import CLASSIC_CAN_BITS, dummy_length_fits, dummy_shape_problem
from .pdo import Pdo, PdoEntry, pdo_map


@dataclass(frozen=True, slots=True)
class EntryView:
    """One value-carrying entry: a VAR (sub-index 0) or a sub-object.

    Slotted, and sharing its values with the model and the identifiers: a large device has
    hundreds of thousands of entries."""

    index: int
    subindex: int
    name: str
    member: str | None  # identifier within the object; None for a VAR
    flat: str  # identifier across the device
    data_type: DataType | None
    access: AccessType | None
    pdo_mappable: bool
    default: Value | None  # ParameterValue else DefaultValue, `$NODEID` kept symbolic
    low_limit: int | float | None
    high_limit: int | float | None
    implicit: bool
    origin: Origin | None  # the entry's section (a VAR's or sub-object's, else its object's)

    @property
    def line(self) -> int:
        """Where the file describes it, 0 when unknown."""
        return self.origin.key("ParameterName").line if self.origin else 0

    @property
    def kind(self) -> ValueKind | None:
        return self.data_type.kind if self.data_type else None

    @property
    def bits(self) -> int | None:
        return self.data_type.bits if self.data_type else None

    @property
    def is_scalar(self) -> bool:
        """A fixed-size number or boolean: it has a C/Rust scalar type."""
        return self.data_type is not None and self.data_type.is_numeric

    @property
    def readable(self) -> bool:
        return self.access is None or self.access.readable

    @property
    def writable(self) -> bool:
        return self.access is not None and self.access.writable

    @property
    def nodeid_offset(self) -> int | None:
        """The constant added to the node-ID when the default is `$NODEID+n`."""
        return self.default.offset if isinstance(self.default, NodeIdExpr) else None

    @property
    def string_length(self) -> int | None:
        """Bytes of a string or octet default (the size generated buffers reserve)."""
        if isinstance(self.default, str):
            return len(self.default.encode("utf-8"))
        if isinstance(self.default, bytes):
            return len(self.default)
        return None


@dataclass(frozen=True, slots=True)
class ObjectView:
    index: int
    name: str
    identifier: str
    kind: ObjectKind
    source: Object = field(repr=False, compare=False)
    device: Device = field(repr=False, compare=False)
    identifiers: Identifiers = field(repr=False, compare=False)

    @property
    def entries(self) -> tuple[EntryView, ...]:
        """The VAR itself, or its sub-objects in sub-index order.

        Made from the model each time they are asked for, not kept: the entries of a large device
        would cost more than its model. Renderers go through the objects one at a time."""
        obj = self.source
        pairs = obj.subs.items() if obj.has_subs else [(0, obj)]
        return tuple(_entry(self.device, self.identifiers, obj, sub, var) for sub, var in pairs)

    @property
    def entry_count(self) -> int:
        """How many entries there are, without making them."""
        return len(self.source.subs) if self.source.has_subs else 1

    @property
    def is_var(self) -> bool:
        return self.kind not in (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT)


@dataclass(frozen=True)
class PdoEntryView:
    entry: EntryView | None  # None for a dummy entry
    bit_offset: int
    bit_length: int
    data_type: DataType | None

    @property
    def is_dummy(self) -> bool:
        return self.entry is None

    @property
    def identifier(self) -> str | None:
        return self.entry.flat if self.entry else None

    @property
    def signed(self) -> bool:
        return self.data_type is not None and self.data_type.kind is ValueKind.SIGNED


@dataclass(frozen=True)
class PdoView:
    pdo: Pdo
    entries: tuple[PdoEntryView, ...]

    @property
    def struct_name(self) -> str:
        """`tpdo1`, `rpdo3`: the base of the generated struct, class and function names."""
        return self.pdo.name.lower()

    @property
    def byte_length(self) -> int:
        return (self.pdo.bit_length + 7) // 8

    @property
    def fields(self) -> tuple[PdoEntryView, ...]:
        return tuple(e for e in self.entries if not e.is_dummy)


@dataclass(frozen=True)
class DeviceView:
    name: str  # the output base name, an identifier
    device: Device
    identifiers: Identifiers
    objects: tuple[ObjectView, ...]
    pdos: tuple[PdoView, ...]
    node_id: int | None  # the one given, else the DCF's NodeID
    problems: tuple[Diagnostic, ...] = field(default=())
    max_pdo_bits: int = CLASSIC_CAN_BITS  # the frame limit PDOs were checked against (512 with CAN FD)
    failed_pdos: frozenset[str] = frozenset()  # names of the PDOs that `problems` are about

    @property
    def source_name(self) -> str:
        """The file the device was read from, without folders: generated text does not depend on where it was."""
        return Path(self.device.source).name if self.device.source else ""

    def entry(self, index: int, subindex: int) -> EntryView | None:
        for obj in self.objects:
            if obj.index == index:
                return next((e for e in obj.entries if e.subindex == subindex), None)
        return None


def _number(value: Value | None) -> int | float | None:
    if isinstance(value, bool):
        return int(value)
    return value if isinstance(value, (int, float)) else None


def _entry(device: Device, ids: Identifiers, obj: Object, subindex: int, var: Variable) -> EntryView:
    value = var.held
    return EntryView(
        index=obj.index,
        subindex=subindex,
        name=var.name,
        member=ids.member(obj.index, subindex) if obj.has_subs else None,
        flat=ids.flat(obj.index, subindex),
        data_type=device.entry_type(var, obj),
        access=var.access,
        pdo_mappable=bool(var.pdo_mapping),
        default=None if isinstance(value, (RawValue, TimeValue)) else value,
        low_limit=_number(var.low_limit),
        high_limit=_number(var.high_limit),
        implicit=getattr(var, "implicit", False),
        origin=var.origin or obj.origin,
    )


def build_view(
    device: Device,
    name: str,
    node_id: int | None = None,
    identifiers: Identifiers | None = None,
    max_pdo_bits: int = CLASSIC_CAN_BITS,
) -> DeviceView:
    """The view of `device`; `problems` lists what makes generated PDO code impossible."""
    device = device.as_built()
    ids = identifiers or assign(device)
    objects: list[ObjectView] = []
    by_index: dict[int, ObjectView] = {}
    for obj in device.objects.values():
        if obj.kind in (ObjectKind.NULL, ObjectKind.DEFTYPE):
            continue
        objects.append(ObjectView(obj.index, obj.name, ids.object(obj.index), obj.kind, obj, device, ids))
        by_index[obj.index] = objects[-1]
    problems: list[Diagnostic] = []
    failed: set[str] = set()
    pdos: list[PdoView] = []
    for pdo in pdo_map(device, node_id, ids):
        view_entries = []
        for mapped in pdo.entries:
            target = None if mapped.is_dummy else _find(by_index.get(mapped.index), mapped.subindex)
            if mapped.is_dummy:
                problem = _dummy_problem(pdo, mapped)
            else:
                problem = _pdo_problem(pdo, mapped.index, mapped.subindex, mapped.bit_length, target)
                if problem and target is None and mapped.module is not None:  # CiA 306 section 6
                    problem += f" in the device itself (module {mapped.module} creates it; gen makes its own objects)"
            if problem:
                problems.append(_diagnostic(device, pdo, problem))
                failed.add(pdo.name)
            view_entries.append(PdoEntryView(target, mapped.bit_offset, mapped.bit_length, mapped.data_type))
        if pdo.count_invalid:
            problems.append(_diagnostic(device, pdo, f"{pdo.name}: its mapping counts {pdo.count} entries, at most 64"))
            failed.add(pdo.name)
        if pdo.bit_length > max_pdo_bits:
            problems.append(
                _diagnostic(device, pdo, f"{pdo.name}: its {pdo.bit_length} bits exceed the {max_pdo_bits}-bit frame")
            )
            failed.add(pdo.name)
        pdos.append(PdoView(pdo, tuple(view_entries)))
    resolved = node_id if node_id is not None else device.node_id  # given, else the DCF's own
    return DeviceView(
        name, device, ids, tuple(objects), tuple(pdos), resolved, tuple(problems), max_pdo_bits, frozenset(failed)
    )


def _find(obj: ObjectView | None, subindex: int) -> EntryView | None:
    """The object's entry at `subindex`, None when it has none."""
    if obj is None:
        return None
    return next((e for e in obj.entries if e.subindex == subindex), None)


def _dummy_problem(pdo: Pdo, mapped: PdoEntry) -> str:
    """What lint reports as PDO050/PDO045 of a dummy entry: the generated layout would not be the device's."""
    dtype = mapped.data_type
    where = f"{pdo.name}: dummy entry {mapped.index:04X}sub{mapped.subindex:X}"
    problem = dummy_shape_problem(dtype, mapped.index, mapped.subindex)
    if problem:
        return f"{where} {problem}"
    if dtype is not None and not dummy_length_fits(dtype, mapped.bit_length):
        return f"{where} maps {mapped.bit_length} bits, but {dtype.name} has {dtype.bits}"
    return ""


def _pdo_problem(pdo: Pdo, index: int, subindex: int, bits: int, entry: EntryView | None) -> str:
    where = f"{pdo.name} maps {index:04X}sub{subindex:X}"
    if entry is None:
        return f"{where}, which does not exist"
    if not entry.is_scalar or entry.bits is None:
        return f"{where}, whose type {entry.data_type.name if entry.data_type else 'is unknown'} has no fixed size"
    if bits != entry.bits and not (entry.kind is ValueKind.BOOL and bits == 8):  # CANopenNode maps BOOLEAN as a byte
        return (
            f"{where} with {bits} bits, but its type {entry.data_type.name if entry.data_type else ''} has {entry.bits}"
        )
    return ""


def _diagnostic(device: Device, pdo: Pdo, message: str) -> Diagnostic:
    obj = device.objects.get(pdo.map_index) or device.objects.get(pdo.comm_index)
    where = obj.origin.header() if obj is not None and obj.origin is not None else Location(file=device.source)
    return Diagnostic(code="GEN001", severity=Severity.ERROR, message=f"cannot generate {message}", location=where)
