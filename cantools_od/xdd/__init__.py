"""CiA 311 XML device descriptions (XDD, XDC): reader and writers.

What lint and gen ask of every device is here, apart from the reader, so that checking an EDS
does not import the XML parser (and, through it, urllib, ssl and email).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from ..model import Device, Diagnostic

# Codes after which no model of the file exists: not XML, hostile XML, too large, not CiA 311.
REFUSED_CODES = ("XDD001", "XDD002", "XDD003", "XDD004")

RAW_PREFIX = "XDD."
"""Names of the sections that keep XML-only parts of a device read from XML (they have no place in an EDS)."""


def refused(device: Device) -> bool:
    """Whether the reader refused the file: nothing read from it may replace it or stand for it."""
    return refusal(device) is not None


def refusal(device: Device) -> Diagnostic | None:
    """The reader's diagnostic that refused the file, None when it read one."""
    return next((d for d in device.diagnostics if d.code in REFUSED_CODES), None)


def is_xml(data: bytes) -> bool:
    """Whether the content is XML (an XDD/XDC) rather than an EDS/DCF: it starts with `<`."""
    head = data[:4096].lstrip(b"\xef\xbb\xbf").lstrip()
    return head.startswith(b"<") or head.startswith(b"\xff\xfe<") or head.startswith(b"\xfe\xff\x00<")
