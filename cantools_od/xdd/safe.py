"""Parses XML without trusting it: a small element tree that remembers where each element is.

The standard library's expat parses; entity declarations (billion laughs) and external references (XXE) are
refused from expat's own handlers for them, so nothing is ever expanded or fetched (the defences of defusedxml,
set on expat directly: its SAX driver imports urllib, http and email, a fifth of reading a large XDD, and adds a
Python call per element). Size, element count and depth are bounded before and while parsing, so a hostile file
costs bounded time and memory. Each element keeps its byte span in the input, which the locations and the
preserving writer build on.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from dataclasses import dataclass, field
from xml.parsers import expat

MAX_BYTES = 32 * 1024 * 1024
"""Far above any real device description (the largest known are a few hundred kB)."""
MAX_ELEMENTS = 500_000
MAX_DEPTH = 64


class XmlRefused(Exception):
    """The input is not well-formed XML, or is refused as hostile or too large."""

    def __init__(self, code: str, message: str, offset: int = 0) -> None:
        super().__init__(message)
        self.code = code
        self.offset = offset


@dataclass(slots=True, eq=False)
class Element:
    name: str
    """The name as written, with its prefix (`q1:parameter`)."""
    local: str
    ns: str
    attrs: dict[str, str]
    start: int
    """Byte offset of `<`."""
    content_start: int = 0
    """Byte offset just after the start tag's `>` (the end, for an empty-element tag)."""
    content_end: int = 0
    """Byte offset of the end tag's `<` (equal to `end` for an empty-element tag)."""
    end: int = 0
    """Byte offset just after the element."""
    children: list[Element] = field(default_factory=list)
    text: str = ""
    parent: Element | None = None
    prologue: tuple[tuple[int, str], ...] = ()
    """Of the root only: the comments before it, as (byte offset of `<!--`, text between the delimiters)."""

    def child(self, local: str) -> Element | None:
        return next((c for c in self.children if c.local == local), None)

    def all(self, local: str) -> list[Element]:
        return [c for c in self.children if c.local == local]

    def walk(self) -> list[Element]:
        """This element and every descendant, in document order (no recursion: depth is bounded anyway)."""
        out: list[Element] = []
        stack = [self]
        while stack:
            node = stack.pop()
            out.append(node)
            stack.extend(reversed(node.children))
        return out


class _Builder:
    """expat's callbacks: the element tree, each element with its byte span."""

    def __init__(self, data: bytes, parser: expat.XMLParserType) -> None:
        self.data = data
        self.parser = parser
        self.stack: list[Element] = []
        self.scopes: list[dict[str, str]] = [{"xml": "http://www.w3.org/XML/1998/namespace"}]
        self.root: Element | None = None
        self.count = 0
        self.texts: list[list[str]] = []
        self.prologue: list[tuple[int, str]] = []

    def comment(self, content: str) -> None:
        """Only the comments before the root element are kept."""
        if self.root is None:
            self.prologue.append((self._offset(), content))

    def _offset(self) -> int:
        return int(self.parser.CurrentByteIndex)

    def entity_declared(
        self, name: str, parameter: bool, value: str | None, base: str | None, system: str | None, *_: object
    ) -> None:
        """An entity declaration, general or parameter: refused before the entity can be used."""
        raise XmlRefused("XDD002", _refusal(f"entity {name!r}", system), self._offset())

    def unparsed_entity_declared(self, name: str, base: str | None, system: str | None, *_: object) -> None:
        raise XmlRefused("XDD002", _refusal(f"entity {name!r}", system), self._offset())

    def external_reference(self, context: str | None, base: str | None, system: str | None, public: str | None) -> int:
        raise XmlRefused("XDD002", _refusal("an external reference", system), self._offset())

    def start(self, name: str, values: dict[str, str]) -> None:
        self.count += 1
        if self.count > MAX_ELEMENTS:
            raise XmlRefused("XDD003", f"more than {MAX_ELEMENTS} elements; refused", self._offset())
        stack = self.stack
        if len(stack) >= MAX_DEPTH:
            raise XmlRefused("XDD003", f"elements nested deeper than {MAX_DEPTH}; refused", self._offset())
        scope = self.scopes[-1]
        if values and any(key.startswith("xmlns") for key in values):
            scope = _declared(scope, values)
        self.scopes.append(scope)
        prefix, _, local = name.rpartition(":")
        start = self.parser.CurrentByteIndex
        element = Element(name, local, scope.get(prefix, ""), values, start, tag_end(self.data, start))
        if stack:
            element.parent = parent = stack[-1]
            parent.children.append(element)
        else:
            self.root = element
        stack.append(element)
        self.texts.append([])

    def end(self, name: str) -> None:
        element = self.stack.pop()
        self.scopes.pop()
        texts = self.texts.pop()
        if texts:
            element.text = texts[0] if len(texts) == 1 else "".join(texts)
        here = self.parser.CurrentByteIndex
        content_start = element.content_start
        if here <= content_start and self.data[content_start - 2 : content_start] == b"/>":
            element.content_end = element.end = content_start
        else:
            element.content_end = here
            element.end = tag_end(self.data, here)

    def characters(self, content: str) -> None:
        if self.texts:
            self.texts[-1].append(content)


