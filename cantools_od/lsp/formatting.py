"""Formatting: `fmt`'s canonical form as text edits, for the whole document or for the sections a range touches.

A range is formatted by replacing each section it touches with that section as `fmt` writes it, in place, and
only when `fmt` of the result is `fmt` of the document: whatever `fmt` does elsewhere (moving sections, adding
or dropping one), the reply can never lose or duplicate a line of the document. When that does not hold, or for
XML, the range gets the whole document's formatting when all of `fmt`'s changes lie in the sections it touches,
else nothing, with the reason (NotFormatted).
"""

from __future__ import annotations

import re
from collections import Counter
from dataclasses import dataclass
from pathlib import Path

from lsprotocol import types

from ..api import dumps, format_for
from ..eds.decode import decode_as, mixed_encoding
from ..lint.config import load_int_style
from ..model import Device
from ..model.device import errors_to_fix
from ..sniff import NotADeviceDescription
from .document import Analysis, Encoding, path_of, read
from .edits import one_edit
from .positions import Lines

_HEADER = re.compile(r"[ \t]*\[([^\]\r\n]*)")
_COMMENT = re.compile(r"[ \t]*;")
_BLANK = re.compile(r"[ \t]*(?:\r\n|\r|\n)?\Z")


class NotFormatted(Exception):
    """fmt leaves the document (or the range) as it is; the message says why, in one line."""


def _path(uri: str) -> Path:
    return path_of(uri) or Path(uri.rsplit("/", 1)[-1])


def refuse_unsafe_text(text: str, encoding: Encoding) -> None:
    """Raise NotFormatted when rewriting the text would save what the file does not say: replacement
    characters the editor put for bytes it could not decode, or UTF-8 mixed with another code page."""
    mangled = encoding.mangled(text)
    if mangled:
        raise NotFormatted(mangled)
    mixed = mixed_encoding(encoding.bytes(text))
    if mixed is not None:
        raise NotFormatted(f"not formatted: {mixed}; save it as UTF-8 first")


def _canonical(uri: str, device: Device, fresh: Device) -> str:
    """`fresh` (read again: dumps may not change the device linted) as fmt writes it, when `device` has no
    errors; integers by the nearest `[tool.cantools-od]`."""
    problems = errors_to_fix(device)
    if problems:
        raise NotFormatted(f"not formatted: {problems}")
    path = _path(uri)
    try:
        style = load_int_style(path.parent if path_of(uri) is not None else Path.cwd())
    except ValueError as error:
        raise NotFormatted(f"configuration: {error}") from None
    # in the file's code page when it is not UTF-8 (api.dumps), read back the same way
    return decode_as(dumps(fresh, format_for(path), style="canonical", int_style=style))[0]


def formatted(uri: str, analysis: Analysis, encoding: Encoding) -> str:
    """The document as `fmt` writes it."""
    device = analysis.device
    if device is None:
        raise NotFormatted(analysis.refusal[1] if analysis.refusal else analysis.config_error or "not read")
    refuse_unsafe_text(analysis.text, encoding)
    return _canonical(uri, device, read(uri, encoding.bytes(analysis.text)))


def _formatted_text(uri: str, text: str, encoding: Encoding) -> str | None:
    """`fmt` of any text, None when fmt would leave it."""
    try:
        device = read(uri, encoding.bytes(text))
        return _canonical(uri, device, device)  # read for this check alone: dumps may use it
    except (NotFormatted, NotADeviceDescription, RecursionError):
        return None


@dataclass(frozen=True)
class Block:
    """One section of an EDS/DCF text as lines (from 0, stop excluded): from the comment lines right above
    its header to the next such block. The preamble is the block of key ("", 0)."""

    key: tuple[str, int]
    """The section's name (upper case, blanks removed) and how many sections of that name come before it."""
    start: int
    stop: int


