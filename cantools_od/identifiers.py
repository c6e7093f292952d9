"""Identifiers of generated code: the one place where C, C++, Rust and Python names are made.

**Names.** `snake_case` turns a display name (ParameterName) into an identifier:

1. Symbols NFKD does not fold are spelled out: ``µ``/``μ`` → ``u``, ``ß`` → ``ss``, ``Ω`` → ``ohm``,
   ``ø`` → ``o``, ``æ`` → ``ae``, ``œ`` → ``oe``, ``²`` → ``2``, ``³`` → ``3``, and as words of
   their own ``°`` → ``deg``, ``%`` → ``percent``, ``‰`` → ``permille``.
2. The text is folded to ASCII with Unicode NFKD: accents are dropped (``ü`` → ``u``), any other
   non-ASCII character separates words (``½`` → ``1 2``, ``电机`` → nothing).
3. Words end at every character that is not an ASCII letter or digit, and at case changes:
   lower → upper (``ControlWord`` → ``control_word``); before the last capital of a run of
   capitals followed by lower case (``HTTPServer`` → ``http_server``), unless that is a lone
   plural ``s`` (``PDOs`` → ``pdos``); digits → capitalised word (``G1OffsetX0`` →
   ``g1_offset_x0``); capital + digits → lower case (``ABC123def`` → ``abc123_def``). Digits
   otherwise stay with their neighbours (``TPDO1`` → ``tpdo1``, ``1st``, ``16bit``), and
   ``CANopen`` in any spelling is one word.
4. The words are lower-cased and joined with ``_``: no leading ``_``, no ``__``, no trailing ``_``
   (except from 6). `snake_case` maps its own results to themselves.
5. A name that starts with a digit gets the prefix ``n_`` (``1st value`` → ``n_1st_value``).
6. A reserved word gets a trailing ``_`` (``type`` → ``type_``): a keyword of C11/C23, C++20
   (with alternative tokens and ``final``/``override``/``import``/``module``), Rust 2021 (strict,
   reserved, weak and primitive types), Python 3 (keywords and soft keywords), or a name that
   breaks generated code (``str``, ``int``, ``object``, ``errno``, ``assert``, ``stdin``,
   ``uint8_t``, ... see `RESERVED`).
7. A name with no letter or digit left (``""``, ``"????"``, ``"---"``) falls back to
   ``object_<index>`` for an object (4 lower-case hex digits: ``object_1a00``) and
   ``sub_<sub-index>`` for a sub-object (lower-case hex: ``sub_1f``).

**Uniqueness.** `assign` names the entries of a device in ascending (index, sub-index) order;
an entry's identifier depends only on the pins and on the entries before it, so objects added at
higher indices never rename existing ones.

- ``object(index)`` is unique among object *and* flat identifiers (one namespace). When taken,
  ``_<index>`` (4 lower-case hex digits) is appended: ``analog_input``, ``analog_input_6402``.
- ``member(index, subindex)`` is unique within its object. When taken, ``_<sub-index>`` (decimal)
  is appended: 0x1003 sub 1..8 "Standard error field" → ``standard_error_field``,
  ``standard_error_field_2``, ..., ``standard_error_field_8``.
- ``flat(index, subindex)`` is ``<object>_<member>`` (``identity_object_vendor_id``), or the object
  identifier for sub-index 0 of a VAR. When taken, ``_<index>`` (hex) is appended.

When the suffixed name is taken too, ``_2``, ``_3``, ... follows the suffix until it is free. A
trailing ``_`` of the left part is dropped when names are joined (``type_`` + ``value`` →
``type_value``) and every composed name goes through rule 6 again (``co`` + ``await`` → ``co_await_``).

**Pins.** A pin maps ``"2000"`` (an object) or ``"2000sub1"`` (a sub-object; hex, any case) to the
identifier to use instead of the generated one, so names survive changes of display names. A pinned
name must have the form of a generated one (``^[a-z][a-z0-9]*(_[a-z0-9]+)*_?$``, not reserved) or
`ValueError` names its key. Pinned names are placed first: generated names yield to them. Pins for
entries the device does not have are ignored. `Identifiers.to_toml` writes an ``[identifiers]``
table with a pin for every object and sub-object; `load_pins` reads it back.
"""

