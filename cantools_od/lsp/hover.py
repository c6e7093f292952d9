"""Hover: what an object, a key, a mapping entry or a COB-ID means, decoded through the model."""

from __future__ import annotations

from ..eds.keys import COMMISSIONING_KEYS, DEVICE_INFO_KEYS, FILE_INFO_KEYS, normalize
from ..model import Commissioning, Device, DeviceInfo, FileInfo, Object, ObjectKind, Variable
from ..model.cia301 import cia402, definitions
from ..model.cia301.cobid import ALL_NODE_IDS, EXTENDED, RTR, VALID, Cob, known_node_id
from ..model.cia301.connections import cob_entries, predefined_cob_base
from ..model.cia301.pdo import MapEntry, decode_entry, dummy_type, is_dummy_index, is_mapping, pdos
from ..model.cia301.slots import as_int
from ..model.datatypes import standard_type
from ..model.values import NodeIdExpr
from .where import Spot


def standard_name(index: int, subindex: int | None) -> str | None:
    """The name CiA 301/302 or CiA 402 gives the object (or its sub-index), with the clause defining it."""
    found = definitions.definition(index) or cia402.definition(index)
    if found is None:
        return None
    name = found.name
    if subindex is not None and found.kind is not ObjectKind.VAR:
        entry = found.entry(subindex)
        if entry is not None:
            name = f"{name}: {entry.name}"
    return f"{name} ({found.clause})"


def type_name(device: Device, index: int | None) -> str:
    if index is None:
        return "not given"
    dtype = standard_type(index)
    if dtype is None:
        alias = device.objects.get(index)
        named = f" ({alias.name})" if alias is not None and alias.name else ""
        return f"{index:04X}h{named}"
    return f"{dtype.name} ({index:04X}h)"


def shown(value: object, node_id: int | None) -> str:
    """A value as written, with what `$NODEID` makes of it for the known node-ID."""
    if isinstance(value, NodeIdExpr):
        if node_id is None:
            return f"`{value.canonical()}` (the node-ID plus 0x{value.offset:X})"
        return f"`{value.canonical()}` = 0x{value.resolve(node_id):X} for node-ID {node_id}"
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, int):
        if value.bit_length() > 128:
            return f"a number of {value.bit_length()} bits"
        return f"{value} (0x{value:X})" if value >= 0 else str(value)
    return f"`{value!r}`" if isinstance(value, bytes) else f"`{value}`"


def _rows(device: Device, var: Variable, owner: Object, node_id: int | None) -> list[str]:
    rows = []
    if var is owner:
        rows.append(f"| object type | {owner.kind.name} |")
    if var is not owner or not owner.has_subs:
        rows.append(f"| data type | {type_name(device, var.data_type)} |")
        rows.append(f"| access | {var.access.value if var.access is not None else 'not given'} |")
        rows.append(f"| PDO mapping | {'yes' if var.pdo_mapping else 'no'} |")
    for label, value in (("low limit", var.low_limit), ("high limit", var.high_limit), ("default", var.default)):
        if value is not None:
            rows.append(f"| {label} | {shown(value, node_id)} |")
    if var.parameter_value is not None:
        rows.append(f"| parameter value | {shown(var.parameter_value, node_id)} |")
    if var is owner and owner.has_subs:
        rows.append(f"| sub-indices | {len(owner.subs)} |")
    return rows


def section_key(spot: Spot) -> str | None:
    """A key of [FileInfo], [DeviceInfo] or [DeviceComissioning]: its CiA 306 spelling and the value as read."""
    tables = {FileInfo: FILE_INFO_KEYS, DeviceInfo: DEVICE_INFO_KEYS, Commissioning: COMMISSIONING_KEYS}
    table = tables.get(type(spot.section))
    found = table.get(normalize(spot.key)) if table is not None and spot.key is not None else None
    if found is None:
        return None
    spelling, field, _ = found
    value: object = spot.section
    for part in field.split("."):
        value = value.get(int(part)) if isinstance(value, dict) else getattr(value, part, None)
    lines = [f"**{spelling}** ({type(spot.section).__name__})", ""]
    if spelling.startswith("BaudRate_"):
        rate = spelling.removeprefix("BaudRate_")
        said = {True: "supported", False: "not supported", None: "not given"}.get(value, f"{value}")  # type: ignore[call-overload]
        return "\n".join([*lines, f"The bit rate {rate} kbit/s: {said}."])
    return "\n".join([*lines, f"Read as {shown(value, None)}." if value is not None else "Not given."])


def pdo_layout(device: Device, owner: Object) -> list[str] | None:
    """A mapping object's PDO, bit by bit: each mapped object with its bits."""
    found = next((pdo for pdo in pdos(device) if pdo.mapping is owner), None) if is_mapping(owner.index) else None
    if found is None:
        return None
    rows = []
    for entry in found.entries():
        index, sub, bits = decode_entry(entry.raw)
        target = device.objects.get(index)
        mapped = target.entry(sub) if target is not None else None
        name = "dummy" if is_dummy_index(index) else (mapped.name or target.name) if mapped and target else "?"
        rows.append(f"| {entry.offset}-{entry.offset + bits - 1} | {index:04X}h sub{sub:X} | {name} |")
    if not rows:
        return [f"{found.name}: no object mapped."]
    total = max(entry.offset + decode_entry(entry.raw)[2] for entry in found.entries())
    return [f"{found.name}, {total} bits:", "", "| bits | object | name |", "|---|---|---|", *rows]


