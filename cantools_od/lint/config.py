"""Lint configuration: `[tool.cantools-od]` in pyproject.toml (or a cantools-od.toml), found per file, and
command-line selections.

[tool.cantools-od]
select = ["EDS", "PDO", "cobid"]   # codes, code prefixes or family names; default: every rule
ignore = ["EDS032"]
per-file-ignores = { "vendor/*.eds" = ["EDS003", "COB006"] }
integer-radix = "as-written"       # how `fmt` spells integers; or a table by key (docs/commands/fmt.md)
"""

from __future__ import annotations

import fnmatch
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..eds.format import IntStyle, Radix
from ..eds.keys import COMMISSIONING_KEYS, DEVICE_INFO_KEYS, FILE_INFO_KEYS, OBJECT_KEYS, Kind
from ..names import UnknownName, check_names
from .codes import matches

KEYS = ("select", "ignore", "per-file-ignores", "integer-radix")
"""Every key `[tool.cantools-od]` may hold; any other is an error, so that a misspelt one is not ignored."""

# Keys whose value is an integer `fmt` spells: the typed values and the integer keys of the CiA 306 tables.
INTEGER_KEYS = tuple(
    spelling
    for table in (OBJECT_KEYS, FILE_INFO_KEYS, DEVICE_INFO_KEYS, COMMISSIONING_KEYS)
    for spelling, _, kind in table.values()
    if kind in (Kind.VALUE, Kind.INT, Kind.OBJECT_TYPE)
)


@dataclass(frozen=True)
class Selection:
    select: tuple[str, ...] = ()
    ignore: tuple[str, ...] = ()
    per_file_ignores: dict[str, tuple[str, ...]] = field(default_factory=dict)
    root: Path = Path()
    # The per-file ignores found for each file name: every rule and finding asks, and resolving paths is slow.
    _ignores: dict[str, tuple[str, ...]] = field(default_factory=dict, compare=False, repr=False)

    def enabled(self, code: str, file: str) -> bool:
        if self.select and not any(matches(selector, code) for selector in self.select):
            return False
        if any(matches(selector, code) for selector in self.ignore):
            return False
        return not any(matches(selector, code) for selector in self._file_ignores(file))

    def _file_ignores(self, file: str) -> tuple[str, ...]:
        if not self.per_file_ignores or not file:
            return ()
        found = self._ignores.get(file)
        if found is None:
            found = self._ignores[file] = self._find_ignores(file)
        return found

    def _find_ignores(self, file: str) -> tuple[str, ...]:
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


CONFIG_NAME = "cantools-od.toml"
"""A configuration file of its own: the keys of `[tool.cantools-od]` at its top level."""


def find_config(start: Path) -> Path | None:
    """The configuration that holds for files in folder `start`, found as ruff finds its own: from `start` upwards,
    the first folder with a pyproject.toml that has a `[tool.cantools-od]` table, or else a cantools-od.toml."""
    for folder in [start, *start.parents]:
        pyproject = folder / "pyproject.toml"
        if pyproject.is_file() and _has_table(pyproject):
            return pyproject
        own = folder / CONFIG_NAME
        if own.is_file():
            return own
    return None


def _has_table(pyproject: Path) -> bool:
    """Whether a pyproject.toml has a `[tool.cantools-od]` table; a malformed one that names it is taken, so that
    reading it reports the error."""
    import tomllib  # here: most lint runs find no configuration, and start-up counts

    try:
        text = pyproject.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return False
    try:
        tool = tomllib.loads(text).get("tool")
    except tomllib.TOMLDecodeError:
        return "cantools-od" in text
    return isinstance(tool, dict) and "cantools-od" in tool