from __future__ import annotations

import bisect
import re
import unicodedata
from collections.abc import Iterator, Mapping
from functools import lru_cache
from pathlib import Path

from .model import Device

__all__ = ["RESERVED", "Identifiers", "assign", "is_identifier", "load_pins", "snake_case"]

_C = """auto break case char const continue default do double else enum extern float for goto if inline int
long register restrict return short signed sizeof static struct switch typedef union unsigned void volatile while
_Alignas _Alignof _Atomic _Bool _Complex _Generic _Imaginary _Noreturn _Static_assert _Thread_local
alignas alignof bool constexpr false nullptr static_assert thread_local true typeof typeof_unqual
_BitInt _Decimal32 _Decimal64 _Decimal128"""
_C_LIBRARY = """NULL EOF FILE errno assert stdin stdout stderr offsetof setjmp longjmp va_list va_start va_arg
va_end va_copy complex imaginary noreturn main unix linux size_t ptrdiff_t wchar_t intptr_t uintptr_t intmax_t
uintmax_t int8_t int16_t int32_t int64_t uint8_t uint16_t uint32_t uint64_t"""
_CPP = """alignas alignof and and_eq asm atomic_cancel atomic_commit atomic_noexcept auto bitand bitor bool
break case catch char char8_t char16_t char32_t class compl concept const consteval constexpr constinit
const_cast continue co_await co_return co_yield decltype default delete do double dynamic_cast else enum
explicit export extern false float for friend goto if inline int long mutable namespace new noexcept not
not_eq nullptr operator or or_eq private protected public reflexpr register reinterpret_cast requires return
short signed sizeof static static_assert static_cast struct switch synchronized template this thread_local
throw true try typedef typeid typename union unsigned using virtual void volatile wchar_t while xor xor_eq
final override import module transaction_safe transaction_safe_dynamic std"""
_RUST = """as break const continue crate else enum extern false fn for if impl in let loop match mod move mut
pub ref return self Self static struct super trait true type unsafe use where while async await dyn
abstract become box do final macro override priv typeof unsized virtual yield try gen union macro_rules raw
safe bool char str u8 u16 u32 u64 u128 usize i8 i16 i32 i64 i128 isize f32 f64
Option Some None Ok Err Result Box String Vec"""
_PYTHON = """False None True and as assert async await break class continue def del elif else except finally
for from global if import in is lambda nonlocal not or pass raise return try while with yield _ case match type
str int bool float bytes object complex list dict set tuple frozenset bytearray property classmethod
staticmethod super self cls"""
RESERVED: frozenset[str] = frozenset(" ".join((_C, _C_LIBRARY, _CPP, _RUST, _PYTHON)).split())
"""Words an identifier must not be: keywords of C, C++, Rust, Python and names that break generated code."""

_SYMBOLS = str.maketrans(
    {"\u00b5": "u", "\u03bc": "u", "\u2126": "ohm", "\u03a9": "ohm", "ß": "ss", "ẞ": "SS", "²": "2", "³": "3"}
    | {
        "ø": "o",
        "Ø": "O",
        "æ": "ae",
        "Æ": "AE",
        "œ": "oe",
        "Œ": "OE",
        "°": " deg ",
        "%": " percent ",
        "‰": " permille ",
    }
)  # micro sign and Greek mu, ohm sign and Greek omega: NFKD folds neither to ASCII
_CANOPEN = re.compile(r"canopen", re.IGNORECASE)
# Word boundaries inside a run of letters and digits: aB, ABc (unless "As" ending a word), 1Ab.
_CASE_CHANGE = re.compile(r"(?<=[a-z])(?=[A-Z])|(?<=[A-Z])(?=[A-Z](?!s(?![a-z]))[a-z])|(?<=[0-9])(?=[A-Z][a-z])")
_LETTER_DIGITS = re.compile(r"([A-Z][0-9]+)(?=[a-z])")  # ABC123def: abc123_def, but 1st and abc1def stay
_NON_WORD = re.compile(r"[^A-Za-z0-9]+")
_IDENTIFIER = re.compile(r"[a-z][a-z0-9]*(?:_[a-z0-9]+)*_?")
_PIN_KEY = re.compile(r"([0-9a-f]{4})(?:sub([0-9a-f]{1,2}))?", re.IGNORECASE)


