"""What the subcommands share: reading inputs, printing diagnostics, exit codes."""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable, Iterator, Mapping
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..model import Device, Diagnostic, Severity
from ..model.device import errors_to_fix as errors_to_fix  # the rule lives with the model; commands import it here
from ..model.source import capped

if TYPE_CHECKING:
    from ..files import Content, Guard
    from ..identifiers import Identifiers

EXIT_OK = 0
EXIT_FINDINGS = 1
EXIT_USAGE = 2


def read_device(path: str, node_id: int | None = None) -> Device:
    """Load a file; a path that cannot be read, or content that is no device description,
    exits with code 2 and one line saying why."""
    found = device_or_reason(path, node_id)
    if isinstance(found, str):
        click.echo(found, err=True)
        sys.exit(EXIT_USAGE)
    return found


def device_or_reason(path: str, node_id: int | None = None) -> Device | str:
    """The file's device, or the one line saying why it cannot be read as one (for work that must not exit: a
    worker process of a batch)."""
    from ..api import load
    from ..sniff import NotADeviceDescription

    try:
        return load(path, node_id=node_id)
    except OSError as error:
        return f"{path}: error: cannot read: {unreadable(error)}"
    except NotADeviceDescription as error:
        return f"{path}: error: {error} [{error.code}]"


def unreadable(error: OSError) -> str:
    """Why a file could not be read, in words: "it is a folder", or the system's reason."""
    if isinstance(error, IsADirectoryError):
        return "it is a folder"
    return error.strerror or str(error)


def check_extension(path: str, role: str, allowed: Iterable[str] | None = None) -> None:
    """A file whose format its extension decides must have a known one (of `allowed`, default every
    format's); else exit 2 with the closest."""
    from ..api import SUFFIXES
    from ..names import UnknownName, check_names

    try:
        check_names("file extension", [Path(path).suffix.lower()], list(allowed or SUFFIXES))
    except UnknownName as error:
        click.echo(f"{path}: error: {role}: {error}", err=True)
        sys.exit(EXIT_USAGE)


def write_outputs(
    outputs: Mapping[Path, bytes] | Iterable[tuple[Path, Content]],
    *,
    rewrites: Iterable[str | os.PathLike[str]] = (),
    force: bool = False,
    ours: Callable[[Path], bool] | None = None,
) -> list[Path]:
    """Write every output or none (see files.py and docs/outputs.md); a refusal or failure exits with code 2 and
    one line. Every file the command read is an input no output may replace, but the `rewrites` it replaces by
    design; a `Generated` output replaces only a file `ours` (default: the banner) recognises, or any with `force`."""
    from ..files import CannotWrite, has_banner, write_all

    try:
        items = outputs.items() if isinstance(outputs, Mapping) else outputs
        return write_all(items, guard(rewrites, None if force else ours or has_banner))
    except CannotWrite as error:
        click.echo(f"error: {error}", err=True)
        sys.exit(EXIT_USAGE)


def guard(rewrites: Iterable[str | os.PathLike[str]], ours: Callable[[Path], bool] | None) -> Guard:
    """The guard of this command's outputs: what it read so far are its inputs (see files.record_reads); `ours`
    recognises the files it generated (None: any file is replaced, --force)."""
    from ..files import Guard, reads

    return Guard(reads(), [Path(p) for p in rewrites], ours)


class Output(click.Path):
    """A path the command writes, through `write_outputs` (the write path): a file, or the folder it fills. Every
    option that writes is declared with it; tests/journeys/test_writing_options.py finds them from the command line's
    own definition and proves each one refuses what docs/outputs.md says."""


class Rewritten(click.Path):
    """Files the command rewrites in place by design (fmt, lint --fix), each read first: a file that cannot be read
    (missing, a folder, no permission) is reported by the command itself, and the others still done."""

    def __init__(self) -> None:
        super().__init__(readable=False)


def force_option(function: click.decorators.FC) -> click.decorators.FC:
    return click.option(
        "--force",
        is_flag=True,
        help="Replace files in the output folder that cantools-od did not generate (no generated-file banner).",
    )(function)


def report(diagnostics: Iterable[Diagnostic], minimum: Severity = Severity.WARNING) -> bool:
    """Print diagnostics at or above `minimum` to stderr, a few of each code per file and a
    count of the rest; True when one is an error."""
    diagnostics = list(diagnostics)
    order = [Severity.ERROR, Severity.WARNING, Severity.INFO]
    chosen = [d for d in diagnostics if order.index(d.severity) <= order.index(minimum)]
    shown, notes = capped(chosen)
    for diagnostic in shown:
        click.echo(diagnostic.format(), err=True)
    for note in notes:
        click.echo(note, err=True)
    return any(d.severity is Severity.ERROR for d in diagnostics)


def node_id_option(function: click.decorators.FC) -> click.decorators.FC:
    return click.option(
        "--node-id",
        type=click.IntRange(1, 127),
        help="Node-ID that $NODEID stands for (1-127); a DCF's own NodeID otherwise.",
    )(function)


def pins_option(function: click.decorators.FC) -> click.decorators.FC:
    return click.option(
        "--pins",
        "pin_file",
        type=click.Path(dir_okay=False),
        help="Pin file of identifiers (from `cantools-od ids`); default: FILE's stem + .ids.toml beside it.",
    )(function)


def identifiers_for(device: Device, file: str, pin_file: str | None) -> Identifiers:
    """The device's identifiers with its pins; a bad pin file exits with code 2."""
    from ..identifiers import assign, load_pins, pin_file_for

    path = pin_file_for(file, pin_file)
    try:
        return assign(device, load_pins(path) if path is not None else None)
    except OSError as error:
        click.echo(f"{path}: error: cannot read: {error.strerror or error}", err=True)
    except ValueError as error:
        click.echo(f"{path}: error: {error}", err=True)
    sys.exit(EXIT_USAGE)


class Progress:
    """A count of long work on stderr, on a terminal only: nothing reaches a pipe, a file or a CI log.

    Each step rewrites one line (`lint: 12/97 device.eds`); `clear` takes it away before the command
    prints anything of its own."""

    def __init__(self, what: str, total: int | None = None) -> None:
        self.what, self.total, self.count = what, total, 0
        self.shown = _on_terminal()

    def step(self, label: str) -> None:
        self.count += 1
        if self.shown:
            of = f"/{self.total}" if self.total else ""
            # the cursor goes back to the start: a message printed next writes over the line
            click.echo(f"\r\x1b[K{self.what}: {self.count}{of} {label}\r", err=True, nl=False)

    def clear(self) -> None:
        """Take the line away, before the command prints something of its own."""
        if self.shown and self.count:
            click.echo("\r\x1b[K", err=True, nl=False)

    def over(self, items: Iterable[str]) -> Iterator[str]:
        """The items, each counted as a step before it is worked on; the line is cleared after the last."""
        for item in items:
            self.step(item)
            yield item
        self.clear()


def _on_terminal() -> bool:
    return sys.stderr.isatty() and not os.environ.get("CI") and os.environ.get("TERM") != "dumb"
