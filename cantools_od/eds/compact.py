"""Compact storage: CompactSubObj with [xxxxName]/[xxxxValue]/[xxxxDenotation], and CompactPDO."""

from __future__ import annotations

from ..model import AccessType, Device, NodeIdExpr, Object, ObjectKind, SubObject
from . import ini
from .keys import Kind
from .report import Report
from .sections import collect, raw_section
from .typed_values import type_entry
from .values import parse_int

NR_OF_OBJECTS = "NrOfObjects"


def implicit_sub_name(parent: Object, subindex: int) -> str:
    return NR_OF_OBJECTS if subindex == 0 else f"{parent.name}{subindex}"


def implicit_sub(parent: Object, subindex: int) -> SubObject:
    """The sub-object CompactSubObj implies at `subindex` of `parent`."""
    if subindex == 0:
        return SubObject(
            name=NR_OF_OBJECTS, data_type=0x0005, access=AccessType.RO, pdo_mapping=False,
            default=parent.compact_sub_obj, implicit=True,
        )  # fmt: skip
    return SubObject(
        name=implicit_sub_name(parent, subindex),
        data_type=parent.data_type,
        access=parent.access,
        pdo_mapping=parent.pdo_mapping,
        default=parent.default,
        implicit=True,
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
        keys = [k for k in collected.extra if k.isdigit() and k == str(int(k)) and 1 <= int(k) <= 0xFE]
        if len(keys) != len(collected.extra):
            odd = ", ".join(k for k in collected.extra if k not in keys)
            report.error(
                "EDS104", f"[{section.name}]: keys must be sub-indices 1-254 in decimal ({odd})", section.line, 1
            )
            _keep(device, section, report)
            continue
        count = collected.fields.get("count")
        if count != len(keys):
            line, column, _ = collected.origin.keys.get("NrOfEntries", (section.line, 1, 1))
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
            if kind == "name":
                sub.name = collected.extra[key]
            elif kind == "denotation":
                sub.denotation = collected.extra[key]
            else:
                type_entry(device, sub, obj, "parameter_value", by_key[key], report)


def _object_links(device: Device, obj: Object, section: ini.IniSection, report: Report) -> None:
    collected = collect(section, {"objectlinks": ("ObjectLinks", "count", Kind.INT)}, report)
    links: list[int] = []
    for key, text in collected.extra.items():
        try:
            target, _ = parse_int(text)
        except ValueError:
            target = None
        if not (key.isdigit() and isinstance(target, int)):
            report.error("EDS104", f"[{section.name}] {key}={text}: not a numbered object index", section.line, 1)
            _keep(device, section, report)
            return
        links.append(target)
    if collected.fields.get("count") != len(links):
        line, column, _ = collected.origin.keys.get("ObjectLinks", (section.line, 1, 1))
        message = f"[{section.name}]: ObjectLinks={collected.fields.get('count')} but {len(links)} entries"
        report.error("EDS104", message, line, column)
    obj.links = links


def _keep(device: Device, section: ini.IniSection, report: Report) -> None:
    device.other_sections.append(raw_section(section, report))


_PDO_KINDS = (("rx", 0x1400, (0x200, 0x300, 0x400, 0x500)), ("tx", 0x1800, (0x180, 0x280, 0x380, 0x480)))
_COMM_SUBS = (  # (sub-index, name, data type)
    (1, "COB-ID", 0x0007),
    (2, "Transmission type", 0x0005),
    (3, "Inhibit time", 0x0006),
    (4, "Compatibility entry", 0x0005),
    (5, "Event timer", 0x0006),
    (6, "SYNC start value", 0x0005),
)


def expand_compact_pdo(device: Device) -> None:
    """With CompactPDO≠0, the PDOs NrOfRXPDO/NrOfTXPDO count but the file omits (cia306.md §8.4)."""
    info = device.device_info
    mask = info.compact_pdo or 0
    if not mask:
        return
    for direction, base, predefined in _PDO_KINDS:
        wanted = (info.nr_of_rx_pdo if direction == "rx" else info.nr_of_tx_pdo) or 0
        present = sum(1 for i in range(base, base + 0x200) if i in device.objects)
        missing = max(0, min(wanted, 0x200) - present)
        number = 0
        while missing and number < 0x200:
            if base + number not in device.objects:
                cob_id = NodeIdExpr(offset=predefined[number]) if number < 4 else 0x80000000
                device.objects[base + number] = _comm_object(base + number, mask, cob_id, direction)
                if base + 0x200 + number not in device.objects:
                    device.objects[base + 0x200 + number] = _mapping_object(base + 0x200 + number, direction)
                missing -= 1
            number += 1


def _comm_object(index: int, mask: int, cob_id: int | NodeIdExpr, direction: str) -> Object:
    subs = {}
    for subindex, name, dtype in _COMM_SUBS:
        if mask & (1 << (subindex - 1)):
            default: int | NodeIdExpr = {1: cob_id, 2: 0xFF}.get(subindex, 0)
            subs[subindex] = SubObject(name=name, data_type=dtype, access=AccessType.RW, default=default, implicit=True)
    subs[0] = SubObject(
        name="Highest sub-index supported", data_type=0x0005, access=AccessType.RO,
        default=max(subs, default=0), implicit=True,
    )  # fmt: skip
    kind = "RPDO" if direction == "rx" else "TPDO"
    return Object(
        index=index, name=f"{kind} communication parameter", object_type=ObjectKind.RECORD,
        subs=dict(sorted(subs.items())), implicit=True,
    )  # fmt: skip


def _mapping_object(index: int, direction: str) -> Object:
    kind = "RPDO" if direction == "rx" else "TPDO"
    subs = {
        0: SubObject(name="Number of mapped objects", data_type=0x0005, access=AccessType.RW, default=0, implicit=True)
    }
    for subindex in range(1, 0x41):
        subs[subindex] = SubObject(
            name=f"Mapped object {subindex}", data_type=0x0007, access=AccessType.RW, default=0, implicit=True
        )
    return Object(
        index=index, name=f"{kind} mapping parameter", object_type=ObjectKind.RECORD, subs=subs, implicit=True
    )


_COMPACT_SECTIONS = {"name", "parameter_value", "denotation", "comments"}  # what [xxxxName/Value/...] carry


def compact_form_holds(parent: Object, subindex: int, sub: SubObject) -> bool:
    """Whether CompactSubObj and its [xxxxName/Value/Denotation] sections still say all of `sub`."""
    implied = implicit_sub(parent, subindex).model_dump(exclude=_COMPACT_SECTIONS | {"origin"})
    return sub.model_dump(exclude=_COMPACT_SECTIONS | {"origin"}) == implied


def implied_pdo_objects(device: Device) -> dict[int, Object]:
    """The objects CompactPDO implies for this device, as the reader creates them."""
    explicit = {index: obj for index, obj in device.objects.items() if not obj.implicit}
    probe = Device.model_construct(device_info=device.device_info, objects=dict(explicit))
    expand_compact_pdo(probe)
    return {index: obj for index, obj in probe.objects.items() if index not in explicit}


def same_object(a: Object, b: Object) -> bool:
    return a.model_dump(exclude={"origin"}) == b.model_dump(exclude={"origin"})
