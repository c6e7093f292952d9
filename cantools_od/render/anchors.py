"""Anchors of an object and a sub-object in a device's reference documents: by index only, never by name, so
that a link into the reference survives a rename. `1400` is object 1400h, `1400-1` its sub-index 1 (hex, upper
case, as the documents write indices). One scheme for every document that has such anchors."""

from __future__ import annotations


def object_anchor(index: int, subindex: int | None = None) -> str:
    """The anchor of object `index`, or of its sub-object `subindex`."""
    return f"{index:04X}" if subindex is None else f"{index:04X}-{subindex:X}"


def anchor_tag(anchor: str) -> str:
    """An empty HTML element that carries the anchor: GFM gives a heading an anchor made from its text, which
    holds the name, so the anchor by index is given explicitly (GitHub keeps `id` on `<a>`)."""
    return f'<a id="{anchor}"></a>'
