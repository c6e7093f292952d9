"""Lines of Rust laid out exactly as `rustfmt` (edition 2021, default options) lays them out.

Generated Rust must pass `rustfmt --check`, and identifiers from an EDS can be 150 characters
long, so every construct that holds one is laid out here by rustfmt's own rules: put it on one
line when it fits in 100 columns, else break where rustfmt breaks. Where rustfmt finds no layout
that fits it keeps the source as it is; the one-line form is returned then.

Expressions passed in are *atomic* for rustfmt (literals, paths, `-1`, `*b"..."`, `[0; 4]`,
`f32::from_bits(0x..)`): it never breaks inside them.
"""

from __future__ import annotations

WIDTH = 100  # max_width
CALL_WIDTH = 60  # fn_call_width: the arguments of a call on one line
STRUCT_WIDTH = 18  # struct_lit_width: the fields of a struct expression on one line
INDENT = "    "


def _fits(*lines: str) -> bool:
    return all(len(line) <= WIDTH for line in lines)


def _type_fits(prefix: str, ty: str) -> bool:
    """Whether rustfmt keeps the type on the line of `{prefix} {ty} =`; a slice type needs 2 columns more."""
    return len(prefix) + 3 + len(ty) + (2 if ty.startswith("&[") else 0) <= WIDTH


def item(pad: str, head: str, name: str, ty: str, rhs: str) -> str:
    """`{head} {name}: {ty} = {rhs};` (a const or static item) at indentation `pad`.

    A block-like `rhs` (ending in `{` or `[`) opens its block on the last line of the item head.
    `ty` is a path, a primitive, `&str` or `&[u8]`: never an array type, which rustfmt may break.
    """
    one = f"{pad}{head} {name}: {ty} = {rhs}"
    block = rhs.endswith(("{", "["))
    if block or _fits(one + ";"):
        # rustfmt: the type goes on its own line when `{head} {name}: ` leaves it no room
        prefix = f"{pad}{head} {name}:"
        if len(prefix) + 2 > WIDTH:
            return one if block else one + ";"
        if _type_fits(prefix, ty) or (block and _fits(one)):
            return one if block else one + ";"
        return f"{prefix}\n{pad}{INDENT}{ty} = {rhs}" + ("" if block else ";")
    prefix = f"{pad}{head} {name}:"
    if len(prefix) + 2 > WIDTH:
        return one + ";"
    if _type_fits(prefix, ty):
        lhs = f"{prefix} {ty} ="
    else:
        if not _fits(f"{pad}{INDENT}{ty} ="):
            return one + ";"
        lhs = f"{prefix}\n{pad}{INDENT}{ty} ="
    last = lhs.rsplit("\n", 1)[-1]
    if _fits(f"{last} {rhs};"):
        return f"{lhs} {rhs};"
    if _fits(f"{pad}{INDENT}{rhs};"):
        return f"{lhs}\n{pad}{INDENT}{rhs};"
    return one + ";"


def fn_head(pad: str, head: str, name: str, params: list[str], ret: str) -> str:
    """`{head} {name}({params}) -> {ret} {` — the parameters one per line when it does not fit."""
    one = f"{pad}{head} {name}({', '.join(params)}) -> {ret} {{"
    if _fits(one) or not params:
        return one
    inner = "".join(f"{pad}{INDENT}{param},\n" for param in params)
    return f"{pad}{head} {name}(\n{inner}{pad}) -> {ret} {{"


def call(pad: str, callee: str, args: list[str]) -> str:
    """The statement `{callee}({args});` — vertical arguments when too wide."""
    joined = ", ".join(args)
    one = f"{pad}{callee}({joined});"
    if _fits(one) and len(joined) <= CALL_WIDTH:
        return one
    lines = [f"{pad}{INDENT}{arg}," for arg in args]
    if not _fits(*lines):
        return one
    return "\n".join([f"{pad}{callee}(", *lines, f"{pad});"])


def field_init(pad: str, name: str, expr: str) -> str:
    """`{name}: {expr},` in a struct expression laid out one field per line."""
    one = f"{pad}{name}: {expr},"
    if _fits(one):
        return one
    if len(pad) + len(name) + 2 > WIDTH or not _fits(f"{pad}{INDENT}{expr},"):
        return one
    return f"{pad}{name}:\n{pad}{INDENT}{expr},"


def field_call(pad: str, name: str, callee: str, args: list[str]) -> str:
    """`{name}: {callee}({args}),` in a struct expression laid out one field per line."""
    joined = ", ".join(args)
    one = f"{pad}{name}: {callee}({joined}),"
    if _fits(one):
        return one
    if _fits(f"{pad}{name}: {callee}(", f"{pad}{INDENT}{joined},"):
        return f"{pad}{name}: {callee}(\n{pad}{INDENT}{joined},\n{pad}),"
    return field_init(pad, name, f"{callee}({joined})")


def struct_body(fields: list[tuple[str, str]]) -> str | None:
    """`{ a: 1, b: 2 }` when rustfmt keeps a struct expression on one line (struct_lit_width), else None."""
    body = ", ".join(f"{name}: {value}" for name, value in fields)
    if not body:
        return "{}"
    return f"{{ {body} }}" if len(body) <= STRUCT_WIDTH else None


def field_decl(pad: str, name: str, ty: str) -> str:
    """`pub {name}: {ty},` in a struct definition."""
    one = f"{pad}pub {name}: {ty},"
    return one if _fits(one) else f"{pad}pub {name}:\n{pad}{INDENT}{ty},"


def type_alias(name: str, ty: str) -> str:
    one = f"pub type {name} = {ty};"
    return one if _fits(one) else f"pub type {name} =\n{INDENT}{ty};"


def struct_open(name: str) -> str:
    """`pub struct {name} {`: the brace on a line of its own when the name is too long."""
    one = f"pub struct {name} {{"
    return one if _fits(one) else f"pub struct {name}\n{{"


def impl_open(name: str, trait: str = "") -> str:
    """`impl {name} {` or `impl {trait} for {name} {`, broken before the type when too long."""
    one = f"impl {trait} for {name} {{" if trait else f"impl {name} {{"
    rest = f"{INDENT}for {name}" if trait else f"{INDENT}{name}"
    if _fits(one) or not _fits(rest):
        return one
    return f"impl {trait}\n{rest}\n{{" if trait else f"impl\n{rest}\n{{"
