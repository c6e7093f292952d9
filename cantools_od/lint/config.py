"""Lint configuration: `[tool.cantools-od]` in pyproject.toml and command-line selections.

[tool.cantools-od]
select = ["EDS", "PDO"]            # codes or code prefixes; default: every rule
ignore = ["EDS032"]
per-file-ignores = { "vendor/*.eds" = ["EDS003", "COB006"] }
"""

from __future__ import annotations

import fnmatch
import tomllib
from dataclasses import dataclass, field
from pathlib import Path

from ..names import UnknownName, check_names

CONFIG_KEYS = ("select", "ignore", "per-file-ignores")
"""The keys of `[tool.cantools-od]`; any other is an error, so that a misspelt one is not ignored."""


@dataclass(frozen=True)
class Selection:
    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    per_file_ignores: dict[str, tuple[str, ...]] = field(default_factory=dict)
    root: Path = Path()

    def enabled(self, code: str, file: str) -> bool:
        if self.select and not any(code.startswith(prefix) for prefix in self.select):
            return False
        if any(code.startswith(prefix) for prefix in self.ignore):
            return False
        return not any(code.startswith(prefix) for prefix in self._file_ignores(file))

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
    try:
        check_names("key in [tool.cantools-od]", table, CONFIG_KEYS)
    except UnknownName as error:
        raise ValueError(f"{path}: {error}") from None
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
        raise ValueError(f"{path}: [tool.cantools-od] {key} must be a list of rule codes")
    codes = tuple(code.strip().upper() for code in value)
    try:
        check_selectors(codes)
    except UnknownName as error:
        raise ValueError(f"{path}: [tool.cantools-od] {key}: {error}") from None
    return codes


def check_selectors(selectors: tuple[str, ...]) -> None:
    """Raise UnknownName for a selector that is no rule code nor the start of one (`EDS`, `PDO0`)."""
    from . import catalog
    from .rules import RULES

    catalog.load()
    codes = set(RULES)
    prefixes = {code[:length] for code in codes for length in range(1, len(code))}
    families = sorted({code[:3] for code in codes})
    hint = f"a rule code (`cantools-od rules` lists them) or a prefix such as {', '.join(families)}"
    check_names("rule code", selectors, codes, accepts=prefixes.__contains__, hint=hint)
