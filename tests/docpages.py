"""The command pages, docs/commands/<name>.md, as the tests read them: each holds its command's synopsis on a line
of its own (`cantools-od NAME ...` in backticks), then a paragraph saying what the command does, then the rest."""

from __future__ import annotations

import re

from support import ROOT

PAGES = ROOT / "docs" / "commands"
SYNOPSIS = r"`(cantools-od [^`]*)`"


def page_text(name: str) -> str:
    return (PAGES / f"{name}.md").read_text(encoding="utf-8")


def page_synopsis(name: str) -> tuple[str, str, str]:
    """The page's synopsis (without its backticks), the paragraph after it, and the rest of the page."""
    lines = page_text(name).splitlines()
    for number, line in enumerate(lines):
        found = re.fullmatch(SYNOPSIS, line)
        if found is not None and found.group(1).split()[1] == name:
            rest = lines[number + 1 :]
            start = next(index for index, text in enumerate(rest) if text.strip())
            end = next((index for index in range(start, len(rest)) if not rest[index].strip()), len(rest))
            return found.group(1), " ".join(rest[start:end]), "\n".join(rest[end:])
    raise AssertionError(f"docs/commands/{name}.md has no synopsis line `cantools-od {name} ...`")
