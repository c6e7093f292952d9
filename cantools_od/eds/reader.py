"""EDS/DCF text → Device. Never raises on content; problems become diagnostics."""

from __future__ import annotations

import re
from collections.abc import Callable, Iterable
from typing import Any

from ..canopennode.info import STORAGE_LOCATION_PREFIX
from ..collector import paused
from ..model import (
    Comments,
    Commissioning,
    Device,
    DeviceInfo,
    Dialect,
    DummyUsage,
    FileInfo,
    Object,
    ObjectList,
    Section,
    SubObject,
    ValueKind,
    Variable,
    standard_type,
)
from ..model.assemble import assemble, construct, field_defaults
from . import ini, keys
from .compact import apply_compact_sections, expand_compact_pdo, expand_compact_sub_objects
from .decode import decode, utf8_pieces
from .dialect import DialectEvidence, directive, may_hold_markers
from .report import Report
from .sections import Collected, collect, raw_section
from .storage import read_storage_groups
from .typed_values import store, type_values
from .values import parse_int, parse_value

_HEX4 = re.compile(r"[0-9a-fA-F]{4}\Z")
_SUB_DEFAULTS = field_defaults(SubObject)
_OBJECT_DEFAULTS = field_defaults(Object)
STORAGE_MARK = STORAGE_LOCATION_PREFIX.encode(
    "ascii"
)  # no file without it has a storage-group comment: a scan spares a walk


def read_bytes(data: bytes, file: str = "", node_id: int | None = None, dcf: bool | None = None) -> Device:
    with paused():  # the model is acyclic: collector passes over its many small objects only cost time
        storage = STORAGE_MARK in data
        try:
            device = _read_twice_if_repeated(lambda: utf8_pieces(data), data, file, storage)
        except UnicodeDecodeError:  # read again as a whole, in the fallback encoding
            text, encoding_note = decode(data)
            note = encoding_note or "not UTF-8"
            device = _read_twice_if_repeated(lambda: [text], text, file, storage, note)
        if dcf is not None:
            device.is_dcf = dcf
        elif file.lower().endswith(".dcf"):
            device.is_dcf = True
        if node_id is not None:
            device.node_id = node_id
        device._original = data
        return device


class _Repeated(Exception):
    """A section name given again, met while reading on the guess that none is."""


def _read_twice_if_repeated(
    pieces: Callable[[], Iterable[str]], text: str | bytes, file: str, storage: bool, encoding_note: str = ""
) -> Device:
    """The device read from `pieces()` on the guess that no section name is given twice (no real file seen so far
    gives one); when one is, read again, holding back every repeated name to merge its sections first. Finding
    them all beforehand would cost a search of the whole text, about 6 % of reading it."""
    markers = may_hold_markers(text)
    try:
        return _build(pieces(), None, _report(file, encoding_note), file, storage, markers)
    except _Repeated:
        repeated = ini.repeated_section_names(text)
        return _build(pieces(), repeated, _report(file, encoding_note), file, storage, markers)


def _report(file: str, encoding_note: str) -> Report:
    report = Report(file)
    if encoding_note:
        report.error("EDS100", encoding_note, 1, 1)
    return report


