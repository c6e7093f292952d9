"""XML the model has no field for, kept as one-line text with its namespaces made explicit.

A kept fragment reads the same wherever it is written back: every element
whose namespace differs from its parent's (and the fragment's root) states it
with `xmlns`, blank-only text between elements is dropped, and no line break
remains, so the fragment also fits an EDS key.
"""

from __future__ import annotations

from .safe import Element
from .xmltext import escape, quoteattr

_TEXT_ESCAPES = {"\n": "&#10;", "\r": "&#13;", "\t": "&#9;"}


def fragment(element: Element, parent_ns: str | None = None) -> str:
    out: list[str] = []
    _write(element, parent_ns, out)
    return "".join(out)


def _write(element: Element, parent_ns: str | None, out: list[str]) -> None:
    attrs = [(k, v) for k, v in element.attrs.items() if k != "xmlns" and not k.startswith("xmlns:")]
    head = element.local
    if element.ns != parent_ns:
        attrs.insert(0, ("xmlns", element.ns))
    text = "".join(f" {k}={quoteattr(v, _TEXT_ESCAPES)}" for k, v in attrs)
    body = element.text if element.text.strip() else ""
    if not element.children and not body:
        out.append(f"<{head}{text} />")
        return
    out.append(f"<{head}{text}>")
    if body and not element.children:
        out.append(escape(body, _TEXT_ESCAPES))
    for child in element.children:
        _write(child, element.ns, out)
    out.append(f"</{head}>")


def one_line(text: str) -> str:
    """Text with its line breaks escaped, so it fits one EDS line; `restore` undoes it."""
    return text.replace("\\", "\\\\").replace("\r", "\\r").replace("\n", "\\n")


def restore(text: str) -> str:
    out: list[str] = []
    chars = iter(text)
    for char in chars:
        if char != "\\":
            out.append(char)
            continue
        following = next(chars, "")
        out.append({"n": "\n", "r": "\r", "\\": "\\"}.get(following, "\\" + following))
    return "".join(out)
