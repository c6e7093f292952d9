"""EDS/DCF text → Device. Never raises on content; problems become diagnostics."""

from __future__ import annotations

import gc
import re
from collections.abc import Iterator
from contextlib import contextmanager
from typing import Any

from ..model import (
    Comments,
    Commissioning,
    Device,
    DeviceInfo,
    DummyUsage,
    FileInfo,
    Object,
    ObjectList,
    SubObject,
)
from ..model.assemble import assemble, field_defaults
from . import ini, keys
from .compact import apply_compact_sections, expand_compact_pdo, expand_compact_sub_objects
from .decode import decode
from .dialect import detect_dialect, directive
from .report import Report
from .sections import Collected, collect, raw_section
from .storage import read_storage_groups
from .typed_values import type_values
from .values import parse_int

_OBJECT_SECTION = re.compile(
    r"([0-9a-fA-F]{1,4})(?:[sS][uU][bB]([0-9a-fA-F]{1,3})|(name|value|denotation|objectlinks))?\Z",
    re.IGNORECASE,
)
_HEX4 = re.compile(r"[0-9a-fA-F]{4}\Z")
_MODULE_SECTION = re.compile(r"(?:m\d+\D.*|supportedmodules|connectedmodules)\Z", re.IGNORECASE)
_SUB_DEFAULTS = field_defaults(SubObject)
_OBJECT_DEFAULTS = field_defaults(Object)