class _Build:
    """One file's sections turned into the model as they are read, so that the text's sections need
    not all be held at once: a large file costs its model, not its model and its parse besides.

    Sections whose name is given again are held back and merged first; so are sub-object sections
    read before their object. Values whose form depends on what is only known at the end (the
    dialect, a DEFTYPE alias) are typed at the end; all others at once."""

    def __init__(self, device: Device, report: Report, repeated: set[str] | None) -> None:
        self.device = device
        self.report = report
        self.repeated = repeated  # None: none guessed; a name given again raises _Repeated
        # While none is guessed: the names of sections that are no object or sub-object read so far (objects and
        # sub-objects read are found in the model), and the sub-objects held back for want of their object.
        self.seen: set[str] = set()
        self.orphaned: set[tuple[int, int]] = set()
        self.held: dict[str, ini.IniSection] = {}  # repeated names, first section, later ones merged in
        self.orphans: list[tuple[int, int, ini.IniSection]] = []  # sub-objects read before their object
        self.compact: list[tuple[int, str, ini.IniSection]] = []
        self.deferred: list[tuple[Object, SubObject | None, Collected]] = []

    def add(self, section: ini.IniSection) -> None:
        if self.repeated is None:
            self.read(section)
            return
        name = section.name.lower()
        if name in self.repeated:
            earlier = self.held.get(name)
            if earlier is None:
                self.held[name] = section
            else:
                _merge(earlier, section, self.report)
            return
        self.read(section)

    def finish(self) -> None:
        for section in self.held.values():
            self.read(section)
        for index, subindex, section in self.orphans:
            parent = self.device.objects.get(index)
            if parent is None:
                why = "its object has no section"
                self.report.error("EDS103", f"[{section.name}]: {why}; kept as text", section.line, section.column)
                self.device.other_sections.append(raw_section(section, self.report))
                continue
            self.read_sub(parent, subindex, section)
        type_values(self.device, self.deferred, self.report)

    def read(self, section: ini.IniSection) -> None:
        device, report = self.device, self.report
        _check_header(section, report)
        guessing = self.repeated is None
        match = keys.OBJECT_SECTION.match(section.name)
        if match is None:
            self.first_time(section)
            _read_file_section(device, section, report)
            return
        index = int(match.group(1), 16)
        if match.group(2) is not None:
            subindex = int(match.group(2), 16)
            parent = device.objects.get(index)
            if subindex > 0xFF:
                self.first_time(section)
                report.error(
                    "EDS103", f"[{section.name}]: sub-index above FFh; kept as text", section.line, section.column
                )
                device.other_sections.append(raw_section(section, report))
            elif parent is None:
                self.first_orphan(index, subindex)
                self.orphans.append((index, subindex, section))
            else:
                if guessing and (subindex in parent.subs or (index, subindex) in self.orphaned):
                    raise _Repeated
                self.read_sub(parent, subindex, section)
        elif match.group(3) is not None:
            self.first_time(section)
            self.compact.append((index, match.group(3).lower(), section))
        else:
            if guessing and index in device.objects:
                raise _Repeated
            collected = collect(section, keys.OBJECT_KEYS, report)
            fields = collected.shared_fields()
            fields["index"] = index
            fields["subs"] = {}
            obj = assemble(Object, fields, _OBJECT_DEFAULTS)
            device.objects[index] = obj
            self.type_or_defer(obj, None, collected)

    def first_time(self, section: ini.IniSection) -> None:
        """While none is guessed repeated: raise _Repeated when a section of this name was read before (names
        folded as `ini.repeated_section_names` folds them)."""
        if self.repeated is not None:
            return
        folded = section.name.strip().lower()
        if folded in self.seen:
            raise _Repeated
        self.seen.add(folded)

    def first_orphan(self, index: int, subindex: int) -> None:
        """`first_time` for a sub-object held back for want of its object."""
        if self.repeated is not None:
            return
        if (index, subindex) in self.orphaned:
            raise _Repeated
        self.orphaned.add((index, subindex))

    def read_sub(self, parent: Object, subindex: int, section: ini.IniSection) -> None:
        collected = collect(section, keys.OBJECT_KEYS, self.report)
        for field, spelling in (("sub_number", "SubNumber"), ("compact_sub_obj", "CompactSubObj")):
            if field in collected.fields:
                del collected.fields[field]
                collected.extra[spelling] = next(
                    e.value for e in section.entries if keys.normalize(e.key) == spelling.lower()
                )
        sub = assemble(SubObject, collected.shared_fields(), _SUB_DEFAULTS)
        parent.subs[subindex] = sub
        self.type_or_defer(parent, sub, collected)

    def type_or_defer(self, obj: Object, sub: SubObject | None, collected: Collected) -> None:
        if not collected.deferred:
            return
        var: Variable = sub if sub is not None else obj
        dtype = standard_type(var.data_type) if var.data_type is not None else None
        if dtype is None or dtype.kind is ValueKind.STRING:
            self.deferred.append((obj, sub, collected))
            return
        # `type_entry` for a CiA 301 type that is no string, written out: this runs for most values of a file.
        kind, bits, name, fields = dtype.kind, dtype.bits, dtype.name, var.__dict__
        for field, entry in collected.deferred.items():
            parsed = parse_value(entry.value, kind, bits, name)
            if parsed.notes or parsed.comment is not None:
                store(var, field, entry, parsed, self.report)
            else:
                fields[field] = parsed.value


