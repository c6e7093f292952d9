"""Collects the reader's diagnostics for one file."""

from __future__ import annotations

from typing import Any

from ..model import Diagnostic, Severity
from ..model.source import diagnostic, location


class Report:
    def __init__(self, file: str) -> None:
        self.file = file
        self.diagnostics: list[Diagnostic] = []
        self.layouts: dict[tuple[tuple[str, tuple[int, int, int]], ...], dict[str, tuple[int, int, int]]] = {}
        """Key layouts of sections read so far, so that sections written alike share one."""
        self.plans: dict[tuple[int, tuple[str, ...]], Any] = {}
        """How to sort the keys of plainly written sections, per key table and list of keys (sections.py)."""
        self.strings: dict[str, str] = {}
        """Texts read so far, so that a text written many times is held once."""

    def add(self, code: str, severity: Severity, message: str, line: int = 0, column: int = 0) -> None:
        self.diagnostics.append(diagnostic(code, severity, message, location(self.file, line, column)))

    def error(self, code: str, message: str, line: int = 0, column: int = 0) -> None:
        self.add(code, Severity.ERROR, message, line, column)

    def warning(self, code: str, message: str, line: int = 0, column: int = 0) -> None:
        self.add(code, Severity.WARNING, message, line, column)

    def info(self, code: str, message: str, line: int = 0, column: int = 0) -> None:
        self.add(code, Severity.INFO, message, line, column)
