"""Lint configuration: `[tool.cantools-od]` in pyproject.toml and command-line selections.

[tool.cantools-od]
select = ["EDS", "PDO", "cobid"]   # codes, code prefixes or family names; default: every rule
ignore = ["EDS032"]
per-file-ignores = { "vendor/*.eds" = ["EDS003", "COB006"] }
"""

from __future__ import annotations

import fnmatch
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from .codes import matches


@dataclass(frozen=True)
class Selection:
    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    per_file_ignores: dict[str, tuple[str, ...]] = field(default_factory=dict)
    root: Path = Path()

    def enabled(self, code: str, file: str) -> bool:
        if self.select and not any(matches(selector, code) for selector in self.select):
            return False
        if any(matches(selector, code) for selector in self.ignore):
            return False
        return not any(matches(selector, code) for selector in self._file_ignores(file))

    def _file_ignores(self, file: str) -> tuple[str, ...]:
        if not self.per_file_ignores or not file:
            return ()
        path = Path(file).resolve()
        try:
            relative = path.relative_to(self.root.resolve()).as_posix()
        except ValueError:
            relative = path.as_posix()
        codes: list[str] = []
        for pattern, ignored in self.per_file_ignores.items():
            if fnmatch.fnmatch(relative, pattern) or fnmatch.fnmatch(path.name, pattern):
                codes.extend(ignored)
        return tuple(codes)

    def merged(self, select: tuple[str, ...], ignore: tuple[str, ...]) -> Selection:
        """Command-line choices: --select replaces the configured one, --ignore adds to it."""
        return Selection(select or self.select, self.ignore + ignore, self.per_file_ignores, self.root)


def find_pyproject(start: Path) -> Path | None:
    for folder in [start, *start.parents]:
        candidate = folder / "pyproject.toml"
        if candidate.is_file():
            return candidate
    return None


def load_selection(start: Path) -> Selection:
    """The `[tool.cantools-od]` table of the nearest pyproject.toml; raises ValueError when malformed."""
    path = find_pyproject(start.resolve())
    if path is None:
        return Selection()
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise ValueError(f"{path}: {error}") from None
    table = data.get("tool", {}).get("cantools-od", {})
    if not isinstance(table, dict):
        raise ValueError(f"{path}: [tool.cantools-od] must be a table")
    return Selection(
        select=_codes(table, "select", path),
        ignore=_codes(table, "ignore", path),
        per_file_ignores={
            pattern: _codes(table["per-file-ignores"], pattern, path) for pattern in table.get("per-file-ignores", {})
        },
        root=path.parent,
    )


def _codes(table: dict[str, object], key: str, path: Path) -> tuple[str, ...]:
    value = table.get(key, [])
    if not isinstance(value, list) or not all(isinstance(code, str) for code in value):
        raise ValueError(f"{path}: [tool.cantools-od] {key} must be a list of rule codes, prefixes or families")
    return tuple(code.strip().upper() for code in value)
