"""The exact device of an edited text, read again only where the edit can change it.

When an edit changes only entry lines of one object's section of an EDS/DCF, every other section
reads as it did: the new device is the previous one with that object read again (from the text
with the sections of the object lists and of every other object but the data-type definitions
blanked, line numbers kept, as quick.py does) and every section
after the edit moved by the lines it added or removed. What a whole-file step of the reader could
make of the edit is ruled out first; where it cannot be, None tells the caller to read the whole
text: an object of the data-type area (others' values are typed by it), CompactSubObj, compact
sections, a PDO of a file with CompactPDO, a file not in UTF-8, a section given twice, a
sub-object of the object kept as text, dialect evidence the edit adds or removes, or comment lines
at the section's end that the next section's header would take. The result equals a fresh read
of the text but for the order of `diagnostics` (lint sorts its findings).
"""

from __future__ import annotations

import re
from bisect import bisect_right
from typing import Any, TypeVar

from pydantic import BaseModel

from ..eds import ini
from ..eds.dialect import _lely, _other
from ..lint import LintOptions
from ..lint.runner import Edit, linted
from ..model import Device, Diagnostic, Object, Origin
from ..model.cia301.objects import COMM_BASE, DATA_TYPE_AREA, MAP_BASE, PDO_SPAN
from ..sniff import NotADeviceDescription
from .document import Analysis, Encoding, read, selection_for
from .quick import _Layout, _only, object_edit

_PLAIN_SECTION = re.compile(r"[ \t]*\[[ \t]*[0-9a-f]{1,4}(?:sub[0-9a-f]{1,3})?[ \t]*\]", re.IGNORECASE)
_WHOLE_FILE_CODES = ("EDS100", "EDS104")

_FIRST = re.compile(r"(\(first on line )(\d+)\)")
_PDO_AREA = range(min(COMM_BASE.values()), max(MAP_BASE.values()) + PDO_SPAN)
_Model = TypeVar("_Model", bound=BaseModel)


def reanalyse(old: Analysis, uri: str, text: str, version: int | None, encoding: Encoding, options: LintOptions
              ) -> Analysis | None:  # fmt: skip
    """The analysis of `text`, an edit of `old`'s, with its device read again where the edit can change it
    (the findings are all lint's, as for a fresh read); None when the edit is not one this covers."""
    try:
        selection = selection_for(uri)
    except ValueError:
        return None  # the full check says so
    found = reread(old, text, uri, encoding)
    if found is None:
        return None
    device, edit = found
    checked = linted(device, options, selection, (old.linted, edit) if old.linted is not None else None)
    return Analysis(version, text, device, checked.findings, linted=checked)


def reread(old: Analysis, text: str, uri: str, encoding: Encoding) -> tuple[Device, Edit] | None:
    """The device `text` describes, `old`'s device read again where the edit can change it, and the edit;
    None when the edit is not one this covers (read the whole text)."""
    device = old.device
    found = object_edit(old, text)
    if device is None or found is None or not _plain_file(device, encoding):
        return None
    before, (index, start, delta, after) = found
    if index in DATA_TYPE_AREA or _compact_pdo(device, index) or not _plain_object(device, index):
        return None
    if not _local(before, after, index, start):
        return None
    data = encoding.bytes(text)
    try:
        reduced = read(uri, encoding.bytes(_only(after, {index, *_type_objects(after)}, lists=False)))
    except (NotADeviceDescription, RecursionError):
        return None
    if reduced.dialect is not device.dialect or not _plain_object(reduced, index):
        return None
    if any(d.code == "EDS103" or _whole_file(d) for d in reduced.diagnostics):  # the object's sub-object kept as text
        return None
    spans = (before.spans(index), after.spans(index))
    return _spliced(device, reduced, index, spans, (start, delta), data), Edit(index, *spans, start, delta)


def _plain_file(device: Device, encoding: Encoding) -> bool:
    """No whole-file step of the reader is at work in the file: UTF-8, no section given twice, no
    compact section error."""
    return encoding.codec == "utf-8" and not any(map(_whole_file, device.diagnostics))


def _whole_file(diagnostic: Diagnostic) -> bool:
    """What one section does to another (a section given again, a compact section) or the file's encoding."""
    return diagnostic.code in _WHOLE_FILE_CODES or diagnostic.message.startswith("section [")


def _compact_pdo(device: Device, index: int) -> bool:
    """A PDO object of a file with CompactPDO: the PDOs it omits are counted from those it has."""
    return bool(device.device_info.compact_pdo) and index in _PDO_AREA


def _plain_object(device: Device, index: int) -> bool:
    found = device.objects.get(index)
    return found is None or not found.compact_sub_obj


def _type_objects(layout: _Layout) -> set[int]:
    """The objects of the data-type area: what the values of other objects may be typed by."""
    return {index for index in layout.objects if index is not None and index in DATA_TYPE_AREA}


