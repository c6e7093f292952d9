"""Rust names derived from the identifiers of `cantools_od.identifiers`, and what they must avoid."""

from __future__ import annotations

from collections.abc import Iterable

# Types every generated module defines, and names from Rust's prelude a generated type must not shadow.
FIXED_TYPES = ("DataType", "Access", "ObjectEntry", "PdoError", "Raw")
_PRELUDE = (
    "Self", "Copy", "Send", "Sized", "Sync", "Unpin", "Drop", "Fn", "FnMut", "FnOnce", "Box", "ToOwned", "Clone",
    "PartialEq", "PartialOrd", "Eq", "Ord", "AsRef", "AsMut", "Into", "From", "Default", "Iterator", "Extend",
    "IntoIterator", "DoubleEndedIterator", "ExactSizeIterator", "Option", "Some", "None", "Result", "Ok", "Err",
    "String", "ToString", "Vec", "TryFrom", "TryInto", "FromIterator", "Debug", "Hash",
)  # fmt: skip


def upper(identifier: str) -> str:
    """SCREAMING_SNAKE_CASE base of constants; the trailing `_` of a reserved word is dropped."""
    return identifier.rstrip("_").upper()


def lower(identifier: str) -> str:
    """snake_case base of functions that append a suffix."""
    return identifier.rstrip("_")


def camel(identifier: str) -> str:
    """UpperCamelCase: `read_input_8_bit` → `ReadInput8Bit`; `_` stays only between two digits."""
    out = ""
    for word in identifier.rstrip("_").split("_"):
        if out and out[-1].isdigit() and word[:1].isdigit():
            out += "_"
        out += word[:1].upper() + word[1:]
    return out


class TypeNames:
    """Unique type names: the fixed ones and the prelude's are taken before any is handed out."""

    def __init__(self, taken: Iterable[str] = ()) -> None:
        self._taken = {*FIXED_TYPES, *_PRELUDE, *taken}

    def claim(self, identifier: str, index: int) -> str:
        """`camel(identifier)`, else with `At<index>` appended, else with `N2`, `N3`, ... too."""
        base = camel(identifier)
        candidate, count = base, 1
        while candidate in self._taken:
            count += 1
            candidate = f"{base}At{index:04X}" if count == 2 else f"{base}At{index:04X}N{count - 1}"
        self._taken.add(candidate)
        return candidate


def unique_fields(identifiers: list[str]) -> list[str]:
    """Field names for a PDO: each identifier once; a repeated one gets `_2`, `_3`, ... (the first free)."""
    natural = set(identifiers)
    seen: set[str] = set()
    names = []
    for identifier in identifiers:
        name, count = identifier, 1
        while name in seen or (count > 1 and name in natural):
            count += 1
            name = f"{lower(identifier)}_{count}"
        seen.add(name)
        names.append(name)
    return names
