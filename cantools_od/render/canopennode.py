"""The canopennode target: CANopenNode v4 `NAME.h`/`NAME.c` (default `OD`) from a NodeView.

Symbols carry the name as prefix, as the stack expects (`OD_CNT_NMT`, `OD_ENTRY_H1017`,
`OD_RAM`, `OD_PERSIST_COMM_t`, `OD_ATTR_RAM`, `OD_INIT_CONFIG`, `OD_t *OD`); a second object
dictionary named `OD1` gets `OD1_...`, for `CO_MULTIPLE_OD`. Variables inside the storage
groups are named `x<INDEX>_<name>` with CANopenEditor's spelling of the display name, so
application code written against CANopenEditor's files keeps compiling.
"""

from __future__ import annotations

import math
import struct
from collections.abc import Iterable
from dataclasses import dataclass, replace

from ..canopennode.profile import (
    CONFIG_ARRAYS,
    CONFIG_COUNTS,
    CONFIG_ENTRIES,
    OBJECT_TYPES,
    attribute_names,
)
from ..model import ValueKind
from ..views.canopennode import ARR, REC, VAR, NodeEntry, NodeObject, NodeView, build_node_view
from ..views.codegen import DeviceView
from . import Each, stream_template, whole

Fields = tuple[tuple[str, str], ...]  # (field, C value) pairs of one OD_obj_*_t
Described = tuple[tuple["Stored", ...], tuple[Fields, ...]]

_INTEGER_TYPES = {1: "int8_t", 2: "int16_t", 4: "int32_t", 8: "int64_t"}


@dataclass(frozen=True)
class Stored:
    """One variable in a storage-group struct."""

    ctype: str
    name: str
    dims: str  # "[4]", "[OD_CNT_ARR_1010][5]"
    init: str  # C initializer


@dataclass(frozen=True)
class CObject:
    index: str  # 4 hex digits
    name: str  # x1000_deviceType
    c_name: str
    kind: str
    group: str
    sub_count: int
    odt: str
    od_type: str
    record: bool
    stored: tuple[Stored, ...]  # a RECORD's members, else the variable(s) of the object
    descriptors: tuple[Fields, ...]  # one per OD_obj_*_t


@dataclass(frozen=True)
class Group:
    name: str
    objects: Each[CObject]


@dataclass(frozen=True)
class Context:
    name: str
    guard: str
    source: str
    counts: tuple[tuple[str, int], ...]
    arrays: tuple[tuple[str, int], ...]
    groups: tuple[Group, ...]
    objects: Each[CObject]
    config: tuple[tuple[str, str], ...]
    needs_math: bool


def ctype(entry: NodeEntry) -> tuple[str, str]:
    """The C type of an entry's memory and the array dimension after the name ('' for scalars)."""
    kind = entry.data_type.kind
    if kind is ValueKind.BOOL:
        return "bool_t", ""
    if kind is ValueKind.REAL:
        return ("float32_t" if entry.length == 4 else "float64_t"), ""
    if kind in (ValueKind.UNSIGNED, ValueKind.SIGNED) and entry.length in _INTEGER_TYPES:
        signed = _INTEGER_TYPES[entry.length]
        return (signed if kind is ValueKind.SIGNED else "u" + signed), ""
    if kind is ValueKind.STRING:
        return "char", f"[{entry.length + 1}]"
    if kind is ValueKind.UNICODE:
        return "uint16_t", f"[{entry.length // 2 + 1}]"
    return "uint8_t", f"[{entry.length}]"  # OCTET_STRING, 24/40/48/56-bit integers, TIME types


def _char(byte: int) -> str:
    if byte == 0:
        return "0"
    if 0x20 <= byte < 0x7F and chr(byte) not in "'\\":
        return f"'{chr(byte)}'"
    return f"(char)0x{byte:02X}"


def _real(value: float, single: bool) -> str:
    if math.isnan(value):
        return "NAN"
    if math.isinf(value):
        return "INFINITY" if value > 0 else "-INFINITY"
    text = repr(value)
    if "e" not in text and "." not in text and "inf" not in text:
        text += ".0"
    return text + ("f" if single else "")


def initializer(entry: NodeEntry) -> str:
    """The C initializer of an entry's memory, from its default bytes."""
    data, kind = entry.default, entry.data_type.kind
    if kind is ValueKind.BOOL:
        return "true" if data[0] else "false"
    if kind is ValueKind.REAL:
        return _real(struct.unpack("<f" if entry.length == 4 else "<d", data)[0], entry.length == 4)
    if kind in (ValueKind.UNSIGNED, ValueKind.SIGNED) and entry.length in _INTEGER_TYPES:
        return _integer(data, kind is ValueKind.SIGNED)
    if kind is ValueKind.STRING:
        return "{" + ", ".join([*(_char(b) for b in data), "0"]) + "}"
    if kind is ValueKind.UNICODE:
        units = [int.from_bytes(data[n : n + 2], "little") for n in range(0, len(data), 2)]
        return "{" + ", ".join([*(f"0x{u:04X}" for u in units), "0"]) + "}"
    return "{" + ", ".join(f"0x{b:02X}" for b in data) + "}"


def _integer(data: bytes, signed: bool) -> str:
    number = int.from_bytes(data, "little", signed=signed)
    suffix = "LL" if len(data) == 8 else ""
    if not signed:
        return f"0x{number:0{2 * len(data)}X}" + ("U" + suffix if suffix or len(data) == 4 else "")
    if number == -(1 << (8 * len(data) - 1)) and len(data) >= 4:  # the most negative value has no literal
        return f"({number + 1}{suffix} - 1)"
    return f"{number}{suffix}"


