"""`cantools-od diff OLD_FOLDER NEW_FOLDER`: every device description under either folder, paired by its path
relative to the folder, compared as `diff OLD NEW` compares two files; a file on one side only is compared with
nothing (added or removed). Pairs run in processes (`--jobs`); the reports come in path order, the same bytes
as with `--jobs 1`, and only pairs that changed are reported, as `diff -r` shows only files that differ."""

from __future__ import annotations

import os
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from functools import partial
from pathlib import Path
from typing import NoReturn

import click

from ..model import Device
from .batch import file_size, run_each
from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Progress, device_or_reason
from .diff_parts import NULL_DEVICE, found_in, missing_side, read_pins, reading_note, refusal, render

# Device descriptions by file name; a JSON model is compared only when named (a folder holds other JSON files).
FOLDER_SUFFIXES = (".eds", ".dcf", ".xdd", ".xdc", ".xpd")


@dataclass(frozen=True)
class Options:
    fmt: str
    fail_on: str
    node_id: int | None


@dataclass(frozen=True)
class Pair:
    name: str  # the path relative to both folders, with "/"
    old: str  # a file, or NULL_DEVICE when only the new folder has it
    new: str


@dataclass(frozen=True)
class Outcome:
    report: str  # the rendered report; "" when unchanged or not compared
    found: bool  # a change at or above --fail-on
    messages: tuple[str, ...]  # lines for stderr: notes of reading, and errors
    failed: bool  # a side could not be read


def device_files(folder: Path) -> dict[str, Path]:
    """Device descriptions under `folder` by relative path (symbolic links to folders are not followed)."""
    found: dict[str, Path] = {}
    for top, folders, files in os.walk(folder):
        folders.sort()
        for name in files:
            path = Path(top, name)
            if path.suffix.lower() in FOLDER_SUFFIXES and path.is_file():
                found[path.relative_to(folder).as_posix()] = path
    return found


def pairs(old: Path, new: Path) -> list[Pair]:
    before, after = device_files(old), device_files(new)
    return [
        Pair(name, str(before.get(name, NULL_DEVICE)), str(after.get(name, NULL_DEVICE)))
        for name in sorted(before.keys() | after.keys())
    ]


def run(old: str, new: str, options: Options, jobs: int | None, color: bool | None) -> NoReturn:
    """Compare the two folders; exit 2 when a file could not be read (every other pair is still compared and
    reported), else 1 when a change at or above --fail-on was found, else 0."""
    found = pairs(Path(old), Path(new))
    if not found:
        click.echo(f"error: no device description ({', '.join(FOLDER_SUFFIXES)}) under {old} or {new}", err=True)
        sys.exit(EXIT_USAGE)
    outcomes = run_each(partial(compare_pair, options), found, jobs, Progress("diff", len(found)), cost=_pair_size)
    reports = [outcome.report for outcome in outcomes if outcome.report]
    for outcome in outcomes:
        for message in outcome.messages:
            click.echo(message, err=True)
    if options.fmt == "json":
        click.echo(_json_array(reports))  # [] when nothing changed: still one JSON document
    elif reports:  # one blank line between reports
        click.echo("\n\n".join(report.rstrip("\n") for report in reports), color=color)
    if any(outcome.failed for outcome in outcomes):
        sys.exit(EXIT_USAGE)
    sys.exit(EXIT_FINDINGS if any(outcome.found for outcome in outcomes) else EXIT_OK)


def _pair_size(pair: Pair) -> int:
    return file_size(pair.old) + file_size(pair.new)


def _json_array(reports: list[str]) -> str:
    """The reports, each as `diff --format json` writes it, as one JSON array."""
    if not reports:
        return "[]"
    indented = ["\n".join("  " + line for line in report.splitlines()) for report in reports]
    return "[\n" + ",\n".join(indented) + "\n]"


class _Unreadable(Exception):
    pass


def compare_pair(options: Options, pair: Pair) -> Outcome:
    """One pair compared and rendered: in a process of its own under --jobs, so it reports rather than exits."""
    from ..changes import compare

    messages: list[str] = []
    try:
        old, old_pins = _side(pair.old, options.node_id, messages)
        new, new_pins = _side(pair.new, options.node_id, messages)
    except _Unreadable as error:
        return Outcome("", False, (*messages, str(error)), True)
    result = compare(old, new, options.node_id, old_pins, new_pins)
    # Titles name the relative path: the files' own names may repeat in other folders (node1/device.eds).
    titles = (_title(pair.old, pair.name), _title(pair.new, pair.name))
    report = "" if result.empty else render(result, options.fmt, titles)
    return Outcome(report, found_in(result, options.fail_on), tuple(messages), False)


def _title(side: str, name: str) -> str:
    return NULL_DEVICE if side == NULL_DEVICE else name


def _side(path: str, node_id: int | None, messages: list[str]) -> tuple[Device, Mapping[str, str] | None]:
    """A side's device and the pin file beside it; what `diff` of one pair reads, reported rather than exiting."""
    from ..identifiers import pin_file_for

    if path == NULL_DEVICE:
        return missing_side(), None
    device = device_or_reason(path, node_id)
    if isinstance(device, str):
        raise _Unreadable(device)
    refused = refusal(device, path)
    if refused:
        raise _Unreadable(refused)
    note = reading_note(device, path)
    if note:
        messages.append(note)
    pin_path = pin_file_for(path)
    try:
        return device, (read_pins(pin_path) if pin_path is not None else None)
    except ValueError as error:
        raise _Unreadable(f"error: {error}") from None
