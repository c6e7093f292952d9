"""docs/diff.md says what diff does: each impact rule's example gives the documented tag, and the examples of
real pairs are what the tool prints today."""

from __future__ import annotations

import re

import pytest
from diffkit import BASE, diff_of, drop_section, set_key

from cantools_od.changes import text

from support import ROOT

DOC = (ROOT / "docs" / "diff.md").read_text(encoding="utf-8")
RULE = re.compile(r"^\| ([^|]+?) \| `\[(\w+)\] (.+?)` \| (\S+) \|$", re.MULTILINE)


def rules() -> list[object]:
    found = [pytest.param(*match.groups()[1:], id=match.group(1)) for match in RULE.finditer(DOC)]
    assert len(found) >= 20, "the rules table of docs/diff.md is gone"
    return found


def _apply(source: str, section: str, edits: str) -> str:
    for edit in edits.split(", "):
        key, _, value = edit.partition("=")
        source = set_key(source, section, key, value)
    return source


def _swap_sections(source: str, first: str, second: str) -> str:
    """The two sections under each other's name: the entries trade places."""
    marker = "\0"
    source = source.replace(f"[{first}]\n", f"[{marker}]\n").replace(f"[{second}]\n", f"[{first}]\n")
    return source.replace(f"[{marker}]\n", f"[{second}]\n")


@pytest.mark.parametrize(("section", "example", "tag"), rules())
def test_each_rule_of_the_docs(section: str, example: str, tag: str) -> None:
    old = BASE
    swapped = re.fullmatch(r"swapped with \[(\w+)\]", example)
    if example == "removed":
        new = drop_section(BASE, section)
    elif swapped:
        new = _swap_sections(BASE, section, swapped[1])
    else:
        given, _, edits = (
            example.removeprefix("with ").rpartition(": ") if example.startswith("with ") else ("", "", example)
        )
        old = _apply(BASE, section, given) if given else BASE
        new = _apply(old, section, edits)
    result = diff_of(new, old)
    tags = {text.tag(change) for change in result.changes()}
    assert tags == {tag}, [(c.kind.value, c.index, c.subindex, text.tag(c), c.note) for c in result.changes()]


HISTORY = ROOT.parent / "shared" / "eds-history"
EXAMPLE = re.compile(
    r"^#### [^\n]*\(`(?P<pair>[\w.-]+)`\)\n.*?```text\n(?P<text>.*?)\n```\n.*?````markdown\n(?P<markdown>.*?)\n````",
    re.MULTILINE | re.DOTALL,
)


def examples() -> list[object]:
    found = [pytest.param(m["pair"], m["text"], m["markdown"], id=m["pair"]) for m in EXAMPLE.finditer(DOC)]
    assert len(found) == 5, "docs/diff.md shows five real pairs"
    return found


@pytest.mark.parametrize(("pair", "shown_text", "shown_markdown"), examples())
def test_examples_of_real_pairs_are_what_diff_prints(pair: str, shown_text: str, shown_markdown: str) -> None:
    import click

    from cantools_od import loads
    from cantools_od.changes import compare, markdown

    folder = HISTORY / pair
    if not folder.is_dir():
        pytest.skip(f"{pair} is not in ../shared/eds-history")
    old, new = (next(f for f in folder.iterdir() if f.stem == stem) for stem in ("old", "new"))
    result = compare(loads(old.read_bytes(), source=old.name), loads(new.read_bytes(), source=new.name))
    assert click.unstyle(text.render(result)) == shown_text
    assert markdown.render(result).rstrip("\n") == shown_markdown
    assert max(len(line) for line in shown_text.splitlines()) <= text.WIDTH
