"""What the readers produce: raw entries with a location per field, before normalisation."""

from __future__ import annotations

from dataclasses import dataclass, field
from enum import IntEnum

from ..model import Diagnostic, Location, Severity

# Canonical field names. Object-level: name, object_code, data_type, category, sub_number.
# Entry-level: name, data_type, access, pdo_mapping, default, range, low, high, unit, note.
FIELDS = (
    "name",
    "object_code",
    "data_type",
    "access",
    "pdo_mapping",
    "default",
    "range",
    "low",
    "high",
    "unit",
    "category",
    "sub_number",
    "description",
    "note",
)


class Kind(IntEnum):
    """What kind of description a value comes from; the number is its weight under the
    default policy (a per-object detail block outweighs a summary table)."""

    INFERRED = 1  # filled in from CiA 301, not from the manual
    DERIVED = 5  # read from another field (a type name written as the value range)
    SUMMARY = 10  # an overview table listing many objects
    HEADING = 12  # the title above a block
    RECORD_DEF = 18  # a data-type record definition (0020h, 0021h ...) applied to its users
    TABLE = 20  # a per-object or per-group table (default values, stored objects, sub-tables)
    DETAIL = 30  # a per-object description block
    OVERRIDE = 100


@dataclass(frozen=True)
class Cell:
    """One raw cell and the line it sits on (1-based)."""

    text: str
    line: int


@dataclass
class RawEntry:
    """One row or block of a source: an index (or range), maybe a sub-index (or range), and fields.

    `object_level` entries describe the object itself (name, object code, element type);
    the others describe one entry (a VAR, or a sub-object)."""

    file: str
    layout: str
    kind: Kind
    index: Cell
    sub: Cell | None = None
    fields: dict[str, list[Cell]] = field(default_factory=dict)
    object_level: bool = False
    hex_singles: bool = False
    bare_index: bool = False
    indices: tuple[int, ...] | None = None  # resolved by the reader (letter tables, lists)
    expanded_from: int = 0  # the elision row this entry was made from

    def add(self, name: str, text: str, line: int) -> None:
        self.fields.setdefault(name, []).append(Cell(text, line))

    @property
    def line(self) -> int:
        return self.index.line


@dataclass
class ReadResult:
    """Everything read from one source file."""

    file: str
    layout: str
    entries: list[RawEntry] = field(default_factory=list)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    vendor_name: str | None = None
    product_name: str | None = None
    excluded: dict[int, Cell] = field(default_factory=dict)  # objects the manual says to leave out of an EDS
    _said: set[tuple[str, str, int]] = field(default_factory=set, init=False, repr=False, compare=False)

    def warn(self, code: str, message: str, line: int, severity: Severity = Severity.WARNING) -> None:
        # A manual's block becomes several entries (the object's fields, the sub-object's): what one of
        # its cells gets wrong is said once.
        if (code, message, line) in self._said:
            return
        self._said.add((code, message, line))
        self.diagnostics.append(
            Diagnostic(code=code, severity=severity, message=message, location=loc(self.file, line))
        )


def loc(file: str, line: int) -> Location:
    return Location(file=file, line=line, column=1 if line else 0)
