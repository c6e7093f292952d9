"""Document symbols: the sections of the file, objects with their sub-objects inside."""

from __future__ import annotations

import re
from bisect import bisect_right

from lsprotocol import types

from ..model import Commissioning, Device, DeviceInfo, DummyUsage, FileInfo, Object, ObjectKind
from .positions import Lines
from .where import Index, Spot

_TAG = re.compile(r"<(/?)([A-Za-z_][\w:.-]*)((?:[^>\"']|\"[^\"]*\"|'[^']*')*?)(/?)>")
_ATTRIBUTE = re.compile(r"=\s*[\"']([^\"']*)[\"']")
_SECTION_NAMES = {FileInfo: "FileInfo", DeviceInfo: "DeviceInfo", DummyUsage: "DummyUsage",
                  Commissioning: "DeviceCommissioning"}  # fmt: skip

_KIND = {
    ObjectKind.VAR: types.SymbolKind.Variable,
    ObjectKind.ARRAY: types.SymbolKind.Array,
    ObjectKind.RECORD: types.SymbolKind.Struct,
    ObjectKind.DEFSTRUCT: types.SymbolKind.Struct,
    ObjectKind.DEFTYPE: types.SymbolKind.TypeParameter,
    ObjectKind.DOMAIN: types.SymbolKind.File,
    ObjectKind.NULL: types.SymbolKind.Null,
}


class Extent:
    """Where a section ends: an EDS section at its last key's line, an XML element at its end tag."""

    def __init__(self, index: Index, lines: Lines, xml: bool) -> None:
        self.index, self.lines, self.xml = index, lines, xml
        self.starts = [0]
        if xml:
            for line in lines.lines:
                self.starts.append(self.starts[-1] + len(line))

    def position(self, offset: int) -> types.Position:
        number = max(bisect_right(self.starts, offset) - 1, 0)
        return types.Position(number, self.lines.units(number, offset - self.starts[number]))

    def element(self, spot: Spot) -> tuple[types.Range, types.Range] | None:
        """The element whose start tag is at the spot: all of it, and its start tag."""
        start = self.starts[spot.line - 1] + max(spot.column - 1, 0)
        first = _TAG.match(self.lines.text, start)
        if first is None or first.group(1):
            return None
        tag = types.Range(self.position(start), self.position(first.end()))
        if first.group(4):
            return tag, tag
        depth = 1
        for found in _TAG.finditer(self.lines.text, first.end()):
            if found.group(2) != first.group(2) or found.group(4):
                continue
            depth += -1 if found.group(1) else 1
            if depth == 0:
                return types.Range(tag.start, self.position(found.end())), tag
        return None

    def range(self, spot: Spot) -> tuple[types.Range, types.Range]:
        found = self.element(spot) if self.xml else None
        if found is not None:
            return found
        header = self.lines.whole_line(spot.line)
        last = self.lines.whole_line(self.index.end_line(spot))
        return types.Range(header.start, last.end), header

    def name(self, spot: Spot) -> str:
        """A section the model names no other way: its EDS name, else its header as written (`[FileInfo]`
        without brackets), or an XML element's name and first attribute's value."""
        known = _SECTION_NAMES.get(type(spot.section))
        if known is not None:
            return known
        text = self.lines.line(spot.line - 1)[max(spot.column - 1, 0) :].strip()
        tag = _TAG.match(text)
        if tag is None:
            return text.strip("[]<> ") or "section"
        value = _ATTRIBUTE.search(tag.group(3))
        name = tag.group(2).rsplit(":", 1)[-1]
        return f"{name} {value.group(1)}" if value else name


def _object(index: Index, extent: Extent, obj: Object, spot: Spot) -> types.DocumentSymbol:
    whole, header = extent.range(spot)
    children = []
    for subindex, sub in obj.subs.items():
        sub_spot = index.header_of(sub)
        if sub_spot is None or sub.implicit or sub_spot is spot:
            continue
        sub_whole, sub_header = extent.range(sub_spot)
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
    extent = Extent(index, lines, device.file_format != "eds")
    for obj in device.objects.values():
        spot = index.header_of(obj)
        if spot is not None and not obj.implicit:
            found.append((spot.line, _object(index, extent, obj, spot)))
    for spot in index.headers:
        if spot.owner is None:
            whole, header = extent.range(spot)
            found.append(
                (spot.line, types.DocumentSymbol(extent.name(spot), types.SymbolKind.Namespace, whole, header))
            )
    return [symbol for _, symbol in sorted(found, key=lambda pair: pair[0])]


def folding(device: Device, index: Index, lines: Lines) -> list[types.FoldingRange]:
    """A fold per section (an EDS section to its last key, an XML element to its end tag)."""
    extent = Extent(index, lines, device.file_format != "eds")
    found = []
    for spot in index.headers:
        whole, _ = extent.range(spot)
        if whole.end.line > whole.start.line:
            found.append(types.FoldingRange(whole.start.line, whole.end.line, kind=types.FoldingRangeKind.Region))
    return found


def workspace_symbols(
    uri: str, device: Device, index: Index, lines: Lines, query: str, limit: int
) -> list[types.WorkspaceSymbol]:
    """The objects of one document whose `index name` holds every word of the query (any case)."""
    words = query.lower().split()
    found = []
    for obj in device.objects.values():
        name = f"{obj.index:04X} {obj.name}".rstrip()
        spot = index.header_of(obj)
        if spot is None or obj.implicit or not all(word in name.lower() for word in words):
            continue
        where = types.Location(uri, lines.whole_line(spot.line))
        found.append(types.WorkspaceSymbol(where, name, _KIND.get(obj.kind, types.SymbolKind.Object)))
        if len(found) >= limit:
            break
    return found