def describe(device: Device, spot: Spot, node_id: int | None) -> str | None:
    """Markdown for the spot: the entry's decoded fields, then what its value means, when it means more."""
    owner, var = spot.owner, spot.var
    if owner is None or var is None:
        return section_key(spot)
    node = known_node_id(device, node_id)
    sub = "" if spot.subindex is None or not owner.has_subs else f" sub{spot.subindex:X}"
    title = f"**{owner.index:04X}h{sub}** {var.name or owner.name}"
    standard = standard_name(owner.index, spot.subindex if owner.has_subs else None)
    lines = [title, ""]
    if standard:
        lines += [f"Standard: {standard}", ""]
    lines += ["| | |", "|---|---|", *_rows(device, var, owner, node)]
    if spot.subindex is not None:
        extra = mapping_entry(device, owner, spot.subindex) or cob_id(device, owner, spot.subindex, node)
        if extra:
            lines += ["", *extra]
    elif spot.key is None:
        layout = pdo_layout(device, owner)
        if layout:
            lines += ["", *layout]
    return "\n".join(lines)


def _find_entry(device: Device, owner: Object, position: int) -> tuple[str, MapEntry | None]:
    for pdo in pdos(device):
        if pdo.mapping is owner:
            entry = next((e for e in pdo.entries() if e.position == position), None)
            return pdo.name, entry
    return "", None


def mapping_entry(device: Device, owner: Object, subindex: int) -> list[str] | None:
    """A PDO mapping entry: the object it maps, its bits in the PDO."""
    if not is_mapping(owner.index) or subindex == 0:
        return None
    pdo_name, entry = _find_entry(device, owner, subindex)
    var = owner.entry(subindex)
    raw = as_int(var.value()) if var is not None else None
    if entry is None and raw is None:
        return None
    value = entry.raw if entry is not None else (raw or 0) & 0xFFFFFFFF
    index, sub, bits = decode_entry(value)
    if value == 0:
        return ["Mapping entry: empty (0), maps nothing."]
    where = (
        f"bits {entry.offset}-{entry.offset + bits - 1} of {pdo_name}" if entry is not None and bits else "not in use"
    )
    if entry is None:
        where = "beyond the number of mapped objects (sub0): not in use"
    lines = [f"Mapping entry 0x{value:08X}: index {index:04X}h, sub-index {sub:X}h, {bits} bits; {where}."]
    if is_dummy_index(index):
        dtype = dummy_type(device, index)
        lines.append(f"A dummy entry of type {dtype.name if dtype else f'{index:04X}h'}: the receiver skips its bits.")
        return lines
    target = device.objects.get(index)
    mapped = target.entry(sub) if target is not None else None
    if target is None or mapped is None:
        lines.append(f"Maps {index:04X}h sub{sub:X}, which this file does not describe.")
    else:
        name = mapped.name or target.name
        lines.append(f"Maps **{index:04X}h sub{sub:X} {name}**: {type_name(device, mapped.data_type)}.")
    return lines


def _cob(device: Device, owner: Object, subindex: int) -> Cob | None:
    for cob in cob_entries(device, pdos(device)):
        if cob.slot is not None and cob.slot.owner is owner and cob.slot.subindex == subindex:
            return cob
    return None


def cob_id(device: Device, owner: Object, subindex: int, node_id: int | None) -> list[str] | None:
    """A COB-ID entry: its bits, its CAN-ID, and whether it follows the node-ID."""
    cob = _cob(device, owner, subindex)
    if cob is None:
        return None
    value = cob.at(node_id or 0)
    extended, can_id = cob.can_id(node_id or 0)
    lines = [
        f"COB-ID of {cob.role}: CAN-ID {can_id:X}h{' (29-bit)' if extended else ''}"
        + (f" for node-ID {node_id}" if cob.symbolic and node_id else ""),
        "",
        f"- bit 31 (valid): {'1, not valid (off)' if value & VALID else '0, valid'}",
        f"- bit 30 (RTR): {'1, no RTR allowed' if value & RTR else '0, RTR allowed'}",
        f"- bit 29 (frame): {'1, 29-bit CAN-ID' if value & EXTENDED else '0, 11-bit CAN-ID'}",
    ]
    base = predefined_cob_base(owner.index, subindex)
    if cob.symbolic:
        lines.append(f"- follows the node-ID: `{cob.written}`")
    elif base is not None and can_id - base in ALL_NODE_IDS:
        lines.append(
            f"- fixed: the pre-defined identifier of node-ID {can_id - base} ({base:X}h + {can_id - base});"
            f" it does not follow the node-ID (write `$NODEID+0x{base:X}` for that)"
        )
    else:
        lines.append("- fixed: does not follow the node-ID")
    return lines
