"""Completion in EDS/DCF text: section names, keys, data types, access and object types, standard names."""

from __future__ import annotations

from lsprotocol import types

from ..eds.keys import COMMISSIONING_KEYS, DEVICE_INFO_KEYS, FILE_INFO_KEYS, OBJECT_KEYS, SUB_ONLY_EXCLUDED, normalize
from ..model import AccessType, Commissioning, DeviceInfo, FileInfo, ObjectKind
from ..model.cia301 import cia402, definitions
from ..model.datatypes import STANDARD_TYPES
from .hover import standard_name
from .where import Index, Spot

_SECTIONS = (
    *("FileInfo", "DeviceInfo", "DummyUsage", "Comments"),
    *("MandatoryObjects", "OptionalObjects", "ManufacturerObjects", "DeviceComissioning"),
)
_VALUE = types.CompletionItemKind.Value


def _item(label: str, detail: str, kind: types.CompletionItemKind, insert: str | None = None) -> types.CompletionItem:
    return types.CompletionItem(label, kind=kind, detail=detail, insert_text=insert, filter_text=f"{label} {detail}")


def _section(name: str, detail: str, kind: types.CompletionItemKind, header: types.Range) -> types.CompletionItem:
    """A header, replacing what `header` covers (the "[" typed, the name begun and a "]" the editor may have
    closed it with): `[name]` once, whatever the editor added."""
    edit = types.TextEdit(header, f"[{name}]")
    return types.CompletionItem(name, kind=kind, detail=detail, text_edit=edit, filter_text=f"[{name} {detail}")


def _sections(present: set[int], header: types.Range) -> list[types.CompletionItem]:
    items = [_section(name, "section", types.CompletionItemKind.Module, header) for name in _SECTIONS]
    for found in (*definitions.DEFINITIONS, *cia402.DEFINITIONS):
        for index in found.indices[:4]:  # the first few of a range (PDOs, SDOs) are the ones written by hand
            if index not in present:
                items.append(_section(f"{index:04X}", found.name, types.CompletionItemKind.Class, header))
    return items


def header_range(line: int, before: str, after: str) -> types.Range:
    """From the "[" that starts the text before the cursor to the cursor, and over a "]" right after it."""
    start = len(before) - len(before.lstrip())  # blanks only: as many UTF-16 units as characters
    end = len(before.encode("utf-16-le")) // 2 + (1 if after.startswith("]") else 0)
    return types.Range(types.Position(line, start), types.Position(line, end))


def _keys(spot: Spot | None, written: set[str]) -> list[types.CompletionItem]:
    if spot is None:
        return []
    section = spot.section
    if spot.owner is not None:
        table = {k: v for k, v in OBJECT_KEYS.items() if spot.section is spot.owner or k not in SUB_ONLY_EXCLUDED}
    elif isinstance(section, FileInfo):
        table = FILE_INFO_KEYS
    elif isinstance(section, DeviceInfo):
        table = DEVICE_INFO_KEYS
    elif isinstance(section, Commissioning):
        table = COMMISSIONING_KEYS
    else:
        return []
    return [
        _item(spelling, f"{kind.value} key", types.CompletionItemKind.Property, f"{spelling}=")
        for key, (spelling, _, kind) in table.items()
        if key not in written
    ]


def _values(key: str, spot: Spot | None) -> list[types.CompletionItem]:
    if key == "datatype":
        return [_item(f"0x{index:04X}", dtype.name, _VALUE) for index, dtype in STANDARD_TYPES.items()]
    if key == "accesstype":
        return [_item(access.value, "access type", _VALUE) for access in AccessType]
    if key == "objecttype":
        return [_item(f"0x{kind.value:X}", kind.name, _VALUE) for kind in ObjectKind]
    if key == "pdomapping":
        return [_item("0", "not mappable", _VALUE), _item("1", "mappable into a PDO", _VALUE)]
    if key == "parametername" and spot is not None and spot.owner is not None:
        subindex = spot.subindex if spot.owner.has_subs else None
        named = standard_name(spot.owner.index, subindex)
        if named is not None:
            name = named.rsplit(" (", 1)[0].rsplit(": ", 1)[-1]
            return [_item(name, named, types.CompletionItemKind.Text)]
    return []


def complete(
    index: Index | None, line_text: str, line: int, present: set[int], after: str = ""
) -> list[types.CompletionItem]:
    """Items for the text before the cursor (and after it, `after`) on a line (from 1) of an EDS/DCF."""
    stripped = line_text.lstrip()
    if stripped.startswith((";", "#")):
        return []
    if stripped.startswith("["):
        return [] if "]" in stripped else _sections(present, header_range(line - 1, line_text, after))
    spot = index.section_at(line) if index is not None else None
    if "=" in stripped:
        return _values(normalize(stripped.split("=", 1)[0]), spot)
    written: set[str] = set()
    if spot is not None and spot.section.origin is not None:
        written = {normalize(key) for key, _ in spot.section.origin.positions()}
    return _keys(spot, written)
