"""Keyed sections → model fields, keeping spelling, comments and positions."""

from __future__ import annotations

from functools import lru_cache
from typing import Any, NamedTuple, NoReturn

from ..model import AccessType, ObjectKind, Origin, RawSection
from ..model.assemble import assemble, construct, field_defaults
from .ini import Entry, IniSection
from .keys import KeySpec, Kind, normalize
from .report import Report
from .values import parse_int

_ORIGIN = {**field_defaults(Origin), "keys": {}, "spelled": {}}  # shared empty dicts: never edited in place


class _Empty(dict[str, Any]):
    """The empty `extra` and `comments` that objects and sub-objects without any share: one empty dict
    each would cost a large file about 160 bytes per section. Being shared, it refuses changes in place
    (assign a new dict instead)."""

    def _refuse(self, *args: object, **kwargs: object) -> NoReturn:
        raise TypeError("a shared empty mapping of the model: assign a new dict instead of changing it")

    __setitem__ = __delitem__ = __ior__ = setdefault = update = pop = popitem = clear = _refuse


NONE: dict[str, Any] = _Empty()
_VALUE, _STR = Kind.VALUE, Kind.STR
# Sections with more keys than this are lists (object lists, module lists, names): each is written once, so a
# plan or a shared layout for it would never be used again, yet the reader would hold it, as large as the
# section, until the whole file is read. Objects have about ten keys.
_SHARED_KEYS_MAX = 64


class Collected:
    """The entries of one section, sorted into fields, extra keys and comments."""

    __slots__ = ("comments", "deferred", "extra", "fields", "origin")

    def __init__(self, origin: Origin) -> None:
        self.fields: dict[str, Any] = {}
        self.extra: dict[str, str] = {}
        self.comments: dict[str, list[str]] = {}
        self.origin = origin
        self.deferred: dict[str, Entry] = {}  # typed values, read once the data type is known

    def shared_fields(self) -> dict[str, Any]:
        """`fields` (itself, no copy) with the common ones added, empty ones the shared `NONE`: an object's or
        sub-object's values, made once per section."""
        fields = self.fields
        fields["extra"] = self.extra or NONE
        fields["comments"] = self.comments or NONE
        fields["origin"] = self.origin
        return fields

    def common(self) -> dict[str, Any]:
        """The fields every section has."""
        return {"extra": self.extra, "comments": self.comments, "origin": self.origin}


class _Plan(NamedTuple):
    """How to sort the keys of sections written plainly with the same keys in the same order (see
    `IniSection.plain`): made once per file for each such list of keys, kept by the report."""

    table: dict[str, KeySpec]  # held, so that the id the plan is kept under stays this table's
    steps: tuple[tuple[int, str, str | None, Kind], ...]  # (position, key, field, kind); field None: an extra key
    layout: dict[str, tuple[int, int, int]]
    spelled: dict[str, str]


def _plan(keys: tuple[str, ...], table: dict[str, KeySpec], report: Report) -> _Plan | None:
    """The plan for plain sections of `keys`; None when a key is given twice (the line by line path warns)."""
    steps: list[tuple[int, str, str | None, Kind]] = []
    layout: dict[str, tuple[int, int, int]] = {}
    spelled: dict[str, str] = {}
    for position, key in enumerate(keys):
        spec = table.get(normalize(key))
        name = spec[0] if spec is not None else key
        if name in layout:
            return None
        layout[name] = (position + 1, 1, len(key) + 2)
        if spec is None:
            steps.append((position, key, None, _STR))
            continue
        if key != name:
            spelled[name] = key
        steps.append((position, key, spec[1], spec[2]))
    return _Plan(table, tuple(steps), report.layouts.setdefault(tuple(layout.items()), layout), spelled)


