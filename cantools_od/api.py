"""The Python API: load, loads, dumps, save."""

from __future__ import annotations

import os
from pathlib import Path
from typing import Literal

from pydantic import ValidationError

from .eds.format import IntStyle
from .eds.reader import read_bytes
from .model import Device
from .sniff import NotADeviceDescription, sniff, xml_refusal
from .xdd import is_xml

Format = Literal["eds", "dcf", "json", "xdd", "xdc"]
Style = Literal["preserve", "canonical"]


def load(path: str | os.PathLike[str], node_id: int | None = None) -> Device:
    """Read an EDS, DCF, XDD/XDC or JSON model file.

    Raises OSError when the path cannot be read, NotADeviceDescription when its content is no
    device description (see `loads`)."""
    data = Path(path).read_bytes()
    return loads(data, node_id=node_id, source=os.fspath(path))


def loads(data: bytes | str, node_id: int | None = None, source: str = "", fmt: Format | None = None) -> Device:
    """Read EDS/DCF/XDD/XDC/JSON content; the format comes from `fmt`, else the content.

    Raises NotADeviceDescription (a ValueError) for content that is none: binary data, an empty
    file, text without a section, XML given as another format, JSON that is not a cantools-od
    model. Any other content is read, with what is wrong in it as diagnostics.
    """
    raw = data.encode("utf-8") if isinstance(data, str) else data
    # XML is read as XDD/XDC unless its name says EDS/DCF: then `fmt` would write INI over it.
    named_ini = Path(source).suffix.lower() in (".eds", ".dcf")
    if fmt in ("xdd", "xdc") or (fmt is None and is_xml(raw) and not named_ini):
        from .xdd.reader import read_bytes as read_xml

        return read_xml(raw, source, node_id=node_id, dcf=True if fmt == "xdc" else None)
    kind = sniff(raw, source)
    if kind == "xml":
        raise xml_refusal(source)
    if fmt == "json" or (fmt is None and kind == "json"):
        return _json_model(raw, source, node_id)
    dcf = True if fmt == "dcf" else None
    return read_bytes(raw, source, node_id=node_id, dcf=dcf)


def _json_model(raw: bytes, source: str, node_id: int | None) -> Device:
    """A model `sniff` recognised (or JSON the caller insists on): JSN001 when it does not validate."""
    try:
        device = Device.model_validate_json(raw)
    except ValidationError as error:
        raise _not_a_model(error) from None
    device.source = source or device.source
    if node_id is not None:
        device.node_id = node_id
    return device


def _not_a_model(error: ValidationError) -> NotADeviceDescription:
    first = error.errors()[0]
    where = ".".join(str(part) for part in first["loc"])
    more = f" (and {error.error_count() - 1} more)" if error.error_count() > 1 else ""
    reason = f"{where + ': ' if where else ''}{first['msg']}{more}"
    return NotADeviceDescription(reason, what="a cantools-od model", code="JSN001")


def dumps(device: Device, fmt: Format = "eds", style: Style = "preserve", int_style: IntStyle | None = None) -> bytes:
    """The device as EDS, DCF, XDD, XDC or JSON.

    *preserve* edits the bytes the device was read from, so an unchanged device
    comes back byte for byte; it falls back to *canonical* for devices built
    in code or read from JSON, and for a DCF made from an EDS. `int_style`
    chooses the radix of integers in canonical output (default: canonical).
    """
    if fmt == "json":
        return device.model_dump_json(indent=2).encode("utf-8") + b"\n"
    if fmt in ("xdd", "xdc"):
        from .xdd.writer import dumps_xml

        return dumps_xml(device, xdc=fmt == "xdc", preserve=style == "preserve")
    from .xdd.eds_form import eds_form

    device = eds_form(device)
    dcf = fmt == "dcf"
    if dcf and not device.is_dcf and device.node_id is None:
        raise ValueError("an EDS becomes a DCF for one node: give its node-ID")
    from .eds.preserve import preserve  # writers load only when something is written
    from .eds.writer import canonical_text

    making_dcf = dcf and not device.is_dcf  # an EDS becomes a DCF: values are resolved, layout is new
    from_eds = device._original is not None and not is_xml(device._original)
    if style == "preserve" and from_eds and not making_dcf:
        return preserve(device)
    # A DCF made from an EDS states its node-ID and the values resolved for it.
    text = canonical_text(device, making_dcf, int_style or IntStyle())
    try:
        return text.encode("ascii")
    except UnicodeEncodeError:
        return _non_ascii(device, text)


def _non_ascii(device: Device, text: str) -> bytes:
    """Text with non-ASCII letters, in the code page the file was read with when that was no UTF-8 and holds them:
    which one a file is in is a guess (eds/decode.py), and written back in it, no byte of a text changes whatever
    the guess; else UTF-8 (names with non-ASCII letters are kept, not transliterated)."""
    from .eds.decode import decode_as, encode

    if device._original is not None:
        _, codec, _ = decode_as(device._original)
        if codec != "utf-8":
            try:
                return encode(text, codec)
            except UnicodeEncodeError:
                pass
    return text.encode("utf-8")


def save(device: Device, path: str | os.PathLike[str], fmt: Format | None = None, style: Style = "preserve") -> bool:
    """Write the device; the format comes from the file extension unless given.

    The file is replaced atomically, keeping its mode, and only when its content changes.
    Returns whether it was written; raises files.CannotWrite when it cannot be.
    """
    target = Path(path)
    chosen: Format = fmt or format_for(target)
    return write_if_changed(target, dumps(device, chosen, style))


SUFFIXES: dict[str, Format] = {
    ".eds": "eds",
    ".dcf": "dcf",
    ".json": "json",
    ".xdd": "xdd",
    ".xpd": "xdd",
    ".xdc": "xdc",
}
"""File extensions (lower case) and the format each stands for."""


def format_for(path: Path) -> Format:
    """The format a file's extension names; EDS for any other extension."""
    return SUFFIXES.get(path.suffix.lower(), "eds")


def write_if_changed(path: Path, data: bytes) -> bool:
    """Atomically replace `path` with `data` unless it already holds exactly that (see files.py)."""
    from . import files  # only when something is written

    return files.write_if_changed(path, data)
