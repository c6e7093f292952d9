"""PDOs for the Rust target: a struct per PDO with `pack`/`unpack` over its bit layout.

Entries are packed from bit 0 of byte 0 in mapping order, each value little-endian (CiA 301
PDO mapping); any offset and length work. Dummy entries have no field and are sent as zeros.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..model import NodeIdExpr
from ..model.datatypes import UNSIGNED32
from ..views.codegen import DeviceView, PdoView
from .rust_layout import struct_body
from .rust_names import camel, unique_fields
from .rust_types import int_literal, node_expr, rust_type


@dataclass(frozen=True)
class RustPdoField:
    name: str  # the struct field
    ty: str
    offset: int
    bits: int
    index: int
    subindex: int
    title: str  # ParameterName of the mapped entry


@dataclass(frozen=True)
class RustDummy:
    offset: int
    bits: int
    type_name: str


@dataclass(frozen=True)
class RustPdo:
    view: PdoView
    name: str  # Tpdo1
    label: str  # TPDO1
    func: str  # tpdo1
    fields: list[RustPdoField]
    dummies: list[RustDummy]
    cob_id: str | None  # COB-ID literal when it is known
    cob_id_node: str | None  # COB-ID as an expression of node_id for `$NODEID` values
    transmission_type: str  # Some(255) or None

    @property
    def bits(self) -> int:
        return self.view.pdo.bit_length

    @property
    def length(self) -> int:
        return self.view.byte_length

    @property
    def body(self) -> str | None:
        """The fields of `unpack`'s struct expression on one line, when rustfmt puts them there."""
        return struct_body([(f.name, f"get(src, {f.offset}, {f.bits})") for f in self.fields])

    frame: int  # bytes of the largest frame the mapping was checked against: 8, or 64 with CAN FD


def _pdo(view: DeviceView, pdo: PdoView, node_id: int | None) -> RustPdo:
    fields: list[RustPdoField] = []
    dummies: list[RustDummy] = []
    mapped = [e for e in pdo.entries if e.entry is not None]
    names = unique_fields([e.entry.flat for e in mapped if e.entry is not None])
    for name, entry in zip(names, mapped, strict=True):
        target = entry.entry
        ty = rust_type(entry.data_type)
        assert target is not None and ty is not None, "build_view reports PDO entries without a fixed size"
        fields.append(
            RustPdoField(name, ty, entry.bit_offset, entry.bit_length, target.index, target.subindex, target.name)
        )
    for entry in pdo.entries:
        if entry.entry is None:
            type_name = entry.data_type.name if entry.data_type is not None else "dummy"
            dummies.append(RustDummy(entry.bit_offset, entry.bit_length, type_name))
    cob = view.entry(pdo.pdo.comm_index, 1)
    raw = cob.default if cob is not None else pdo.pdo.cob_id
    node = node_expr("u32", raw.offset) if isinstance(raw, NodeIdExpr) else None
    value = raw.resolve(node_id) if isinstance(raw, NodeIdExpr) and node_id is not None else raw
    literal = int_literal(value, UNSIGNED32) if isinstance(value, int) else None
    transmission = pdo.pdo.transmission_type
    return RustPdo(
        view=pdo,
        name=camel(pdo.struct_name),
        label=pdo.pdo.name,
        func=pdo.struct_name,
        fields=fields,
        dummies=dummies,
        cob_id=literal,
        cob_id_node=node,
        transmission_type=f"Some({transmission})" if transmission is not None and 0 <= transmission <= 255 else "None",
        frame=view.max_pdo_bits // 8,
    )


def pdos(view: DeviceView, node_id: int | None) -> list[RustPdo]:
    """The PDOs of the view, RPDOs first."""
    return [_pdo(view, pdo, node_id) for pdo in view.pdos]
