"""Every relative link of the README and of docs/ leads somewhere: the file it names exists, and the anchor it names
is a heading of that file, spelled as GitHub makes anchors of headings. A page moved or a heading renamed fails here
with the link that broke."""

from __future__ import annotations

import re
from pathlib import Path
from urllib.parse import unquote

import pytest

from support import ROOT

PAGES = [ROOT / "README.md", *sorted((ROOT / "docs").rglob("*.md"))]
FENCE = re.compile(r"^(```|~~~).*?^\1", re.DOTALL | re.MULTILINE)
CODE = re.compile(r"(`+)(?!`).*?(?<!`)\1", re.DOTALL)
LINK = re.compile(r"\]\(\s*<?([^)\s>]+)>?(?:\s+\"[^\"]*\")?\s*\)")
HEADING = re.compile(r"^#{1,6}\s+(.*?)\s*#*\s*$", re.MULTILINE)


def prose(text: str) -> str:
    """The text with its code blocks and code spans left out, where a `[x](y)` is no link."""
    return CODE.sub("", FENCE.sub("", text))


def slug(heading: str) -> str:
    """GitHub's anchor of a heading: its text (links by their words, code by its letters) in lower case, every
    character but letters, digits, `-`, `_` and blanks dropped, blanks made `-`."""
    text = re.sub(r"!?\[([^]]*)\]\([^)]*\)", r"\1", heading).replace("`", "")
    return re.sub(r"[^\w\- ]", "", text.lower()).replace(" ", "-")


def anchors(page: Path) -> set[str]:
    """Every anchor of a page's headings; a repeated heading's anchor gets `-1`, `-2`, ... as GitHub numbers them."""
    found: set[str] = set()
    seen: dict[str, int] = {}
    for heading in HEADING.findall(FENCE.sub("", page.read_text(encoding="utf-8"))):
        base = slug(heading)
        count = seen.get(base, 0)
        seen[base] = count + 1
        found.add(base if count == 0 else f"{base}-{count}")
    found |= set(re.findall(r"<a (?:name|id)=\"([^\"]+)\"", page.read_text(encoding="utf-8")))
    return found


def links(page: Path) -> list[str]:
    return [link for link in LINK.findall(prose(page.read_text(encoding="utf-8"))) if not re.match(r"[a-z]+:", link)]


def broken(page: Path) -> list[str]:
    wrong = []
    for link in links(page):
        path, _, anchor = link.partition("#")
        target = (page.parent / unquote(path)).resolve() if path else page
        if not target.exists():
            wrong.append(f"{link}: no such file")
        elif anchor and target.suffix == ".md" and anchor not in anchors(target):
            wrong.append(f"{link}: no heading #{anchor} in {target.name}")
    return wrong


@pytest.mark.parametrize("page", PAGES, ids=lambda page: str(page.relative_to(ROOT)))
def test_every_relative_link_leads_somewhere(page: Path) -> None:
    assert broken(page) == []


def test_the_code_points_at_pages_that_exist() -> None:
    """Help texts and comments send the reader to docs/ pages (`see docs/editors.md`), not to README sections."""
    sources = [*sorted((ROOT / "cantools_od").rglob("*.py")), ROOT / ".ci" / "run", ROOT / "Makefile"]
    text = {str(source.relative_to(ROOT)): source.read_text("utf-8") for source in sources}
    named = {(source, name) for source, said in text.items() for name in re.findall(r"\bdocs/[\w/.-]*\w\.md", said)}
    assert named, "no source names a docs/ page"
    assert sorted((source, name) for source, name in named if not (ROOT / name).is_file()) == []
    sections = [(source, line) for source, said in text.items() for line in said.splitlines() if "README," in line]
    assert sections == [], "README sections named in the code (its detail lives in docs/ now)"


def test_the_checker_sees_a_broken_file_and_a_broken_anchor(tmp_path: Path) -> None:
    (tmp_path / "b.md").write_text("# A heading, with `code`\n\n## Twice\n\n## Twice\n", encoding="utf-8")
    page = tmp_path / "a.md"
    good = "[1](b.md) [2](b.md#a-heading-with-code) [3](b.md#twice-1) [4](#own) `[5](no.md)`\n\n## Own\n"
    page.write_text(good, encoding="utf-8")
    assert broken(page) == []
    page.write_text(good + "[6](c.md) [7](b.md#twice-2) [8](https://example.invalid/x.md)\n", encoding="utf-8")
    assert broken(page) == ["c.md: no such file", "b.md#twice-2: no heading #twice-2 in b.md"]