def blocks(lines: list[str]) -> list[Block]:
    heads = [(n, match.group(1)) for n, line in enumerate(lines) if (match := _HEADER.match(line))]
    starts, floor = [], 0
    for number, _ in heads:
        first = number
        while first > floor and _COMMENT.match(lines[first - 1]):
            first -= 1
        starts.append(first)
        floor = number + 1
    found = [Block(("", 0), 0, starts[0] if starts else len(lines))]
    seen: Counter[str] = Counter()
    for at, (_, name) in enumerate(heads):
        key = "".join(name.split()).upper()
        found.append(Block((key, seen[key]), starts[at], starts[at + 1] if at + 1 < len(starts) else len(lines)))
        seen[key] += 1
    return found


def _selected(within: types.Range, count: int) -> tuple[int, int]:
    """The first and last line (from 0) a range covers: a range ending at a line's start leaves that line out."""
    first = min(within.start.line, count - 1)
    last = within.end.line - 1 if within.end.character == 0 and within.end.line > within.start.line else within.end.line
    return first, max(first, min(last, count - 1))


def _eol(lines: list[str]) -> str:
    ends = Counter(line[len(line.rstrip("\r\n")) :] for line in lines)
    ends.pop("", None)
    return ends.most_common(1)[0][0] if ends else "\n"


def _trailing_blanks(lines: list[str]) -> int:
    count = 0
    while count < len(lines) and _BLANK.match(lines[len(lines) - 1 - count]):
        count += 1
    return count


def _section_text(old: list[str], block: Block, new: dict[tuple[str, int], list[str]], eol: str) -> str:
    """The block as fmt writes its section, with the document's line ends and the blank lines it had after it;
    nothing when fmt drops the section."""
    wanted = new.get(block.key, [])
    body = wanted[: len(wanted) - _trailing_blanks(wanted)]
    spacing = old[block.start : block.stop]
    spacing = spacing[len(spacing) - _trailing_blanks(spacing) :]
    if not body:
        return ""
    text = "".join(line.rstrip("\r\n") + eol for line in body)
    return text + "".join(spacing)


def _in_place(uri: str, old_text: str, new_text: str, encoding: Encoding, lines: tuple[int, int]) -> str | None:
    """The text with the sections holding `lines` formatted in place, when fmt of it is fmt of the text."""
    old, new = Lines(old_text).lines, Lines(new_text).lines
    first, last = lines
    touched = [b for b in blocks(old) if b.start <= last and b.stop > first]
    by_key = {b.key: new[b.start : b.stop] for b in blocks(new)}
    eol = _eol(old)
    middle = "".join(_section_text(old, b, by_key, eol) for b in touched)
    result = "".join(old[: touched[0].start]) + middle + "".join(old[touched[-1].stop :])
    if result == old_text or _formatted_text(uri, result, encoding) == new_text:
        return result
    return None


def _span(text: str, lines: tuple[int, int]) -> tuple[int, int]:
    """The lines (first, past the last) of the sections holding `lines`."""
    first, last = lines
    touched = [b for b in blocks(Lines(text).lines) if b.start <= last and b.stop > first]
    return touched[0].start, touched[-1].stop


def format_edits(uri: str, analysis: Analysis, encoding: Encoding, within: types.Range | None) -> list[types.TextEdit]:
    """fmt's changes as one edit (the lines between the common head and tail), for the whole document or for
    the sections a range touches (see the module's text)."""
    old = analysis.text
    new = formatted(uri, analysis, encoding)
    whole = one_edit(old, new)
    if within is None or not whole:
        return whole
    lines = _selected(within, len(Lines(old)))
    start, stop = _span(old, lines)
    change = whole[0].range
    if start <= change.start.line and (
        change.end.line < stop or (change.end.line == stop and change.end.character == 0)
    ):
        return whole
    if format_for(_path(uri)) in ("eds", "dcf"):
        result = _in_place(uri, old, new, encoding, lines)
        if result is not None:
            return one_edit(old, result)
    raise NotFormatted(
        "the selection cannot be formatted alone (fmt would move or change sections outside it): "
        "format the whole document"
    )
