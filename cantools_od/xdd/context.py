"""What the XDD reader's parts share: the input, its positions, the report, and origins of elements."""

from __future__ import annotations

from ..eds.report import Report
from ..model import Origin
from ..model.assemble import fresh
from .locations import Positions, attribute_spans
from .safe import Element


class ReadContext:
    def __init__(self, data: bytes, file: str, report: Report) -> None:
        self.data = data
        self.file = file
        self.report = report
        self.positions = Positions(data)
        self._spans: dict[int, dict[str, tuple[int, int, int]]] = {}
        # For the preserving writer: the element each origin describes, and where each of its keys is written.
        self.elements: dict[int, Element] = {}
        self.marks: dict[int, dict[str, tuple[Element, str | None]]] = {}

    def spans(self, element: Element) -> dict[str, tuple[int, int, int]]:
        key = id(element)
        found = self._spans.get(key)
        if found is None:
            found = self._spans[key] = attribute_spans(self.data, element)
        return found

    def where(self, element: Element, attr: str | None = None) -> tuple[int, int]:
        """(line, column) of the element, or of the attribute's value when it has it."""
        if attr is not None:
            span = self.spans(element).get(attr)
            if span is not None:
                return self.positions.at(span[1])
        return self.positions.at(element.start)

    def origin(self, element: Element) -> Origin:
        line, column = self.positions.at(element.start)
        origin = fresh(Origin, {"file": self.file, "line": line, "column": column})
        self.elements[id(origin)] = element
        return origin

    def mark(self, origin: Origin, key: str, element: Element, attr: str | None = None) -> None:
        """Record where `key` of the model is written: an attribute, or (attr None) an element's text."""
        at = self.positions.at
        if attr is None:
            line, column = at(element.start)
            where = (line, column, at(element.content_start)[1] if element.content_start else column)
        else:
            span = self.spans(element).get(attr)
            if span is None:
                return
            line, column = at(span[0])
            value_line, value_column = at(span[1])
            where = (line, column, value_column if value_line == line else column)
        self.marks.setdefault(id(origin), {})[key] = (element, attr)
        origin.keys[key] = where

    def error(self, code: str, message: str, element: Element, attr: str | None = None) -> None:
        self.report.error(code, message, *self.where(element, attr))

    def warning(self, code: str, message: str, element: Element, attr: str | None = None) -> None:
        self.report.warning(code, message, *self.where(element, attr))
