"""CANopenEditor's OD.c/OD.h read as text: what the stack would see, in the shape od_walk.c prints for ours.

Fetched projects' files are test material we may read but never build, so their OD is not compiled:
this reads the layout CANopenEditor v4 writes (the storage-group initializers `OD_<group>_t OD_<group> =
{...}`, the `ODObjs` descriptions with `.dataOrig`, `.attribute`, `.dataLength` and the ARRAY/RECORD
forms, the `ODList` of `{index, sub-entries, ODT_*, &ODObjs.o_..., ...}`) and the C types of the
members from OD.h, and yields per object the sub-entry count and type, per sub-entry the attribute,
the length, the storage group of its memory and its initial bytes, as `cnokit.walk` does for ours.
"""

from __future__ import annotations

import re
import struct
from dataclasses import dataclass, field

from cnokit import Entry, Sub

ODA = {"ODA_SDO_R": 0x01, "ODA_SDO_W": 0x02, "ODA_SDO_RW": 0x03, "ODA_TPDO": 0x04, "ODA_RPDO": 0x08,
       "ODA_TRPDO": 0x0C, "ODA_TSRDO": 0x10, "ODA_RSRDO": 0x20, "ODA_TRSRDO": 0x30, "ODA_MB": 0x40,
       "ODA_STR": 0x80}  # fmt: skip
ODT = {"ODT_VAR": 1, "ODT_ARR": 2, "ODT_REC": 3}
_TOKEN = re.compile(
    r"""\s*(?:(//[^\n]*|/\*.*?\*/)|('(?:\\.|[^'\\])*'|"(?:\\.|[^"\\])*")|(\(char\))|([{}=,;\[\]&.()])|([^\s{}=,;\[\]&.()'"]+(?:\.[0-9][^\s{}=,;\[\]&()'"]*)?))""",
    re.S,
)


def tokens(text: str) -> list[str]:
    """C tokens, roughly: literals, punctuation, words (numbers with their dots and exponents)."""
    out = []
    at = 0
    while at < len(text):
        match = _TOKEN.match(text, at)
        if match is None:
            if text[at:].strip() == "":
                break
            raise ValueError(f"cannot read C text at {text[at : at + 40]!r}")
        at = match.end()
        comment, literal, cast, punct, word = match.groups()
        if not comment:
            out.append(literal or cast or punct or word)
    return out


@dataclass
class Init:
    """A parsed initializer: a scalar's tokens, or a brace list of items (named for designated members)."""

    scalar: list[str] = field(default_factory=list)
    items: list[tuple[str | None, Init]] | None = None

    def member(self, name: str) -> Init:
        assert self.items is not None
        return next(value for key, value in self.items if key == name)


class _Parser:
    def __init__(self, toks: list[str]) -> None:
        self.toks, self.at = toks, 0

    def peek(self) -> str:
        return self.toks[self.at]

    def take(self, expected: str | None = None) -> str:
        tok = self.toks[self.at]
        if expected is not None and tok != expected:
            raise ValueError(f"expected {expected!r}, found {tok!r}")
        self.at += 1
        return tok

    def init(self) -> Init:
        if self.peek() != "{":
            scalar = []
            while self.peek() not in (",", "}", ";"):
                scalar.append(self.take())
            return Init(scalar)
        self.take("{")
        items: list[tuple[str | None, Init]] = []
        while self.peek() != "}":
            name = None
            if self.peek() == ".":
                self.take(".")
                name = self.take()
                self.take("=")
            items.append((name, self.init()))
            if self.peek() == ",":
                self.take(",")
        self.take("}")
        return Init(items=items)


def _definition(text: str, pattern: str) -> Init:
    """The initializer after `pattern =` (a regex) in `text`."""
    match = re.search(pattern + r"\s*=", text)
    if match is None:
        raise ValueError(f"no {pattern} in CANopenEditor's OD.c")
    parser = _Parser(tokens(text[match.end() :]))
    return parser.init()


def _c_types(header: str) -> dict[str, str]:
    """Member path (x1000_deviceType, x1018_identity.vendor_ID) → C type, from OD.h's group structs."""
    types: dict[str, str] = {}
    toks = tokens(header)
    stack: list[list[tuple[str, str]]] = []
    at = 0
    while at < len(toks):
        tok = toks[at]
        if tok == "struct" and toks[at + 1] == "{":
            stack.append([])
            at += 2
            continue
        if tok == "}" and stack:
            members = stack.pop()
            name = toks[at + 1]
            record = re.fullmatch(r"x[0-9A-F]{4}_\w+", name) is not None  # a RECORD's struct inside a group
            for member, ctype in members:
                types[f"{name}.{member}" if record else member] = ctype
            at += 2
            continue
        declares = stack and at + 2 < len(toks) and re.fullmatch(r"\w+", tok) and re.fullmatch(r"\w+", toks[at + 1])
        if declares and toks[at + 2] in (";", "["):  # `uint32_t x1000_deviceType;`, `char x1008_name[12];`
            stack[-1].append((toks[at + 1], tok))
            at += 2
            continue
        at += 1
    return types


