"""The CANopenNode v4 view: what the stack's OD.h/OD.c hold, computed from the model.

The stack (`301/CO_ODinterface.h`) keeps every object as an `OD_entry_t` (index, number of
sub-entries, VAR/ARRAY/RECORD) pointing at constant descriptions (attribute bits, data length)
and at the values, which live in one C struct per storage group (`OD_RAM`, `OD_PERSIST_COMM`...).
This module decides all of that; the renderer only spells it in C.

Where the CANopenNode settings come from, in order: the model's `CanopenNodeInfo` (XDD
properties, EDS `;StorageLocation=`, the `<stem>.canopennode.toml` overrides), else the
inference below, which `inferences` lists one line each:

- count label: by index range (`standard_count_label`): 1000h NMT, 1001h EM, 1005h SYNC,
  1006h SYNC_PROD, 1010h STORAGE, 1012h TIME, 1014h EM_PROD, 1016h HB_CONS, 1017h HB_PROD,
  1200h-127Fh SDO_SRV, 1280h-12FFh SDO_CLI, 1300h GFC, 1301h-1340h SRDO, 1400h-15FFh RPDO,
  1800h-19FFh TPDO;
- storage group: PERSIST_COMM in the communication area 1000h-1FFFh except the status and
  command objects 1001h-1003h, 1010h, 1011h, 1013h and 1200h; RAM elsewhere.

Values follow the stack's conventions: `$NODEID+n` is stored as n (the stack adds the node-ID
to the COB-IDs it manages at run time); an entry without a default gets no memory (`dataOrig`
NULL, for the application to provide through `OD_extension_init`), as does a DOMAIN, except the
objects CO_CANopenInit reads (`stack_reads_at_init`: 0 then); an ARRAY's elements have memory all
or none, as its first element decides (CANopenEditor's exporter); strings
reserve max(default length, `string_length_min`) bytes, VISIBLE_STRING one more for the
terminator; 24/40/48/56-bit integers and TIME types are byte arrays in CANopen byte order.
"""

from __future__ import annotations

import functools
import struct
from collections.abc import Sequence
from dataclasses import dataclass, field, replace

from ..canopennode.editor import (
    array_has_memory,
    c_name,
    editor_entry_type,
    editor_integer,
    editor_octets,
    editor_pdo_word,
    editor_real,
    entry_has_memory,
    pdo_bits_pair,
    pdo_directions,
    sdo_directions,
)
from ..canopennode.profile import (
    RAM,
    SRDO_DIRECTIONS,
    count_label_for,
    count_macro,
    pdo_attribute_text,
    stack_reads_at_init,
    standard_storage_group,
)
from ..identifiers import RESERVED
from ..model import (
    CanopenNodeInfo,
    DataType,
    Device,
    Dialect,
    NodeIdExpr,
    Object,
    ObjectKind,
    RawValue,
    TimeValue,
    Value,
    ValueKind,
    Variable,
)
from ..model.datatypes import DOMAIN

VAR, ARR, REC = "VAR", "ARR", "REC"
_KINDS = {ObjectKind.VAR: VAR, ObjectKind.DOMAIN: VAR, ObjectKind.ARRAY: ARR, ObjectKind.RECORD: REC}


@dataclass(frozen=True, slots=True)
class Attributes:
    """The ODA_* bits of one entry, by meaning."""

    sdo: str  # "R", "W", "RW" or ""
    pdo: str  # "T", "R", "TR" or ""
    srdo: str  # "T", "R", "TR" or ""
    multibyte: bool  # ODA_MB: a 16/32/64-bit number the stack byte-swaps on big-endian targets
    string: bool  # ODA_STR: a shorter value may be written (VISIBLE_STRING, UNICODE_STRING)


@dataclass(frozen=True, slots=True)
class NodeEntry:
    """One sub-entry: the VAR itself, an ARRAY element or a RECORD member."""

    subindex: int
    name: str
    member: str  # identifier inside a RECORD struct (CANopenEditor's spelling)
    data_type: DataType
    attributes: Attributes
    length: int  # dataLength: the bytes SDO reads and writes
    stored: bool  # False: no memory in the OD (dataOrig NULL)
    default: bytes  # the initial bytes, `length` long, CANopen (little-endian) byte order

    @property
    def terminated(self) -> bool:
        """Strings keep one more zero unit after `length` so C code can use them as strings."""
        return self.data_type.kind in (ValueKind.STRING, ValueKind.UNICODE)


