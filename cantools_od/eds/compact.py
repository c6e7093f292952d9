"""Compact storage: CompactSubObj with [xxxxName]/[xxxxValue]/[xxxxDenotation], and CompactPDO."""

from __future__ import annotations

from ..model import AccessType, Device, NodeIdExpr, Object, ObjectKind, Origin, SubObject
from ..model.assemble import construct, fresh
from ..model.cia301.cobid import VALID
from ..model.cia301.pdo import (
    COMM_BASE,
    COMM_SUBS,
    MAP_BASE,
    MAPPING_ENTRY_TYPE,
    MAX_ENTRIES,
    PDO_SPAN,
    PREDEFINED,
    RX,
    count_pdos,
)
from ..model.datatypes import UNSIGNED8
from ..model.plain import plain
from . import ini
from .keys import Kind, is_decimal, list_number
from .report import Report
from .sections import collect, raw_section
from .typed_values import type_entry
from .values import parse_int

NR_OF_OBJECTS = "NrOfObjects"


def implicit_sub_name(parent: Object, subindex: int) -> str:
    return NR_OF_OBJECTS if subindex == 0 else f"{parent.name}{subindex}"


def implicit_sub(parent: Object, subindex: int) -> SubObject:
    """The sub-object CompactSubObj implies at `subindex` of `parent`: of values the parent's fields already typed,
    so made without validation (which costs more than the rest of reading a sub-object, and at its first use in a
    process builds the class's schema and loads pydantic's plugins: 30 ms)."""
    if subindex == 0:
        return fresh(SubObject, {
            "name": NR_OF_OBJECTS, "data_type": UNSIGNED8.index, "access": AccessType.RO, "pdo_mapping": False,
            "default": parent.compact_sub_obj, "implicit": True,
        })  # fmt: skip
    return fresh(
        SubObject,
        {
            "name": implicit_sub_name(parent, subindex),
            "data_type": parent.data_type,
            "access": parent.access,
            "pdo_mapping": parent.pdo_mapping,
            "default": parent.default,
            "implicit": True,
        },
    )


def expand_compact_sub_objects(device: Device) -> None:
    """Every CompactSubObj parent gets sub0 and subs 1..n unless a section gives them."""
    for obj in device.objects.values():
        count = obj.compact_sub_obj
        if not count or count < 0:
            continue
        subs = dict(obj.subs)
        for subindex in range(0, min(count, 0xFE) + 1):
            if subindex not in subs:
                subs[subindex] = implicit_sub(obj, subindex)
        obj.subs = dict(sorted(subs.items()))


def apply_compact_sections(device: Device, sections: list[tuple[int, str, ini.IniSection]], report: Report) -> None:
    """[xxxxName], [xxxxValue], [xxxxDenotation] and [xxxxObjectLinks]."""
    for index, kind, section in sections:
        obj = device.objects.get(index)
        if obj is None:
            report.error("EDS104", f"[{section.name}]: object {index:04X} has no section", section.line, section.column)
            _keep(device, section, report)
            continue
        if kind == "objectlinks":
            _object_links(device, obj, section, report)
            continue
        if not obj.compact_sub_obj:
            report.error(
                "EDS104", f"[{section.name}]: object {index:04X} has no CompactSubObj", section.line, section.column
            )
            _keep(device, section, report)
            continue
        collected = collect(section, {"nrofentries": ("NrOfEntries", "count", Kind.INT)}, report)
        keys = [k for k in collected.extra if (list_number(k) or 0xFF) <= 0xFE]
        if len(keys) != len(collected.extra):
            odd = ", ".join(k for k in collected.extra if k not in keys)
            report.error(
                "EDS104", f"[{section.name}]: keys must be sub-indices 1-254 in decimal ({odd})", section.line, 1
            )
            _keep(device, section, report)
            continue
        count = collected.fields.get("count")
        if count != len(keys):
            line, column, _ = collected.origin.where("NrOfEntries") or (section.line, 1, 1)
            report.error("EDS104", f"[{section.name}]: NrOfEntries={count} but {len(keys)} entries", line, column)
        by_key = {e.key: e for e in section.entries}
        for key in keys:
            subindex = int(key)
            sub = obj.subs.get(subindex)
            if sub is None:
                report.error(
                    "EDS104", f"[{section.name}] {key}: beyond CompactSubObj={obj.compact_sub_obj}", by_key[key].line, 1
                )
                sub = obj.subs[subindex] = implicit_sub(obj, subindex)
                obj.subs = dict(sorted(obj.subs.items()))
            _locate(sub, section, kind, by_key[key], report.file)
            if kind == "name":
                sub.name = collected.extra[key]
            elif kind == "denotation":
                sub.denotation = collected.extra[key]
            else:
                type_entry(device, sub, obj, "parameter_value", by_key[key], report)


_COMPACT_KEYS = {"name": "ParameterName", "value": "ParameterValue", "denotation": "Denotation"}


