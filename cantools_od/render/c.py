"""The C target: NAME.h and NAME.c from a DeviceView (C99, usable from C++).

Naming (NAME is the --name identifier, PREFIX its upper case; FLAT, OBJECT and
MEMBER are identifiers from `cantools_od.identifiers`, upper-cased for macros):

- Per object: ``PREFIX_<OBJECT>_INDEX``.
- Per value-carrying entry (a VAR, or a sub-object under its flat identifier):
  ``PREFIX_<FLAT>_INDEX``, ``_SUBINDEX``, ``_DATA_TYPE``, ``_ACCESS``, ``_PDO_MAPPABLE``,
  ``_DEFAULT`` (a function-like macro ``_DEFAULT(node_id)`` for ``$NODEID`` values),
  ``_LOW_LIMIT``, ``_HIGH_LIMIT``, ``_LENGTH`` (strings). A constant the type cannot hold
  is left out with a comment saying why.
- Values: ``struct NAME_od`` holds every stored value; RECORD and ARRAY objects are
  ``struct NAME_od_<object>`` (an ARRAY whose elements share one type as
  ``<sub0 member>`` and ``values[n]``); ``NAME_init(od, node_id)`` fills in the defaults.
- ``struct NAME_object_info NAME_objects[PREFIX_OBJECT_COUNT]``: every entry's index,
  sub-index, access, data type, mappability, bits and place in ``struct NAME_od``.
- Per PDO with mapped objects: ``struct NAME_tpdoN`` (members: flat identifiers, ``_2``
  ... when mapped twice), ``NAME_tpdoN_pack``/``_unpack`` and
  ``NAME_tpdoN_<member>_is_in_range``; ``PREFIX_TPDON_DLC`` and ``PREFIX_TPDON_COB_ID``.

Every macro ends in a suffix that no other macro name can end in, and lower-case
names outside ``NAME_od_<object>`` do not contain an object identifier, so no two
generated names collide whatever the identifiers are.
"""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from dataclasses import dataclass

from ..model import AccessType, ObjectKind, ValueKind
from ..views.codegen import DeviceView, EntryView, ObjectView
from . import Each, stream_template, whole
from .c_pdo import CPdo, Helpers, c_pdos
from .c_types import Storage, constant, storage, utf16_units

ACCESS_CODES = {
    AccessType.RO: ("RO", 0x01),
    AccessType.WO: ("WO", 0x02),
    AccessType.RW: ("RW", 0x03),
    AccessType.RWR: ("RWR", 0x07),
    AccessType.RWW: ("RWW", 0x0B),
    AccessType.CONST: ("CONST", 0x11),
}
ARRAY_MEMBER = "values"


@dataclass(frozen=True)
class Macro:
    name: str
    value: str = ""  # C text
    params: str = ""  # "(node_id)"
    text: str | bytes | None = None  # a string from the file, for c_string
    comment: str = ""  # for c_comment after the definition
    omitted: str = ""  # for c_comment: why the macro is not defined


@dataclass(frozen=True)
class Block:
    title: str  # for c_comment
    macros: tuple[Macro, ...]


@dataclass(frozen=True)
class Member:
    ctype: str
    name: str
    suffix: str  # array dimensions
    comment: str  # for c_comment


@dataclass(frozen=True)
class Record:
    struct: str
    title: str
    members: tuple[Member, ...]


@dataclass(frozen=True)
class Row:
    index: int
    subindex: int
    access: str
    data_type: int
    mappable: bool
    bits: int
    offset: str
    size: str


@dataclass(frozen=True)
class Context:
    name: str
    prefix: str  # lower case, with the trailing underscore
    macro: str  # upper case, with the trailing underscore
    guard: str
    source: str
    vendor: str
    product: str
    node_id: int | None
    max_dlc: int
    access_codes: tuple[tuple[str, int], ...]
    blocks: Each[Block]
    records: Each[Record]
    od_members: Each[Member]
    init: Each[str]
    uses_node_id: bool
    rows: Each[Row]
    pdos: tuple[CPdo, ...]
    helpers: Helpers


@dataclass(frozen=True)
class Placed:
    """An object's storage: its struct (RECORD/ARRAY), its member of `struct NAME_od`, and where each
    entry's value is (`paths`, `held`), from which its lines of NAME_init and its rows of the object
    table follow."""

    entries: list[EntryView]
    held: dict[int, Storage | None]
    paths: dict[int, str]
    record: Record | None
    member: Member | None


