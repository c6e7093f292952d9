"""Per-object CANopenNode settings from `<stem>.canopennode.toml` beside the device description.

An EDS cannot say everything CANopenNode needs (CANopenEditor keeps it in its XDD project). This
file fills the gap, the same way a pin file fixes identifiers: one table per object or
sub-object, keyed like EDS sections, with the fields of `CanopenNodeInfo`::

    [2121]
    storage_group = "PERSIST_APP"

    [2121sub2]
    string_length_min = 1000

    [1280]
    disabled = true

A value here wins over the file's own (`;StorageLocation=`, XDD properties) and over inference.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Any

from .model import CanopenNodeInfo, Device, SrdoAccess, Variable

_KEY = re.compile(r"([0-9A-Fa-f]{4})(?:sub([0-9A-Fa-f]{1,2}))?")
_FIELDS: dict[str, type] = {
    "storage_group": str,
    "count_label": str,
    "disabled": bool,
    "flags_pdo": bool,
    "access_srdo": str,
    "string_length_min": int,
}
SUFFIX = ".canopennode.toml"


def override_file_for(source: str | Path) -> Path | None:
    """`<source stem>.canopennode.toml` beside the source, when it exists."""
    beside = Path(source).with_suffix(SUFFIX)
    return beside if beside.is_file() else None


def _value(key: str, field: str, value: Any) -> Any:
    wanted = _FIELDS.get(field)
    if wanted is None:
        raise ValueError(f"[{key}]: unknown setting {field!r} (known: {', '.join(_FIELDS)})")
    if not isinstance(value, wanted) or (wanted is int and isinstance(value, bool)):
        expected = {str: "a string", bool: "true or false", int: "an integer"}[wanted]
        raise ValueError(f"[{key}] {field}: expected {expected}, not {value!r}")
    if field == "access_srdo":
        try:
            return SrdoAccess(str(value))
        except ValueError:
            raise ValueError(f"[{key}] access_srdo: one of {', '.join(a.value for a in SrdoAccess)}") from None
    if field == "string_length_min" and isinstance(value, int) and not 0 <= value <= 0xFFFF:
        raise ValueError(f"[{key}] string_length_min: {value} is out of range 0-65535")
    return value


def _target(device: Device, key: str) -> Variable:
    match = _KEY.fullmatch(key)
    if match is None:
        raise ValueError(f"[{key}]: a table name is an index like '2000' or a sub-object like '2000sub1' (hex)")
    obj = device.objects.get(int(match[1], 16))
    if obj is None:
        raise ValueError(f"[{key}]: the device has no object {match[1].upper()}h")
    if match[2] is None:
        return obj
    sub = obj.subs.get(int(match[2], 16))
    if sub is None:
        raise ValueError(f"[{key}]: object {obj.index:04X}h has no sub-index {match[2].upper()}h")
    return sub


def apply_overrides(device: Device, path: str | Path) -> list[str]:
    """Merge the file's settings into the device's `canopennode` fields; ValueError names what is wrong.

    Returns one line per setting applied, for --explain.
    """
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"not a TOML file: {error}") from None
    except UnicodeDecodeError:
        raise ValueError("not a UTF-8 text file") from None
    applied: list[str] = []
    for key, table in data.items():
        if not isinstance(table, dict):
            raise ValueError(f"{key!r}: expected a table like [2000] or [2000sub1]")
        var = _target(device, key)
        info = var.canopennode.model_copy() if var.canopennode is not None else CanopenNodeInfo()
        for field, value in table.items():
            setattr(info, field, _value(key, field, value))
            applied.append(f"{key.upper().replace('SUB', 'sub')}: {field} = {value!r} from {Path(path).name}")
        var.canopennode = info
    return applied
