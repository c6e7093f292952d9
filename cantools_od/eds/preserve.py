"""Writes a device back over the bytes it was read from, touching only what changed.

The original is read again and both it and the device are put in canonical
form; where the two agree, the original lines stay byte for byte.
"""

from __future__ import annotations

import re
from collections import Counter

from ..model import Device
from . import ini
from .decode import decode_as, encode
from .keys import COMMISSIONING_KEYS, DEVICE_INFO_KEYS, FILE_INFO_KEYS, OBJECT_KEYS, normalize
from .reader import read_bytes
from .writer import OutSection, render, sections

_OBJECT = re.compile(r"([0-9a-fA-F]{1,4})(?:[sS][uU][bB]([0-9a-fA-F]{1,3})|(\w+))?\Z")
_SECTION_TABLES = {
    "fileinfo": ("FileInfo", FILE_INFO_KEYS),
    "deviceinfo": ("DeviceInfo", DEVICE_INFO_KEYS),
    "devicecomissioning": ("DeviceComissioning", COMMISSIONING_KEYS),
    "devicecommissioning": ("DeviceComissioning", COMMISSIONING_KEYS),
}
_SUFFIXES = {"name": "Name", "value": "Value", "denotation": "Denotation", "objectlinks": "ObjectLinks"}
_LIST_NAMES = {
    n.lower(): n for n in ("MandatoryObjects", "OptionalObjects", "ManufacturerObjects", "DummyUsage", "Comments")
}


def canonical_section_name(name: str) -> str:
    match = _OBJECT.match(name)
    if match is not None and (match.group(3) is None or match.group(3).lower() in _SUFFIXES):
        index = f"{int(match.group(1), 16):04X}"
        if match.group(2) is not None:
            return f"{index}sub{int(match.group(2), 16):X}"
        return index + (_SUFFIXES[match.group(3).lower()] if match.group(3) else "")
    lower = name.lower()
    if lower in _SECTION_TABLES:
        return _SECTION_TABLES[lower][0]
    return _LIST_NAMES.get(lower, name)


def _canonical_key(section: str, key: str) -> str:
    table = _SECTION_TABLES.get(section.lower(), (None, OBJECT_KEYS if _OBJECT.match(section) else {}))[1]
    spec = table.get(normalize(key))
    if spec is not None:
        return spec[0]
    if (
        section in ("MandatoryObjects", "OptionalObjects", "ManufacturerObjects")
        and normalize(key) == "supportedobjects"
    ):
        return "SupportedObjects"
    return key


def respell(device: Device, line: int, column: int, written: str, spelling: str) -> None:
    """Have the preserving writer write `spelling` for `written` (a key, a section name or a list
    number) at line:column of the original, and nothing else on that line."""
    device._respell[line] = (column, written, spelling)


def _respelled(lines: list[str], edits: dict[int, tuple[int, str, str]]) -> list[str]:
    out = list(lines)
    for line, (column, written, spelling) in edits.items():
        raw = out[line - 1] if 0 < line <= len(out) else ""
        start = column - 1
        if raw[start : start + len(written)] != written:
            start = raw.find(written)  # a column counted otherwise (blanks inside a header's brackets)
        if start >= 0:
            out[line - 1] = raw[:start] + spelling + raw[start + len(written) :]
    return out


def preserve(device: Device) -> bytes:
    original = device._original
    if original is None:
        raise ValueError("the device was not read from EDS/DCF bytes")
    text, encoding, _ = decode_as(original)
    bom = b"\xef\xbb\xbf" if original.startswith(b"\xef\xbb\xbf") else b""
    if device._respell:
        # Respelling is a text edit; the respelled text, read again, is what the model is compared with.
        text = "".join(_respelled(ini.split_lines(text), device._respell))
        original = bom + _encoded(text, encoding)
    before = {s.name: s for s in sections(read_bytes(original, device.source, dcf=device.is_dcf), as_written=True)}
    after = {s.name: s for s in sections(device, as_written=True)}
    parsed: ini.IniFile | None = None
    if device._recount:
        parsed = ini.parse(text)
        _written_counts(parsed, before, device._recount)
    if _entries(before) == _entries(after):
        return original  # the common case: no second parse of the text
    parsed = parsed or ini.parse(text)
    lines = ini.split_lines(text)
    return bom + _encoded(_apply(lines, _plan(parsed, lines, before, after)), encoding)