@dataclass(frozen=True, slots=True)
class NodeObject:
    index: int
    name: str
    c_name: str  # CANopenEditor's identifier for the object (deviceType, COB_ID_SYNCMessage)
    kind: str  # VAR, ARR or REC
    group: str  # storage group
    count_label: str | None
    entries: tuple[NodeEntry, ...]  # by sub-index

    @property
    def stored(self) -> bool:
        return any(e.stored for e in self.entries)

    @property
    def elements(self) -> tuple[NodeEntry, ...]:
        """ARRAY elements (sub-index 1 and up)."""
        return self.entries[1:]


@dataclass(frozen=True, slots=True)
class Inference:
    where: str  # "1000h", "1400sub1"
    text: str

    def format(self) -> str:
        return f"{self.where}: {self.text}"


@dataclass(frozen=True)
class NodeView:
    name: str  # base of the files and the symbol prefix (OD)
    source: str  # the input's file name, without folders
    objects: tuple[NodeObject, ...]  # by index, without disabled ones
    inferences: tuple[Inference, ...]
    counts: tuple[tuple[str, int], ...] = field(default=())  # count label → objects, in index order

    @property
    def groups(self) -> tuple[str, ...]:
        """Storage groups holding memory, in order of their first object."""
        return tuple(dict.fromkeys(o.group for o in self.objects if o.stored))

    @property
    def arrays(self) -> tuple[NodeObject, ...]:
        return tuple(o for o in self.objects if o.kind == ARR)

    def in_group(self, group: str) -> tuple[NodeObject, ...]:
        return tuple(o for o in self.objects if o.stored and o.group == group)

    def position(self, index: int) -> int | None:
        """The object's place in the OD list, or None when it is not there."""
        return next((n for n, o in enumerate(self.objects) if o.index == index), None)


# --- names -----------------------------------------------------------------------------------


def _member_names(subs: Sequence[tuple[int, Variable]]) -> dict[int, str]:
    names: dict[int, str] = {}
    taken: set[str] = set()
    for subindex, var in subs:
        name = c_name(var.name) or f"sub{subindex}"
        if name[0].isdigit():
            name = "_" + name
        if name in RESERVED:
            name += "_"
        if name in taken:
            name = f"{name}_{subindex}"
        taken.add(name)
        names[subindex] = name
    return names


# --- values ----------------------------------------------------------------------------------


def _length(dtype: DataType, value: Value | None, minimum: int | None) -> int:
    if dtype.kind is ValueKind.BOOL:
        return 1
    if dtype.bits is not None:
        return dtype.bits // 8
    if dtype.index == DOMAIN.index:  # DOMAIN: the application streams it
        return 0
    held = _text_bytes(dtype, value)
    return max(len(held) if held is not None else 0, (minimum or 0) * (2 if dtype.kind is ValueKind.UNICODE else 1))


def _text_bytes(dtype: DataType, value: Value | None) -> bytes | None:
    if isinstance(value, bytes):
        return value
    if isinstance(value, str):
        return value.encode("utf-16-le" if dtype.kind is ValueKind.UNICODE else "utf-8")
    return None


def value_bytes(dtype: DataType, value: Value | None, length: int) -> bytes | None:
    """The value as the stack holds it, `length` bytes; None when there is no usable value."""
    if isinstance(value, NodeIdExpr):
        value = value.offset
    kind = dtype.kind
    if kind in (ValueKind.BOOL, ValueKind.UNSIGNED, ValueKind.SIGNED) and isinstance(value, (bool, int)):
        return (int(value) % (1 << (8 * length))).to_bytes(length, "little")
    if kind is ValueKind.REAL and isinstance(value, (int, float)) and not isinstance(value, bool):
        return struct.pack("<f" if length == 4 else "<d", float(value))
    if kind is ValueKind.TIME and isinstance(value, TimeValue):
        return (value.ms & 0x0FFFFFFF).to_bytes(4, "little") + (value.days & 0xFFFF).to_bytes(2, "little")
    held = _text_bytes(dtype, value)
    if held is not None and kind in (ValueKind.STRING, ValueKind.UNICODE, ValueKind.OCTETS):
        return held[:length].ljust(length, b"\0")
    return None


