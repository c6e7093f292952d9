"""Python source text for the generated bindings: literals, docstrings and PDO field names.

Literals are spelled the way `ruff format` spells them (double quotes, upper-case hex digits), so
generated modules are stable under the formatter. Whatever a file's text holds, a literal or docstring
made here is one valid Python token that evaluates back to that text.
"""

from __future__ import annotations

import math
import textwrap
from collections.abc import Iterable

from ..model import NodeIdExpr

LINE_LENGTH = 120


def py_str(text: str) -> str:
    """A str literal, double-quoted unless that needs more escapes."""
    literal = repr(text)
    if literal.startswith("'") and '"' not in text:
        return '"' + literal[1:-1] + '"'
    return literal


def py_bytes(data: bytes) -> str:
    literal = repr(data)
    if literal.startswith("b'") and b'"' not in data:
        return 'b"' + literal[2:-1] + '"'
    return literal


def py_hex(number: int, digits: int = 4) -> str:
    return f"-0x{-number:0{digits}X}" if number < 0 else f"0x{number:0{digits}X}"


def py_value(value: object) -> str:
    """A literal for a value of the object dictionary tables."""
    if value is None or isinstance(value, bool):
        return repr(value)
    if isinstance(value, NodeIdExpr):
        return f"_NodeId({py_hex(value.offset, 1)})"
    if isinstance(value, int):
        return str(value)
    if isinstance(value, float):
        if math.isnan(value):
            return 'float("nan")'
        if math.isinf(value):
            return 'float("inf")' if value > 0 else '-float("inf")'
        return repr(value).replace("e+", "e")  # as `ruff format` writes exponents
    if isinstance(value, str):
        return py_str(value)
    if isinstance(value, bytes):
        return py_bytes(value)
    raise TypeError(f"no literal for {value!r}")


def doc_text(text: str) -> str:
    """Text for inside a \"\"\"docstring\"\"\": one line, printable ASCII, escapes that evaluate back to `text`."""
    out: list[str] = []
    for char in " ".join(text.split()):
        code = ord(char)
        if char in '\\"':
            out.append("\\" + char)
        elif 0x20 <= code < 0x7F:
            out.append(char)
        elif code < 0x100:
            out.append(f"\\x{code:02x}")
        elif code < 0x10000:
            out.append(f"\\u{code:04x}")
        else:
            out.append(f"\\U{code:08x}")
    return "".join(out)


def docstring(text: str, indent: int) -> str:
    """The inside of a docstring at `indent` spaces: one line when it fits, else wrapped lines."""
    width = LINE_LENGTH - indent - 3
    lines = textwrap.wrap(text, width, break_long_words=False, break_on_hyphens=False)
    if len(text) <= width - 3 or len(lines) < 2:
        return text
    pad = "\n" + " " * indent
    return pad.join(lines) + pad


def wrap(lines: Iterable[str], indent: int) -> list[str]:
    """Docstring body lines wrapped to the line length, continuation lines indented by two more spaces."""
    out: list[str] = []
    for line in lines:
        out += textwrap.wrap(
            line,
            LINE_LENGTH - indent,
            subsequent_indent="  ",
            break_long_words=False,
            break_on_hyphens=False,
        ) or [""]
    return out


def field_names(identifiers: list[str], reserved: frozenset[str]) -> list[str]:
    """Dataclass field names: each identifier as is the first time; `_2`, `_3`, ... when seen before or reserved.

    A suffixed name never takes an identifier that comes later in the list, so names do not depend on order
    beyond the entries before them.
    """
    taken = {name for name in identifiers if name not in reserved} | set(reserved)
    seen: set[str] = set()
    names: list[str] = []
    for base in identifiers:
        if base not in seen and base not in reserved:
            seen.add(base)
            names.append(base)
            continue
        number = 2
        while f"{base.rstrip('_')}_{number}" in taken:
            number += 1
        name = f"{base.rstrip('_')}_{number}"
        taken.add(name)
        names.append(name)
    return names


def py_long_str(text: str, indent: int, room: int) -> str:
    """A str literal for after `room` characters of a line: one literal when it fits, else implicitly
    concatenated pieces in parentheses, one per line of `text` (cut further to fit)."""
    literal = py_str(text)
    if indent + room + len(literal) <= LINE_LENGTH:
        return literal
    pieces: list[str] = []
    for line in text.splitlines(keepends=True) or [""]:
        while len(line) > 80:
            pieces.append(line[:80])
            line = line[80:]
        pieces.append(line)
    pad = " " * (indent + 4)
    return "(\n" + "".join(f"{pad}{py_str(piece)}\n" for piece in pieces if piece) + " " * indent + ")"


def py_tuple_inline(items: list[str], indent: int, room: int) -> str | None:
    """A tuple on one line when `ruff format` would keep it there (empty, or one item that fits), else None."""
    if not items:
        return "()"
    if len(items) == 1 and indent + room + len(items[0]) + 3 <= LINE_LENGTH:
        return f"({items[0]},)"
    return None


def py_call(function: str, args: list[str], indent: int, suffix: str = "") -> str:
    """`function(args)` + `suffix` at `indent` spaces, laid out as `ruff format` lays out a call: on one line when
    it fits, else the arguments on one line of their own, else one argument per line with a trailing comma."""
    pad = " " * indent
    flat = f"{pad}{function}({', '.join(args)}){suffix}"
    if len(flat) <= LINE_LENGTH:
        return flat
    inner = " " * (indent + 4)
    hugged = f"{inner}{', '.join(args)}"
    if len(hugged) <= LINE_LENGTH:
        return f"{pad}{function}(\n{hugged}\n{pad}){suffix}"
    return f"{pad}{function}(\n" + "".join(f"{inner}{arg},\n" for arg in args) + f"{pad}){suffix}"


def py_def(name: str, params: list[str], returns: str, indent: int) -> str:
    """A `def` line as `ruff format` lays it out: when too long, a lone parameter goes on a line of its own with a
    trailing comma; several go together on one line when they fit, else one per line."""
    pad, inner = " " * indent, " " * (indent + 4)
    flat = f"{pad}def {name}({', '.join(params)}) -> {returns}:"
    if len(flat) <= LINE_LENGTH:
        return flat
    if len(params) > 1 and len(inner) + len(", ".join(params)) <= LINE_LENGTH:
        return f"{pad}def {name}(\n{inner}{', '.join(params)}\n{pad}) -> {returns}:"
    return f"{pad}def {name}(\n" + "".join(f"{inner}{p},\n" for p in params) + f"{pad}) -> {returns}:"


def py_constant(name: str, value: str) -> str:
    """`NAME: Final = value`, in parentheses on lines of their own when too long and that helps."""
    line = f"{name}: Final = {value}"
    if len(line) <= LINE_LENGTH or len(f"{name}: Final = (") > LINE_LENGTH:
        return line
    return f"{name}: Final = (\n    {value}\n)"
