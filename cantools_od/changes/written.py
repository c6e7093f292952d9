"""Keys no reader takes as written, compared as written: `DataType=0x0007 # UNSIGNED32` is no number to the
reader (nor to python-canopen or lely), so the model keeps the text in `extra` and the field stays unset.

A change of such a key is told as a change of its field (data type, access, PDO mapping, object type), its
impact judged on what the text means when read without the words after the value, and on whether the entry
became readable or unreadable: a peer that read it before and refuses it now has lost it.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass

from ..eds.values import parse_int
from ..model import AccessType, NodeIdExpr, ObjectKind, RawValue, Value, Variable, standard_type
from .impact import access_impact, data_type_impact, flag_impact
from .records import Change, Impact, Kind, new_change

Meaning = int | AccessType | bool | None


@dataclass(frozen=True)
class Key:
    """A key of an entry section kept as written when it cannot be read, and the field it feeds."""

    field: str
    kind: Kind
    meaning: Callable[[str], Meaning]
    """What the written text means without what follows the value (None: nothing)."""
    shown: Callable[[Meaning], str]


def _value_part(text: str) -> str:
    """The text before a trailing comment (`0x0007 # UNSIGNED32` → `0x0007`)."""
    for mark in ("#", ";"):
        text = text.partition(mark)[0]
    return text.strip()


def _number(text: str) -> int | None:
    try:
        value = parse_int(_value_part(text))[0]
    except ValueError:
        return None
    return None if isinstance(value, NodeIdExpr) else value


def _access(text: str) -> AccessType | None:
    word = _value_part(text).lower()
    return AccessType(word) if word in set(AccessType) else None


def _flag(text: str) -> bool | None:
    number = _number(text)
    return None if number is None else bool(number)


def _type_shown(meaning: Meaning) -> str:
    if not isinstance(meaning, int) or isinstance(meaning, bool):
        return "-"
    dtype = standard_type(meaning)
    return f"0x{meaning:04X}" + (f" ({dtype.name})" if dtype is not None else "")


def _kind_shown(meaning: Meaning) -> str:
    if not isinstance(meaning, int) or isinstance(meaning, bool):
        return "-"
    try:
        return f"{ObjectKind(meaning).name} (0x{meaning:X})"
    except ValueError:
        return f"0x{meaning:X}"


def _access_shown(meaning: Meaning) -> str:
    return meaning.value if isinstance(meaning, AccessType) else "-"


def _flag_shown(meaning: Meaning) -> str:
    return "-" if meaning is None else "yes" if meaning else "no"


KEYS = {
    "datatype": Key("data_type", Kind.DATA_TYPE, _number, _type_shown),
    "accesstype": Key("access", Kind.ACCESS, _access, _access_shown),
    "pdomapping": Key("pdo_mapping", Kind.PDO_MAPPING, _flag, _flag_shown),
    "objecttype": Key("object_type", Kind.OBJECT_TYPE, _number, _kind_shown),
}


def _written(var: Variable) -> dict[str, str]:
    """The keys of KEYS this entry wrote so that no reader takes them: lower-case key → text."""
    return {key.lower(): text for key, text in var.extra.items() if key.lower() in KEYS}


def unread(old: Variable, new: Variable) -> frozenset[str]:
    """The keys of KEYS that one side or both wrote unreadably (lower case)."""
    if not (old.extra or new.extra):
        return frozenset()
    return frozenset(_written(old)) | frozenset(_written(new))


def fields(keys: frozenset[str]) -> frozenset[str]:
    """The change fields `changes` tells for these keys: the field and the raw key alike."""
    return frozenset(KEYS[key].field for key in keys)


def _read(var: Variable, key: str) -> Meaning:
    """What the reader made of a readable key."""
    if key == "objecttype":
        return int(getattr(var, "object_type", None) or ObjectKind.VAR)
    if key == "pdomapping":
        return bool(var.pdo_mapping)
    value = getattr(var, KEYS[key].field)
    return value if isinstance(value, (int, AccessType)) else None


def _impact(key: str, before: Meaning, after: Meaning) -> tuple[Impact, str]:
    if key == "datatype":
        types = [standard_type(m) if isinstance(m, int) and not isinstance(m, bool) else None for m in (before, after)]
        return data_type_impact(types[0], types[1])
    if key == "accesstype":
        return access_impact(
            before if isinstance(before, AccessType) else None, after if isinstance(after, AccessType) else None
        )
    if key == "pdomapping":
        return flag_impact(bool(before), bool(after), "PDO-mappable")
    return Impact.BREAKING, "the generated structure changes"


def changes(old: Variable, new: Variable, keys: frozenset[str], index: int, subindex: int | None) -> Iterator[Change]:
    """One change per key of `keys` whose text differs: as written on an unreadable side, as read on the other."""
    old_written, new_written = _written(old), _written(new)
    for key in sorted(keys):
        spec = KEYS[key]
        sides = []
        for var, written in ((old, old_written), (new, new_written)):
            if key in written:
                meaning = spec.meaning(written[key])
                sides.append((meaning, f"{written[key]!r} (unreadable)", False))
            else:
                meaning = _read(var, key)
                sides.append((meaning, spec.shown(meaning), True))
        (before, old_text, old_readable), (after, new_text, new_readable) = sides
        if old_text == new_text:
            continue
        impact, note = _judged(key, before, after, old_readable, new_readable)
        yield new_change(
            kind=spec.kind,
            impact=impact,
            index=index,
            subindex=subindex,
            field=spec.field,
            old=old_text,
            new=new_text,
            old_text=old_text,
            new_text=new_text,
            note=note,
        )


def _judged(key: str, before: Meaning, after: Meaning, old_readable: bool, new_readable: bool) -> tuple[Impact, str]:
    """The field's own impact when the meaning changed; else what the change of readability does to a peer."""
    spec = KEYS[key]
    if before is None and after is None:
        severe = key in ("datatype", "objecttype")  # the generated type and what a master transfers
        return (Impact.BREAKING if severe else Impact.VALUE), "readable on neither side: compared as written"
    meant = f"read without the words after the value: {spec.shown(before)} → {spec.shown(after)}"
    if before != after:
        impact, why = _impact(key, before, after)
        return impact, f"{why}; {meant}" if why else meant
    if old_readable and not new_readable:
        return Impact.BREAKING, f"no longer readable as written (python-canopen refuses it); meant {spec.shown(after)}"
    if new_readable and not old_readable:
        return Impact.COMPATIBLE, f"now readable as written; meant {spec.shown(after)} before too"
    return Impact.COSMETIC, f"unreadable as written on both sides; both mean {spec.shown(after)}"


def same_as_written(old: Value | None, new: Value | None) -> bool:
    """A value kept as written on one side (its type could not be read) that states the number the other side
    read: the line did not change, the reading of its type did (told as that type's change)."""
    raw, typed = (old, new) if isinstance(old, RawValue) else (new, old)
    if not isinstance(raw, RawValue) or isinstance(typed, (RawValue, bool)) or not isinstance(typed, (int, float)):
        return False
    number: float | None = _number(raw.text)
    if number is None:
        try:
            number = float(_value_part(raw.text))
        except ValueError:
            return False
    return number == typed