def _attributes(dtype: DataType, var: Variable, info: CanopenNodeInfo | None) -> Attributes:
    access = var.access
    sdo = sdo_directions(access.value if access else None)
    pdo = pdo_directions(var.pdo_mapping_kind(), access.value if access else None)
    srdo = SRDO_DIRECTIONS.get(info.access_srdo.value if info and info.access_srdo else "", "")
    multibyte = dtype.is_numeric and dtype.bits in (16, 32, 64)
    return _shared_attributes(sdo, pdo, srdo, multibyte, dtype.kind in (ValueKind.STRING, ValueKind.UNICODE))


@functools.cache
def _shared_attributes(sdo: str, pdo: str, srdo: str, multibyte: bool, string: bool) -> Attributes:
    # A few dozen combinations exist; entries share them instead of one record each.
    return Attributes(sdo, pdo, srdo, multibyte, string)


# --- the view --------------------------------------------------------------------------------


class _Builder:
    def __init__(self, device: Device, explain: bool) -> None:
        self.device = device
        self.explain = explain
        self.inferences: list[Inference] = []
        self.defaults: dict[bytes, bytes] = {}  # equal initial values, mostly zeros, held once
        # A CANopenEditor project (its CO_* properties, ;StorageLocation=) omits the storage group where it is RAM.
        self.editor_project = device.dialect is Dialect.CANOPENNODE

    def note(self, where: str, text: str) -> None:
        # Only --explain reads them; a note per object would be a large part of a large file's view.
        if self.explain:
            self.inferences.append(Inference(where, text))

    def entry(self, obj: Object, subindex: int, var: Variable, member: str, length: int | None = None) -> NodeEntry:
        dtype = editor_entry_type(self.device, var, obj)
        assert dtype is not None, "the canopennode profile refuses entries without a type"
        info = var.canopennode
        value = var.held
        where = f"{obj.index:04X}" + (f"sub{subindex:X}" if obj.has_subs else "")
        if isinstance(value, NodeIdExpr):
            self.note(where, f"default {value.canonical()} stored as 0x{value.offset:X}: the stack adds the node-ID")
        value = self.as_editor_reads(where, dtype, value)
        size = length if length is not None else _length(dtype, value, info.string_length_min if info else None)
        held = value_bytes(dtype, value, size)
        textual = dtype.kind in (ValueKind.STRING, ValueKind.UNICODE, ValueKind.OCTETS)
        if held is None and size > 0 and not textual and stack_reads_at_init(obj.index):
            held = bytes(size)
            self.note(where, "no default value: 0, as CO_CANopenInit reads it from the OD")
        stored = entry_has_memory(size, held is not None, textual)
        if not stored and dtype.index != DOMAIN.index:
            self.note(where, "no default value: no memory in the OD, the application provides it (OD_extension_init)")
        default = held if held is not None else bytes(size)
        default = self.defaults.setdefault(default, default)
        return NodeEntry(subindex, var.name, member, dtype, _attributes(dtype, var, info), size, stored, default)

    def as_editor_reads(self, where: str, dtype: DataType, value: Value | None) -> Value | None:
        """Defaults CiA 306 leaves unreadable but CANopenEditor reads (short hex octets, C float literals);
        DOMAIN defaults ignored."""
        if dtype.index == DOMAIN.index and value is not None:
            self.note(where, "DOMAIN default ignored: no memory in the OD, the application streams the data "
                             "(OD_extension_init), as in CANopenEditor")  # fmt: skip
            return None
        if dtype.kind is ValueKind.OCTETS and isinstance(value, RawValue):
            octets = editor_octets(value.text)
            if octets is not None:
                self.note(where, f"default {value.text!r} read as the bytes {octets.hex(' ')}, as CANopenEditor does")
                return octets
        if dtype.kind in (ValueKind.UNSIGNED, ValueKind.SIGNED) and isinstance(value, RawValue):
            number = editor_integer(value.text)
            if number is not None:
                self.note(where, f"default {value.text!r} read as {number} of the ARRAY's type, as CANopenEditor does")
                return number
        if dtype.kind is ValueKind.REAL and isinstance(value, RawValue):
            real = editor_real(value.text)
            if real is not None:
                self.note(where, f"default {value.text!r} read as {real!r}, the C literal CANopenEditor copies")
                return real
        return value

    def one_array(self, obj: Object, entries: tuple[NodeEntry, ...]) -> tuple[NodeEntry, ...]:
        """An ARRAY's elements are one C array: all have memory or none, as the first element decides (CANopenEditor
        reads the first element's default for the whole array). Elements that disagree are 0, or lose their default."""
        sub0, elements = entries[0], entries[1:]
        stored = array_has_memory([e.stored for e in elements])
        for e in elements[1:]:
            if e.stored != stored:
                where = f"{obj.index:04X}sub{e.subindex:X}"
                self.note(where, "no default value: 0, as the ARRAY's first element has one" if stored else
                                 "default ignored: the ARRAY's first element has none, so the ARRAY has no memory "
                                 "(OD_extension_init), as in CANopenEditor")  # fmt: skip
        return (sub0, *(e if e.stored == stored else replace(e, stored=stored) for e in elements))

    def settings(self, obj: Object) -> tuple[str, str | None]:
        info = obj.canopennode or CanopenNodeInfo.model_construct()
        where = f"{obj.index:04X}h"
        group = info.storage_group
        if not group and self.editor_project:
            group = RAM
            self.note(where, f"storage group {group}: a CANopenEditor project leaves it unsaid where it is RAM")
        elif not group:
            group = standard_storage_group(obj.index)
            self.note(where, f"storage group {group} inferred from the index")
        label = count_label_for(obj.index, obj.canopennode)
        if info.count_label is None and label is not None:
            self.note(where, f"count label {label} inferred from the index ({count_macro(label)})")
        return group, label

    def build(self, obj: Object) -> NodeObject:
        kind = _KINDS[obj.kind]
        group, label = self.settings(obj)
        if kind == VAR:
            entries: tuple[NodeEntry, ...] = (self.entry(obj, 0, obj, ""),)
        else:
            subs = sorted(obj.subs.items())
            members = _member_names(subs)
            length = None
            if kind == ARR:  # one element size for the whole array: the longest element's
                lengths = [self.entry(obj, n, v, "").length for n, v in subs[1:]]
                length = max(lengths, default=0)
            entries = tuple(self.entry(obj, n, v, members[n], length if n > 0 else None) for n, v in subs if n >= 0)
            if kind == ARR:
                entries = self.one_array(obj, entries)
        return NodeObject(obj.index, obj.name, c_name(obj.name) or "object", kind, group, label, entries)