def _number(word: str) -> int:
    word = word.rstrip("uUlL")
    return int(word, 16) if word.lower().startswith("0x") else int(word, 10)


def _scalar_bytes(scalar: list[str], ctype: str, length: int) -> bytes:
    text = "".join(scalar)
    if ctype == "bool_t":
        return bytes([1 if text == "true" else 0])
    if ctype in ("float32_t", "float64_t"):
        value = float(text.rstrip("fF")) if not text.lower().startswith(("0x", "-0x")) else float(_number(text))
        return struct.pack("<f" if ctype == "float32_t" else "<d", value)
    negative = text.startswith("-")
    value = _number(text.lstrip("-"))
    return ((-value if negative else value) % (1 << (8 * length))).to_bytes(length, "little")


def _element(scalar: list[str]) -> int:
    text = "".join(t for t in scalar if t != "(char)")
    if text.startswith("'"):
        body = text[1:-1]
        return ord(body.encode().decode("unicode_escape")) if body.startswith("\\") else ord(body)
    return _number(text)


def value_bytes(init: Init, ctype: str, length: int) -> bytes:
    """The first `length` bytes of a member's memory, from its initializer and C type."""
    if init.items is None:
        return _scalar_bytes(init.scalar, ctype, length)
    width = 2 if ctype == "uint16_t" else 1
    raw = b"".join(_element(item.scalar).to_bytes(width, "little") for _, item in init.items)
    return raw[:length].ljust(length, b"\0")


_POINTER = re.compile(r"&(\w+?)_(\w+)\.(x[0-9A-F]{4}_\w+?)(?:\.(\w+))?(?:\[0\])*$")


def _fields(init: Init) -> dict[str, str]:
    assert init.items is not None
    return {str(key): "".join(value.scalar) for key, value in init.items}


def _attribute(text: str) -> int:
    return sum(ODA[bit] for bit in text.split("|") if bit in ODA)


class EditorOD:
    """One CANopenEditor OD.c/OD.h pair, read."""

    def __init__(self, source: str, header: str, name: str = "OD") -> None:
        self.name = name
        self.types = _c_types(header)
        groups = re.findall(rf"\b{name}_(\w+)_t\s+{name}_(\w+)\s*=", source)
        self.groups = {group: _definition(source, rf"\b{name}_{group}_t\s+{name}_{group}") for group, _ in groups}
        self.objects = _definition(source, r"\bODObjs_t\s+ODObjs")
        self.list = _definition(source, r"\bOD_entry_t\s+ODList\[\]")

    def memory(self, pointer: str, length: int, element: int = 0, size: int = 0) -> tuple[str, bytes | None]:
        """The storage group and bytes `pointer` (`&OD_RAM.x1003_...[0]`) designates; ("-", None) for NULL."""
        if pointer == "NULL":
            return "-", None
        match = _POINTER.fullmatch(pointer.replace(" ", ""))
        assert match is not None and match[1] == self.name, pointer
        group, variable, member = match[2], match[3], match[4]
        init = self.groups[group].member(variable)
        path = variable
        if member is not None:
            init, path = init.member(member), f"{variable}.{member}"
        ctype = self.types.get(path, "uint8_t")
        if size:  # an ARRAY element
            assert init.items is not None
            init = init.items[element][1]
        return group, value_bytes(init, ctype, length)

    def entries(self) -> dict[int, Entry]:
        found: dict[int, Entry] = {}
        assert self.list.items is not None
        for _, row in self.list.items:
            assert row.items is not None
            index, count, odt, target = ("".join(item.scalar) for _, item in row.items[:4])
            if int(index, 16) == 0 and target == "NULL":
                continue
            entry = Entry(int(index, 16), int(count, 16), ODT[odt], {})
            self._subs(entry, self.objects.member(target.removeprefix("&ODObjs.")))
            found[entry.index] = entry
        return found

    def _subs(self, entry: Entry, obj: Init) -> None:
        if entry.kind == ODT["ODT_VAR"]:
            f = _fields(obj)
            length = int(f["dataLength"])
            group, data = self.memory(f["dataOrig"], length)
            entry.subs[0] = Sub(_attribute(f["attribute"]), length, group, data)
        elif entry.kind == ODT["ODT_ARR"]:
            f = _fields(obj)
            group, data = self.memory(f["dataOrig0"], 1)
            entry.subs[0] = Sub(_attribute(f["attribute0"]), 1, group, data)
            length = int(f["dataElementLength"])
            for n in range(1, entry.sub_count):
                group, data = self.memory(f["dataOrig"], length, n - 1, 1)
                entry.subs[n] = Sub(_attribute(f["attribute"]), length, group, data)
        else:
            assert obj.items is not None
            for _, record in obj.items:
                f = _fields(record)
                length = int(f["dataLength"])
                group, data = self.memory(f["dataOrig"], length)
                entry.subs[int(f["subIndex"])] = Sub(_attribute(f["attribute"]), length, group, data)
