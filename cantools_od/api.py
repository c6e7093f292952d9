"""The Python API: load, loads, dumps, save."""

from __future__ import annotations

import os
import tempfile
from pathlib import Path
from typing import Literal

from pydantic import ValidationError

from .eds.format import IntStyle
from .eds.reader import read_bytes
from .model import Device
from .xdd import is_xml

Format = Literal["eds", "dcf", "json", "xdd", "xdc"]
Style = Literal["preserve", "canonical"]


def load(path: str | os.PathLike[str], node_id: int | None = None) -> Device:
    """Read an EDS, DCF, XDD/XDC or JSON model file. Raises OSError only when the path cannot be read."""
    data = Path(path).read_bytes()
    return loads(data, node_id=node_id, source=os.fspath(path))


def loads(data: bytes | str, node_id: int | None = None, source: str = "", fmt: Format | None = None) -> Device:
    """Read EDS/DCF/XDD/XDC/JSON content; the format comes from `fmt`, else the content.

    EDS/DCF/XDD/XDC content never raises; JSON that is not a cantools-od model raises ValueError.
    """
    raw = data.encode("utf-8") if isinstance(data, str) else data
    if fmt in ("xdd", "xdc") or (fmt is None and is_xml(raw)):
        from .xdd.reader import read_bytes as read_xml

        return read_xml(raw, source, node_id=node_id, dcf=True if fmt == "xdc" else None)
    if fmt == "json" or (fmt is None and raw.lstrip()[:1] == b"{"):
        try:
            device = Device.model_validate_json(raw)
        except ValidationError as error:
            if fmt == "json" or not _not_json(error):
                raise  # JSON, but not a cantools-od model: a ValueError
            return read_bytes(raw, source, node_id=node_id)  # an EDS that happens to start with "{"
        device.source = source or device.source
        if node_id is not None:
            device.node_id = node_id
        return device
    dcf = True if fmt == "dcf" else None
    return read_bytes(raw, source, node_id=node_id, dcf=dcf)


def _not_json(error: ValidationError) -> bool:
    return any(detail["type"] == "json_invalid" for detail in error.errors())


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
        return text.encode("utf-8")  # names with non-ASCII letters are kept, not transliterated


def save(device: Device, path: str | os.PathLike[str], fmt: Format | None = None, style: Style = "preserve") -> bool:
    """Write the device; the format comes from the file extension unless given.

    The file is replaced atomically and only when its content changes.
    Returns whether it was written.
    """
    target = Path(path)
    chosen: Format = fmt or format_for(target)
    return write_if_changed(target, dumps(device, chosen, style))


def format_for(path: Path) -> Format:
    suffix = path.suffix.lower()
    if suffix == ".dcf":
        return "dcf"
    if suffix == ".json":
        return "json"
    if suffix in (".xdd", ".xpd"):
        return "xdd"
    if suffix == ".xdc":
        return "xdc"
    return "eds"


def write_if_changed(path: Path, data: bytes) -> bool:
    """Atomically replace `path` with `data` unless it already holds exactly that."""
    try:
        if path.read_bytes() == data:
            return False
    except OSError:
        pass
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb") as handle:
            handle.write(data)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return True
