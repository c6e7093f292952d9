"""What a format cannot hold: the sections of a device that its output in another format does not
give back when read again, measured on the output itself rather than declared, so that `convert`
never drops something without a word.
"""

from __future__ import annotations

from .model import Device

# Sections compared, their names as a user knows them, and the formats that keep each.
_SECTIONS: tuple[tuple[str, str, str], ...] = (
    ("commissioning", "[DeviceComissioning] (node-ID, bit rate, node name)", "XDC and DCF keep it"),
    # an XDD/XDC keeps them in an XML comment (see xdd/file_comments.py): no format is known to lose them
    ("comments", "[Comments]", "EDS, DCF, XDD and XDC keep it"),
    ("dummy_usage", "[DummyUsage]", "EDS and DCF keep it"),
    ("module_sections", "the module sections (M1SubExtends, ...)", "EDS and DCF keep them"),
    ("trailing_comments", "the comment lines at the end of the file", "EDS and DCF keep them"),
)


def losses(device: Device, written: Device, fmt: str) -> list[str]:
    """One line per section of `device` that `written` (its output in `fmt`, read back) lacks or holds
    otherwise: `[Comments] is not kept in XDD (EDS and DCF keep it)`."""
    fields = [key for key, _, _ in _SECTIONS]
    before, after = device.content(fields), written.content(fields)
    found = []
    for key, label, keeper in _SECTIONS:
        old, new = before.get(key), after.get(key)
        if old in (None, [], {}) or old == new:
            continue
        how = "are not kept" if keeper.endswith("them") else "is not kept"
        if isinstance(old, dict) and isinstance(new, dict):  # some fields kept: name the others
            fields = sorted(name for name in old if name not in ("extra", "comments") and old[name] != new.get(name))
            how = f"is not all kept ({', '.join(fields) or 'unknown keys'})"
            keeper = "EDS and DCF keep every key"  # the target has the section, but no place for these keys
        found.append(f"{label} {how} in {fmt.upper()}" + ("" if fmt.upper() in keeper else f" ({keeper})"))
    kept = {section.name for section in written.other_sections}
    dropped = list(dict.fromkeys(section.name for section in device.other_sections if section.name not in kept))
    if dropped:
        names = ", ".join(f"[{name}]" for name in dropped[:5]) + (" ..." if len(dropped) > 5 else "")
        found.append(f"{names} {'is' if len(dropped) == 1 else 'are'} not kept in {fmt.upper()}")
    return found + _compact_losses(device, written, fmt.upper()) + _access_losses(device, written, fmt.upper())


def _access_losses(device: Device, written: Device, fmt: str) -> list[str]:
    """The entries an XDD gives access="noAccess" that `written` gives an access type (an EDS has none for it)."""
    lost = []
    for index, obj in device.objects.items():
        kept = written.objects.get(index)
        for subindex, var in [(0, obj), *obj.subs.items()]:
            again = kept.entry(subindex) if kept is not None and var is not obj else kept
            if var.no_access and again is not None and not again.no_access:
                lost.append(f"{index:04X}" + ("" if var is obj else f"sub{subindex:X}"))
    if not lost:
        return []
    names = ", ".join(lost[:5]) + (" ..." if len(lost) > 5 else "")
    return [f'access="noAccess" of {names} is not kept in {fmt} (no AccessType says it): written as ro']


def _compact_losses(device: Device, written: Device, fmt: str) -> list[str]:
    """The objects whose compact form (CompactSubObj, CompactPDO) `written` no longer implies: a peer reads
    them otherwise from an EDS written from it, since that EDS lists them in full."""
    arrays = []
    for index, obj in device.objects.items():
        kept = written.objects.get(index)
        implied = [n for n, sub in obj.subs.items() if sub.implicit and obj.compact_sub_obj]
        if implied and (kept is None or any(n not in kept.subs or not kept.subs[n].implicit for n in implied)):
            arrays.append(f"{index:04X}")
    pdos = [
        f"{i:04X}"
        for i, o in device.objects.items()
        if o.implicit and not getattr(written.objects.get(i), "implicit", False)
    ]
    found = []
    if arrays:
        found.append(
            f"the CompactSubObj form of {', '.join(arrays)} is not kept in {fmt} (its sub-objects are listed in full)"
        )
    if pdos:
        found.append(f"the PDO objects CompactPDO implies ({', '.join(pdos)}) are not kept implied in {fmt}")
    return found
