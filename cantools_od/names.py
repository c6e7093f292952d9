"""Names a user types (rule codes, file extensions, configuration keys): an unknown one is an
error that names the closest valid ones, never silently ignored."""

from __future__ import annotations

from collections.abc import Callable, Collection, Iterable


class UnknownName(ValueError):
    """`name` is none of the valid names of its kind; the message suggests the closest."""

    def __init__(self, what: str, name: str, valid: Collection[str], hint: str = "", cutoff: float = 0.5) -> None:
        super().__init__(f"unknown {what} {name!r}; {suggest(name, valid, hint, cutoff)}")
        self.name = name


def suggest(name: str, valid: Collection[str], hint: str = "", cutoff: float = 0.5) -> str:
    """`did you mean A, B?` with the valid names closest to `name` (difflib's ratio at least `cutoff`), else
    `hint` or a few valid names."""
    import difflib  # only for a mistake: start-up counts

    by_folded = {v.casefold(): v for v in valid}
    close = difflib.get_close_matches(name.casefold(), list(by_folded), n=3, cutoff=cutoff)
    if close:
        return "did you mean " + ", ".join(by_folded[c] for c in close) + "?"
    if hint:
        return hint
    ordered = sorted(valid)
    return "valid: " + ", ".join(ordered[:8]) + (", ..." if len(ordered) > 8 else "")


def check_names(
    what: str,
    given: Iterable[str],
    valid: Collection[str],
    accepts: Callable[[str], bool] | None = None,
    hint: str = "",
    cutoff: float = 0.5,
) -> None:
    """Raise UnknownName for the first of `given` that is not in `valid` (nor taken by `accepts`);
    `hint` stands in for suggestions when no valid name is close (by `cutoff`, see `suggest`)."""
    for name in given:
        if name not in valid and not (accepts is not None and accepts(name)):
            raise UnknownName(what, name, valid, hint, cutoff)
