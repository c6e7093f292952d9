"""Device → CiA 306 text in canonical form: sections sorted, keys in CiA order."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

from ..model import Device, NodeIdExpr, Object, Section, SubObject, Variable
from ..model.cia301.pdo import partner
from ..model.device import OBJECT_LISTS, Comments, Commissioning, DeviceInfo, FileInfo, ObjectList, object_lists_of
from .compact import compact_form_holds, implicit_sub_name, implied_pdo_objects, same_object
from .dialect import text_dialect
from .format import CANONICAL, IntStyle, Radix, format_key, format_value, reads_hint
from .hints import NO_HINTS, Hints
from .keys import COMMISSIONING, COMMISSIONING_KEYS, DEVICE_INFO_KEYS, FILE_INFO_KEYS, OBJECT_KEYS, KeySpec, Kind
from .peer_names import peer_spelling
from .storage import storage_comments


@dataclass(frozen=True)
class _Style:
    dcf: bool
    as_written: bool
    ints: IntStyle = CANONICAL
    hints: Hints = NO_HINTS

    def radix_and_hint(self, section: Section, key: str, value: object) -> tuple[Radix, str | None]:
        """The radix of `key`, and the text `value` was read from where formatting reads it (format.reads_hint)."""
        radix = self.ints.radix(key)
        return radix, self.hints.text(section, key) if reads_hint(value, radix) else None


@dataclass
class OutSection:
    name: str
    entries: dict[str, str] = field(default_factory=dict)
    comments: dict[str, list[str]] = field(default_factory=dict)


def sections(
    device: Device, dcf: bool = False, as_written: bool = False, ints: IntStyle = CANONICAL
) -> list[OutSection]:
    """The canonical sections of a device, in order. `dcf` adds commissioning and resolved values;
    `as_written` keeps `$NODEID` formulas spelled as read (the preserving writer compares spellings);
    `ints` chooses the radix of integers. Canonical output (not `as_written`) keeps keys the source
    had with an empty value: peers read `DefaultValue=` as an empty string or no value, not as absent."""
    hints = Hints.of(device) if not as_written else NO_HINTS
    style = _Style(dcf, as_written, ints, hints)
    # [FileInfo] and [DeviceInfo] are mandatory, but are not made up when the model has nothing for them; an
    # empty one the file has is kept (it may be all that tells the file is an EDS).
    heads = (
        (device.file_info, _keyed("FileInfo", device.file_info, FILE_INFO_KEYS, style)),
        (device.device_info, _keyed("DeviceInfo", device.device_info, DEVICE_INFO_KEYS, style)),
    )
    out = [section for part, section in heads if part.origin is not None or section.entries or section.comments]
    if device.commissioning is not None or dcf:
        commissioning = device.commissioning or Commissioning.model_construct()  # no schema built to write
        if dcf and device.node_id is not None:
            commissioning = commissioning.model_copy(update={"node_id": device.node_id})
        out.append(_keyed(COMMISSIONING, commissioning, COMMISSIONING_KEYS, style))
    if device.dummy_usage is not None:
        usage = device.dummy_usage
        entries = {f"Dummy{index:04X}": "1" if on else "0" for index, on in sorted(usage.enabled.items())}
        out.append(_with_extra("DummyUsage", entries, usage, style))
    if device.comments is not None:
        out.append(comments_section(device.comments, style))
    written = _explicit_indices(device)
    for name, attr in _object_lists(device, written).items():
        if attr is not None:
            entries = (
                {"SupportedObjects": format_key("", attr.supported_objects)}
                if attr.supported_objects is not None
                else {}
            )
            entries.update({str(pos): f"0x{index:04X}" for pos, index in sorted(attr.entries.items())})
            out.append(_with_extra(name, entries, attr, style))
    for index, obj in device.objects.items():
        if index in written:
            out.extend(_object_sections(device, obj, style))
    for raw in [*device.module_sections, *device.other_sections]:
        out.append(_with_extra(raw.name, dict(raw.entries), raw, style))
    return out


def _object_lists(device: Device, written: set[int]) -> dict[str, ObjectList | None]:
    """The lists as the model holds them; for a device read from an XDD, which has none (CiA 311 lists no
    objects), the lists CiA 306 requires of the objects `written`, so that the EDS is complete for tools that
    follow them."""
    held: dict[str, ObjectList | None] = {name: getattr(device, attr) for name, attr in OBJECT_LISTS.items()}
    if device.file_format != "xdd" or any(found is not None for found in held.values()):
        return held
    return dict(object_lists_of(written))


def _explicit_indices(device: Device) -> set[int]:
    """Objects to write: all but CompactPDO ones the reader implies again unchanged.

    A changed implied PDO is written whole, communication and mapping record together, since
    the reader implies the two only as a pair.
    """
    written = {index for index, obj in device.objects.items() if not obj.implicit}
    if len(written) == len(device.objects):
        return written
    implied = implied_pdo_objects(device)
    changed = {
        index
        for index, obj in device.objects.items()
        if obj.implicit and (index not in implied or not same_object(obj, implied[index]))
    }
    partners = {partner(index) for index in changed}
    return written | changed | {index for index in partners if index is not None and index in device.objects}


def comments_section(comments: Comments, style: _Style | None = None) -> OutSection:
    """[Comments]: `Lines`, then `Line1`... as numbered, then the keys kept as written."""
    entries = {"Lines": format_key("Lines", comments.line_count)} if comments.line_count is not None else {}
    entries.update({f"Line{n}": text for n, text in comments.lines.items()})
    return _with_extra("Comments", entries, comments, style)


def _with_extra(name: str, entries: dict[str, str], section: Section, style: _Style | None = None) -> OutSection:
    """The section with its extra keys and comments; in canonical output (a `style` not `as_written`), a name
    python-canopen looks up keeps the file's spelling: respelled, it would read other values."""
    canonical = style is not None and not style.as_written
    spelled = section.origin.spelled if canonical and section.origin is not None else {}
    if spelled:
        name = peer_spelling(name, spelled.get(""))
        entries = {peer_spelling(key, spelled.get(key)): text for key, text in entries.items()}
    for key, text in section.extra.items():
        entries.setdefault(key, text)
    if isinstance(section, Variable) and section.canopennode is not None:
        comments = storage_comments(section, list(entries))
    else:
        comments = dict(section.comments)
    if spelled:
        comments = {peer_spelling(key, spelled.get(key)) if key else key: lines for key, lines in comments.items()}
    return OutSection(name, entries, comments)


