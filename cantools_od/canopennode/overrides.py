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

One more table, `[stack]`, declares the stack's build configuration: `CO_CONFIG_*` switches as
`CO_driver_target.h` sets them (an integer, or flag names joined by `|`), which decide the objects
CANopen.c needs, and `pdo_attributes = "canopeneditor"` to keep CANopenEditor's ODA_*PDO bits.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path
from typing import Any

from ..model import Device, Variable
from .info import CanopenNodeInfo, SrdoAccess
from .profile import STACK_DEFAULTS, STACK_FLAGS, SWITCH_PREFIX, StackConfig

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


def read_settings(path: str | Path) -> dict[str, Any]:
    """The settings file's tables; ValueError when it is not TOML."""
    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"not a TOML file: {error}") from None
    except UnicodeDecodeError:
        raise ValueError("not a UTF-8 text file") from None
    table = data.get(STACK_TABLE)
    if table is not None and not isinstance(table, dict):
        raise ValueError(f"{STACK_TABLE!r}: expected a table [{STACK_TABLE}]")
    return data


def apply_overrides(device: Device, path: str | Path) -> list[str]:
    """Merge the file's settings into the device's `canopennode` fields; ValueError names what is wrong.

    Returns one line per setting applied, for --explain.
    """
    applied: list[str] = []
    for key, table in read_settings(path).items():
        if key == STACK_TABLE:
            continue
        if not isinstance(table, dict):
            raise ValueError(f"{key!r}: expected a table like [2000] or [2000sub1]")
        var = _target(device, key)
        info = var.canopennode.model_copy() if var.canopennode is not None else CanopenNodeInfo.model_construct()
        for field, value in table.items():
            setattr(info, field, _value(key, field, value))
            applied.append(f"{key.upper().replace('SUB', 'sub')}: {field} = {value!r} from {Path(path).name}")
        var.canopennode = info
    return applied


# --- the stack's build configuration -----------------------------------------------------------

STACK_TABLE = "stack"
_DEFINE = re.compile(r"^[ \t]*#[ \t]*define[ \t]+([A-Za-z_]\w*)(?![\w(])[ \t]*(.*)$", re.M)
_TOKEN = re.compile(r"\s*(?:(0[xX][0-9A-Fa-f]+|\d+)[uUlL]*|([A-Za-z_]\w*)|(<<|>>|[|&~()^+]))")


def c_defines(text: str) -> dict[str, str]:
    """The object-like `#define NAME body` of a C header, the first of each name (as `#ifndef` guards keep it)."""
    joined = re.sub(r"\\\r?\n", " ", text)
    joined = re.sub(r"/\*.*?\*/", " ", joined, flags=re.S)
    found: dict[str, str] = {}
    for name, body in _DEFINE.findall(joined):
        found.setdefault(name, body.split("//")[0].strip())
    return found


class _Expression:
    """A C constant expression of numbers, names, | & ^ ~ + << >> and parentheses, with names looked up."""

    def __init__(self, text: str, names: dict[str, str], depth: int) -> None:
        self.tokens: list[tuple[str, str]] = []
        at = 0
        while at < len(text.rstrip()):
            match = _TOKEN.match(text, at)
            if match is None:
                raise ValueError(f"cannot read {text.strip()!r} as a constant")
            number, name, op = match.groups()
            self.tokens.append(("n", number) if number else ("a", name) if name else ("o", op))
            at = match.end()
        self.names, self.depth, self.at = names, depth, 0

    def evaluate(self) -> int:
        value = self._binary(0)
        if self.at != len(self.tokens):
            raise ValueError("cannot read the expression to its end")
        return value

    _LEVELS = (("|",), ("^",), ("&",), ("<<", ">>"), ("+",))

    def _binary(self, level: int) -> int:
        if level == len(self._LEVELS):
            return self._unary()
        value = self._binary(level + 1)
        while self.at < len(self.tokens) and self.tokens[self.at] in [("o", op) for op in self._LEVELS[level]]:
            op = self.tokens[self.at][1]
            self.at += 1
            right = self._binary(level + 1)
            value = {"|": value | right, "^": value ^ right, "&": value & right, "<<": value << right,
                     ">>": value >> right, "+": value + right}[op]  # fmt: skip
        return value

    def _unary(self) -> int:
        if self.at >= len(self.tokens):
            raise ValueError("the expression ends early")
        kind, text = self.tokens[self.at]
        self.at += 1
        if (kind, text) == ("o", "~"):
            return ~self._unary() & 0xFFFFFFFF
        if (kind, text) == ("o", "("):
            value = self._binary(0)
            if self.tokens[self.at : self.at + 1] != [("o", ")")]:
                raise ValueError("a '(' is not closed")
            self.at += 1
            return value
        if kind == "n":
            return int(text, 0) if not re.fullmatch(r"0\d+", text) else int(text, 8)
        if kind == "a":
            return switch_value(text, self.names, self.depth + 1)
        raise ValueError(f"unexpected {text!r}")


def switch_value(name: str, names: dict[str, str], depth: int = 0) -> int:
    """The value of a macro: the project's definition, else the stack's flag of that name, else 0."""
    if depth > 32:
        raise ValueError(f"{name} is defined in terms of itself")
    if name in names:
        return _Expression(names[name] or "1", names, depth).evaluate()
    return STACK_FLAGS.get(name, 0)


def stack_config(files: list[str | Path], table: dict[str, Any] | None, table_file: str = "") -> StackConfig:
    """The configuration from C headers (`#define CO_CONFIG_...`, first wins) and a `[stack]` table (which wins).

    ValueError names what cannot be read.
    """
    names: dict[str, str] = {}
    for file in files:
        try:
            text = Path(file).read_text(encoding="utf-8", errors="replace")
        except OSError as error:
            raise ValueError(f"{file}: {error.strerror or error}") from None
        for name, body in c_defines(text).items():
            names.setdefault(name, body)
    editor_pdo = False
    where = f"{table_file}: [{STACK_TABLE}]" if table_file else f"[{STACK_TABLE}]"
    for key, value in (table or {}).items():
        if key == "pdo_attributes":
            if value not in ("cantools-od", "canopeneditor"):
                raise ValueError(f"{where} pdo_attributes: 'cantools-od' or 'canopeneditor', not {value!r}")
            editor_pdo = value == "canopeneditor"
        elif key.startswith(SWITCH_PREFIX) and isinstance(value, (int, str)) and not isinstance(value, bool):
            names[key] = str(value)
        else:
            raise ValueError(f"{where} {key}: expected a {SWITCH_PREFIX}* switch (an integer or flag names "
                             "joined by '|') or pdo_attributes")  # fmt: skip
    switches = []
    for switch in STACK_DEFAULTS:
        if switch in names:
            try:
                switches.append((switch, switch_value(switch, names)))
            except ValueError as error:
                raise ValueError(f"{switch}: {error}") from None
    sources = tuple(str(f) for f in files) + ((table_file,) if table and table_file else ())
    declared = bool(files) or any(k.startswith(SWITCH_PREFIX) for k in table or {})
    return StackConfig(tuple(switches), declared, editor_pdo, sources)
