"""PDO bit-field pictures as SVG: where each cell, field, label and legend line goes, in pixels.

Every text is real SVG text (searchable, selectable), set in a monospaced font so that its width can be
known here: a label is put inside its field only where it fits, else the field shows its number and the
legend below the grid names it. Fields carry their bits in `data-low`/`data-high` and cells their bit
in `data-bit`, which the browser tests read to check the geometry against the model.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass

from ..views.bitfield import CELLS_PER_ROW, Diagram, Field, FieldKind, Segment
from . import render_template

CELL = 18  # px a bit
MARGIN = 12
ROW_HEIGHT = 40
BYTE_LINE, BIT_LINE = 14, 12  # the byte numbers and the bit numbers above each row
ROW_GAP = 10
TITLE, TIMING, LEGEND = 13, 11, 11  # font sizes
LABEL, DETAIL, BIT_NUMBER = 11, 9, 8
ADVANCE = 0.61  # a monospaced character's width in em (DejaVu Sans Mono: 0.602)
LINE_HEIGHT = 16  # px from one line of the title, timing or legend to the next
FILLS = ("#cfe2f3", "#d9ead3", "#fff2cc", "#f4cccc", "#d9d2e9", "#fce5cd", "#d0e0e3", "#ead1dc")


def text_width(text: str, size: float) -> float:
    return len(text) * size * ADVANCE


@dataclass(frozen=True)
class Text:
    x: float
    y: float  # the baseline
    size: float
    text: str
    css: str  # its class
    anchor: str = "middle"
    number: int | None = None  # the field it labels


@dataclass(frozen=True)
class Box:
    x: float
    y: float
    width: float
    height: float
    css: str
    fill: str
    field: Field | None = None
    segment: Segment | None = None
    bit: int | None = None  # a cell's bit


@dataclass(frozen=True)
class Picture:
    """One PDO's drawing: its boxes and texts, relative to its own top left corner."""

    diagram: Diagram
    width: float
    height: float
    boxes: tuple[Box, ...]
    texts: tuple[Text, ...]
    ticks: str  # an SVG path: the bit marks drawn over the fields


def picture(diagram: Diagram) -> Picture:
    boxes: list[Box] = []
    texts = [
        Text(MARGIN, MARGIN + TITLE, TITLE, diagram.title, "title", "start"),
        Text(MARGIN, MARGIN + TITLE + LINE_HEIGHT, TIMING, diagram.timing, "timing", "start"),
    ]
    top = MARGIN + TITLE + LINE_HEIGHT + 10
    row_cells = diagram.row_bytes * 8
    for row in range(diagram.rows):
        y = top + row * (BYTE_LINE + BIT_LINE + ROW_HEIGHT + ROW_GAP)
        _grid(diagram, row, y, row_cells, boxes, texts)
    for field in diagram.fields:
        _field(field, top, _fill(field, diagram.anchor), boxes, texts)
    cells_in = [min(row_cells, diagram.byte_count * 8 - row * CELLS_PER_ROW) for row in range(diagram.rows)]
    ticks = "".join(_ticks(_row_top(top, row), cells) for row, cells in enumerate(cells_in))
    legend_top = top + diagram.rows * (BYTE_LINE + BIT_LINE + ROW_HEIGHT + ROW_GAP) + LEGEND
    legend = list(_legend(diagram.fields, legend_top))
    texts += legend
    widest = max((t.x + text_width(t.text, t.size) for t in texts if t.anchor == "start"), default=0.0)
    width = max(2 * MARGIN + row_cells * CELL, widest + MARGIN)
    height = (legend[-1].y if legend else legend_top) + MARGIN
    return Picture(diagram, round(width), round(height), tuple(boxes), tuple(texts), ticks)


def _x(cell: int) -> float:
    return MARGIN + cell * CELL


