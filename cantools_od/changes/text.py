"""The text report: device changes, then each object and PDO with its changes, one line each (wrapped at 100
columns), and a compact before/after layout for each PDO whose mapping changed."""

from __future__ import annotations

import textwrap
from collections.abc import Iterator

import click

from . import describe
from .pdos import entry_text
from .records import IMPACT_ORDER, Breaks, Change, DeviceDiff, Impact, Kind, PdoDiff, PdoView

WIDTH = 100
_COLOURS = {Impact.BREAKING: "red", Impact.COMPATIBLE: "green", Impact.VALUE: "yellow", Impact.COSMETIC: "bright_black"}
_TAG = max(len(impact.value) for impact in Impact)
_INDENT = " " * (2 + _TAG + 2)
_COLUMN = (WIDTH - 4 - 2) // 2  # each side of a before/after layout


def summary(diff: DeviceDiff) -> str:
    """`2 breaking (1 wire, 2 code), 1 compatible, 0 value, 3 cosmetic`, or `no changes`."""
    if diff.empty:
        return "no changes"
    counts = diff.counts()
    parts = [f"{counts[impact]} {impact.value}" for impact in IMPACT_ORDER]
    if counts[Impact.BREAKING]:
        who = [f"{sum(hurt in c.breaks for c in diff.changes())} {hurt.value}" for hurt in Breaks]
        parts[0] += f" ({', '.join(who)})"
    return ", ".join(parts)


def render(diff: DeviceDiff) -> str:
    """The report, styled with ANSI colours (click.echo drops them when the output is not a terminal)."""
    lines = [click.style(f"--- {diff.old}", bold=True), click.style(f"+++ {diff.new}", bold=True), summary(diff)]
    if diff.device:
        lines += ["", click.style("Device", bold=True)]
        lines += [line for change in diff.device for line in _line(change)]
    for obj in diff.objects:
        lines += ["", click.style(_cut(f"0x{obj.index:04X} {obj.name}", WIDTH), bold=True)]
        lines += [line for change in obj.changes for line in _line(change)]
    for pdo in diff.pdos:
        lines += ["", click.style(f"{pdo.name} (0x{pdo.comm_index:04X}/0x{pdo.map_index:04X})", bold=True)]
        lines += [line for change in pdo.changes for line in _line(change, named=False)]
        lines += list(_layouts(pdo))
    return "\n".join(lines)


def tag(change: Change) -> str:
    """The first column: who a breaking change hurts (`wire`, `code`, `wire+code`), else the impact."""
    return "+".join(hurt.value for hurt in change.breaks) or change.impact.value


def _line(change: Change, named: bool = True) -> list[str]:
    where = describe.address(change.index, change.subindex)
    if named and change.subindex is not None and change.kind is not Kind.NAME:
        where += f" {describe.text(change.name)}"
    body = f"{where} {sentence(change)}" if where else sentence(change)
    wrapped = textwrap.wrap(body, WIDTH - len(_INDENT), subsequent_indent="  ", break_on_hyphens=False) or [""]
    first = "  " + click.style(f"{tag(change):<{_TAG}}", fg=_COLOURS[change.impact]) + "  " + wrapped[0]
    return [first, *(_INDENT + rest for rest in wrapped[1:])]


def sentence(change: Change) -> str:
    """As describe.sentence, but a PDO's mapping says what happened to it (the layout is drawn below)."""
    if change.kind is Kind.PDO_LAYOUT:
        return f"mapping: {change.note}"
    return describe.sentence(change)


def _cut(text: str, width: int) -> str:
    return text if len(text) <= width else text[: width - 1] + "…"


def _column(view: PdoView | None) -> list[str]:
    if view is None:
        return ["(absent)"]
    if not view.entries:
        return ["(no entries)"]
    return [
        _cut(f"{e.bit_offset:>3}-{e.bit_offset + e.bit_length - 1:<3} {entry_text(e)}", _COLUMN) for e in view.entries
    ]


def _layouts(pdo: PdoDiff) -> Iterator[str]:
    """Before and after, one line per mapped entry, side by side, when the mapping changed."""
    if not any(change.kind is Kind.PDO_LAYOUT for change in pdo.changes):
        return
    left, right = _column(pdo.before), _column(pdo.after)
    yield ""
    yield f"    {'   bits before':<{_COLUMN}}     bits after"
    for number in range(max(len(left), len(right))):
        a = left[number] if number < len(left) else ""
        b = right[number] if number < len(right) else ""
        yield f"    {a:<{_COLUMN}}  {b}".rstrip()