class _Builder:
    def __init__(self, view: DeviceView) -> None:
        base = view.name.rstrip("_")
        self.prefix = base + "_"
        self.macro = base.upper() + "_"

    def blocks(self, obj: ObjectView) -> list[Block]:
        entries = sorted(obj.entries, key=lambda e: e.subindex)
        title = _title(obj)
        macros = [Macro(self._name(obj.identifier, "INDEX"), f"0x{obj.index:04X}u")]
        if obj.is_var:
            macros += [m for e in entries for m in self.entry_macros(e)]
            return [Block(title, tuple(macros))]
        blocks = [Block(title, tuple(macros))]
        for e in entries:
            head = Macro(self._name(e.flat, "INDEX"), f"0x{e.index:04X}u")
            where = f"{e.index:04X}sub{e.subindex:X} {e.name}"
            blocks.append(Block(where, (head, *self.entry_macros(e))))
        return blocks

    def _name(self, identifier: str, suffix: str) -> str:
        return f"{self.macro}{identifier.rstrip('_').upper()}_{suffix}"

    def _access(self, e: EntryView) -> str:
        return f"{self.macro}ACCESS_{ACCESS_CODES[e.access][0]}" if e.access else "0x00u"

    def entry_macros(self, e: EntryView) -> list[Macro]:
        dtype = e.data_type
        macros = [
            Macro(self._name(e.flat, "SUBINDEX"), f"0x{e.subindex:02X}u"),
            Macro(self._name(e.flat, "DATA_TYPE"), f"0x{dtype.index if dtype else 0:04X}u", comment=_type_name(e)),
            Macro(self._name(e.flat, "ACCESS"), self._access(e)),
            Macro(self._name(e.flat, "PDO_MAPPABLE"), "1" if e.pdo_mappable else "0"),
        ]
        kind = e.kind
        if kind in (ValueKind.STRING, ValueKind.OCTETS, ValueKind.UNICODE):
            held = storage(dtype, e.default)
            if held is not None:
                macros.append(Macro(self._name(e.flat, "LENGTH"), f"{held.length}u"))
            if isinstance(e.default, (str, bytes)) and kind is not ValueKind.UNICODE and held is not None:
                macros.append(Macro(self._name(e.flat, "DEFAULT"), text=e.default))
            return macros
        for suffix, value in (("DEFAULT", e.default), ("LOW_LIMIT", e.low_limit), ("HIGH_LIMIT", e.high_limit)):
            if value is None:
                continue
            spelled = constant(dtype, value)
            name = self._name(e.flat, suffix)
            if spelled.text:
                macros.append(Macro(name, spelled.text, spelled.params))
            else:
                macros.append(Macro(name, omitted=f"{name} is not defined: {spelled.reason}"))
        return macros

    def place(self, obj: ObjectView) -> Placed:
        """Storage in `struct NAME_od`."""
        entries = sorted(obj.entries, key=lambda e: e.subindex)
        title = _title(obj)
        held = {e.subindex: storage(e.data_type, e.default) for e in entries}
        paths: dict[int, str] = {}
        record = member = None
        if obj.is_var:
            var = held.get(0)
            if var is not None:
                member = Member(var.ctype, obj.identifier, var.suffix, title)
                paths[0] = obj.identifier
        else:
            members, paths = self._record(obj, entries, held)
            if members:
                struct = f"{self.prefix}od_{obj.identifier}"
                record = Record(struct, title, tuple(members))
                member = Member(f"struct {struct}", obj.identifier, "", title)
        return Placed(entries, held, paths, record, member)

    def init(self, placed: Placed) -> Iterator[str]:
        """The object's lines of NAME_init: its defaults."""
        for e in placed.entries:
            path, place = placed.paths.get(e.subindex), placed.held.get(e.subindex)
            if path is not None and place is not None:
                yield from self._init(e, path, place)

    def rows(self, placed: Placed) -> Iterator[Row]:
        """The object's rows of the object table."""
        for e in placed.entries:
            path, place = placed.paths.get(e.subindex), placed.held.get(e.subindex)
            yield Row(
                index=e.index,
                subindex=e.subindex,
                access=self._access(e),
                data_type=e.data_type.index if e.data_type else 0,
                mappable=e.pdo_mappable,
                bits=place.bits if place is not None else (e.bits or 0),
                offset=f"offsetof(struct {self.prefix}od, {path})" if path else "0u",
                size=place.sizeof if path and place else "0u",
            )

    def _record(
        self, obj: ObjectView, entries: list[EntryView], held: dict[int, Storage | None]
    ) -> tuple[list[Member], dict[int, str]]:
        def where(e: EntryView) -> str:
            return f"{e.index:04X}sub{e.subindex:X} {e.name}"

        subs = [e.subindex for e in entries]
        elements = {held[s] for s in subs[1:]}
        first = entries[0] if entries else None
        if (
            obj.kind is ObjectKind.ARRAY
            and len(subs) > 1
            and subs == list(range(len(subs)))
            and len(elements) == 1
            and None not in elements
            and held[0] is not None
            and first is not None
            and first.member != ARRAY_MEMBER
        ):
            element = held[1]
            sub0 = held[0]
            assert element is not None and sub0 is not None and first.member is not None
            members = [
                Member(sub0.ctype, first.member, sub0.suffix, where(first)),
                Member(
                    element.ctype, ARRAY_MEMBER, f"[{len(subs) - 1}]{element.suffix}", f"sub-indices 1-{len(subs) - 1}"
                ),
            ]
            paths = {0: f"{obj.identifier}.{first.member}"}
            paths |= {s: f"{obj.identifier}.{ARRAY_MEMBER}[{s - 1}]" for s in subs[1:]}
            return members, paths
        members, paths = [], {}
        for e in entries:
            place = held[e.subindex]
            if place is not None and e.member is not None:
                members.append(Member(place.ctype, e.member, place.suffix, where(e)))
                paths[e.subindex] = f"{obj.identifier}.{e.member}"
        return members, paths

    def _init(self, e: EntryView, path: str, place: Storage) -> list[str]:
        if e.default is None:
            return []
        if e.kind is ValueKind.UNICODE and isinstance(e.default, str):
            return [f"od->{path}[{i}] = 0x{unit:04X}u;" for i, unit in enumerate(utf16_units(e.default))]
        if isinstance(e.default, (str, bytes)):
            if not place.bits:
                return []
            return [f"memcpy(od->{path}, {self._name(e.flat, 'DEFAULT')}, {self._name(e.flat, 'LENGTH')});"]
        spelled = constant(e.data_type, e.default)
        if not spelled.text:
            return []
        return [f"od->{path} = {self._name(e.flat, 'DEFAULT')}{'(node_id)' if spelled.params else ''};"]