def _local(before: _Layout, after: _Layout, index: int, start: int) -> bool:
    """The object's sections are all [xxxx] or [xxxxsubn] sections, old and new (no compact section, no
    CompactSubObj), and the edited section gives the same dialect evidence and ends in the same comments."""
    for layout in (before, after):
        for at, owner in enumerate(layout.objects):
            if owner == index and _PLAIN_SECTION.match(layout.text, layout.starts[at]) is None:
                return False
    old, new = _section_text(before, start), _section_text(after, start)
    if "compactsubobj" in old.lower() or "compactsubobj" in new.lower():
        return False
    old_parse, new_parse = ini.parse(old), ini.parse(new)
    if len(old_parse.sections) != 1 or len(new_parse.sections) != 1:
        return False
    first, second = old_parse.sections[0], new_parse.sections[0]
    if _lely(first) != _lely(second) or _other(first) != _other(second):
        return False
    return first.trailing == second.trailing  # comment lines at the end stand above the next header


def _section_text(layout: _Layout, line_before: int) -> str:
    """The text of the section that holds line `line_before` + 1."""
    at = bisect_right(layout.lines, line_before + 1) - 1
    finish = layout.starts[at + 1] if at + 1 < len(layout.starts) else len(layout.text)
    return layout.text[layout.starts[at] : finish]


def _spliced(
    device: Device,
    reduced: Device,
    index: int,
    spans: tuple[set[int], set[int]],
    moved: tuple[int, int],
    data: bytes,
) -> Device:
    """`device` with object `index` and its diagnostics taken from `reduced`, later sections moved."""
    start, delta = moved
    objects: dict[int, Object] = {}
    for number, obj in device.objects.items():
        if number == index:
            found = reduced.objects.get(index)
            if found is not None:
                objects[index] = found
        else:
            objects[number] = _moved_object(obj, start, delta)
    if index in reduced.objects and index not in device.objects:
        objects = dict(sorted({**objects, index: reduced.objects[index]}.items()))
    old_spans, new_spans = spans
    diagnostics = [_moved_diagnostic(d, start, delta) for d in device.diagnostics if d.location.line not in old_spans]
    diagnostics += [d for d in reduced.diagnostics if d.location.line in new_spans]
    update: dict[str, Any] = {"objects": objects, "diagnostics": diagnostics}
    for name in ("file_info", "device_info", "dummy_usage", "comments", "commissioning"):
        update[name] = _moved_part(getattr(device, name), start, delta)
    for name in ("mandatory_objects", "optional_objects", "manufacturer_objects"):
        update[name] = _moved_list(getattr(device, name), start, delta)
    for name in ("module_sections", "other_sections"):
        update[name] = [_moved_part(part, start, delta) for part in getattr(device, name)]
    result = device.model_copy(update=update)
    result.__pydantic_private__ = {**(device.__pydantic_private__ or {}), "_original": data, "_recount": set(),
                                   "_respell": {}}  # fmt: skip
    return result


def _moved_origin(origin: Origin | None, start: int, delta: int) -> Origin | None:
    if origin is None or delta == 0 or origin.line <= start:
        return origin
    update: dict[str, Any] = {"line": origin.line + delta}
    if origin.keys:
        update["keys"] = {key: (line + delta, *columns) for key, (line, *columns) in origin.keys.items()}
    return origin.model_copy(update=update)


def _moved_part(part: _Model, start: int, delta: int) -> _Model:
    """A section's model with its origin moved when it lies after the edit (None stays None)."""
    if part is None or delta == 0:
        return part
    origin = getattr(part, "origin", None)
    moved = _moved_origin(origin, start, delta)
    return part if moved is origin else part.model_copy(update={"origin": moved})


def _moved_object(obj: Object, start: int, delta: int) -> Object:
    if delta == 0:
        return obj
    subs = {number: _moved_part(sub, start, delta) for number, sub in obj.subs.items()}
    moved = _moved_part(obj, start, delta)
    if all(subs[number] is sub for number, sub in obj.subs.items()):
        return moved
    if moved is obj:
        return obj.model_copy(update={"subs": subs})
    moved.__dict__["subs"] = subs  # a copy of our own
    return moved


def _moved_list(part: _Model, start: int, delta: int) -> _Model:
    """An object list moved: its origin and the lines of the positions it gives twice."""
    moved = _moved_part(part, start, delta)
    private = getattr(moved, "__pydantic_private__", None)
    if moved is part or not private or not private.get("_repeats"):
        return moved
    repeats = {
        position: [(line + delta, column, index) for line, column, index in found]
        for position, found in private["_repeats"].items()
    }
    object.__setattr__(moved, "__pydantic_private__", {**private, "_repeats": repeats})
    return moved


def _moved_diagnostic(diagnostic: Diagnostic, start: int, delta: int) -> Diagnostic:
    where = diagnostic.location
    if delta == 0 or where.line <= start:
        return diagnostic
    update: dict[str, Any] = {"location": where.model_copy(update={"line": where.line + delta})}
    if diagnostic.code == "EDS002":  # a key given again names the line of the first, in the same section
        update["message"] = _FIRST.sub(lambda m: f"{m.group(1)}{int(m.group(2)) + delta})", diagnostic.message)
    return diagnostic.model_copy(update=update)
