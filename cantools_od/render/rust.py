"""The Rust target: one `#![no_std]`-ready module `<name>.rs` without dependencies.

Per entry: index/sub-index, data type, access, PDO-mappable flag, default, limits and string
length as typed constants, `<entry>_default(node_id)` for `$NODEID` values and
`<entry>_is_in_range(value)` from the limits. Records become structs, uniform arrays `[T; N]`
aliases, and `OBJECTS` lists every entry. PDOs (see `rust_pdo`) get structs with `pack`/`unpack`.
Names come from `cantools_od.identifiers`; layouts follow rustfmt (see `rust_layout`).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field

from ..model import STANDARD_TYPES, NodeIdExpr, ObjectKind, ValueKind
from ..views.codegen import DeviceView, EntryView, ObjectView
from . import Each, escape, rust_layout, stream_template, whole
from .rust_names import TypeNames, lower, upper
from .rust_pdo import RustPdo, pdos
from .rust_types import byte_string, in_type_range, node_expr, rust_type, scalar_literal, zero


@dataclass(frozen=True)
class RustEntry:
    view: EntryView
    const: str  # base of the constants: IDENTITY_OBJECT_VENDOR_ID
    func: str  # base of the functions: identity_object_vendor_id
    ty: str | None  # the Rust type of a number or boolean
    data_type: str | None  # DataType::UNSIGNED32
    access: str | None  # Access::Ro
    default: str | None  # the default as a literal of `default_type`
    default_type: str | None
    node: str | None  # the default as an expression of `node_id` for `$NODEID` values
    length: int | None  # bytes of a string or octet default
    low: str | None
    high: str | None
    in_range: str | None  # an expression of `value` that checks the limits
    note: str  # why a default or a range check is missing, for a comment
    size: int  # bytes of a value, 0 when unknown

    @property
    def subindex(self) -> str:
        return f"0x{self.view.subindex:02X}"


@dataclass(frozen=True)
class RustField:
    member: str
    ty: str
    value: str  # the default, an atomic expression
    entry: EntryView


@dataclass(frozen=True)
class RustRecord:
    """A struct with a field per sub-object that has a value of known size."""

    name: str
    fields: list[RustField]
    node_values: list[tuple[str, str]]  # (local, expression of node_id) the defaults refer to
    skipped: list[str]  # members without a fixed-size value

    @property
    def body(self) -> str | None:
        """The fields of the default on one line, when rustfmt puts them there."""
        return rust_layout.struct_body([(f.member, f.value) for f in self.fields])


@dataclass(frozen=True)
class RustArray:
    """`[T; N]` for the sub-objects 1..N of an ARRAY of one scalar type."""

    name: str
    element: str
    count: int
    fill: str  # the value most elements default to
    others: list[tuple[int, str]]  # (position, literal or expression of node_id)
    node: bool  # some default is relative to the node-ID


@dataclass(frozen=True)
class RustObject:
    view: ObjectView
    const: str
    func: str
    kind: str
    entries: list[RustEntry]
    record: RustRecord | None = None
    array: RustArray | None = None

    @property
    def own_index(self) -> bool:
        """Whether the object needs an `_INDEX` constant besides its entries' (a VAR's is its entry's)."""
        return all(entry.const != self.const for entry in self.entries)


@dataclass(frozen=True)
class RustModule:
    view: DeviceView
    node_id: int | None
    objects: Each[RustObject]
    entries: Each[RustEntry]
    pdos: list[RustPdo]
    data_types: list[tuple[str, str]] = field(default_factory=list)  # (NAME, 0x0007)


def _limits(entry: EntryView, ty: str | None) -> tuple[str | None, str | None, str | None, str]:
    """Literals of the limits and the range check they make; a note when the check is impossible."""
    dtype = entry.data_type
    if ty is None or dtype is None or ty == "bool":
        return None, None, None, ""
    low_value, high_value = entry.low_limit, entry.high_limit
    low = scalar_literal(low_value, dtype) if low_value is not None and in_type_range(low_value, dtype) else None
    high = scalar_literal(high_value, dtype) if high_value is not None and in_type_range(high_value, dtype) else None
    bounds = dtype.int_range() or (None, None)
    real = dtype.kind is ValueKind.REAL
    check_low = low is not None and low_value is not None and (real or low_value != bounds[0])
    check_high = high is not None and high_value is not None and (real or high_value != bounds[1])
    if check_low and check_high:
        assert low_value is not None and high_value is not None
        if low_value > high_value:
            return low, high, None, "LowLimit is above HighLimit: no range check"
        return low, high, f"({low}..={high}).contains(&value)", ""
    if check_low:  # a limit at the other end of the type's range allows one value only
        return low, high, f"value {'==' if low_value == bounds[1] else '>='} {low}", ""
    if check_high:
        return low, high, f"value {'==' if high_value == bounds[0] else '<='} {high}", ""
    return low, high, None, ""