def collect(section: IniSection, table: dict[str, KeySpec], report: Report) -> Collected:
    origin = assemble(Origin, {"file": report.file, "line": section.line, "column": section.column}, _ORIGIN)
    collected = Collected(origin)
    if section.comments:
        collected.comments[""] = section.comments
    if section.plain is not None and len(section.entries) <= _SHARED_KEYS_MAX:
        plan_key = (id(table), section.plain[0])
        plan = report.plans.get(plan_key, False)
        if plan is False:
            plan = report.plans[plan_key] = _plan(section.plain[0], table, report)
        if plan is not None:
            _collect_plain(section, plan, collected, report)
            return collected
    layout: dict[str, tuple[int, int, int]] = {}  # key positions relative to the header line
    spelled: dict[str, str] = {}  # canonical name → the spelling its last entry used, when not canonical
    fields, extra, comments, deferred = collected.fields, collected.extra, collected.comments, collected.deferred
    strings = report.strings
    header = section.line
    # This loop runs once per entry of the file: locals and tuple unpacking rather than attribute look-ups.
    for entry in section.entries:
        key, value, line, key_col, value_col, above, _ = entry
        spec = table.get(normalize(key))
        name = spec[0] if spec is not None else key
        if name in layout:
            _repeated(section, entry, name, spec, collected, report, layout[name][0])
            spelled.pop(name, None)  # spelled again below if this entry is not spelled right either
        layout[name] = (line - header, key_col, value_col)
        if above:
            comments[name] = list(above)
        if spec is None:
            extra[key] = value
            continue
        if key != name:
            spelled[name] = key
        _, field, kind = spec
        if kind is _VALUE:
            deferred[field] = entry
        elif kind is _STR:
            # Names repeat across sections ("Highest sub-index supported"): one string for each.
            fields[field] = strings.setdefault(value, value)
        else:
            _convert_into(collected, field, key, value, kind, report, line, value_col)
    # Sections written by one tool share few layouts: one dict each saves a dict of tuples per section.
    # Set in the reader's own instance directly: pydantic's __setattr__ costs more than the rest of a line.
    shared = len(layout) <= _SHARED_KEYS_MAX
    origin.__dict__["layout"] = report.layouts.setdefault(tuple(layout.items()), layout) if shared else layout
    if spelled:
        origin.__dict__["spelled"] = spelled
    return collected


def _collect_plain(section: IniSection, plan: _Plan, collected: Collected, report: Report) -> None:
    """`collect` of a section written plainly, by its plan: what the loop of `collect` would do, without
    looking each key up again."""
    values = section.plain[1] if section.plain is not None else ()
    fields, extra, deferred, strings = collected.fields, collected.extra, collected.deferred, report.strings
    for position, key, field, kind in plan.steps:
        value = values[position]
        if field is None:
            extra[key] = value
        elif kind is _VALUE:
            deferred[field] = section.entries[position]
        elif kind is _STR:
            fields[field] = strings.setdefault(value, value)
        else:
            _convert_into(collected, field, key, value, kind, report, section.line + position + 1, len(key) + 2)
    origin = collected.origin
    origin.__dict__["layout"] = plan.layout
    if plan.spelled:
        origin.__dict__["spelled"] = dict(plan.spelled)


def _convert_into(
    collected: Collected, field: str, key: str, value: str, kind: Kind, report: Report, line: int, column: int
) -> None:
    """A value of a kind known without the data type into its field; one it is not, kept as text and reported."""
    try:
        collected.fields[field] = convert(value, kind)
    except ValueError as error:
        report.error("EDS030", f"{key}: {error}", line, column)
        collected.extra[key] = value


def _repeated(
    section: IniSection,
    entry: Entry,
    name: str,
    spec: KeySpec | None,
    collected: Collected,
    report: Report,
    offset: int,
) -> None:
    """A key given again: warn, and drop the earlier value, whichever form it took."""
    report.error(
        "EDS002",
        f"[{section.name}] {entry.key} given again (first on line {section.line + offset}); the last one counts",
        entry.line,
        entry.key_col,
    )
    earlier = _last_spelling(section, entry, name, spec)
    collected.extra.pop(earlier, None)
    if spec is not None:
        collected.fields.pop(spec[1], None)
        collected.deferred.pop(spec[1], None)


def _last_spelling(section: IniSection, entry: Entry, name: str, spec: KeySpec | None) -> str:
    """How the last entry before `entry` that gives key `name` spelled it (an unknown key is its own name)."""
    if spec is None:
        return name
    found = name
    wanted = normalize(name)
    for earlier in section.entries:
        if earlier is entry:
            break
        if normalize(earlier.key) == wanted:
            found = earlier.key
    return found


@lru_cache(maxsize=4096)  # files repeat a few texts per key thousands of times; errors are not kept
def convert(text: str, kind: Kind) -> Any:
    """A key's text as its kind; None for an empty value. Raises ValueError."""
    if kind is Kind.STR:
        return text
    if text == "":
        return None
    if kind is Kind.ACCESS:
        try:
            return AccessType(text.lower())
        except ValueError:
            raise ValueError(f"{text!r} is not an access type (ro, wo, rw, rwr, rww, const)") from None
    number, _ = parse_int(text)
    if not isinstance(number, int):
        raise ValueError(f"{text!r}: $NODEID is not allowed here")
    if kind is Kind.BOOL:
        if number not in (0, 1):
            raise ValueError(f"{text!r} is not 0 or 1")
        return bool(number)
    if kind is Kind.OBJECT_TYPE:
        try:
            return ObjectKind(number)
        except ValueError:
            raise ValueError(f"{text!r} is not an object type (0, 2, 5, 6, 7, 8, 9)") from None
    return number


def raw_section(section: IniSection, report: Report) -> RawSection:
    """A section kept as text, keys in file order."""
    collected = collect(section, {}, report)
    fields = {
        "name": section.name,
        "entries": collected.extra,
        "comments": collected.comments,
        "origin": collected.origin,
    }
    return construct(RawSection, fields)
