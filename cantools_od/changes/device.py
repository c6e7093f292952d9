"""Device-level comparison: identity, device info, baud rates, dummy usage, file info, commissioning, sections."""

from __future__ import annotations

from collections.abc import Iterator

from ..model import Comments, Commissioning, Device, DummyUsage, RawSection, Section, standard_type
from . import describe
from .compare import section_changes
from .impact import count_impact, flag_impact
from .records import Change, Impact, Kind, new_change

_IDENTITY = {
    "vendor_number": (Impact.BREAKING, "a master checks the vendor-ID (0x1018 sub 1) against its configuration"),
    "product_number": (Impact.BREAKING, "a master checks the product code (0x1018 sub 2) against its configuration"),
    "revision_number": (Impact.VALUE, "a master that checks the revision (0x1018 sub 3) needs the new one"),
}
_FLAGS = {
    "simple_boot_up_master": "a simple boot-up master",
    "simple_boot_up_slave": "a simple boot-up slave",
    "group_messaging": "supporting group messaging",
    "lss_supported": "supporting LSS",
    "canopen_safety_supported": "supporting CANopen Safety",
}
_COUNTS = {
    "nr_of_rx_pdo": "RPDOs",
    "nr_of_tx_pdo": "TPDOs",
    "dynamic_channels_supported": "dynamic channels",
}
_TEXT = ("vendor_name", "product_name", "order_code")


def device_changes(old: Device, new: Device) -> Iterator[Change]:
    """Every device-level change, in a fixed order."""
    yield from _device_info(old, new)
    yield from _baud_rates(old, new)
    yield from _dummy_usage(
        old.dummy_usage or DummyUsage.model_construct(), new.dummy_usage or DummyUsage.model_construct()
    )
    yield from _plain_section(Kind.FILE_INFO, Impact.COSMETIC, "file_info", old.file_info, new.file_info)
    yield from _plain_section(
        Kind.COMMISSIONING,
        Impact.VALUE,
        "commissioning",
        old.commissioning or Commissioning.model_construct(),
        new.commissioning or Commissioning.model_construct(),
    )
    yield from _comments(
        old.comments or Comments.model_construct(), new.comments or Comments.model_construct(), old, new
    )
    yield from _raw_sections(old.module_sections, new.module_sections, Impact.VALUE)
    yield from _raw_sections(old.other_sections, new.other_sections, Impact.COSMETIC)


def _field_change(kind: Kind, impact: Impact, field: str, old: object, new: object, note: str = "") -> Change:
    def storable(value: object) -> bool | int | float | str | None:
        return value if value is None or isinstance(value, (bool, int, float, str)) else str(value)

    return new_change(
        kind=kind,
        impact=impact,
        field=field,
        old=storable(old),
        new=storable(new),
        old_text=_text(old, field),
        new_text=_text(new, field),
        note=note,
    )


def _text(value: object, field: str) -> str:
    if isinstance(value, int) and not isinstance(value, bool) and field.endswith("_number"):
        return f"0x{value:08X}"
    return describe.text(value)


def _device_info(old: Device, new: Device) -> Iterator[Change]:
    before, after = old.device_info, new.device_info
    for field in type(before).model_fields:
        was, now = getattr(before, field), getattr(after, field)
        if field in ("baud_rates", "extra", "comments", "origin") or was == now:
            continue
        name = f"device_info.{field}"
        if field in _IDENTITY:
            impact, note = _IDENTITY[field] if was is not None and now is not None else _stated(was)
            yield _field_change(Kind.IDENTITY, impact, name, was, now, note)
        elif field in _FLAGS:
            if bool(was) != bool(now):
                impact, note = flag_impact(was, now, _FLAGS[field])
                yield _field_change(Kind.DEVICE_INFO, impact, name, was, now, note)
        elif field in _COUNTS:
            impact, note = count_impact(was, now, _COUNTS[field])
            yield _field_change(Kind.DEVICE_INFO, impact, name, was, now, note)
        else:
            yield _field_change(Kind.DEVICE_INFO, Impact.COSMETIC if field in _TEXT else Impact.VALUE, name, was, now)
    yield from section_changes(before, after, None, None, "device_info.")


