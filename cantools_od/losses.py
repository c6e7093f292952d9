"""What a format cannot hold: the sections of a device that its output in another format does not
give back when read again, measured on the output itself rather than declared, so that `convert`
never drops something without a word.
"""

from __future__ import annotations

from typing import Any

from .eds.format import twos_complement
from .eds.hints import Hints
from .eds.keys import DEVICE_INFO_KEYS, FILE_INFO_KEYS
from .model import Device, Section

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
    upper = fmt.upper()
    return (
        found
        + _key_losses(device, written, upper)
        + _compact_losses(device, written, upper)
        + _access_losses(device, written, upper)
    )


def _key_losses(device: Device, written: Device, fmt: str) -> list[str]:
    """The [FileInfo] and [DeviceInfo] keys (LastEDS, CompactPDO, ...) `written` does not give back, and the signed
    values written as two's-complement hex (`0xFFFF` for -1), which python-canopen reads as the unsigned number
    from an EDS and as -1 from one written from a format that keeps only the number."""
    found = []
    for label, old, new, table in (
        ("[FileInfo]", device.file_info, written.file_info, FILE_INFO_KEYS),
        ("[DeviceInfo]", device.device_info, written.device_info, DEVICE_INFO_KEYS),
    ):
        lost = [spelling for spelling, attr, _ in table.values() if _value(old, attr) != _value(new, attr)]
        if lost:
            keys = f"key{'s' if len(lost) > 1 else ''} {', '.join(lost)}"
            found.append(f"{label} {keys} {'are' if len(lost) > 1 else 'is'} not kept in {fmt} (EDS and DCF keep them)")
    if fmt not in ("EDS", "DCF"):
        signed = _twos_complement_hex(device)
        if signed:
            found.append(
                f"the two's-complement hex of {', '.join(signed)} is not kept in {fmt}: an EDS written from it says"
                " the negative number, which python-canopen reads otherwise than the hex (EDS and DCF keep it)"
            )
    return found


def _value(section: Section, attr: str) -> Any:
    """A key's value; a baud rate not listed is one not supported, as every reader takes it."""
    if attr.startswith("baud_rates."):
        return bool(getattr(section, "baud_rates", {}).get(int(attr.split(".")[1])))
    return getattr(section, attr, None)


def _twos_complement_hex(device: Device) -> list[str]:
    """The entries (`60C0`, `60C2sub2`) whose DefaultValue or ParameterValue the file wrote as two's-complement hex."""
    hints = Hints.of(device)
    found = []
    for index, obj in device.objects.items():
        for subindex, var in obj.subs.items() if obj.subs else [(None, obj)]:
            for key, value in (("DefaultValue", var.default), ("ParameterValue", var.parameter_value)):
                if not isinstance(value, int) or isinstance(value, bool) or value >= 0:
                    continue
                if twos_complement(hints.text(var, key), value, device.entry_type(var, obj)):
                    found.append(f"{index:04X}" + (f"sub{subindex:X}" if subindex is not None else ""))
                    break
    return found


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
