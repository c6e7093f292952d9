"""Markdown reference documents: `<name>.md`, from a DeviceView.

The document is CommonMark with GFM tables and no raw HTML. Every text taken from the file goes
through `escape.markdown_text`/`markdown_cell` and renders literally; everything else in it is made
here from numbers, identifiers and fixed words.

Anchors: each object's section is headed ``Object XXXXh: <name>`` (upper-case hex index), whose GFM
anchor is ``#object-xxxxh-<name as GitHub spells it in an anchor>``, made here the way GitHub makes it so
that every link in the document reaches its heading; each PDO's section is headed with its name
(``#rpdo1``, ``#tpdo1``). The title, ``Object dictionary: <product>``, has the anchor
``object-dictionary-...`` and so cannot take one of the others.
"""

from __future__ import annotations

import unicodedata
from collections.abc import Iterable
from pathlib import Path

from ..model import DataType, Device, NodeIdExpr, Object, ObjectKind, RawValue, TimeValue, ValueKind, Variable
from ..model.datatypes import standard_type
from ..views.codegen import DeviceView, EntryView, ObjectView, PdoView
from . import Each, stream_template, whole
from .escape import markdown_cell, markdown_plain, markdown_text
from .prose import count

NONE = "\u2014"
VALID_BIT = 0x80000000


def stream(view: DeviceView) -> dict[str, Iterable[str]]:
    """`<name>.md`, rendered as it is read."""
    return {f"{view.name}.md": stream_template("markdown/reference.md.j2", d=_document(view))}


def render(view: DeviceView) -> dict[str, str]:
    return whole(stream(view))


def heading(index: int, name: str) -> str:
    """The text of an object's section heading (Markdown)."""
    shown = markdown_text(name)
    return f"Object {index:04X}h: {shown}" if shown else f"Object {index:04X}h"


def anchor(index: int, name: str) -> str:
    """GitHub's anchor of the heading: lower case; letters, digits, marks, `_` and `-` kept; blanks to `-`."""
    text = f"Object {index:04X}h: {markdown_plain(name)}".lower()
    return "".join("-" if c in " -" else c for c in text if c in " -_" or unicodedata.category(c)[0] in "LNM")


def _anchors(view: DeviceView) -> dict[int, str]:
    return {obj.index: anchor(obj.index, obj.name) for obj in view.objects}


def link(index: int, anchors: dict[int, str]) -> str:
    """A link to the object when the document has its section, else its index marked absent."""
    target = anchors.get(index)
    return f"[{index:04X}h](#{target})" if target is not None else f"{index:04X}h (absent)"


def _source(view: DeviceView) -> str:
    return view.source_name or f"{view.name}.eds"


TYPE_KINDS = (ObjectKind.NULL, ObjectKind.DEFTYPE)
"""The objects the code views leave out (they define types, hold no data): listed in their own table."""


def _type_row(view: DeviceView, obj: Object) -> list[str]:
    """Index, name, kind, the type of its value, the value (for a DEFTYPE: the type's size in bits), source."""
    known = standard_type(obj.data_type)
    type_name = known.name if known is not None else NONE
    if known is None and obj.data_type is not None:
        type_name = f"0x{obj.data_type:04X} (unknown)"
    value = NONE if obj.default is None else _number(obj.default, known)
    if obj.kind is ObjectKind.DEFTYPE and isinstance(obj.default, int):
        value = f"{obj.default} bits"
    where = f"{_source(view)}:{obj.origin.line}" if obj.origin is not None and obj.origin.line else ""
    name = markdown_cell(obj.name) or NONE
    return [f"{obj.index:04X}h", name, obj.kind.name, type_name, value, markdown_text(where) or NONE]


def _document(view: DeviceView) -> dict[str, object]:
    device = view.device
    mapped = _mapped(view)
    anchors = _anchors(view)
    return {
        "title": markdown_text(device.device_info.product_name or view.name) or markdown_text(view.name),
        "source": markdown_text(_source(view)),
        "summary": _summary(view),
        "pdos": [_pdo(pdo, anchors) for pdo in view.pdos],
        "pdo_rows": [_pdo_row(pdo, anchors) for pdo in view.pdos],
        "types": [_type_row(view, obj) for obj in view.device.objects.values() if obj.kind in TYPE_KINDS],
        # One object at a time, as the template reads them: a large device's rows are not all held.
        "object_rows": Each(lambda: (_object_row(view, obj, mapped, anchors) for obj in view.objects)),
        "objects": Each(lambda: (_object(view, obj, mapped) for obj in view.objects)),
    }