def _encoded(text: str, encoding: str) -> bytes:
    try:
        return encode(text, encoding)
    except UnicodeEncodeError:
        return text.encode("utf-8")  # new text the old code page cannot hold


_DECIMAL = re.compile(r"-?(?:0|[1-9][0-9]*)\Z")
_HEX = re.compile(r"-?0x[0-9A-F]+\Z")


def _in_style_of(old: str, new: str) -> str:
    """A changed number keeps the radix it was written in: `500` becomes `250`, not `0x00FA`.

    A bare `0` says nothing about the radix; the canonical form is taken then.
    """
    if old != "0" and _DECIMAL.match(old) and _HEX.match(new):
        return str(int(new, 16))
    return new


_COUNT_KEYS = {"NrOfEntries", "ObjectLinks"}


def _written_counts(parsed: ini.IniFile, before: dict[str, OutSection], recount: set[str]) -> None:
    """Put the counts of [xxxxName/Value/Denotation/ObjectLinks] named in `recount` as written in place of the
    derived ones, so that a wrong count differs from the device's and is rewritten."""
    for section in parsed.sections:
        old = before.get(canonical_section_name(section.name))
        if old is None:
            continue
        for entry in section.entries:
            key = next((k for k in _COUNT_KEYS & recount if k.lower() == normalize(entry.key)), None)
            if key is not None and key in old.entries:
                old.entries[key] = entry.value


def _entries(by_name: dict[str, OutSection]) -> dict[str, dict[str, str]]:
    return {name: section.entries for name, section in by_name.items()}


def _eol(line: str) -> str:
    return line[len(line.rstrip("\r\n")) :]


def _dominant_eol(lines: list[str]) -> str:
    counts = Counter(_eol(line) for line in lines)
    counts.pop("", None)
    return counts.most_common(1)[0][0] if counts else "\n"


def _apply(lines: list[str], edits: dict[int, list[str]]) -> str:
    """Lines with edits applied; edits[len(lines)+1] is text to append."""
    out: list[str] = []
    for number, line in enumerate(lines, 1):
        out.extend(edits.get(number, [line]))
    tail = edits.get(len(lines) + 1, [])
    if tail and out and not _eol(out[-1]):
        out[-1] += _dominant_eol(lines)
    out.extend(tail)
    return "".join(out)


def _plan(
    parsed: ini.IniFile, lines: list[str], before: dict[str, OutSection], after: dict[str, OutSection]
) -> dict[int, list[str]]:
    """Line number → the lines that replace it."""
    eol = _dominant_eol(lines)
    edits: dict[int, list[str]] = {}
    for section in parsed.sections:
        name = canonical_section_name(section.name)
        old, new = before.get(name), after.get(name)
        if old is None or (new is not None and old.entries == new.entries):
            continue
        last_line = max([section.line, *(e.line for e in section.entries)])
        if new is None:
            for line in range(section.line, last_line + 1):
                edits[line] = []
            continue
        by_key: dict[str, list[ini.Entry]] = {}
        for entry in section.entries:
            by_key.setdefault(_canonical_key(name, entry.key), []).append(entry)
        for key, entries in by_key.items():
            last = entries[-1]  # the one that counts when a key is repeated
            raw = lines[last.line - 1]
            if key not in new.entries:
                if key in old.entries:  # a key that had a value and lost it; an empty key stays
                    for entry in entries:
                        edits[entry.line] = []
                    if new.comments.get(key):  # as the canonical writer: a commented key is left empty
                        edits[last.line] = [raw[: last.value_col - 1] + (_eol(raw) or eol)]
            elif new.entries[key] != old.entries.get(key):
                text = _in_style_of(last.value, new.entries[key])
                edits[last.line] = [raw[: last.value_col - 1] + text + (_eol(raw) or eol)]
        added = [f"{key}={text}{eol}" for key, text in new.entries.items() if key not in by_key]
        if added:
            kept = edits.get(last_line, [lines[last_line - 1]])
            if kept and not _eol(kept[-1]):
                kept = [*kept[:-1], kept[-1] + eol]
            edits[last_line] = kept + added
    appended = [s for name, s in after.items() if name not in before]
    if appended:
        edits[len(lines) + 1] = [eol] + [line + eol for line in render(appended, []).splitlines()]
    return edits
