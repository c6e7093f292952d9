"""A plain text diff of each object's section of two EDS/DCF files, and whether `diff` tells each changed line.

Independent of our reader on purpose: sections and `key=value` lines are split here, as a reviewer reads the
text, so that a line our reader could not interpret still counts. A changed line is told when `diff` has a
change of its field at its entry (or of the whole object or sub-object, or of the PDO made of it), or it is
formatting: the same value in another spelling (radix, case, blanks, a key absent that reads as its default).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from cantools_od.changes import DeviceDiff, Kind
from cantools_od.xdd.vocabulary import PARAMETER_ACCESS, TYPE_ELEMENTS

OBJECT_SECTION = re.compile(r"^([0-9A-F]{4})(?:sub([0-9A-F]{1,2})|(Name|Value))?$", re.IGNORECASE)
Entry = tuple[int, int | None]

# Key → the change fields that tell it.
FIELDS = {
    "parametername": {"name", "identifier", "flat_identifier"},
    "objecttype": {"object_type"},
    "datatype": {"data_type"},
    "accesstype": {"access"},
    "pdomapping": {"pdo_mapping"},
    "defaultvalue": {"default"},
    "parametervalue": {"parameter_value"},
    "lowlimit": {"low_limit"},
    "highlimit": {"high_limit"},
    "objflags": {"obj_flags"},
    "denotation": {"denotation"},
    "paramrefd": {"param_refd"},
    "uploadfile": {"upload_file"},
    "downloadfile": {"download_file"},
    "objectlinks": {"links"},
    # XDD: attributes of CANopenObject and CANopenSubObject, and what their parameter states
    "name": {"name", "identifier", "flat_identifier"},
    "parameter/label": {"name", "identifier", "flat_identifier"},
    "actualvalue": {"parameter_value"},
    "parameter/defaultvalue@value": {"default"},
    "parameter/actualvalue@value": {"parameter_value"},
    "parameter/description": {"extra.Description"},
}
# XDD keys that only link or label what other keys state: the reference between an object and its parameter,
# the language of a text.
LINKS = ("uniqueidref", "@lang", "@uniqueidref")
# Keys whose absence reads as this value (CiA 306).
ABSENT_READS_AS = {"pdomapping": "0", "parameter/label": "", "objflags": "0", "compactsubobj": "0", "objecttype": "7"}
# Signed types by data-type index → bits: a hex value of one is its two's complement (CiA 306: 0xFD of an
# INTEGER8 is -3), the same value as the decimal.
SIGNED_BITS = {0x2: 8, 0x3: 16, 0x4: 32, 0x10: 24, 0x12: 40, 0x13: 48, 0x14: 56, 0x15: 64}
# Keys of the sub-object list, told by the sub-objects added or removed.
COUNTS = {"subnumber", "nrofentries", "compactsubobj"}


def sections(path: Path) -> dict[Entry, dict[str, str]]:
    """(index, sub-index) → {lower-case key: value as written}; [xxxxName]/[xxxxValue] lines (CompactSubObj)
    go to the sub-object their key numbers, with the key ParameterName or ParameterValue."""
    found: dict[Entry, dict[str, str]] = {}
    current: tuple[int, int | None, str | None] | None = None
    for raw in path.read_bytes().decode("latin-1").splitlines():
        line = raw.strip()
        if not line or line.startswith(";"):
            continue
        if line.startswith("[") and "]" in line:
            match = OBJECT_SECTION.match(line[1 : line.index("]")].strip())
            current = None
            if match:
                index, sub, table = match.groups()
                current = (int(index, 16), int(sub, 16) if sub else None, table.lower() if table else None)
                found.setdefault(current[:2], {})
            continue
        key, equals, value = line.partition("=")
        if current is None or not equals:
            continue
        index, sub, table = current
        if table is None:
            found[(index, sub)][key.strip().lower()] = value.strip()
        elif key.strip().isdigit():
            name = "parametername" if table == "name" else "parametervalue"
            found.setdefault((index, int(key.strip())), {})[name] = value.strip()
    return found


@dataclass(frozen=True)
class Line:
    entry: Entry
    key: str
    old: str | None
    new: str | None
    bits: int | None = None
    """The width of the entry's signed type, as written on the new side (None: not signed)."""


def changed_lines(old: Path, new: Path) -> Iterator[Line]:
    read = xml_sections if new.suffix.lower() in (".xdd", ".xdc") else sections
    before, after = read(old), read(new)
    for entry in sorted(set(before) | set(after), key=lambda e: (e[0], -1 if e[1] is None else e[1])):
        was, now = before.get(entry, {}), after.get(entry, {})
        for key in sorted(set(was) | set(now)):
            if was.get(key) != now.get(key):
                yield Line(entry, key, was.get(key), now.get(key), _signed_bits(now.get("datatype")))


def _signed_bits(text: str | None) -> int | None:
    try:
        return SIGNED_BITS.get(int(text or "", 0))
    except ValueError:
        return None


def _normal(key: str, text: str | None, bits: int | None) -> str | None:
    """A value in one spelling: numbers by value, words in lower case without blanks; empty as absent."""
    if not text:
        return ABSENT_READS_AS.get(key)
    compact = re.sub(r"\s+", "", text).lower()
    try:
        number = int(compact, 0)
    except ValueError:
        pass
    else:
        return str(number % (1 << bits) if bits else number)
    if re.fullmatch(r"0x[0-9a-f]+\+\$nodeid|\$nodeid\+0x[0-9a-f]+|\$nodeid\+\d+|\d+\+\$nodeid", compact):
        offset = compact.replace("$nodeid", "").strip("+")
        return f"$nodeid+{int(offset, 0)}"
    return compact


