"""What python-canopen reads differently where CiA 306 reads the same: a key or section name it looks up
case-sensitively (lint's DIA018), written as it spells it on one side only. `BaudRate=500` → `Baudrate=500` in
[DeviceComissioning] means 500 kbit/s to CiA 306 and lely on both sides; python-canopen reads no bit rate
before and 500 kbit/s after. Such a change is reported whatever the text says.

Which names python-canopen looks up is lint's knowledge (`lint/syntax.py`), used here as it is.
"""

from __future__ import annotations

from collections.abc import Iterator

from ..eds.peer_names import python_canopen_reads
from ..eds.preserve import canonical_section_name
from ..model import Device, Section
from . import describe
from .records import Change, Impact, Kind, new_change

_DEVICE_SECTIONS = {
    "file_info": "[FileInfo]",
    "device_info": "[DeviceInfo]",
    "dummy_usage": "[DummyUsage]",
    "comments": "[Comments]",
    "commissioning": "[DeviceComissioning]",
}


def _found(section: Section | None, name: str) -> bool | None:
    """Whether python-canopen finds the key (`""`: the section's own name); None when the file has none."""
    origin = section.origin if section is not None else None
    if origin is None:
        return None
    if name and origin.where(name) is None:
        return None
    return name not in origin.spelled


def _pairs(old: Device, new: Device) -> Iterator[tuple[str, int | None, int | None, Section | None, Section | None]]:
    """(where, index, sub-index, old section, new section) of every section both files may have."""
    for name in _DEVICE_SECTIONS:
        yield name, None, None, getattr(old, name), getattr(new, name)
    for index in sorted(set(old.objects) & set(new.objects)):
        before, after = old.objects[index], new.objects[index]
        yield "", index, None, before, after
        for sub in sorted(set(before.subs) & set(after.subs)):
            yield "", index, sub, before.subs[sub], after.subs[sub]


def _names(before: Section, after: Section) -> set[str]:
    """The names written otherwise on either side that python-canopen looks up (`""`: the section's own)."""
    names: set[str] = set()
    for section in (before, after):
        if section.origin is not None:
            names |= {name for name in section.origin.spelled if python_canopen_reads(_canonical(section, name))}
    return names


def _canonical(section: Section, name: str) -> str:
    if name:
        return name
    assert section.origin is not None
    return canonical_section_name(section.origin.spelled[""])


def spelling_changes(old: Device, new: Device) -> Iterator[Change]:
    """One change per name python-canopen finds on one side only, though both sides have it."""
    for where, index, sub, before, after in _pairs(old, new):
        if before is None or after is None or (before.origin is None and after.origin is None):
            continue
        if not (before.origin and before.origin.spelled) and not (after.origin and after.origin.spelled):
            continue  # the common case: both written as CiA 306 spells them
        was, now = _found(before, ""), _found(after, "")
        if was is not None and now is not None and was != now:  # the section itself: its keys go with it
            yield _change(where, index, sub, "", before, after, now)
            continue
        for name in sorted(_names(before, after) - {""}):
            was, now = _found(before, name), _found(after, name)
            if was is None or now is None or was == now:
                continue
            yield _change(where, index, sub, name, before, after, now)


def _written(section: Section, name: str) -> str:
    assert section.origin is not None
    return section.origin.spelled.get(name, name)


def _change(
    where: str, index: int | None, sub: int | None, name: str, before: Section, after: Section, now: bool
) -> Change:
    what = f"[{_written(before, name)}]" if not name else _written(before, name)
    shown = f"[{_written(after, name)}]" if not name else _written(after, name)
    place = describe.address(index, sub) or _DEVICE_SECTIONS[where]
    note = (
        f"python-canopen now reads {'the section' if not name else 'this key'} in {place}: it did not before"
        if now
        else f"python-canopen no longer reads {'the section' if not name else 'this key'} in {place}: "
        "it looks names up case-sensitively"
    )
    return new_change(
        kind=Kind.PEER_READING,
        impact=Impact.VALUE,
        index=index,
        subindex=sub,
        field=f"{where + '.' if where else ''}spelling.{name or 'section'}",
        old=what,
        new=shown,
        old_text=what,
        new_text=shown,
        note=note,
    )