def keep_editor_pdo_bits(device: Device) -> list[str]:
    """Give every entry CANopenEditor's ODA_*PDO bits (`pdo_attributes = "canopeneditor"`); lines for --explain."""
    lines = []
    for obj in generated_objects(device):
        for subindex, var in sorted(obj.subs.items()) if obj.has_subs else [(0, obj)]:
            ours, its = pdo_bits_pair(var)
            if ours != its:
                var.state_pdo_mapping(editor_pdo_word(var.stated_pdo_mapping, var.pdo_mapping))
                where = f"{obj.index:04X}" + (f"sub{subindex:X}" if obj.has_subs else "")
                text = f"{pdo_attribute_text(its)} as CANopenEditor writes it, not {pdo_attribute_text(ours)}"
                lines.append(f"{where}: {text} (pdo_attributes)")
    return lines


def generated_objects(device: Device) -> list[Object]:
    """The objects that go into the OD: VAR, DOMAIN, ARRAY and RECORD objects not disabled."""
    return [  # by index, whatever the file's order: OD_find searches the list by bisection
        obj for _, obj in sorted(device.objects.items()) if obj.kind in _KINDS and not obj.left_out
    ]


def build_node_view(device: Device, name: str = "OD", source: str = "", explain: bool = False) -> NodeView:
    """The CANopenNode view of a device the canopennode lint profile accepts; with `explain`, the
    settings that were inferred rather than given are listed in its `inferences`."""
    builder = _Builder(device, explain)
    objects = tuple(builder.build(obj) for obj in generated_objects(device))
    # Only one array element length is noted per object, and each entry once.
    inferences = tuple(dict.fromkeys(builder.inferences))
    counts: dict[str, int] = {}
    for obj in objects:
        if obj.count_label:
            counts[obj.count_label] = counts.get(obj.count_label, 0) + 1
    return NodeView(name, source, objects, inferences, tuple(counts.items()))