def _keyed(
    name: str, model: FileInfo | DeviceInfo | Commissioning, table: dict[str, KeySpec], style: _Style
) -> OutSection:
    entries: dict[str, str] = {}
    data: dict[str, Any] = dict(model.__dict__)
    for spelling, attr, kind in table.values():
        if attr.startswith("baud_rates."):
            value: Any = data["baud_rates"].get(int(attr.split(".")[1]))
        else:
            value = data[attr]
        if value is not None:
            entries[spelling] = format_key(spelling, value, *style.radix_and_hint(model, spelling, value))
        elif _kept_empty(model, spelling, kind, style):
            entries[spelling] = ""
    return _with_extra(name, entries, model, style)


def _kept_empty(section: Section, key: str, kind: Kind, style: _Style) -> bool:
    """Whether canonical output writes `key=` for a key with no value. Kept in place: a commented key,
    and an empty typed value or AccessType the source had (python-canopen reads `DefaultValue=` as `''`
    or `b''`, not as absent). Dropped: other empty numbers and booleans, which no peer reads a value
    from (python-canopen fails on `int('')`). A key whose value could not be read is in `extra`."""
    if style.as_written or key in section.extra:
        return False
    if key in section.comments:
        return True
    return kind in (Kind.VALUE, Kind.ACCESS) and section.origin is not None and section.origin.where(key) is not None


