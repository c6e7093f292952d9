"""Document symbols: the sections of the file, objects with their sub-objects inside."""

from __future__ import annotations

from lsprotocol import types

from ..model import Device, Object, ObjectKind
from .positions import Lines
from .where import Index, Spot

_KIND = {
    ObjectKind.VAR: types.SymbolKind.Variable,
    ObjectKind.ARRAY: types.SymbolKind.Array,
    ObjectKind.RECORD: types.SymbolKind.Struct,
    ObjectKind.DEFSTRUCT: types.SymbolKind.Struct,
    ObjectKind.DEFTYPE: types.SymbolKind.TypeParameter,
    ObjectKind.DOMAIN: types.SymbolKind.File,
    ObjectKind.NULL: types.SymbolKind.Null,
}


def _range(index: Index, lines: Lines, spot: Spot) -> tuple[types.Range, types.Range]:
    header = lines.whole_line(spot.line)
    last = lines.whole_line(index.end_line(spot))
    return types.Range(header.start, last.end), header


def _name(spot: Spot, lines: Lines) -> str:
    """A section's header as written (`[FileInfo]` without brackets, an XML element's start), for sections
    the model names no other way."""
    text = lines.line(spot.line - 1)[max(spot.column - 1, 0) :].strip()
    return text.strip("[]<> ") or "section"


def _object(index: Index, lines: Lines, obj: Object, spot: Spot) -> types.DocumentSymbol:
    whole, header = _range(index, lines, spot)
    children = []
    for subindex, sub in obj.subs.items():
        sub_spot = index.header_of(sub)
        if sub_spot is None or sub.implicit or sub_spot is spot:
            continue
        sub_whole, sub_header = _range(index, lines, sub_spot)
        children.append(
            types.DocumentSymbol(
                name=f"sub{subindex:X} {sub.name}".rstrip(),
                kind=types.SymbolKind.Field,
                range=sub_whole,
                selection_range=sub_header,
            )
        )
    for child in children:  # a sub-object written apart from its object widens the object's range
        if (child.range.end.line, child.range.end.character) > (whole.end.line, whole.end.character):
            whole = types.Range(whole.start, child.range.end)
    return types.DocumentSymbol(
        name=f"{obj.index:04X} {obj.name}".rstrip(),
        detail=obj.kind.name,
        kind=_KIND.get(obj.kind, types.SymbolKind.Object),
        range=whole,
        selection_range=header,
        children=children or None,
    )


def symbols(device: Device, index: Index, lines: Lines) -> list[types.DocumentSymbol]:
    found: list[tuple[int, types.DocumentSymbol]] = []
    for obj in device.objects.values():
        spot = index.header_of(obj)
        if spot is not None and not obj.implicit:
            found.append((spot.line, _object(index, lines, obj, spot)))
    for spot in index.headers:
        if spot.owner is None:
            whole, header = _range(index, lines, spot)
            found.append(
                (spot.line, types.DocumentSymbol(_name(spot, lines), types.SymbolKind.Namespace, whole, header))
            )
    return [symbol for _, symbol in sorted(found, key=lambda pair: pair[0])]
