"""Parses XML without trusting it: a small element tree that remembers where each element is.

defusedxml's SAX driver over the standard library's expat refuses entity
declarations (billion laughs) and external references (XXE); nothing is ever
fetched. Size, element count and depth are bounded before and while parsing,
so a hostile file costs bounded time and memory. Each element keeps its byte
span in the input, which the locations and the preserving writer build on.
"""

from __future__ import annotations

import io
import re
from dataclasses import dataclass, field
from xml.sax import SAXException, handler
from xml.sax.xmlreader import AttributesImpl, InputSource

from defusedxml import DefusedXmlException
from defusedxml.expatreader import DefusedExpatParser

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


class _Builder(handler.ContentHandler):
    def __init__(self, data: bytes, reader: DefusedExpatParser) -> None:
        super().__init__()
        self.data = data
        self.reader = reader
        self.stack: list[Element] = []
        self.scopes: list[dict[str, str]] = [{"xml": "http://www.w3.org/XML/1998/namespace"}]
        self.root: Element | None = None
        self.count = 0
        self.texts: list[list[str]] = []
        self.prologue: list[tuple[int, str]] = []

    # The lexical handler's methods: only the comments before the root element are kept.
    def comment(self, content: str) -> None:
        if self.root is None:
            self.prologue.append((self._offset(), content))

    def startDTD(self, name: str, public_id: str | None, system_id: str | None) -> None:
        pass

    def endDTD(self) -> None:
        pass

    def startCDATA(self) -> None:
        pass

    def endCDATA(self) -> None:
        pass

    def _offset(self) -> int:
        return int(getattr(self.reader, "_parser").CurrentByteIndex)  # noqa: B009 (private in typeshed)

    def startElement(self, name: str, attrs: AttributesImpl) -> None:
        self.count += 1
        if self.count > MAX_ELEMENTS:
            raise XmlRefused("XDD003", f"more than {MAX_ELEMENTS} elements; refused", self._offset())
        if len(self.stack) >= MAX_DEPTH:
            raise XmlRefused("XDD003", f"elements nested deeper than {MAX_DEPTH}; refused", self._offset())
        values = dict(attrs.items())
        scope = self.scopes[-1]
        declared = [key for key in values if key == "xmlns" or key.startswith("xmlns:")]
        if declared:
            scope = dict(scope)
            for key in declared:
                scope[key[6:]] = values[key]  # "xmlns" gives the default namespace, the "" prefix
        self.scopes.append(scope)
        prefix, _, local = name.rpartition(":")
        start = self._offset()
        element = Element(name, local, scope.get(prefix, ""), values, start)
        element.content_start = tag_end(self.data, start)
        if self.stack:
            element.parent = self.stack[-1]
            self.stack[-1].children.append(element)
        else:
            self.root = element
        self.stack.append(element)
        self.texts.append([])

    def endElement(self, name: str) -> None:
        element = self.stack.pop()
        self.scopes.pop()
        element.text = "".join(self.texts.pop())
        here = self._offset()
        if self.data[element.content_start - 2 : element.content_start] == b"/>" and here <= element.content_start:
            element.content_end = element.end = element.content_start
        else:
            element.content_end = here
            element.end = tag_end(self.data, here)

    def characters(self, content: str) -> None:
        if self.texts:
            self.texts[-1].append(content)


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


def tag_end(data: bytes, start: int) -> int:
    """The offset just after the `>` closing the tag that starts at `start`, skipping quoted values."""
    match = _TAG.match(data, start)
    return match.end() if match is not None else len(data)


def parse(data: bytes) -> Element:
    """The document's root element. Raises XmlRefused with a reader code."""
    if len(data) > MAX_BYTES:
        raise XmlRefused("XDD003", f"{len(data)} bytes: larger than the {MAX_BYTES} bytes accepted for XML")
    reader = DefusedExpatParser(forbid_dtd=False, forbid_entities=True, forbid_external=True)
    builder = _Builder(data, reader)
    reader.setContentHandler(builder)
    reader.setProperty(handler.property_lexical_handler, builder)
    reader.setFeature(handler.feature_external_ges, False)
    reader.setFeature(handler.feature_external_pes, False)
    source = InputSource()
    source.setByteStream(io.BytesIO(data))
    try:
        reader.parse(source)
    except XmlRefused:
        raise
    except DefusedXmlException as error:
        raise XmlRefused("XDD002", _refusal(error), builder._offset()) from None
    except SAXException as error:
        raise XmlRefused("XDD001", f"not well-formed XML: {error.getMessage()}", _error_offset(reader)) from None
    except (LookupError, ValueError) as error:  # an encoding expat does not know
        raise XmlRefused("XDD001", f"not readable XML: {error}", 0) from None
    if builder.root is None:
        raise XmlRefused("XDD001", "not well-formed XML: no root element")
    builder.root.prologue = tuple(builder.prologue)
    return builder.root


def _refusal(error: DefusedXmlException) -> str:
    name = getattr(error, "name", None)
    system = getattr(error, "sysid", None) or getattr(error, "system_id", None)
    what = f"entity {name!r}" if name else "an external reference"
    where = f" (pointing at {system!r})" if system else ""
    return f"declares {what}{where}; entity declarations and external references are not read"


def _error_offset(reader: DefusedExpatParser) -> int:
    try:
        return int(getattr(reader, "_parser").ErrorByteIndex)  # noqa: B009
    except AttributeError:
        return 0