def _fold(name: str) -> str:
    """ASCII with accents dropped; other non-ASCII characters become spaces."""
    if name.isascii() and "%" not in name:
        return name
    decomposed = unicodedata.normalize("NFKD", name.translate(_SYMBOLS))
    if decomposed.isascii():
        return decomposed
    return "".join(c if c.isascii() else "" if unicodedata.combining(c) else " " for c in decomposed)


def _safe(name: str) -> str:
    """A lower-case snake_case name made safe: `n_` before a leading digit, `_` after a reserved word."""
    if name[:1].isdigit():
        name = "n_" + name
    return name + "_" if name in RESERVED else name


@lru_cache(maxsize=65536)
def _snake(name: str) -> str:
    text = _CANOPEN.sub("Canopen", _fold(name))
    words = _NON_WORD.sub("_", _LETTER_DIGITS.sub(r"\1_", _CASE_CHANGE.sub("_", text))).strip("_").lower()
    return _safe(words) if words else ""


def snake_case(name: str, fallback: str = "unnamed") -> str:
    """The identifier for a display name (see the module docstring); `fallback` when nothing is left."""
    return _snake(name) or _safe(fallback)


def is_identifier(name: str) -> bool:
    """True for a name of the form `snake_case` produces: usable as is in C, C++, Rust and Python."""
    return _IDENTIFIER.fullmatch(name) is not None and name not in RESERVED


def _join(head: str, tail: str) -> str:
    return _safe(head.rstrip("_") + "_" + tail)


def _claim(base: str, suffix: str, taken: set[str]) -> str:
    """`base`, else `base_suffix`, else `base_suffix_2`, `_3`, ...: the first one not taken, now taken."""
    candidate, count = base, 1
    while candidate in taken:
        count += 1
        candidate = _join(base, suffix) if count == 2 else _join(_join(base, suffix), str(count - 1))
    taken.add(candidate)
    return candidate


def _parse_key(key: str) -> tuple[int, int | None]:
    match = _PIN_KEY.fullmatch(key)
    if match is None:
        raise ValueError(f"pin {key!r}: key must be an index like '2000' or a sub-object like '2000sub1' (hex)")
    return int(match[1], 16), None if match[2] is None else int(match[2], 16)


def _key(index: int, subindex: int | None = None) -> str:
    return f"{index:04X}" if subindex is None else f"{index:04X}sub{subindex:X}"


class _Subs:
    """An object's sub-objects: their sub-indices in ascending order, and their member and flat
    identifiers in the same order. Lists, not tables keyed by (index, sub-index): a large device
    has hundreds of thousands of sub-objects."""

    __slots__ = ("flats", "members", "subindices")

    def __init__(self) -> None:
        self.subindices: list[int] = []
        self.members: list[str] = []
        self.flats: list[str] = []

    def position(self, index: int, subindex: int) -> int:
        found = bisect.bisect_left(self.subindices, subindex)
        if found == len(self.subindices) or self.subindices[found] != subindex:
            raise KeyError((index, subindex))
        return found


class Identifiers:
    """The identifiers of one device's objects and sub-objects; made by `assign`."""

    def __init__(self, objects: dict[int, str], subs: dict[int, _Subs]):
        self._objects = objects
        self._subs = subs  # objects with sub-objects only

    def object(self, index: int) -> str:
        """The object's identifier, unique among object and flat identifiers."""
        return self._objects[index]

    def member(self, index: int, subindex: int) -> str:
        """The sub-object's identifier, unique within its object."""
        subs = self._subs.get(index)
        if subs is None:
            raise KeyError((index, subindex))
        return subs.members[subs.position(index, subindex)]

    def flat(self, index: int, subindex: int) -> str:
        """`<object>_<member>`, or the object's identifier for sub-index 0 of a VAR; unique in the device."""
        subs = self._subs.get(index)
        if subs is None:
            if subindex == 0 and index in self._objects:
                return self._objects[index]
            raise KeyError((index, subindex))
        return subs.flats[subs.position(index, subindex)]

    def items(self) -> Iterator[tuple[str, str]]:
        """(pin key, identifier) of every object and sub-object in (index, sub-index) order."""
        for index in sorted(self._objects):
            yield _key(index), self._objects[index]
            subs = self._subs.get(index)
            if subs is not None:
                for subindex, member in zip(subs.subindices, subs.members, strict=True):
                    yield _key(index, subindex), member

    def to_toml(self) -> str:
        """A pin file for every object and sub-object; `load_pins` reads it back."""
        lines = ["# Identifiers of generated code. Pass this file with --pins to keep them.", "[identifiers]"]
        lines += [f'"{key}" = "{name}"' for key, name in self.items()]
        return "\n".join(lines) + "\n"