def formatting(line: Line) -> bool:
    """The same value in another spelling, or a key that only links or labels."""
    if line.key.endswith(LINKS):
        return True
    return _normal(line.key, line.old, line.bits) == _normal(line.key, line.new, line.bits)


_WHOLE = {Kind.OBJECT_ADDED, Kind.OBJECT_REMOVED, Kind.OBJECT_MOVED, Kind.OBJECT_TYPE}
_ENTRY = {Kind.SUB_ADDED, Kind.SUB_REMOVED, Kind.SUB_MOVED}


def told(line: Line, result: DeviceDiff) -> bool:
    """`diff` tells the line: a change of its field at its entry, of the whole object or entry, of its PDO."""
    index, sub = line.entry
    wanted = FIELDS.get(line.key, set())
    if line.key.startswith("property.co_"):  # CANopenNode properties: CO_storageGroup → storage_group...
        wanted = {change.field for change in result.changes() if change.field.startswith("canopennode.")}
    for change in result.changes():
        if change.index != index and not (change.kind is Kind.OBJECT_MOVED and change.old == index):
            continue
        if change.kind in _WHOLE and change.subindex is None:
            return True
        if change.subindex == sub and (
            change.kind in _ENTRY or change.field in wanted or change.field.lower() == f"extra.{line.key}"
        ):
            return True
        if line.key in COUNTS and change.kind in _ENTRY:
            return True
        if change.kind is Kind.SUB_MOVED and change.old == sub:  # moved away from this sub-index
            return True
    return _pdo_told(line, result)


def _pdo_told(line: Line, result: DeviceDiff) -> bool:
    index, sub = line.entry
    for pdo in result.pdos:
        for change in pdo.changes:
            if change.kind in (Kind.PDO_ADDED, Kind.PDO_REMOVED) and index in (pdo.comm_index, pdo.map_index):
                return True
            if change.kind is Kind.PDO_LAYOUT and index == pdo.map_index:
                return True
            if change.index == index and change.subindex == sub:
                return True
    return False


def misses(old: Path, new: Path, result: DeviceDiff) -> list[Line]:
    """The changed lines `diff` does not tell and that are not formatting."""
    return [line for line in changed_lines(old, new) if not formatting(line) and not told(line, result)]


def _local(tag: str) -> str:
    return tag.rpartition("}")[2]


def _flat(element: ET.Element, prefix: str, into: dict[str, str]) -> None:
    """Every attribute and text under `element` as `path@attribute` → value; `property.NAME` for properties."""
    for child in element:
        name = _local(child.tag)
        if name == "property" and "name" in child.attrib:
            into[f"property.{child.attrib['name']}"] = child.attrib.get("value", "")
            continue
        path = f"{prefix}/{name}"
        for attribute, value in child.attrib.items():
            into[f"{path}@{_local(attribute)}"] = value
        if child.text and child.text.strip():
            into[path] = child.text.strip()
        elif not child.attrib and not len(child):
            into[path] = ""  # an element that states by its name only (the type of a parameter: <USINT />)
        _flat(child, path, into)


def xml_sections(path: Path) -> dict[Entry, dict[str, str]]:
    """(index, sub-index) → the attributes of its CANopenObject or CANopenSubObject, and what the parameter it
    refers to (uniqueIDRef) states under `parameter...` keys."""
    root = ET.parse(path).getroot()
    parameters: dict[str, dict[str, str]] = {}
    for element in root.iter():
        if _local(element.tag) == "parameter" and "uniqueID" in element.attrib:
            flat = {f"parameter@{_local(k)}": v for k, v in element.attrib.items() if _local(k) != "uniqueID"}
            _flat(element, "parameter", flat)
            parameters[element.attrib["uniqueID"]] = flat
    found: dict[Entry, dict[str, str]] = {}
    for element in root.iter():
        if _local(element.tag) != "CANopenObject":
            continue
        index = int(element.attrib["index"], 16)
        found[(index, None)] = _entry(element, parameters)
        for sub in element:
            if _local(sub.tag) == "CANopenSubObject":
                found[(index, int(sub.attrib["subIndex"], 16))] = _entry(sub, parameters)
    return found


def _entry(element: ET.Element, parameters: dict[str, dict[str, str]]) -> dict[str, str]:
    """The entry's keys; type and access that CiA 311 lets the parameter state instead (as CANopenEditor's
    later versions do) under the object's keys, so that moving them from one place to the other is no change."""
    keys = {_local(k).lower(): v for k, v in element.attrib.items() if _local(k) not in ("index", "subIndex")}
    parameter = dict(parameters.get(element.attrib.get("uniqueIDRef", ""), {}))
    access = parameter.pop("parameter@access", "read")  # CiA 311: a parameter is read-only unless it says
    if "accesstype" not in keys and access in PARAMETER_ACCESS:
        keys["accesstype"] = PARAMETER_ACCESS[access].value
    if "datatype" in keys:
        keys["datatype"] = f"0x{int(keys['datatype'], 16):04X}"  # hex digits without 0x in CiA 311
    for key in [key for key in parameter if key.startswith("parameter/") and key[10:] in TYPE_ELEMENTS]:
        keys.setdefault("datatype", f"0x{TYPE_ELEMENTS[key[10:]]:04X}")
        del parameter[key]
    keys.setdefault("pdomapping", "no")
    if "parameter/label" in parameter and parameter["parameter/label"] == keys.get("name"):
        del parameter["parameter/label"]
    return keys | {key.lower(): value for key, value in parameter.items()}
