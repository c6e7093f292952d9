"""The compact forms of an EDS (`CompactSubObj`, `CompactPDO`) in an XDD/XDC, where CiA 311 has no
attribute for them: one XML comment before the root element, as for `[Comments]` (see file_comments).

An XDD lists every object and sub-object explicitly; the comment says which of them an EDS left to
CompactSubObj and CompactPDO, so that an EDS written from the XDD leaves them out again. Without it, a
peer reads that EDS otherwise: python-canopen names and types the sub-objects of a compact array by its
own rules, and implies no PDO from CompactPDO.

The comment's first line is MARKER; each line after it is `<index in hex>=<count in decimal>` for an
array written with CompactSubObj, `<index in hex>=CompactPDO` for an object CompactPDO implies, and
`CompactPDO=<mask in hex>`. Reading gives a compact form back only where the XDD still says what that form
implies: an array listing exactly sub-indices 0 to its count (at most 254), whose sub-objects that no
longer follow it keep entries of their own as in an EDS; a PDO object equal to the one implied.
"""

from __future__ import annotations

import re
from typing import Any

from ..eds.compact import compact_form_holds, implied_pdo_objects
from ..model import Device, Object
from . import file_comments

MARKER = "cantools-od: EDS CompactSubObj/CompactPDO"
_FIRST_LINE = MARKER + " (index=count, index=CompactPDO, CompactPDO=mask): what an EDS writes compactly"
_PDO = "CompactPDO"
_LINE = re.compile(r"([0-9A-F]{4})=([0-9]{1,3}|CompactPDO)|CompactPDO=0x([0-9A-F]{1,2})")


def compact_block(device: Device) -> str | None:
    """The XML comment naming what `device` leaves to its compact forms; None when nothing."""
    lines = [f"{i:04X}={o.compact_sub_obj}" for i, o in device.objects.items() if _compact(o.compact_sub_obj)]
    implied = [f"{index:04X}={_PDO}" for index, obj in device.objects.items() if obj.implicit]
    if implied and device.device_info.compact_pdo:
        lines += [f"{_PDO}=0x{device.device_info.compact_pdo:02X}", *implied]
    return f"<!--{_FIRST_LINE}\n" + "".join(f"{line}\n" for line in lines) + "-->" if lines else None


def marked(text: str) -> bool:
    return file_comments.marked(text, MARKER)


def restore_compact(device: Device, text: str) -> None:
    """Gives back the compact forms the marked comment `text` names, where the objects still allow it."""
    implied: list[int] = []
    mask = None
    for line in text.splitlines()[1:]:
        match = _LINE.fullmatch(line.strip())
        if match is None:
            continue
        if match.group(3) is not None:
            mask = int(match.group(3), 16)
        elif match.group(2) == _PDO:
            implied.append(int(match.group(1), 16))
        else:
            _restore_array(device.objects.get(int(match.group(1), 16)), int(match.group(2)))
    if mask and implied and device.device_info.compact_pdo in (None, 0):
        _restore_pdos(device, mask, implied)


def _restore_array(obj: Object | None, count: int) -> None:
    if obj is None or not _compact(count) or list(obj.subs) != list(range(min(count, 0xFE) + 1)):
        return
    obj.compact_sub_obj, obj.sub_number = count, None
    for subindex, sub in obj.subs.items():
        sub.implicit = True
        sub.implicit = compact_form_holds(obj, subindex, sub)


def _restore_pdos(device: Device, mask: int, listed: list[int]) -> None:
    """The listed objects CompactPDO implies again unchanged become implied; CompactPDO is kept if any does."""
    device.device_info.compact_pdo = mask
    candidates = {index: _as_implied(device.objects[index]) for index in listed if index in device.objects}
    outside = {index: obj for index, obj in device.objects.items() if index not in candidates}
    probe = Device.model_construct(device_info=device.device_info, objects=outside)
    expected = implied_pdo_objects(probe)
    same = [
        index for index, obj in candidates.items() if index in expected and _essence(obj) == _essence(expected[index])
    ]
    for index in same:
        device.objects[index] = expected[index]  # as the EDS reader implies it
    if not same:
        device.device_info.compact_pdo = None


def _essence(obj: Object) -> dict[str, Any]:
    """What an object says, without where it was read and how its $NODEID values were spelled."""
    dump = obj.model_dump(exclude={"origin"})
    for sub in dump["subs"].values():
        sub.pop("origin", None)
        if isinstance(sub.get("default"), dict):
            sub["default"].pop("text", None)
    return dump


def _as_implied(obj: Object) -> Object:
    copy = obj.model_copy(deep=True)
    copy.implicit, copy.sub_number = True, None
    for sub in copy.subs.values():
        sub.implicit = True
    return copy


def _compact(count: int | None) -> bool:
    return count is not None and 0 < count <= 0xFF  # 255 is read as 254 sub-objects, as the EDS reader does
