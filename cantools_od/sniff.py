"""What kind of device description some bytes are, decided once, before any reader runs.

Every command reads its inputs through `api.loads`, which asks `sniff` first: content that is no
device description at all (binary data, an empty file, text without a single `[section]`, XML
given where an EDS is expected) is refused with one reason instead of being read into an empty
model, which a formatter would then write back over the user's file. A device description is
recognised, not assumed: INI text counts only with CiA 306 evidence (a section of the file's own
such as `[FileInfo]`, or an object's section with an object's key such as `ParameterName`), so
`setup.cfg` or `.gitconfig` is refused; JSON only as an object with the model's keys, so `[]` is.
"""

from __future__ import annotations

import json
import re
from typing import Literal

from .eds.ini import header_names
from .eds.keys import OBJECT_KEYS, OBJECT_SECTION, is_file_section
from .model import Device

Kind = Literal["eds", "json", "xml"]

NOT_A_DEVICE_DESCRIPTION = "EDS000"

_UTF16_BOMS = (b"\xff\xfe", b"\xfe\xff")
_BLANK = b" \t\r\n\x0c\x0b"
_XML_SUFFIXES = (".xdd", ".xdc", ".xpd", ".xml")
_XML_FILE = "an XDD/XDC (CiA 311) file"
_MODEL = "a cantools-od model"
_DESCRIPTION = "a device description"
# A line giving one of an object's keys (`ParameterName=...`): with an object's section, CiA 306 evidence.
# Lines end in LF, CRLF or CR alone.
_OBJECT_KEY = re.compile(
    rb"(?:^|\r)[ \t]*(?:"
    + b"|".join(re.escape(spec[0].encode("ascii")) for spec in OBJECT_KEYS.values())
    + rb")[ \t]*=",
    re.MULTILINE | re.IGNORECASE,
)


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
        return _json_object(body, what)
    missing = _cia306_missing(body)
    if missing is None:
        return "eds"  # `[1000]` alone is JSON too, and an (empty) object's section
    if body.startswith(b"[") and isinstance(_json(body), list):  # `[]` or `[1,2,3]` has a "section" but is JSON
        raise NotADeviceDescription(f"JSON that is not {_MODEL} (a list)", what=_DESCRIPTION)
    raise NotADeviceDescription(missing, what)


def _expected(name: str) -> str:
    """What a file of this name was meant to be, for a refusal that content alone decides: a binary
    `device.xdd` is no XDD/XDC file, whatever the EDS reader would have said."""
    return _XML_FILE if _named_xml(name) else "an EDS/DCF file"


def _named_xml(name: str) -> bool:
    return name.lower().endswith(_XML_SUFFIXES)


def _json(data: bytes) -> object:
    """The JSON value `data` holds, or None when it holds none (JSON's `null` alone is none either)."""
    try:
        return json.loads(data)
    except (ValueError, RecursionError):
        return None


def _json_object(body: bytes, what: str) -> Kind:
    """Text starting with "{": a model (JSON with the model's keys), an EDS (not JSON, with CiA 306 evidence), or
    JSON for the model's reader to refuse (not JSON, no evidence: a broken model, JSN001)."""
    parsed = _json(body)
    if not isinstance(parsed, dict):  # not JSON at all: text starting with "{" is JSON only if it parses
        return "eds" if _cia306_missing(body) is None else "json"
    known = Device.model_fields.keys()
    if not known & parsed.keys():
        keys = ", ".join(sorted(parsed)[:5]) or "none"
        raise NotADeviceDescription(f"JSON that is not {_MODEL} (its keys: {keys})", what=_DESCRIPTION)
    unknown = sorted(parsed.keys() - known)
    if unknown:
        raise NotADeviceDescription(f"unknown keys: {', '.join(unknown[:5])}", what=_MODEL, code="JSN001")
    return "json"


def _cia306_missing(body: bytes) -> str | None:
    """None when `body` has CiA 306 evidence: a section of the file's own (`[FileInfo]`, `[DeviceInfo]`, an object
    list, `[DeviceComissioning]`, a module's, ...), an object's section of four hex digits as CiA 306 writes them
    (`[1000]`, `[1018sub1]`), or a shorter one (`[a]` is also any INI's) with an object's key; else why not."""
    seen: list[str] = []
    objects = False
    for raw in header_names(body):
        name = raw.decode("utf-8", "replace").strip()
        found = OBJECT_SECTION.match(name)
        if is_file_section(name) or (found is not None and len(found.group(1)) == 4):
            return None
        objects = objects or found is not None
        if len(seen) < 4:
            seen.append(f"[{name}]")
    if objects and _OBJECT_KEY.search(body) is not None:
        return None
    if not seen:
        return "text without a [section] header"
    shown = ", ".join(seen[:3]) + (", ..." if len(seen) > 3 else "")
    return f"INI text without a CiA 306 section or object ({shown})"


def xml_refusal(name: str) -> NotADeviceDescription:
    """XML handed to the EDS/DCF reader."""
    what = _XML_FILE if _named_xml(name) else "XML"
    return NotADeviceDescription(f"{what}; this reader takes CiA 306 EDS/DCF text")
