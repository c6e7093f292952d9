"""Go to definition and find references: mapping entries, object-list entries and XDD uniqueIDRefs
to the object or element they name, and back."""

from __future__ import annotations

import re
from collections.abc import Iterator

from ..lint.rules import Context, LintOptions
from ..model import Device, Location, Object, ObjectList
from ..model.cia301.pdo import decode_entry, is_dummy_index, is_mapping, pdos
from ..model.cia301.slots import as_int
from .where import Spot

_ID_REF = re.compile(r"""uniqueIDRef\s*=\s*["']([^"']*)["']""")


def _object_lists(device: Device) -> Iterator[ObjectList]:
    for found in (device.mandatory_objects, device.optional_objects, device.manufacturer_objects):
        if found is not None:
            yield found


def entry_header(obj: Object, subindex: int | None) -> Location | None:
    """The header of the section describing the entry: the sub-object's own, else the object's."""
    if subindex is not None and obj.has_subs:
        sub = obj.subs.get(subindex)
        if sub is not None and not sub.implicit and sub.origin is not None and sub.origin.line > 0:
            return sub.origin.header()
    return obj.origin.header() if obj.origin is not None and obj.origin.line > 0 else None


def mapped_by(spot: Spot) -> tuple[int, int] | None:
    """(index, sub-index) that a mapping entry's value maps, when the spot is one."""
    owner, var = spot.owner, spot.var
    if owner is None or var is None or spot.subindex in (None, 0) or not is_mapping(owner.index):
        return None
    raw = as_int(var.value())
    if raw is None or raw == 0:
        return None
    index, subindex, _ = decode_entry(raw & 0xFFFFFFFF)
    return None if is_dummy_index(index) else (index, subindex)


def definition(device: Device, spot: Spot) -> Location | None:
    """Where the object a mapping entry or an object-list entry names is described."""
    mapped = mapped_by(spot)
    if mapped is not None:
        target = device.objects.get(mapped[0])
        return entry_header(target, mapped[1]) if target is not None else None
    if isinstance(spot.section, ObjectList) and spot.key is not None and spot.key.isdigit():
        index = spot.section.entries.get(int(spot.key))
        target = device.objects.get(index) if index is not None else None
        return entry_header(target, None) if target is not None else None
    return None


def references(device: Device, spot: Spot) -> list[Location]:
    """The mapping entries that map the object (or the sub-object) at the spot, and the list entries naming it."""
    owner = spot.owner
    if owner is None:
        return []
    wanted_sub = spot.subindex if owner.has_subs else None
    at = Context(device, LintOptions())
    found: list[Location] = []
    for pdo in pdos(device):
        for entry in pdo.mapped():
            if entry.index == owner.index and wanted_sub in (None, entry.subindex):
                found.append(entry.slot.location(at))
    for listed in _object_lists(device):
        for position, index in listed.entries.items():
            if index == owner.index and listed.origin is not None:
                found.append(listed.origin.key(str(position)))
    return found


def id_ref_at(line_text: str, column: int) -> str | None:
    """The uniqueIDRef value under the cursor (column from 0) on an XDD line."""
    for match in _ID_REF.finditer(line_text):
        if match.start() <= column <= match.end():
            return match.group(1)
    return None


def parameter_element(data: bytes, source: str, unique_id: str) -> Location | None:
    """Where the XDD element with uniqueID=`unique_id` starts (a parameter, a data type)."""
    from ..xdd.locations import Positions
    from ..xdd.safe import XmlRefused, parse, utf8_form

    data = utf8_form(data)
    try:
        root = parse(data)
    except XmlRefused:
        return None
    pending = [root]
    while pending:
        element = pending.pop()
        if element.attrs.get("uniqueID") == unique_id:
            line, column = Positions(data).at(element.start)
            return Location(file=source, line=line, column=column)
        pending.extend(reversed(element.children))
    return None


_ID = re.compile(r"""\buniqueID\s*=\s*["']([^"']*)["']""")


def id_at(line_text: str, column: int) -> str | None:
    """The uniqueID value under the cursor (column from 0) on an XDD line."""
    for match in _ID.finditer(line_text):
        if match.start() <= column <= match.end():
            return match.group(1)
    return None


def id_ref_users(lines: list[str], unique_id: str) -> list[tuple[int, int]]:
    """(line, column) from 0 of every uniqueIDRef naming `unique_id`."""
    found = []
    for number, text in enumerate(lines):
        for match in _ID_REF.finditer(text):
            if match.group(1) == unique_id:
                found.append((number, match.start()))
    return found
