"""The module concept of CiA 306 (section 6): the objects a modular device's modules create.

A bus coupler's EDS lists in [SupportedModules] the modules that may be plugged in. Each module's
[M<x>FixedObjects] names objects created once when at least one such module is connected; its
[M<x>SubExtends] names objects that every connected module of that kind extends by sub-indices.
A DCF's [ConnectedModules] lists the modules plugged in, in slot order. The sections stay raw text
in the model (`Device.module_sections`); this module reads what the PDO checks and views need.
"""

from __future__ import annotations

import dataclasses
import re
from dataclasses import dataclass

from ..datatypes import DataType, standard_type
from ..device import Device, RawSection

_LIST = re.compile(r"m([1-9][0-9]*)(fixedobjects|subextends)\Z", re.IGNORECASE)


@dataclass(frozen=True)
class ModuleObject:
    """An object a module creates: its index, the first module that lists it, and its description."""

    index: int
    module: int
    name: str
    data_type: DataType | None
    highest: int | None = None  # with [ConnectedModules]: the highest sub-index the connected modules extend
    # it to ([M<x>SubExt<idx>] Count added per connected module); None where that is not known

    def has(self, subindex: int) -> bool:
        return self.highest is None or subindex <= self.highest


def _value(raw: RawSection, key: str) -> str | None:
    return next((v for k, v in raw.entries.items() if k.lower() == key.lower()), None)


def _number(text: str | None) -> int | None:
    try:
        return int(text.strip(), 0) if text is not None else None
    except ValueError:
        return None


def object_section_name(module: int, part: str, index: int) -> str:
    """`M3SubExtA0`: the section describing a module's object, its index in hex without leading zeros."""
    return f"M{module}{part}{index:X}"


def _object_section(device: Device, module: int, part: str, index: int) -> RawSection | None:
    """The [M<x>Fixed<idx>] or [M<x>SubExt<idx>] section, with or without leading zeros in <idx>."""
    prefix = f"m{module}{part}".lower()
    for raw in device.module_sections:
        name = raw.name.lower()
        digits = name[len(prefix) :]
        if name.startswith(prefix) and re.fullmatch(r"[0-9a-f]+", digits) and int(digits, 16) == index:
            return raw
    return None


def has_module_section(device: Device, module: int, part: str, index: int) -> bool:
    return _object_section(device, module, part, index) is not None


def supports_modules(device: Device) -> bool:
    return any(raw.name.lower() == "supportedmodules" for raw in device.module_sections)


def connected_modules(device: Device) -> list[int] | None:
    """The module numbers [ConnectedModules] lists in slot order; None when the file has no such section."""
    for raw in device.module_sections:
        if raw.name.lower() == "connectedmodules":
            listed = sorted((int(k), v) for k, v in raw.entries.items() if k.isdigit())
            return [n for n in (_number(v) for _, v in listed) if n is not None]
    return None


def module_objects(device: Device) -> dict[int, ModuleObject]:
    """The objects modules may create: of the connected modules when a DCF lists them, else of every
    supported module (an EDS describes what may be plugged in)."""
    connected = connected_modules(device)
    wanted = set(connected) if connected is not None else None
    found: dict[int, ModuleObject] = {}
    for raw in device.module_sections:
        match = _LIST.match(raw.name)
        if match is None:
            continue
        module = int(match.group(1))
        if wanted is not None and module not in wanted:
            continue
        part = "Fixed" if match.group(2).lower() == "fixedobjects" else "SubExt"
        for key, text in raw.entries.items():
            index = _number(text) if key.isdigit() else None
            if index is None or index in found:
                continue
            section = _object_section(device, module, part, index)
            name = (_value(section, "ParameterName") or "") if section is not None else ""
            dtype = standard_type(_number(_value(section, "DataType"))) if section is not None else None
            found[index] = ModuleObject(index, module, name, dtype)
    if connected is not None:
        _count_extensions(device, connected, found)
    return found


def _count_extensions(device: Device, connected: list[int], found: dict[int, ModuleObject]) -> None:
    """Sub-indices of each extended object: the Count of every connected module that extends it, added up.
    A packed Count (`0;<bits>`, several modules in one sub-index) leaves the object's size unknown."""
    totals: dict[int, int | None] = {}
    for module in connected:
        for index in found:
            section = _object_section(device, module, "SubExt", index)
            if section is None:
                continue
            count = _number((_value(section, "Count") or "").split(";")[0])
            before = totals.get(index, 0)
            totals[index] = None if before is None or not count else before + count
    for index, total in totals.items():
        found[index] = dataclasses.replace(found[index], highest=total)