def _table(path: Path | None) -> tuple[Path | None, dict[str, Any]]:
    """The configuration file's table (`[tool.cantools-od]` of a pyproject.toml, the whole of a cantools-od.toml);
    raises ValueError when it is malformed or cannot be read. A folder stands for the configuration found from it
    upwards."""
    if path is not None and path.is_dir():
        path = find_config(path.resolve())
    if path is None:
        return None, {}
    import tomllib

    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as error:
        raise ValueError(f"{path}: cannot read: {error.strerror or error}") from None
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        raise ValueError(f"{path}: {error}") from None
    where = "[tool.cantools-od]" if path.name == "pyproject.toml" else "the file"
    table = data.get("tool", {}).get("cantools-od", {}) if path.name == "pyproject.toml" else data
    if not isinstance(table, dict):
        raise ValueError(f"{path}: [tool.cantools-od] must be a table")
    try:
        check_names(f"key in {where}", table, KEYS)
    except UnknownName as error:
        raise ValueError(f"{path}: {error}") from None
    return path, table


def load_int_style(config: Path | None, override: str | None = None) -> IntStyle:
    """How `fmt` spells integers: `integer-radix` of the configuration file (or folder) `config`, one radix
    or a table by key (`"*"` for the keys not named); `override` (the command line's) replaces it. Raises
    ValueError."""
    if override is not None:
        return IntStyle(_radix(override, "--radix"))
    path, table = _table(config)
    value = table.get("integer-radix")
    if value is None:
        return IntStyle()
    where = f"{path}: [tool.cantools-od] integer-radix"
    if isinstance(value, str):
        return IntStyle(_radix(value, where))
    if not isinstance(value, dict):
        raise ValueError(f"{where} must be a radix or a table of key = radix")
    by_key: dict[str, Radix] = {}
    for key, radix in value.items():
        if key != "*" and key not in INTEGER_KEYS:
            raise ValueError(f"{where}: {key!r} is not an integer key{_closest(key, INTEGER_KEYS)}")
        by_key[key] = _radix(radix, f"{where}.{key}")
    return IntStyle(by_key.pop("*", Radix.CANONICAL), by_key)


def _radix(value: object, where: str) -> Radix:
    names = tuple(r.value for r in Radix)
    if not isinstance(value, str) or value not in names:
        raise ValueError(f"{where}: {value!r} is not one of {', '.join(names)}{_closest(str(value), names)}")
    return Radix(value)


def _closest(name: str, names: tuple[str, ...]) -> str:
    import difflib  # only for a mistake

    found = difflib.get_close_matches(name, names, n=1)
    return f" (did you mean {found[0]!r}?)" if found else ""


def load_selection(config: Path | None) -> Selection:
    """The selection the configuration file `config` makes (a folder: the one found from it upwards, see
    `find_config`); raises ValueError when malformed."""
    path, table = _table(config)
    if path is None:
        return Selection()
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
    try:
        check_selectors(tuple(code.strip() for code in value))
    except UnknownName as error:
        raise ValueError(f"{path}: [tool.cantools-od] {key}: {error}") from None
    return tuple(code.strip().upper() for code in value)


RULE_CUTOFF = 0.6
"""How close a misspelt rule code, name or family must be to be suggested: codes, names and families together
are many, and at difflib's usual 0.6 a stray word (`NOPE`) is not offered `canopennode`."""


def check_selectors(selectors: tuple[str, ...]) -> None:
    """Raise UnknownName for a selector (as typed, any case) that is no rule code, rule name, code prefix (`EDS`,
    `PDO0`) or family name; it names the closest of all of them (`line-to-long`: did you mean line-too-long?)."""
    from .codes import FAMILIES, load
    from .codes import codes as all_codes
    from .rules import RULES

    load()
    codes = set(RULES)
    prefixes = {code[:length] for code in codes for length in range(1, len(code))}
    families = set(FAMILIES)
    hint = "a rule code or name (`cantools-od rules` lists them), a prefix such as EDS or PDO0, or a family "
    hint += f"({', '.join(sorted(families))})"

    names = {code.name for code in all_codes().values()}  # kebab-case, as `rules` prints them

    def accepted(name: str) -> bool:
        return name.upper() in codes | prefixes or name.lower() in families | names

    check_names("rule code", selectors, codes | names | families, accepted, hint, RULE_CUTOFF)