def _grid(diagram: Diagram, row: int, y: float, row_cells: int, boxes: list[Box], texts: list[Text]) -> None:
    """Byte numbers, bit numbers and the empty cells of one row."""
    cells_top = y + BYTE_LINE + BIT_LINE
    for column in range(row_cells // 8):
        byte = row * (CELLS_PER_ROW // 8) + column
        if byte >= diagram.byte_count:
            break
        texts.append(Text(_x(column * 8) + 4 * CELL, y + BYTE_LINE - 3, 10, f"byte {byte}", "byte"))
        for within in range(8):
            bit = byte * 8 + 7 - within
            x = _x(column * 8 + within)
            texts.append(Text(x + CELL // 2, cells_top - 3, BIT_NUMBER, str(bit), "bitno"))
            boxes.append(Box(x, cells_top, CELL, ROW_HEIGHT, "cell", "#ffffff", bit=bit))


def _row_top(top: float, row: int) -> float:
    return top + row * (BYTE_LINE + BIT_LINE + ROW_HEIGHT + ROW_GAP) + BYTE_LINE + BIT_LINE


def _field(field: Field, top: float, fill: str, boxes: list[Box], texts: list[Text]) -> None:
    widest = max(field.segments, key=lambda s: s.cells)
    for segment in field.segments:
        x, y = _x(segment.first_cell), _row_top(top, segment.row)
        width = segment.cells * CELL
        boxes.append(Box(x, y, width, ROW_HEIGHT, f"field {field.kind.value}", fill, field, segment))
        room = width - 4
        if segment is widest:
            texts += _labels(field, x + width // 2, y, room)
        elif field.number and text_width(str(field.number), LABEL) <= room:
            texts.append(
                Text(x + width // 2, y + ROW_HEIGHT // 2 + 4, LABEL, str(field.number), "label", number=field.number)
            )


def _fill(field: Field, anchor: str) -> str:
    if field.kind is FieldKind.DUMMY:
        return f"url(#hatch-{anchor})"
    if field.kind is FieldKind.MISSING:
        return "#ffffff"
    if field.kind is FieldKind.UNUSED:
        return "#eeeeee"
    return FILLS[(field.number - 1) % len(FILLS)]


def _labels(field: Field, middle: float, y: float, room: float) -> list[Text]:
    """The field's name inside it where it fits, else its legend number; its object and type below where
    those fit too."""
    number = str(field.number) if field.number else ""
    first = next((t for t in (field.label, number) if t and text_width(t, LABEL) <= room), "")
    detail = f"{field.where} {field.type_name}".strip()
    second = next((t for t in (detail, field.where) if t and text_width(t, DETAIL) <= room), "")
    tag = field.number
    if not first:
        return []
    if not second:
        return [Text(middle, y + ROW_HEIGHT // 2 + 4, LABEL, first, "label", number=tag)]
    return [
        Text(middle, y + ROW_HEIGHT // 2 - 2, LABEL, first, "label", number=tag),
        Text(middle, y + ROW_HEIGHT // 2 + DETAIL + 2, DETAIL, second, "detail", number=tag),
    ]


def _ticks(y: float, cells: int) -> str:
    """A ruler over the fields of a row: a short mark at each bit, a longer one at each byte."""
    marks = []
    for cell in range(1, cells):
        length = 8 if cell % 8 == 0 else 4
        x = _x(cell)
        marks.append(f"M{x} {y}v{length}M{x} {y + ROW_HEIGHT}v-{length}")
    return "".join(marks)


def legend_line(field: Field) -> str:
    if field.kind is FieldKind.UNUSED:
        return f"    {field.bits_text:<12} unused"
    what = {FieldKind.DUMMY: "dummy", FieldKind.MISSING: "missing object"}.get(field.kind, field.label)
    name = f"  {field.name}" if field.kind is FieldKind.OBJECT and field.name and field.name != field.label else ""
    return f"{field.number:>2}  {field.bits_text:<12} {field.where}  {field.type_name:<11} {what}{name}"


def _legend(fields: Iterable[Field], top: float) -> Iterable[Text]:
    for line, field in enumerate(fields):
        yield Text(MARGIN, top + line * LINE_HEIGHT, LEGEND, legend_line(field), "legend", "start", field.number)


def sheet(diagrams: Iterable[Diagram], banner: str = "", gap: float = 16) -> str:
    """One SVG document with each PDO's picture below the one before; `banner` goes in a comment first."""
    placed: list[tuple[float, Picture]] = []
    y = 0.0
    for diagram in diagrams:
        drawn = picture(diagram)
        placed.append((y, drawn))
        y += drawn.height + gap
    width = max((p.width for _, p in placed), default=2 * MARGIN)
    height = max(y - gap, 2 * MARGIN)
    return render_template("svg/sheet.svg.j2", placed=placed, width=width, height=round(height), banner=banner)