def _locate(sub: SubObject, section: ini.IniSection, kind: str, entry: ini.Entry, file: str) -> None:
    """An implicit sub-object's value is written in [xxxxName/Value/Denotation]: findings about it go there."""
    if sub.origin is None:
        sub.origin = fresh(Origin, {"file": file, "line": section.line, "column": section.column})
    # a new dict: origins built by the reader may share one empty dict
    sub.origin.keys = {**sub.origin.keys, _COMPACT_KEYS[kind]: (entry.line, entry.key_col, entry.value_col)}


def _object_links(device: Device, obj: Object, section: ini.IniSection, report: Report) -> None:
    collected = collect(section, {"objectlinks": ("ObjectLinks", "count", Kind.INT)}, report)
    links: list[int] = []
    for key, text in collected.extra.items():
        try:
            target, _ = parse_int(text)
        except ValueError:
            target = None
        if not (is_decimal(key) and isinstance(target, int)):
            report.error("EDS104", f"[{section.name}] {key}={text}: not a numbered object index", section.line, 1)
            _keep(device, section, report)
            return
        links.append(target)
    if collected.fields.get("count") != len(links):
        line, column, _ = collected.origin.where("ObjectLinks") or (section.line, 1, 1)
        message = f"[{section.name}]: ObjectLinks={collected.fields.get('count')} but {len(links)} entries"
        report.error("EDS104", message, line, column)
    obj.links = links


def _keep(device: Device, section: ini.IniSection, report: Report) -> None:
    device.other_sections.append(raw_section(section, report))


def expand_compact_pdo(device: Device) -> None:
    """With CompactPDO≠0, the PDOs NrOfRXPDO/NrOfTXPDO count but the file omits (CiA 306 §4.6.3.4.1)."""
    info = device.device_info
    mask = info.compact_pdo or 0
    if not mask:
        return
    for direction, base in COMM_BASE.items():
        predefined, map_base = PREDEFINED[direction], MAP_BASE[direction]
        wanted = (info.nr_of_rx_pdo if direction == RX else info.nr_of_tx_pdo) or 0
        present = count_pdos(device.objects, direction)
        missing = max(0, min(wanted, PDO_SPAN) - present)
        number = 0
        while missing and number < PDO_SPAN:
            if base + number not in device.objects:
                cob_id = construct(NodeIdExpr, {"offset": predefined[number]}) if number < len(predefined) else VALID
                device.objects[base + number] = _comm_object(base + number, mask, cob_id, direction)
                if map_base + number not in device.objects:
                    device.objects[map_base + number] = _mapping_object(map_base + number, direction)
                missing -= 1
            number += 1


def _comm_object(index: int, mask: int, cob_id: int | NodeIdExpr, direction: str) -> Object:
    subs = {}
    for subindex, (name, dtype) in COMM_SUBS.items():
        if mask & (1 << (subindex - 1)):
            default: int | NodeIdExpr = {1: cob_id, 2: 0xFF}.get(subindex, 0)
            subs[subindex] = _implied(name, dtype, AccessType.RW, default)
    subs[0] = _implied("Highest sub-index supported", UNSIGNED8.index, AccessType.RO, max(subs, default=0))
    kind = "RPDO" if direction == RX else "TPDO"
    return fresh(Object, {
        "index": index, "name": f"{kind} communication parameter", "object_type": ObjectKind.RECORD,
        "subs": dict(sorted(subs.items())), "implicit": True,
    })  # fmt: skip


def _mapping_object(index: int, direction: str) -> Object:
    kind = "RPDO" if direction == RX else "TPDO"
    subs = {0: _implied("Number of mapped objects", UNSIGNED8.index, AccessType.RW, 0)}
    for subindex in range(1, MAX_ENTRIES + 1):
        subs[subindex] = _implied(f"Mapped object {subindex}", MAPPING_ENTRY_TYPE, AccessType.RW, 0)
    return fresh(Object, {
        "index": index, "name": f"{kind} mapping parameter", "object_type": ObjectKind.RECORD, "subs": subs,
        "implicit": True,
    })  # fmt: skip


def _implied(name: str, data_type: int, access: AccessType, default: int | NodeIdExpr) -> SubObject:
    """A sub-object CompactPDO implies, of values known to be of the right types (see `implicit_sub`)."""
    return fresh(
        SubObject, {"name": name, "data_type": data_type, "access": access, "default": default, "implicit": True}
    )


_COMPACT_SECTIONS = {"name", "parameter_value", "denotation", "comments"}  # what [xxxxName/Value/...] carry


def compact_form_holds(parent: Object, subindex: int, sub: SubObject) -> bool:
    """Whether CompactSubObj and its [xxxxName/Value/Denotation] sections still say all of `sub`."""
    left_out = _COMPACT_SECTIONS | {"origin"}
    return plain(sub, left_out) == plain(implicit_sub(parent, subindex), left_out)


def implied_pdo_objects(device: Device) -> dict[int, Object]:
    """The objects CompactPDO implies for this device, as the reader creates them."""
    explicit = {index: obj for index, obj in device.objects.items() if not obj.implicit}
    probe = Device.model_construct(device_info=device.device_info, objects=dict(explicit))
    expand_compact_pdo(probe)
    return {index: obj for index, obj in probe.objects.items() if index not in explicit}


def same_object(a: Object, b: Object) -> bool:
    return plain(a, ("origin",)) == plain(b, ("origin",))