def attribute(entry: NodeEntry) -> str:
    a = entry.attributes
    return " | ".join(attribute_names(a.sdo, a.pdo, a.srdo, a.multibyte, a.string)) or "0"


class _Builder:
    def __init__(self, view: NodeView) -> None:
        self.p = view.name

    def c_object(self, obj: NodeObject) -> CObject:
        name = f"x{obj.index:04X}_{obj.c_name}"
        where = f"&{self.p}_{obj.group}.{name}"
        if obj.kind == VAR:
            stored, descriptors = self.var(obj.entries[0], name, where)
        elif obj.kind == ARR:
            stored, descriptors = self.array(obj, name, where)
        else:
            stored, descriptors = self.record(obj, where)
        odt, od_type = OBJECT_TYPES[obj.kind]
        return CObject(f"{obj.index:04X}", name, obj.c_name, obj.kind, obj.group, len(obj.entries), odt, od_type,
                       obj.kind == REC, stored, descriptors)  # fmt: skip

    def var(self, e: NodeEntry, name: str, where: str) -> Described:
        c, dims = ctype(e)
        stored = (Stored(c, name, dims, initializer(e)),) if e.stored else ()
        data = (where + ("[0]" if dims else "")) if e.stored else "NULL"
        return stored, ((("dataOrig", data), ("attribute", attribute(e)), ("dataLength", str(e.length))),)

    def array(self, obj: NodeObject, name: str, where: str) -> Described:
        sub0, elements = obj.entries[0], obj.elements
        first = elements[0]
        c, dims = ctype(first)
        stored: list[Stored] = []
        if sub0.stored:
            stored.append(Stored("uint8_t", f"{name}_sub0", "", initializer(sub0)))
        held = first.stored  # the view gives all elements memory or none
        if held:
            inits = [initializer(replace(e, data_type=first.data_type)) for e in elements]
            stored.append(Stored(c, name, f"[{self.p}_CNT_ARR_{obj.index:04X}]{dims}", "{" + ", ".join(inits) + "}"))
        descriptor = (
            ("dataOrig0", f"{where}_sub0" if sub0.stored else "NULL"),
            ("dataOrig", f"{where}[0]" + ("[0]" if dims else "") if held else "NULL"),
            ("attribute0", attribute(sub0)),
            ("attribute", attribute(first)),
            ("dataElementLength", str(first.length)),
            ("dataElementSizeof", f"sizeof({c}{dims})"),
        )
        return tuple(stored), (descriptor,)

    def record(self, obj: NodeObject, where: str) -> Described:
        stored: list[Stored] = []
        descriptors = []
        for e in obj.entries:
            c, dims = ctype(e)
            if e.stored:
                stored.append(Stored(c, e.member, dims, initializer(e)))
            data = f"{where}.{e.member}" + ("[0]" if dims else "") if e.stored else "NULL"
            fields = (("dataOrig", data), ("subIndex", str(e.subindex)), ("attribute", attribute(e)))
            descriptors.append((*fields, ("dataLength", str(e.length))))
        return tuple(stored), tuple(descriptors)


def _in_group(view: NodeView, builder: _Builder, group: str) -> Each[CObject]:
    return Each(lambda: (builder.c_object(o) for o in view.objects if o.stored and o.group == group))


def context(view: NodeView) -> Context:
    """What the templates lay out; the objects' C forms are made as the templates read them, not all held."""
    builder = _Builder(view)
    objects = Each(lambda: (builder.c_object(o) for o in view.objects), len(view.objects))
    groups = tuple(Group(g, _in_group(view, builder, g)) for g in view.groups)
    # Only an object with a REAL entry can have a NAN or INFINITY initializer.
    real = (builder.c_object(o) for o in view.objects if any(e.data_type.kind is ValueKind.REAL for e in o.entries))
    p = view.name
    present = {o.index for o in view.objects}
    counts = dict(view.counts)
    config = [(f"CNT_{label}", f"{p}_CNT_{label}" if label in counts else "0") for label in CONFIG_COUNTS]
    config += [(f"CNT_ARR_{i:04X}", f"{p}_CNT_ARR_{i:04X}" if _is_array(view, i) else "0") for i in CONFIG_ARRAYS]
    config += [(f"ENTRY_H{i:04X}", f"{p}_ENTRY_H{i:04X}" if i in present else "NULL") for i in CONFIG_ENTRIES]
    needs_math = any("NAN" in s.init or "INFINITY" in s.init for o in real for s in o.stored)
    return Context(
        name=p,
        guard=f"{p.upper()}_H",
        source=view.source,
        counts=view.counts,
        arrays=tuple((f"{o.index:04X}", len(o.entries) - 1) for o in view.arrays),
        groups=groups,
        objects=objects,
        config=tuple(config),
        needs_math=needs_math,
    )


def _is_array(view: NodeView, index: int) -> bool:
    return any(o.index == index for o in view.arrays)


def stream_node_view(view: NodeView) -> dict[str, Iterable[str]]:
    ctx = context(view)
    return {
        f"{view.name}.h": stream_template("canopennode/OD.h.j2", ctx=ctx),
        f"{view.name}.c": stream_template("canopennode/OD.c.j2", ctx=ctx),
    }


def render_node_view(view: NodeView) -> dict[str, str]:
    return whole(stream_node_view(view))


def stream(view: DeviceView) -> dict[str, Iterable[str]]:
    """`gen -t canopennode`, rendered as it is read: the device must have passed the canopennode lint profile."""
    return stream_node_view(build_node_view(view.device, view.name, view.source_name))


def render(view: DeviceView) -> dict[str, str]:
    """`gen -t canopennode`: the device must have passed the canopennode lint profile."""
    return whole(stream(view))
