"""Where model data came from, and what was found wrong with it."""

from __future__ import annotations

from collections.abc import Iterable, Iterator
from enum import StrEnum
from typing import Protocol, TypeVar

from pydantic import BaseModel, ConfigDict

from .assemble import assemble


class Severity(StrEnum):
    ERROR = "error"
    WARNING = "warning"
    INFO = "info"


class Location(BaseModel):
    """A place in a source file; line and column count from 1 (0 = unknown: shown as `shown` says)."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    file: str = ""
    line: int = 0
    column: int = 0

    @property
    def shown(self) -> tuple[int, int]:
        """(line, column) as every output shows them, from 1: a place known by its line alone is the line's first
        column, and one not known within the file (a model from JSON keeps no positions) is the file's start, 1:1."""
        if self.line < 1:
            return 1, 1
        return self.line, max(self.column, 1)

    def __str__(self) -> str:
        line, column = self.shown
        return f"{self.file or '<input>'}:{line}:{column}"


def location(file: str, line: int, column: int) -> Location:
    """A Location of values known to be of the right types, made without validation: validating would build
    the class's schema on first use (and load pydantic's plugins), a cost at every start of a command."""
    return assemble(Location, {"file": file, "line": line, "column": column}, _LOCATION)


_LOCATION = {"file": "", "line": 0, "column": 0}


class Origin(BaseModel):
    """Where a section came from: its header and each key.

    A key's position is (line, key column, value column). Readers give it in `keys`, or, more
    compactly, in `layout` relative to the header line: sections written alike share one layout.
    Look positions up with `where`, `positions`, `key` and `value` rather than in either mapping.
    """

    model_config = ConfigDict(defer_build=True)

    file: str = ""
    line: int = 0
    column: int = 1
    keys: dict[str, tuple[int, int, int]] = {}
    """Canonical key name → (line, key column, value column)."""
    layout: dict[str, tuple[int, int, int]] = {}
    """Canonical key name → (lines after the header, key column, value column); shared, never edit it."""
    spelled: dict[str, str] = {}
    """Known keys written otherwise than CiA 306 spells them (`NrOfRxPDO`): canonical name → as written;
    under "" the section's own name when written otherwise (`DeviceCommissioning`)."""

    def header(self) -> Location:
        return location(self.file, self.line, self.column)

    def where(self, name: str) -> tuple[int, int, int] | None:
        """The key's (line, key column, value column), None when the section has no such key."""
        where = self.keys.get(name)
        if where is not None:
            return where
        relative = self.layout.get(name)
        if relative is None:
            return None
        return (self.line + relative[0], relative[1], relative[2])

    def positions(self) -> Iterator[tuple[str, tuple[int, int, int]]]:
        """Every key with its (line, key column, value column)."""
        yield from self.keys.items()
        for name, (offset, key_column, value_column) in self.layout.items():
            if name not in self.keys:
                yield name, (self.line + offset, key_column, value_column)

    def key(self, name: str) -> Location:
        """The key's line, or the section header when the key is absent."""
        where = self.where(name)
        if where is None:
            return self.header()
        return location(self.file, where[0], where[1])

    def value(self, name: str) -> Location:
        where = self.where(name)
        if where is None:
            return self.header()
        return location(self.file, where[0], where[2])


class Diagnostic(BaseModel):
    """One finding with a stable rule code."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    code: str
    severity: Severity
    message: str
    # Made without validation: validating would build Location's schema, and load pydantic's plugins, at import.
    location: Location = Location.model_construct()

    def format(self) -> str:
        return f"{self.location}: {self.severity.value}: {self.message} [{self.code}]"


def diagnostic(code: str, severity: Severity, message: str, where: Location) -> Diagnostic:
    """A Diagnostic of values known to be of the right types, made without validation (see `location`)."""
    return assemble(
        Diagnostic, {"code": code, "severity": severity, "message": message, "location": where}, _DIAGNOSTIC
    )


_DIAGNOSTIC = {"code": "", "severity": Severity.ERROR, "message": "", "location": None}


class Reported(Protocol):
    """A diagnostic or a lint finding: what `capped` needs of one."""

    @property
    def code(self) -> str: ...

    @property
    def location(self) -> Location: ...


R = TypeVar("R", bound=Reported)

REPEAT_LIMIT = 10
"""Findings of one code in one file shown before the rest are summed up in one line."""


def capped(items: Iterable[R], limit: int = REPEAT_LIMIT) -> tuple[list[R], list[str]]:
    """The items to show, at most `limit` per code and file, and one line for each group cut short.

    A file of garbage yields thousands of findings of one kind; after the first few, a count says more."""
    groups: dict[tuple[str, str], int] = {}
    shown: list[R] = []
    for item in items:
        key = (item.location.file, item.code)
        groups[key] = groups.get(key, 0) + 1
        if groups[key] <= limit:
            shown.append(item)
    notes = [
        f"{file or '<input>'}: note: {count - limit} more {code} finding{'s' if count - limit != 1 else ''} not shown"
        for (file, code), count in groups.items()
        if count > limit
    ]
    return shown, notes
