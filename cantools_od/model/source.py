"""Where model data came from, and what was found wrong with it."""

from __future__ import annotations

from enum import StrEnum

from pydantic import BaseModel, ConfigDict


class Severity(StrEnum):
    ERROR = "error"
    WARNING = "warning"
    INFO = "info"


class Location(BaseModel):
    """A place in a source file; line and column count from 1 (0 = unknown)."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    file: str = ""
    line: int = 0
    column: int = 0

    def __str__(self) -> str:
        return f"{self.file or '<input>'}:{self.line}:{self.column}"


class Origin(BaseModel):
    """Where a section came from: its header and each key.

    `keys` maps the canonical key name to (line, key column, value column).
    """

    model_config = ConfigDict(defer_build=True)

    file: str = ""
    line: int = 0
    column: int = 1
    keys: dict[str, tuple[int, int, int]] = {}
    spelled: dict[str, str] = {}
    """Known keys written otherwise than CiA 306 spells them (`NrOfRxPDO`): canonical name → as written;
    under "" the section's own name when written otherwise (`DeviceCommissioning`)."""

    def header(self) -> Location:
        return Location(file=self.file, line=self.line, column=self.column)

    def key(self, name: str) -> Location:
        """The key's line, or the section header when the key is absent."""
        where = self.keys.get(name)
        if where is None:
            return self.header()
        return Location(file=self.file, line=where[0], column=where[1])

    def value(self, name: str) -> Location:
        where = self.keys.get(name)
        if where is None:
            return self.header()
        return Location(file=self.file, line=where[0], column=where[2])


class Diagnostic(BaseModel):
    """One finding with a stable rule code."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    code: str
    severity: Severity
    message: str
    location: Location = Location()

    def format(self) -> str:
        return f"{self.location}: {self.severity.value}: {self.message} [{self.code}]"
