"""What kind of device description some bytes are, decided once, before any reader runs.

Every command reads its inputs through `api.loads`, which asks `sniff` first: content that is no
device description at all (binary data, an empty file, text without a single `[section]`, XML
given where an EDS is expected) is refused with one reason instead of being read into an empty
model, which a formatter would then write back over the user's file.
"""

from __future__ import annotations

import re
from typing import Literal

Kind = Literal["eds", "json", "xml"]

NOT_A_DEVICE_DESCRIPTION = "EDS000"

_UTF16_BOMS = (b"\xff\xfe", b"\xfe\xff")
_BLANK = b" \t\r\n\x0c\x0b"
_SECTION = re.compile(rb"^[ \t]*\[", re.MULTILINE)
_XML_SUFFIXES = (".xdd", ".xdc", ".xpd", ".xml")
_XML_FILE = "an XDD/XDC (CiA 311) file"


class NotADeviceDescription(ValueError):
    """The content is not a device description this tool reads; `reason` says what it is instead.

    Its text is one line: `not an EDS/DCF file: REASON` (or `not a cantools-od model: REASON` for JSON)."""

    def __init__(self, reason: str, what: str = "an EDS/DCF file", code: str = NOT_A_DEVICE_DESCRIPTION) -> None:
        super().__init__(f"not {what}: {reason}")
        self.reason = reason
        self.code = code


def sniff(data: bytes, name: str = "") -> Kind:
    """The kind of `data` (named `name`, whose extension counts when content alone cannot tell).

    Raises NotADeviceDescription for content that no reader takes."""
    what = _expected(name)
    if data.startswith(_UTF16_BOMS):
        raise NotADeviceDescription("UTF-16 text; save it as UTF-8 or ASCII", what)
    nul = data.find(b"\0")
    if nul >= 0:
        line = data.count(b"\n", 0, nul) + 1
        raise NotADeviceDescription(f"binary data (a NUL byte on line {line})", what)
    body = data.removeprefix(b"\xef\xbb\xbf").lstrip(_BLANK)
    if not body:
        raise NotADeviceDescription("the file is empty" if not data else "the file holds only blank space", what)
    if body.startswith(b"<"):
        return "xml"
    if body.startswith(b"{"):
        return "json"
    if body.startswith(b"[") and _is_json_array(body):  # `[1,2,3]` has a "section" but is JSON
        raise NotADeviceDescription("JSON that is not a cantools-od model (an array)", what="a device description")
    if not has_section(body):
        raise NotADeviceDescription("text without a [section] header", what)
    return "eds"


def _expected(name: str) -> str:
    """What a file of this name was meant to be, for a refusal that content alone decides: a binary
    `device.xdd` is no XDD/XDC file, whatever the EDS reader would have said."""
    return _XML_FILE if _named_xml(name) else "an EDS/DCF file"


def _named_xml(name: str) -> bool:
    return name.lower().endswith(_XML_SUFFIXES)


def _is_json_array(data: bytes) -> bool:
    """JSON of an array with several items or nested ones; `[]` or `[1000]` alone is also a section header."""
    import json  # rare: a file that starts with "["

    try:
        parsed = json.loads(data)
    except ValueError:
        return False
    return len(parsed) > 1 or any(isinstance(item, (list, dict)) for item in parsed)


def has_section(data: bytes) -> bool:
    """Whether some line of `data` starts a `[section]`."""
    return _SECTION.search(data) is not None


def xml_refusal(name: str) -> NotADeviceDescription:
    """XML handed to the EDS/DCF reader."""
    what = _XML_FILE if _named_xml(name) else "XML"
    return NotADeviceDescription(f"{what}; this reader takes CiA 306 EDS/DCF text")