def _declared(scope: dict[str, str], values: dict[str, str]) -> dict[str, str]:
    """`scope` with the namespaces an element's attributes declare ("xmlns" the default one, the "" prefix)."""
    scope = dict(scope)
    for key, value in values.items():
        if key == "xmlns" or key.startswith("xmlns:"):
            scope[key[6:]] = value
    return scope


def utf8_form(data: bytes) -> bytes:
    """UTF-16 input as UTF-8, so byte offsets and the scanning of tags work on one encoding."""
    if data[:2] not in (b"\xff\xfe", b"\xfe\xff"):
        return data
    try:
        text = data.decode("utf-16")
    except UnicodeDecodeError:
        return data
    text = re.sub(r"""^(<\?xml[^>]*encoding\s*=\s*)(["'])[^"']*\2""", r"\1\2utf-8\2", text)
    return text.encode("utf-8")


_TAG = re.compile(rb"""<[^>"']*(?:(?:"[^"]*"|'[^']*')[^>"']*)*>""")


def _tag_end_python(data: bytes, start: int) -> int:
    """The offset just after the `>` closing the tag that starts at `start`, skipping quoted values.

    The reference for the compiled `_tags.tag_end`, which does the same and is used when it is installed."""
    match = _TAG.match(data, start)
    return match.end() if match is not None else len(data)


tag_end: Callable[[bytes, int], int]
try:
    from ._tags import tag_end
except ImportError:  # built without a C compiler: the same, in Python
    tag_end = _tag_end_python


def parse(data: bytes) -> Element:
    """The document's root element. Raises XmlRefused with a reader code."""
    if len(data) > MAX_BYTES:
        raise XmlRefused("XDD003", f"{len(data)} bytes: larger than the {MAX_BYTES} bytes accepted for XML")
    parser = expat.ParserCreate()
    builder = _Builder(data, parser)
    parser.buffer_text = True  # one call for a run of text, not one a line
    parser.StartElementHandler = builder.start
    parser.EndElementHandler = builder.end
    parser.CharacterDataHandler = builder.characters
    parser.CommentHandler = builder.comment
    parser.EntityDeclHandler = builder.entity_declared
    parser.UnparsedEntityDeclHandler = builder.unparsed_entity_declared
    parser.ExternalEntityRefHandler = builder.external_reference
    # External parameter entities reach `external_reference` (and are refused) instead of passing unseen.
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_UNLESS_STANDALONE)
    try:
        parser.Parse(data, True)
    except XmlRefused:
        raise
    except expat.ExpatError as error:
        message = f"not well-formed XML: {expat.ErrorString(error.code)}"
        raise XmlRefused("XDD001", message, int(parser.ErrorByteIndex)) from None
    except (LookupError, ValueError) as error:  # an encoding expat does not know
        raise XmlRefused("XDD001", f"not readable XML: {error}", 0) from None
    if builder.root is None:
        raise XmlRefused("XDD001", "not well-formed XML: no root element")
    builder.root.prologue = tuple(builder.prologue)
    return builder.root


def _refusal(what: str, system: object) -> str:
    where = f" (pointing at {system!r})" if system else ""
    return f"declares {what}{where}; entity declarations and external references are not read"