def _summary(view: DeviceView) -> list[list[str]]:
    device = view.device
    info, file_info = device.device_info, device.file_info
    nid = view.node_id
    rates = [f"{rate}" for rate, on in sorted(info.baud_rates.items()) if on]
    rows = [
        ("File", markdown_cell(_source(view))),
        ("FileName", markdown_cell(file_info.file_name or "")),
        ("Description", markdown_cell(file_info.description or "")),
        ("Vendor", _named(info.vendor_name, info.vendor_number)),
        ("Product", _named(info.product_name, info.product_number)),
        ("Revision number", _hex32(info.revision_number)),
        ("Order code", markdown_cell(info.order_code or "")),
        ("File version", _version(file_info.file_version, file_info.file_revision)),
        ("EDS version", markdown_cell(file_info.eds_version or "")),
        ("Kind", "DCF" if device.is_dcf else "EDS"),
        ("Node-ID", str(nid) if nid is not None else "not given: COB-IDs are shown as `$NODEID+offset`"),
        ("Baud rates", f"{', '.join(rates)} kbit/s" if rates else NONE),
        ("Objects", str(len(view.objects))),
    ]
    return [[name, value] for name, value in rows]


def _named(name: str | None, number: int | None) -> str:
    parts = [markdown_text(name)] if name else []
    if number is not None:
        parts.append(f"({_hex32(number)})" if parts else _hex32(number))
    return " ".join(parts) or NONE


def _hex32(number: int | None) -> str:
    return NONE if number is None else f"0x{number:08X}"


def _version(version: int | None, revision: int | None) -> str:
    if version is None and revision is None:
        return NONE
    return f"{version if version is not None else '?'}.{revision if revision is not None else '?'}"


# --- PDOs ---------------------------------------------------------------------------------------------------


def _cob_id(pdo: PdoView) -> str:
    cob = pdo.pdo.cob_id
    if cob is None:
        return NONE
    value = cob.offset if isinstance(cob, NodeIdExpr) else cob
    text = f"`{cob.canonical()}`" if isinstance(cob, NodeIdExpr) else f"`0x{cob:X}`"
    return text + (" (not valid)" if value & VALID_BIT else "")


def _pdo_row(pdo: PdoView, anchors: dict[int, str]) -> list[str]:
    p = pdo.pdo
    return [
        f"[{p.name}](#{pdo.struct_name})",
        _cob_id(pdo),
        str(p.transmission_type) if p.transmission_type is not None else NONE,
        link(p.comm_index, anchors),
        link(p.map_index, anchors),
        str(p.bit_length),
        str(len(p.entries)),
    ]


def _pdo(pdo: PdoView, anchors: dict[int, str]) -> dict[str, object]:
    p = pdo.pdo
    transmission = f"transmission type {p.transmission_type}" if p.transmission_type is not None else "no type"
    summary = (
        f"COB-ID {_cob_id(pdo)}, {transmission}, {count(p.bit_length, 'bit')} ({count(pdo.byte_length, 'byte')}). "
        f"Communication parameters {link(p.comm_index, anchors)}, mapping {link(p.map_index, anchors)}."
    )
    entries: list[list[str]] = []
    for number, entry in enumerate(pdo.entries, 1):
        last = entry.bit_offset + entry.bit_length - 1
        type_name = entry.data_type.name if entry.data_type else "unknown"
        if entry.entry is None:
            entries.append([str(number), f"{entry.bit_offset}..{last}", str(entry.bit_length), NONE, "dummy"])
            entries[-1] += [type_name, NONE]
            continue
        target = entry.entry
        where = link(target.index, anchors) + (f" sub {target.subindex:X}h" if target.member is not None else "")
        entries.append([str(number), f"{entry.bit_offset}..{last}", str(entry.bit_length), where])
        entries[-1] += [markdown_cell(target.name), type_name, f"`{target.flat}`"]
    return {
        "name": p.name,
        "anchor": pdo.struct_name,
        "summary": summary,
        "entries": entries,
        "grid": _grid(pdo),
    }


def _grid(pdo: PdoView) -> list[list[str]]:
    owner: dict[int, int] = {}
    for number, entry in enumerate(pdo.entries, 1):
        for bit in range(entry.bit_offset, entry.bit_offset + entry.bit_length):
            owner[bit] = number
    rows: list[list[str]] = []
    for byte in range(pdo.byte_length):
        cells = [str(owner[bit]) if bit in owner else NONE for bit in range(byte * 8 + 7, byte * 8 - 1, -1)]
        rows.append([str(byte), *cells])
    return rows


def _mapped(view: DeviceView) -> dict[tuple[int, int], list[str]]:
    """(index, sub-index) → the PDOs that map it by default, as links."""
    found: dict[tuple[int, int], list[str]] = {}
    for pdo in view.pdos:
        for entry in pdo.fields:
            if entry.entry is not None:
                names = found.setdefault((entry.entry.index, entry.entry.subindex), [])
                name = f"[{pdo.pdo.name}](#{pdo.struct_name})"
                if name not in names:
                    names.append(name)
    return found


# --- objects ------------------------------------------------------------------------------------------------


def _variable(device: Device, entry: EntryView) -> tuple[Object, Variable]:
    obj = device.objects[entry.index]
    var = obj.entry(entry.subindex)
    return obj, var if var is not None else obj


