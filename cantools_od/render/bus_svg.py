"""The bus picture as SVG: the nodes side by side, a lifeline under each, and one row a message with an
arrow from its producer to each consumer, labelled with CAN-ID, name and rate on the left.

Rows never share a line and labels keep to their column, so nothing overlaps however many PDOs a bus has.
Each message's group carries its producer and consumers (`data-producer`, `data-consumers`) and each
lifeline its node (`data-node`), which the browser tests check the arrows against.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..network.picture import BusPicture, Message, Node
from . import render_template
from .svg import MARGIN, text_width

TITLE, LABEL, NODE_NAME, NODE_LINE = 13, 11, 12, 10
BOX_HEIGHT, ROW = 58, 24
BOX_TOP = MARGIN + TITLE + 14
ROWS_TOP = BOX_TOP + BOX_HEIGHT + 22
HEAD = 6  # an arrowhead's length


@dataclass(frozen=True)
class PlacedNode:
    node: Node
    x: float  # its lifeline
    box_x: float
    box_width: float
    lines: tuple[str, ...]


@dataclass(frozen=True)
class PlacedMessage:
    message: Message
    y: float
    start: float
    end: float
    producer_x: float
    heads: tuple[str, ...]  # an SVG path each: the arrowheads at the consumers


def _node_lines(node: Node) -> tuple[str, ...]:
    who = "master" if node.is_master else "slave"
    return (node.name, f"{who}, node-ID {node.node_id}", f"{node.load:.1f} % of the bus")


def render(picture: BusPicture, banner: str = "") -> str:
    """The picture as one SVG document; `banner` goes in a comment first."""
    lines = {node.name: _node_lines(node) for node in picture.nodes}
    label_width = max([text_width(m.label, LABEL) for m in picture.messages] + [60]) + 2 * MARGIN
    widest = max(text_width(text, NODE_NAME) for texts in lines.values() for text in texts)
    column = max(150, round(widest + 24))
    placed: dict[str, PlacedNode] = {}
    for n, node in enumerate(picture.nodes):
        left = label_width + n * column
        x = left + column // 2
        placed[node.name] = PlacedNode(node, x, left + 10, column - 20, lines[node.name])
    rows = [_message(m, ROWS_TOP + i * ROW, placed) for i, m in enumerate(picture.messages)]
    bottom = ROWS_TOP + len(rows) * ROW
    width = max(label_width + len(picture.nodes) * column + MARGIN, text_width(picture.title, TITLE) + 2 * MARGIN)
    return render_template(
        "svg/bus.svg.j2",
        picture=picture,
        nodes=list(placed.values()),
        rows=rows,
        width=round(width),
        height=round(bottom + MARGIN),
        bottom=bottom,
        sizes={"title": TITLE, "label": LABEL, "name": NODE_NAME, "line": NODE_LINE},
        box_top=BOX_TOP,
        box_height=BOX_HEIGHT,
        margin=MARGIN,
        banner=banner,
    )


def _message(message: Message, y: float, placed: dict[str, PlacedNode]) -> PlacedMessage:
    producer = placed[message.producer].x
    targets = [placed[name].x for name in message.consumers if name in placed]
    xs = [producer, *targets]
    heads = tuple(_head(x, y, x > producer) for x in targets)
    return PlacedMessage(message, y, min(xs), max(xs), producer, heads)


def _head(x: float, y: float, rightwards: bool) -> str:
    back = -HEAD if rightwards else HEAD
    return f"M{x} {y}l{back} -{HEAD / 2}v{HEAD}z"