def _stated(was: object) -> tuple[Impact, str]:
    """Identity stated on one side only (a new file, or a key added or dropped): nothing a master relied on."""
    return (Impact.COMPATIBLE, "stated now") if was is None else (Impact.VALUE, "no longer stated")


def _baud_rates(old: Device, new: Device) -> Iterator[Change]:
    before, after = old.device_info.baud_rates, new.device_info.baud_rates
    for rate in sorted(set(before) | set(after)):
        was, now = bool(before.get(rate)), bool(after.get(rate))
        if was != now:
            # A supported rate (CiA 306 BaudRate_<kbit/s>), not the rate the device runs at.
            impact, note = flag_impact(was, now, f"able to run at {rate} kbit/s")
            yield _field_change(Kind.BAUD_RATE, impact, f"device_info.baud_rates.{rate}", was, now, note)


def _dummy_usage(old: DummyUsage, new: DummyUsage) -> Iterator[Change]:
    for index in sorted(set(old.enabled) | set(new.enabled)):
        was, now = bool(old.enabled.get(index)), bool(new.enabled.get(index))
        if was != now:
            dtype = standard_type(index)
            what = f"mapping dummy entries of {dtype.name if dtype else f'type 0x{index:04X}'}"
            impact, note = flag_impact(was, now, f"{what} (0x{index:04X})")
            yield _field_change(Kind.DUMMY_USAGE, impact, f"dummy_usage.{index:04X}", was, now, note)
    yield from section_changes(old, new, None, None, "dummy_usage.")


def _plain_section(kind: Kind, impact: Impact, where: str, old: Section, new: Section) -> Iterator[Change]:
    for field in type(old).model_fields:
        if field in ("extra", "comments", "origin"):
            continue
        was, now = getattr(old, field), getattr(new, field)
        if was != now:
            yield _field_change(kind, impact, f"{where}.{field}", was, now)
    yield from section_changes(old, new, None, None, f"{where}.")


def _comments(old: Comments, new: Comments, old_device: Device, new_device: Device) -> Iterator[Change]:
    before, after = _lines_text(old), _lines_text(new)
    if old_device.trailing_comments != new_device.trailing_comments:
        yield _field_change(
            Kind.COMMENT,
            Impact.COSMETIC,
            "trailing_comments",
            " / ".join(old_device.trailing_comments),
            " / ".join(new_device.trailing_comments),
        )
    if before != after:
        yield _field_change(Kind.COMMENT, Impact.COSMETIC, "comments.lines", before, after)
    yield from section_changes(old, new, None, None, "comments.")


def _lines_text(comments: Comments) -> str:
    """The [Comments] lines on one line: blank lines dropped, the rest joined with ` / `."""
    return " / ".join(text.strip() for _, text in sorted(comments.lines.items()) if text.strip())


def _raw_sections(old: list[RawSection], new: list[RawSection], impact: Impact) -> Iterator[Change]:
    before = {section.name.upper(): section for section in old}
    after = {section.name.upper(): section for section in new}
    for key in sorted(set(before) | set(after)):
        was, now = before.get(key), after.get(key)
        name = now.name if now is not None else was.name if was is not None else key
        entries_before = was.entries if was else {}
        entries_after = now.entries if now else {}
        for entry in sorted(set(entries_before) | set(entries_after), key=str.lower):
            if entries_before.get(entry) != entries_after.get(entry):
                yield _field_change(
                    Kind.SECTION, impact, f"[{name}].{entry}", entries_before.get(entry), entries_after.get(entry)
                )
        if was is not None and now is not None:
            yield from section_changes(was, now, None, None, f"[{name}].")
        elif was is None or now is None:
            yield _field_change(
                Kind.SECTION, impact, f"[{name}]", "present" if was else None, "present" if now else None
            )
