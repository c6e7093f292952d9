"""What of a device read from XML an EDS/DCF can hold.

CiA 306 has no place for the XML-only parts this reader keeps (profile
headers, DeviceFunction and other elements, parameter attributes, labels,
non-CANopenNode properties), and a key line holds at most 255 characters.
Those parts are left out of an EDS written from an XDD, as CANopenEditor's own
EDS export leaves them out; the CANopenNode storage group travels as
`;StorageLocation=`.
"""

from __future__ import annotations

from ..model import Device
from . import RAW_PREFIX  # not from the reader: writing an EDS needs no XML parser

_LINE = 255


def _eds_key(key: str, text: str) -> bool:
    if key[:1].islower() or any(mark in key for mark in ".@<"):
        return False  # attributes and elements of the XML, not EDS keys
    return "\n" not in text and len(key) + 1 + len(text) <= _LINE


def eds_form(device: Device) -> Device:
    """A copy of an XML-read device without what an EDS cannot hold; other devices as they are."""
    if device.file_format != "xdd":
        return device
    copy = device.model_copy(deep=True)
    copy.other_sections = [s for s in copy.other_sections if not s.name.startswith(RAW_PREFIX)]
    for section in copy.sections():
        if section.extra:
            section.extra = {k: v for k, v in section.extra.items() if _eds_key(k, v)}
    return copy