def _type_name(e: EntryView) -> str:
    return e.data_type.name if e.data_type else "unknown data type"


def _title(obj: ObjectView) -> str:
    return f"{obj.index:04X} {obj.name} ({obj.kind.name})"


def context(view: DeviceView) -> Context:
    """What the templates lay out; the per-object parts are made as the templates read them."""
    builder = _Builder(view)
    objects = sorted(view.objects, key=lambda o: o.index)

    def placed() -> Iterator[Placed]:
        return (builder.place(obj) for obj in objects)

    init = Each(lambda: (line for p in placed() for line in builder.init(p)))
    pdos, helpers = c_pdos(view, builder.prefix, builder.macro)
    info = view.device.device_info
    return Context(
        name=view.name,
        prefix=builder.prefix,
        macro=builder.macro,
        guard=f"{builder.macro}H",
        source=view.source_name,
        vendor=info.vendor_name or "",
        product=info.product_name or "",
        node_id=view.node_id,
        max_dlc=(view.max_pdo_bits + 7) // 8,
        access_codes=tuple(ACCESS_CODES.values()),
        blocks=Each(lambda: (block for obj in objects for block in builder.blocks(obj))),
        records=Each(lambda: (p.record for p in placed() if p.record is not None)),
        od_members=Each(lambda: (p.member for p in placed() if p.member is not None)),
        init=init,
        uses_node_id=any("(node_id)" in line for line in init),
        rows=Each(lambda: (row for p in placed() for row in builder.rows(p)), sum(obj.entry_count for obj in objects)),
        pdos=tuple(pdos),
        helpers=helpers,
    )


def stream(view: DeviceView) -> dict[str, Iterable[str]]:
    """NAME.h and NAME.c, rendered as they are read."""
    ctx = context(view)
    return {
        f"{view.name}.h": stream_template("c/header.h.j2", c=ctx),
        f"{view.name}.c": stream_template("c/source.c.j2", c=ctx),
    }


def render(view: DeviceView) -> dict[str, str]:
    """NAME.h and NAME.c."""
    return whole(stream(view))