def _build(
    pieces: Iterable[str], repeated: set[str] | None, report: Report, file: str, storage: bool, markers: bool = True
) -> Device:
    """The device; `storage`: the text may hold CANopenNode's storage-group comments (see storage.py); `markers`:
    it may hold dialect evidence besides keys (see dialect.may_hold_markers)."""
    stream = ini.Stream(pieces)
    device = Device.model_construct(
        file_info=construct(FileInfo, {}),
        device_info=construct(DeviceInfo, {}),
        dummy_usage=None,
        comments=None,
        mandatory_objects=None,
        optional_objects=None,
        manufacturer_objects=None,
        objects={},
        commissioning=None,
        module_sections=[],
        other_sections=[],
        trailing_comments=[],
        dialect=Dialect.CIA306,
        is_dcf=False,
        node_id=None,
        source=file,
        diagnostics=report.diagnostics,
    )
    build = _Build(device, report, repeated)
    evidence = DialectEvidence(markers)
    first = True
    for section in stream:
        evidence.see(section)  # before the directive leaves the first section's comments
        if first:
            first = False
            # A dialect directive is file metadata (kept in `dialect`), not a comment on the first section.
            section.comments = [c for c in section.comments if directive(c) is None]
            for line, stray in stream.preamble_stray:
                report.error("EDS101", f"text before the first section: {stray[:60]!r}", line, 1)
        build.add(section)
    if first:
        for line, stray in stream.preamble_stray:
            report.error("EDS101", f"text before the first section: {stray[:60]!r}", line, 1)
    device.trailing_comments = stream.trailing
    device.dialect = evidence.dialect(stream.trailing)
    for line, length in stream.long_lines:
        report.warning("EDS001", f"line has {length} characters; CiA 306 allows {ini.MAX_LINE}", line, ini.MAX_LINE + 1)
    build.finish()
    for obj in device.objects.values():
        if len(obj.subs) > 1:
            obj.subs = dict(sorted(obj.subs.items()))
    expand_compact_sub_objects(device)
    apply_compact_sections(device, build.compact, report)
    expand_compact_pdo(device)
    device.objects = dict(sorted(device.objects.items()))
    if storage:
        read_storage_groups(device)
    if device.commissioning is not None:
        device.node_id = device.commissioning.node_id
        device.is_dcf = True
    return device


def _merge(earlier: ini.IniSection, section: ini.IniSection, report: Report) -> None:
    """A repeated section's entries join the first one's."""
    report.error(
        "EDS002",
        f"section [{section.name}] given again (first on line {earlier.line}); its keys are merged",
        section.line,
        section.column,
    )
    earlier.entries.extend(section.entries)
    earlier.stray.extend(section.stray)
    earlier.plain = None  # its entries are no longer those of one plain section


def _check_header(section: ini.IniSection, report: Report) -> None:
    if not section.closed:
        report.error("EDS102", f"section header {section.header_text.strip()!r} lacks ']'", section.line, 1)
    for line, text in section.stray:
        report.error("EDS101", f"not a key=value entry: {text[:60]!r}", line, 1)


def _read_file_section(device: Device, section: ini.IniSection, report: Report) -> None:
    name = section.name.lower()
    part: Section | None = None
    if name == "fileinfo":
        part = device.file_info = _keyed(FileInfo, section, keys.FILE_INFO_KEYS, report)
    elif name == "deviceinfo":
        part = device.device_info = _keyed(DeviceInfo, section, keys.DEVICE_INFO_KEYS, report)
    elif name in keys.COMMISSIONING_SPELLINGS:
        part = device.commissioning = _keyed(Commissioning, section, keys.COMMISSIONING_KEYS, report)
    elif name in keys.OBJECT_LISTS:
        part = _object_list(section, report)
        setattr(device, keys.OBJECT_LISTS[name][1], part)
    elif name == "dummyusage":
        part = device.dummy_usage = _dummy_usage(section, report)
    elif name == "comments":
        part = device.comments = _comments(section, report)
    if part is not None:
        if part.origin is not None and section.name != keys.SECTION_SPELLINGS[name]:
            # "" is the section's own name, as for comments; a new dict, as origins may share an empty one
            part.origin.spelled = {**part.origin.spelled, "": section.name}
    elif keys.MODULE_SECTION.match(section.name):
        device.module_sections.append(raw_section(section, report))
    else:
        device.other_sections.append(raw_section(section, report))


