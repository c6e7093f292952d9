"""The text report: device changes, then each object and PDO with its changes, one line each."""

from __future__ import annotations

from collections.abc import Iterator

import click

from ..views.layout import draw
from . import describe
from .records import IMPACT_ORDER, Change, DeviceDiff, Impact, PdoDiff, PdoView

_COLOURS = {Impact.BREAKING: "red", Impact.COMPATIBLE: "green", Impact.VALUE: "yellow", Impact.COSMETIC: "bright_black"}
_WIDTH = max(len(impact.value) for impact in Impact)


def summary(diff: DeviceDiff) -> str:
    """`2 breaking, 1 compatible, 0 value, 3 cosmetic`, or `no changes`."""
    if diff.empty:
        return "no changes"
    counts = diff.counts()
    return ", ".join(f"{counts[impact]} {impact.value}" for impact in IMPACT_ORDER)


def render(diff: DeviceDiff) -> str:
    """The report, styled with ANSI colours (click.echo drops them when the output is not a terminal)."""
    lines = [click.style(f"--- {diff.old}", bold=True), click.style(f"+++ {diff.new}", bold=True), summary(diff)]
    if diff.device:
        lines += ["", click.style("Device", bold=True)]
        lines += [_line(change) for change in diff.device]
    for obj in diff.objects:
        lines += ["", click.style(f"0x{obj.index:04X} {obj.name}", bold=True)]
        lines += [_line(change) for change in obj.changes]
    for pdo in diff.pdos:
        lines += ["", click.style(f"{pdo.name} (0x{pdo.comm_index:04X}/0x{pdo.map_index:04X})", bold=True)]
        lines += [_line(change, entry=False) for change in pdo.changes]
        lines += list(_drawings(pdo))
    return "\n".join(lines)


def _line(change: Change, entry: bool = True) -> str:
    tag = click.style(f"{change.impact.value:<{_WIDTH}}", fg=_COLOURS[change.impact])
    where = "" if change.subindex is None or not entry else f"sub {change.subindex} {describe.text(change.name)} "
    return f"  {tag}  {where}{describe.sentence(change)}"


def _drawing(view: PdoView | None) -> list[str]:
    if view is None:
        return ["(absent)"]
    if view.pdo is None or not view.pdo.entries:
        return ["(no entries)"]
    return draw(view.pdo).splitlines()


def _drawings(pdo: PdoDiff) -> Iterator[str]:
    """Before and after, side by side, when the layout changed."""
    if not any(change.kind.value in ("pdo-layout", "pdo-added", "pdo-removed") for change in pdo.changes):
        return
    left, right = _drawing(pdo.before), _drawing(pdo.after)
    width = max(44, *(len(line) for line in left)) + 2
    yield ""
    yield f"    {'before':<{width}}after"
    for number in range(max(len(left), len(right))):
        a = left[number] if number < len(left) else ""
        b = right[number] if number < len(right) else ""
        yield f"    {a:<{width}}{b}".rstrip()
