"""What of a device read from XML an EDS/DCF can hold.

CiA 306 has no place for the XML-only parts this reader keeps (profile
headers, DeviceFunction and other elements, parameter attributes, labels,
non-CANopenNode properties), nor an access type for an entry no SDO reaches
(access="noAccess", written as ro), and a key line holds at most 255 characters.
Those parts are left out of an EDS written from an XDD, as CANopenEditor's own
EDS export leaves them out; the CANopenNode storage group travels as
`;StorageLocation=`.
"""

from __future__ import annotations

from typing import TypeVar

from ..model import AccessType, Device, Object, Section, Variable
from . import RAW_PREFIX  # not from the reader: writing an EDS needs no XML parser

_LINE = 255


def _eds_key(key: str, text: str) -> bool:
    if key[:1].islower() or any(mark in key for mark in ".@<"):
        return False  # attributes and elements of the XML, not EDS keys
    return "\n" not in text and len(key) + 1 + len(text) <= _LINE


def eds_form(device: Device) -> Device:
    """A copy of an XML-read device without what an EDS cannot hold; other devices as they are.

    Only the parts that lose a key are copied (shallowly); the rest is shared with `device`, which is left as
    it was. A deep copy of a large XDD cost more than reading it."""
    if device.file_format != "xdd":
        return device
    # Every field that holds one section (file_info, comments, the object lists, ...), whichever there are.
    update: dict[str, object] = {
        name: _form(part) for name in type(device).model_fields if isinstance(part := getattr(device, name), Section)
    }
    update["objects"] = {index: _object_form(obj) for index, obj in device.objects.items()}
    update["module_sections"] = [_form(s) for s in device.module_sections]
    update["other_sections"] = [_form(s) for s in device.other_sections if not s.name.startswith(RAW_PREFIX)]
    return device.model_copy(update=update)


_S = TypeVar("_S", bound=Section)


def _form(section: _S, **update: object) -> _S:
    if isinstance(section, Variable) and section.no_access:
        update["access"] = AccessType.RO  # no AccessType says "no SDO access": the least an EDS can (losses.py)
    kept = {k: v for k, v in section.extra.items() if _eds_key(k, v)}
    if len(kept) < len(section.extra):
        update["extra"] = kept
    return section.model_copy(update=update) if update else section


def _object_form(obj: Object) -> Object:
    subs = {subindex: _form(sub) for subindex, sub in obj.subs.items()}
    changed = any(sub is not obj.subs[subindex] for subindex, sub in subs.items())
    return _form(obj, subs=subs) if changed else _form(obj)