@contextmanager
def _no_cyclic_gc() -> Iterator[None]:
    """The model is acyclic; collector passes over its many small objects only cost time."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.enable()


def read_bytes(data: bytes, file: str = "", node_id: int | None = None, dcf: bool | None = None) -> Device:
    with _no_cyclic_gc():
        report = Report(file)
        text, encoding_note = decode(data)
        if encoding_note:
            report.warning("EDS100", encoding_note, 1, 1)
        device = _build(ini.parse(text), report, file)
        if dcf is not None:
            device.is_dcf = dcf
        elif file.lower().endswith(".dcf"):
            device.is_dcf = True
        if node_id is not None:
            device.node_id = node_id
        device._original = data
        return device


def _build(parsed: ini.IniFile, report: Report, file: str) -> Device:
    for line, length in parsed.long_lines:
        report.error("EDS001", f"line has {length} characters; CiA 306 allows {ini.MAX_LINE}", line, ini.MAX_LINE + 1)
    for line, text in parsed.preamble_stray:
        report.error("EDS101", f"text before the first section: {text[:60]!r}", line, 1)
    device = Device.model_construct(
        file_info=FileInfo(),
        device_info=DeviceInfo(),
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
        dialect=detect_dialect(parsed),
        is_dcf=False,
        node_id=None,
        source=file,
        diagnostics=report.diagnostics,
    )
    if parsed.sections:
        # A dialect directive is file metadata (kept in `dialect`), not a comment on the first section.
        top = parsed.preamble_comments + parsed.sections[0].comments
        parsed.sections[0].comments = [c for c in top if directive(c) is None]
        device.trailing_comments = parsed.sections[-1].trailing
    elif parsed.preamble_comments:
        device.trailing_comments = parsed.preamble_comments
    subs: list[tuple[int, int, ini.IniSection]] = []
    compact: list[tuple[int, str, ini.IniSection]] = []
    deferred: list[tuple[Object, SubObject | None, Collected]] = []
    for section in _merge_duplicates(parsed.sections, report):
        _check_header(section, report)
        match = _OBJECT_SECTION.match(section.name)
        if match is None:
            _read_file_section(device, section, report)
            continue
        index = int(match.group(1), 16)
        if match.group(2) is not None:
            subs.append((index, int(match.group(2), 16), section))
        elif match.group(3) is not None:
            compact.append((index, match.group(3).lower(), section))
        else:
            collected = collect(section, keys.OBJECT_KEYS, report)
            fields = {"index": index, "subs": {}, **collected.fields, **collected.common()}
            obj = assemble(Object, fields, _OBJECT_DEFAULTS)
            device.objects[index] = obj
            deferred.append((obj, None, collected))
    for index, subindex, section in subs:
        parent = device.objects.get(index)
        if parent is None or subindex > 0xFF:
            why = "its object has no section" if parent is None else "sub-index above FFh"
            report.error("EDS103", f"[{section.name}]: {why}; kept as text", section.line, section.column)
            device.other_sections.append(raw_section(section, report))
            continue
        collected = collect(section, keys.OBJECT_KEYS, report)
        for field, spelling in (("sub_number", "SubNumber"), ("compact_sub_obj", "CompactSubObj")):
            if field in collected.fields:
                del collected.fields[field]
                collected.extra[spelling] = next(
                    e.value for e in section.entries if keys.normalize(e.key) == spelling.lower()
                )
        sub = assemble(SubObject, {**collected.fields, **collected.common()}, _SUB_DEFAULTS)
        parent.subs[subindex] = sub
        deferred.append((parent, sub, collected))
    for obj in device.objects.values():
        if len(obj.subs) > 1:
            obj.subs = dict(sorted(obj.subs.items()))
    type_values(device, deferred, report)
    expand_compact_sub_objects(device)
    apply_compact_sections(device, compact, report)
    expand_compact_pdo(device)
    device.objects = dict(sorted(device.objects.items()))
    read_storage_groups(device)
    if device.commissioning is not None:
        device.node_id = device.commissioning.node_id
        device.is_dcf = True
    return device


def _merge_duplicates(sections: list[ini.IniSection], report: Report) -> list[ini.IniSection]:
    """One section per name: a repeated section's entries join the first one's."""
    first: dict[str, ini.IniSection] = {}
    merged: list[ini.IniSection] = []
    for section in sections:
        name = section.name.lower()
        earlier = first.get(name)
        if earlier is None:
            first[name] = section
            merged.append(section)
            continue
        report.warning(
            "EDS002",
            f"section [{section.name}] given again (first on line {earlier.line}); its keys are merged",
            section.line,
            section.column,
        )
        earlier.entries.extend(section.entries)
        earlier.stray.extend(section.stray)
    return merged


def _check_header(section: ini.IniSection, report: Report) -> None:
    if not section.closed:
        report.error("EDS102", f"section header {section.header_text.strip()!r} lacks ']'", section.line, 1)
    for line, text in section.stray:
        report.error("EDS101", f"not a key=value entry: {text[:60]!r}", line, 1)


def _read_file_section(device: Device, section: ini.IniSection, report: Report) -> None:
    name = section.name.lower()
    if name == "fileinfo":
        device.file_info = _keyed(FileInfo, section, keys.FILE_INFO_KEYS, report)
    elif name == "deviceinfo":
        device.device_info = _keyed(DeviceInfo, section, keys.DEVICE_INFO_KEYS, report)
    elif name in keys.COMMISSIONING_SPELLINGS:
        device.commissioning = _keyed(Commissioning, section, keys.COMMISSIONING_KEYS, report)
    elif name in keys.OBJECT_LISTS:
        setattr(device, keys.OBJECT_LISTS[name][1], _object_list(section, report))
    elif name == "dummyusage":
        device.dummy_usage = _dummy_usage(section, report)
    elif name == "comments":
        device.comments = _comments(section, report)
    elif _MODULE_SECTION.match(section.name):
        device.module_sections.append(raw_section(section, report))
    else:
        device.other_sections.append(raw_section(section, report))


def _keyed(model: type[Any], section: ini.IniSection, table: dict[str, keys.KeySpec], report: Report) -> Any:
    collected = collect(section, table, report)
    fields = collected.fields
    rates = {int(f.split(".")[1]): fields.pop(f) for f in list(fields) if f.startswith("baud_rates.")}
    if rates:
        fields["baud_rates"] = {rate: value for rate, value in rates.items() if value is not None}
    return model(**fields, **collected.common())


def _numbered(
    section: ini.IniSection, report: Report, count_key: str, prefix: str = ""
) -> tuple[Collected, int | None, dict[int, str]]:
    """A list section: a count key and keys `<prefix><n>`, n decimal from 1."""
    collected = collect(section, {keys.normalize(count_key): (count_key, "count", keys.Kind.INT)}, report)
    numbered: dict[int, str] = {}
    for key in list(collected.extra):
        tail = key[len(prefix) :] if key.lower().startswith(prefix.lower()) else ""
        if tail.isdigit() and tail == str(int(tail)) and int(tail) > 0:
            numbered[int(tail)] = collected.extra.pop(key)
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
            report.error("EDS030", f"[{section.name}] {position}={text}: not an object index", section.line)
            collected.extra[str(position)] = text
            continue
        entries[position] = index
    return ObjectList(supported_objects=count, entries=entries, **collected.common())


def _dummy_usage(section: ini.IniSection, report: Report) -> DummyUsage:
    collected = collect(section, {}, report)
    enabled: dict[int, bool] = {}
    for key in list(collected.extra):
        tail, text = key[5:], collected.extra[key].strip()
        if key.lower().startswith("dummy") and _HEX4.match(tail) and text in ("0", "1"):
            enabled[int(tail, 16)] = text == "1"
            del collected.extra[key]
    return DummyUsage(enabled=enabled, **collected.common())


def _comments(section: ini.IniSection, report: Report) -> Comments:
    collected, count, numbered = _numbered(section, report, "Lines", prefix="Line")
    return Comments(line_count=count, lines=dict(sorted(numbered.items())), **collected.common())