def _variable_entries(device: Device, var: Variable, owner: Object, style: _Style) -> dict[str, str]:
    entries: dict[str, str] = {}
    data = var.__dict__
    dtype = None
    for spelling, attr, kind in OBJECT_KEYS.values():
        value = data.get(attr)
        if (
            attr == "parameter_value"
            and value is None
            and style.dcf
            and isinstance(var.default, NodeIdExpr)
            and device.node_id is not None
        ):
            value = device.resolve(var.default)  # a DCF states the value for its node-ID
        if value is None:
            if _kept_empty(var, spelling, kind, style):
                entries[spelling] = ""
            continue
        radix, hint = style.radix_and_hint(var, spelling, value)
        if kind is Kind.VALUE:
            dtype = dtype or device.entry_type(var, owner)
            entries[spelling] = format_value(value, dtype, device.dialect, style.as_written, radix, hint)
        else:
            entries[spelling] = format_key(spelling, value, radix, hint)
    return entries


def _object_sections(device: Device, obj: Object, style: _Style) -> list[OutSection]:
    name = f"{obj.index:04X}"
    out = [_with_extra(name, _variable_entries(device, obj, obj, style), obj, style)]
    compact: dict[str, dict[str, str]] = {"Name": {}, "Value": {}, "Denotation": {}}
    dtype = device.entry_type(obj, obj)
    for subindex, sub in obj.subs.items():
        if sub.implicit and obj.compact_sub_obj and compact_form_holds(obj, subindex, sub):
            _compact_entries(device, obj, subindex, sub, compact, dtype, style)
            continue
        # An edited compact sub-object no longer follows its parent: it gets a section of its own.
        out.append(_with_extra(f"{name}sub{subindex:X}", _variable_entries(device, sub, obj, style), sub, style))
    for suffix, entries in compact.items():
        if entries:
            out.append(OutSection(f"{name}{suffix}", {"NrOfEntries": str(len(entries)), **entries}))
    if obj.links is not None:
        links = {str(n): f"0x{index:04X}" for n, index in enumerate(obj.links, 1)}
        out.append(OutSection(f"{name}ObjectLinks", {"ObjectLinks": str(len(links)), **links}))
    return out


def _compact_entries(
    device: Device,
    obj: Object,
    subindex: int,
    sub: SubObject,
    compact: dict[str, dict[str, str]],
    dtype: Any,
    style: _Style,
) -> None:
    if subindex == 0:
        return
    key = str(subindex)
    if sub.name != implicit_sub_name(obj, subindex):
        compact["Name"][key] = sub.name
    if sub.parameter_value is not None:
        radix = style.ints.radix("ParameterValue")
        compact["Value"][key] = format_value(sub.parameter_value, dtype, device.dialect, style.as_written, radix)
    if sub.denotation is not None:
        compact["Denotation"][key] = sub.denotation


def render(out: list[OutSection], trailing: list[str], eol: str = "\n") -> str:
    lines: list[str] = []
    for section in out:
        lines.extend(section.comments.get("", []))
        lines.append(f"[{section.name}]")
        for key, text in section.entries.items():
            lines.extend(section.comments.get(key, []))
            lines.append(f"{key}={text}")
        for key, comments in section.comments.items():
            if key and key not in section.entries:  # a commented key left empty keeps its comment
                lines.extend(comments)
                lines.append(f"{key}=")
        lines.append("")
    lines.extend(trailing)
    while lines and lines[-1] == "":
        lines.pop()
    return eol.join(lines) + eol if lines else ""


def canonical_text(device: Device, dcf: bool = False, ints: IntStyle = CANONICAL) -> str:
    out = sections(device, dcf, ints=ints)
    text = render(out, device.trailing_comments)
    if text_dialect(text) is not device.dialect:
        # Quoting and REAL forms depend on the dialect: say it where the text alone would mislead.
        text = f"; cantools-od: dialect={device.dialect.value}\n" + text
    return text