def _entry(entry: EntryView, node_id: int | None) -> RustEntry:
    dtype, ty = entry.data_type, rust_type(entry.data_type)
    value: object = entry.default
    default = default_type = node = None
    length: int | None = None
    note = ""
    if isinstance(value, NodeIdExpr):
        node = node_expr(ty, value.offset) if ty is not None and ty != "bool" else None
        if node is None:
            note = f"default {value.canonical()} is not a number"
        value = value.resolve(node_id) if node is not None and node_id is not None else None
    if value is not None and ty is not None and dtype is not None:
        default, default_type = scalar_literal(value, dtype), ty
        if default is None:
            note = f"default {value!r} is not a {dtype.name}"
    elif isinstance(value, str):
        default, default_type, length = escape.rust_string(value), "&str", len(value.encode("utf-8"))
    elif isinstance(value, bytes):
        default, default_type, length = byte_string(value), "&[u8]", len(value)
    low, high, in_range, limit_note = _limits(entry, ty)
    bits = entry.bits
    return RustEntry(
        view=entry,
        const=upper(entry.flat),
        func=lower(entry.flat),
        ty=ty,
        data_type=f"DataType::{dtype.name}" if dtype is not None and dtype.index in STANDARD_TYPES else None,
        access=f"Access::{entry.access.value.capitalize()}" if entry.access is not None else None,
        default=default,
        default_type=default_type if default is not None else None,
        node=node,
        length=length,
        low=low,
        high=high,
        in_range=in_range,
        note=note or limit_note,
        size=(bits + 7) // 8 if bits is not None and ty is not None else length or 0,
    )


def _value(entry: RustEntry) -> str | None:
    """The default as a struct field value: a literal, or None for one relative to the node-ID."""
    if entry.node is not None and entry.default is None:
        return None
    return entry.default or zero(entry.ty or "")


def _array(obj: ObjectView, entries: list[RustEntry], name: str) -> RustArray | None:
    elements = [e for e in entries if e.view.subindex > 0]
    if obj.kind is not ObjectKind.ARRAY or not elements or entries[0].view.subindex != 0:
        return None
    if [e.view.subindex for e in elements] != list(range(1, len(elements) + 1)):
        return None
    kinds = {(e.ty, e.view.data_type) for e in elements}
    ty = elements[0].ty
    if len(kinds) != 1 or ty is None:
        return None
    values = [_value(e) for e in elements]
    counts = Counter(v for v in values if v is not None)
    fill = counts.most_common(1)[0][0] if counts else zero(ty)
    pairs = enumerate(zip(elements, values, strict=True))
    others = [(i, v if v is not None else e.node or "") for i, (e, v) in pairs if v != fill]
    node = any(v is None for v in values)
    return RustArray(name, ty, len(elements), fill, others, node)


def _record(entries: list[RustEntry], name: str) -> RustRecord | None:
    fields: list[RustField] = []
    node_values: list[tuple[str, str]] = []
    skipped: list[str] = []
    for entry in entries:
        member = entry.view.member or entry.func
        value = _value(entry)
        if entry.ty is not None:
            if value is None:
                node_values.append((f"v{len(node_values) + 1}", entry.node or ""))
                value = node_values[-1][0]
            fields.append(RustField(member, entry.ty, value, entry.view))
        elif entry.length is not None and isinstance(entry.view.default, (str, bytes)):
            data = entry.view.default
            raw = data.encode("utf-8") if isinstance(data, str) else data
            fields.append(RustField(member, f"[u8; {entry.length}]", "*" + byte_string(raw), entry.view))
        else:
            skipped.append(member)
    if not fields:
        return None
    return RustRecord(name, fields, node_values, skipped)


def _entries(obj: ObjectView, node_id: int | None) -> list[RustEntry]:
    return [_entry(entry, node_id) for entry in sorted(obj.entries, key=lambda e: e.subindex)]


def _object(obj: ObjectView, node_id: int | None, type_name: str | None) -> RustObject:
    entries = _entries(obj, node_id)
    kind = obj.kind.name
    if obj.is_var or type_name is None:
        return RustObject(obj, upper(obj.identifier), lower(obj.identifier), kind, entries)
    array = _array(obj, entries, type_name)
    record = None if array is not None else _record(entries, type_name)
    return RustObject(obj, upper(obj.identifier), lower(obj.identifier), kind, entries, record, array)


def _type_names(objects: list[ObjectView], node_id: int | None, types: TypeNames) -> dict[int, str]:
    """The type name of each ARRAY or RECORD that gets a type, claimed in index order: a first pass that
    keeps only the names, so that the objects' Rust forms can be made one at a time as they are rendered."""
    names: dict[int, str] = {}
    for obj in objects:
        if obj.is_var:
            continue
        entries = _entries(obj, node_id)
        if _array(obj, entries, "") is not None or _record(entries, "") is not None:
            names[obj.index] = types.claim(obj.identifier, obj.index)
    return names


def module(view: DeviceView) -> RustModule:
    """Everything the templates lay out, in index order; objects and entries are made as they are read."""
    if view.problems:
        raise ValueError(f"cannot generate Rust: {view.problems[0].message}")
    node_id = view.node_id
    node_id = node_id if node_id is not None and 0 <= node_id <= 0xFF else None  # a DCF's NodeID may be anything
    rust_pdos = pdos(view, node_id)
    ordered = sorted(view.objects, key=lambda o: o.index)
    names = _type_names(ordered, node_id, TypeNames(pdo.name for pdo in rust_pdos))
    objects = Each(lambda: (_object(obj, node_id, names.get(obj.index)) for obj in ordered), len(ordered))
    entries = Each(
        lambda: (entry for obj in ordered for entry in _entries(obj, node_id)),
        sum(obj.entry_count for obj in ordered),
    )
    data_types = [(t.name, f"0x{t.index:04X}") for t in STANDARD_TYPES.values()]
    return RustModule(view, node_id, objects, entries, rust_pdos, data_types)


def stream(view: DeviceView) -> dict[str, Iterable[str]]:
    """`<name>.rs` for the view, rendered as it is read."""
    context = module(view)
    product = view.device.device_info.product_name or ""
    text = stream_template("rust/module.rs.j2", m=context, source=view.source_name, product=product, fmt=rust_layout)
    return {f"{view.name}.rs": text}


def render(view: DeviceView) -> dict[str, str]:
    """`<name>.rs` for the view."""
    return whole(stream(view))