def _keyed(model: type[Any], section: ini.IniSection, table: dict[str, keys.KeySpec], report: Report) -> Any:
    collected = collect(section, table, report)
    fields = collected.fields
    rates = {int(f.split(".")[1]): fields.pop(f) for f in list(fields) if f.startswith("baud_rates.")}
    if rates:
        fields["baud_rates"] = {rate: value for rate, value in rates.items() if value is not None}
    return construct(model, {**fields, **collected.common()})


def _numbered(
    section: ini.IniSection, report: Report, count_key: str, prefix: str = ""
) -> tuple[Collected, int | None, dict[int, str]]:
    """A list section: a count key and keys `<prefix><n>`, n decimal from 1."""
    collected = collect(section, {keys.normalize(count_key): (count_key, "count", keys.Kind.INT)}, report)
    numbered: dict[int, str] = {}
    for key in list(collected.extra):
        tail = key[len(prefix) :] if key.lower().startswith(prefix.lower()) else ""
        number = keys.list_number(tail)
        if number is not None:
            numbered[number] = collected.extra.pop(key)
    return collected, collected.fields.get("count"), numbered


def _object_list(section: ini.IniSection, report: Report) -> ObjectList:
    collected, count, numbered = _numbered(section, report, "SupportedObjects")
    entries: dict[int, int] = {}
    for position, text in numbered.items():
        try:
            index, _ = parse_int(text)
        except ValueError:
            index = None
        if not isinstance(index, int) or not 0 <= index <= 0xFFFF:
            line, column = _list_value_at(section, position)
            report.error("EDS030", f"[{section.name}] {position}={text}: not an object index", line, column)
            collected.extra[str(position)] = text
            continue
        entries[position] = index
    found = construct(ObjectList, {"supported_objects": count, "entries": entries, **collected.common()})
    object.__setattr__(found, "__pydantic_private__", {"_repeats": _repeated_positions(section)})
    return found


def _list_value_at(section: ini.IniSection, position: int) -> tuple[int, int]:
    """Where the value of the list's entry `position` is written (its last writing, the one read)."""
    written = [(entry.line, entry.value_col) for entry in section.entries if keys.list_number(entry.key) == position]
    return written[-1] if written else (section.line, section.column)


def _repeated_positions(section: ini.IniSection) -> dict[int, list[tuple[int, int, int]]]:
    """Positions written more than once: each of their entries as (line, key column, object index)."""
    written = [entry.key for entry in section.entries]
    if len(set(written)) == len(written):
        return {}  # the common case
    by_position: dict[int, list[tuple[int, int, int]]] = {}
    for entry in section.entries:
        position = keys.list_number(entry.key)
        if position is None:
            continue
        try:
            index, _ = parse_int(entry.value)
        except ValueError:
            continue
        if isinstance(index, int) and 0 <= index <= 0xFFFF:
            by_position.setdefault(position, []).append((entry.line, entry.key_col, index))
    return {position: found for position, found in by_position.items() if len(found) > 1}


def _dummy_usage(section: ini.IniSection, report: Report) -> DummyUsage:
    collected = collect(section, {}, report)
    enabled: dict[int, bool] = {}
    for key in list(collected.extra):
        tail, text = key[5:], collected.extra[key].strip()
        if key.lower().startswith("dummy") and _HEX4.match(tail) and text in ("0", "1"):
            enabled[int(tail, 16)] = text == "1"
            del collected.extra[key]
    return construct(DummyUsage, {"enabled": enabled, **collected.common()})


def comments_in(text: str, report: Report) -> Comments | None:
    """The [Comments] section of CiA 306 text: an XDD keeps the section so, in an XML comment."""
    for section in ini.parse(text).sections:
        if section.name.lower() == "comments":
            _check_header(section, report)
            return _comments(section, report)
    return None


def _comments(section: ini.IniSection, report: Report) -> Comments:
    collected, count, numbered = _numbered(section, report, "Lines", prefix="Line")
    return construct(Comments, {"line_count": count, "lines": dict(sorted(numbered.items())), **collected.common()})