def _check_pins(pins: Mapping[str, str]) -> tuple[dict[int, str], dict[tuple[int, int], str]]:
    objects: dict[int, str] = {}
    members: dict[tuple[int, int], str] = {}
    owners: dict[tuple[int, str], str] = {}  # (namespace, name) → key: objects share -1, members their index
    seen: dict[str, str] = {}  # canonical key → key as written
    for key, name in pins.items():
        index, subindex = _parse_key(key)
        if not isinstance(name, str) or not is_identifier(name):
            raise ValueError(
                f"pin {key!r}: {name!r} is not a usable identifier (lower-case snake_case starting with a letter, "
                "no '__', not a reserved word of C, C++, Rust or Python)"
            )
        address = _key(index, subindex)
        if address in seen:
            raise ValueError(f"pin {key!r}: {seen[address]!r} pins the same entry")
        seen[address] = key
        other = owners.setdefault((-1 if subindex is None else index, name), key)
        if other != key:
            raise ValueError(f"pin {key!r}: {name!r} is pinned for {other!r} as well")
        if subindex is None:
            objects[index] = name
        else:
            members[index, subindex] = name
    return objects, members


def assign(device: Device, pins: Mapping[str, str] | None = None) -> Identifiers:
    """Identifiers for every object and sub-object of `device`, following the rule of this module."""
    pinned_objects, pinned_members = _check_pins(pins or {})
    objects: dict[int, str] = {}
    subs: dict[int, _Subs] = {}
    taken = {name for index, name in pinned_objects.items() if index in device.objects}
    names: dict[str, str] = {}
    for index in sorted(device.objects):
        obj = device.objects[index]
        name = pinned_objects.get(index)
        if name is None:
            name = _claim(snake_case(obj.name, f"object_{index:04x}"), f"{index:04x}", taken)
        objects[index] = name
        if not obj.has_subs:
            continue
        local = {pinned_members[index, sub] for sub in obj.subs if (index, sub) in pinned_members}
        found = subs[index] = _Subs()
        for sub in sorted(obj.subs):
            member = pinned_members.get((index, sub))
            if member is None:
                member = _claim(snake_case(obj.subs[sub].name, f"sub_{sub:x}"), str(sub), local)
            found.subindices.append(sub)
            found.members.append(names.setdefault(member, member))  # one string for a name many objects use
            found.flats.append(_claim(_join(name, member), f"{index:04x}", taken))
    return Identifiers(objects, subs)


def load_pins(path: str | Path) -> dict[str, str]:
    """The `[identifiers]` table of a TOML pin file; ValueError when the file is not one."""
    import tomllib  # only with a pin file: start-up counts

    try:
        data = tomllib.loads(Path(path).read_text(encoding="utf-8"))
    except tomllib.TOMLDecodeError as error:
        raise ValueError(f"{path}: not a TOML file: {error}") from error
    if not data:
        return {}  # an empty file (or only comments) pins nothing, as when `ids FILE > PINS` has just emptied it
    table = data.get("identifiers")
    if not isinstance(table, dict):
        raise ValueError(f"{path}: no [identifiers] table")
    pins: dict[str, str] = {}
    for key, name in table.items():
        if not isinstance(name, str):
            raise ValueError(f"{path}: pin {key!r}: the identifier must be a string, not {name!r}")
        _parse_key(key)
        pins[key] = name
    _check_pins(pins)
    return pins


def pin_file_for(source: str | Path, explicit: str | Path | None = None) -> Path | None:
    """The pin file to use for `source`: the one given, else `<source stem>.ids.toml` beside it."""
    if explicit is not None:
        return Path(explicit)
    beside = Path(source).with_suffix(".ids.toml")
    return beside if beside.is_file() else None
