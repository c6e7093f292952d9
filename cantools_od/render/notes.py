"""A note at the top of every generated file listing what `gen --keep-going` left out.

It goes by the file's extension, so that every target, present and future, carries it."""

from __future__ import annotations

from pathlib import PurePath

from .escape import c_comment, line_comment, markdown_text, xml_comment

HEADLINE = "cantools-od gen --keep-going left out what errors in the input touch:"
XML_HEADLINE = "cantools-od gen (keep going) left out what errors in the input touch:"
"""An XML comment (SVG, HTML) may not hold `--`."""


def left_out_note(filename: str, left_out: list[str]) -> str:
    """The comment naming each item of `left_out` that goes before a file's text; "" when nothing was."""
    if not left_out:
        return ""
    suffix = PurePath(filename).suffix.lower()
    if suffix in (".c", ".h", ".cpp", ".hpp", ".cc"):
        lines = [f"/* {c_comment(line)} */" for line in [HEADLINE, *(f"- {item}" for item in left_out)]]
    elif suffix in (".svg", ".html"):
        lines = [f"<!-- {xml_comment(line)} -->" for line in [XML_HEADLINE, *(f"- {item}" for item in left_out)]]
    elif suffix == ".md":
        lines = [f"> {HEADLINE}", ">", *(f"> - {markdown_text(item)}" for item in left_out), ""]
    else:  # Rust, Python, TOML and other languages with line comments
        mark = "//" if suffix == ".rs" else "#"
        lines = [f"{mark} {line_comment(line)}" for line in [HEADLINE, *(f"- {item}" for item in left_out)]]
    return "\n".join(lines) + "\n"