def _type(device: Device, entry: EntryView) -> str:
    if entry.data_type is not None:
        return entry.data_type.name
    _, var = _variable(device, entry)
    return f"0x{var.data_type:04X} (unknown)" if var.data_type is not None else NONE


def _pdo_cell(entry: EntryView, mapped: dict[tuple[int, int], list[str]]) -> str:
    names = mapped.get((entry.index, entry.subindex))
    if names:
        return ", ".join(names)
    return "mappable" if entry.pdo_mappable else "no"


def _value(view: DeviceView, entry: EntryView) -> str:
    _, var = _variable(view.device, entry)
    value = var.held
    if value is None:
        return NONE
    if isinstance(value, RawValue):
        return markdown_text(value.text) + " (unreadable)"
    if isinstance(value, TimeValue):
        return f"{value.days} days {value.ms} ms"
    if isinstance(value, NodeIdExpr):
        nid = view.node_id
        text = markdown_text(value.canonical())
        return text if nid is None else f"0x{value.resolve(nid):X} ({text})"
    return _number(value, entry.data_type)


def _number(value: object, dtype: DataType | None) -> str:
    if dtype is not None and dtype.kind is ValueKind.BOOL and value in (0, 1):
        return "true" if value else "false"
    if isinstance(value, bool):
        return str(int(value))
    if isinstance(value, int):
        unsigned = dtype is not None and dtype.kind is ValueKind.UNSIGNED and (dtype.bits or 0) >= 32
        return f"0x{value:0{(dtype.bits or 32) // 4 if dtype else 8}X}" if unsigned and value > 9 else str(value)
    if isinstance(value, float):
        return markdown_text(repr(value))
    if isinstance(value, bytes):
        return " ".join(f"{byte:02X}" for byte in value) or '""'
    if isinstance(value, str):
        return f'"{markdown_text(value)}"'
    return markdown_cell(str(value))


def _limits(entry: EntryView) -> str:
    low, high = entry.low_limit, entry.high_limit
    if low is None and high is None:
        return NONE
    if low is None:
        return f"max {markdown_text(str(high))}"
    if high is None:
        return f"min {markdown_text(str(low))}"
    return f"{markdown_text(str(low))}..{markdown_text(str(high))}"


def _where(view: DeviceView, entry: EntryView) -> str:
    obj, var = _variable(view.device, entry)
    origin = var.origin or obj.origin
    if origin is None or not origin.line:
        return NONE
    # The origin names its own file: a model imported from a manual points into the manual.
    file = Path(origin.file).name if origin.file else _source(view)
    return markdown_text(f"{file}:{origin.line}") + (" (compact)" if entry.implicit else "")


def _object_row(
    view: DeviceView, obj: ObjectView, mapped: dict[tuple[int, int], list[str]], anchors: dict[int, str]
) -> list[str]:
    first = obj.entries[0] if obj.entries else None
    name = markdown_cell(obj.name)
    if obj.is_var and first is not None:
        cells = [_type(view.device, first), (first.access.value if first.access else NONE), _pdo_cell(first, mapped)]
        cells += [_value(view, first), _limits(first)]
        kind = obj.kind.name
    else:
        pdos = [name for e in obj.entries for name in mapped.get((e.index, e.subindex), [])]
        mappable = "mappable" if any(e.pdo_mappable for e in obj.entries) else "no"
        cells = [NONE, NONE, ", ".join(dict.fromkeys(pdos)) or mappable, NONE, NONE]
        kind = f"{obj.kind.name}, {count(len(obj.entries), 'sub-object')}"
    source = _where(view, first) if first is not None else NONE
    if not obj.is_var:
        header = view.device.objects[obj.index].origin
        source = markdown_text(f"{_source(view)}:{header.line}") if header is not None and header.line else NONE
    return [link(obj.index, anchors), name, kind, *cells, source]


def _object(view: DeviceView, obj: ObjectView, mapped: dict[tuple[int, int], list[str]]) -> dict[str, object]:
    header = view.device.objects[obj.index].origin
    where = f"{_source(view)}:{header.line}" if header is not None and header.line else ""
    kind = obj.kind.name if obj.is_var else f"{obj.kind.name} with {count(len(obj.entries), 'sub-object')}"
    summary = f"{markdown_text(obj.name) or NONE}: {kind}, identifier `{obj.identifier}`"
    summary += f", described at {markdown_text(where)}." if where else "."
    rows = []
    for entry in obj.entries:
        rows.append(
            [
                f"{entry.subindex:X}h",
                markdown_cell(entry.name),
                _type(view.device, entry),
                entry.access.value if entry.access else NONE,
                _pdo_cell(entry, mapped),
                _value(view, entry),
                _limits(entry),
                f"`{entry.flat}`",
                _where(view, entry),
            ]
        )
    return {"heading": heading(obj.index, obj.name), "summary": summary, "rows": rows}
