"""`cantools-od fmt`: canonical form in place, or a check/diff for pre-commit and CI."""

from __future__ import annotations

import difflib
import sys
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING

import click

from .batch import config_option, config_path, file_size, jobs_option, run_each
from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Progress, Rewritten

if TYPE_CHECKING:
    from ..eds.format import IntStyle

RADIXES = ("canonical", "as-written", "hex", "decimal")


@click.command(name="fmt")
@click.argument("files", nargs=-1, required=True, type=Rewritten())
@click.option("--check", is_flag=True, help="Change nothing; exit 1 when a file would change.")
@click.option("--diff", "show_diff", is_flag=True, help="Change nothing; print what would change as a diff.")
@click.option(
    "--radix",
    type=click.Choice(RADIXES),
    help="How integers are spelled; replaces integer-radix of [tool.cantools-od] (default: canonical).",
)
@config_option
@jobs_option
def command(
    files: tuple[str, ...], check: bool, show_diff: bool, radix: str | None, config: str | None, jobs: int | None
) -> None:
    """Rewrite FILES in canonical form (CiA 306 key order and spelling, sorted
    sections, integers by the radix style, LF line ends), spelled so that every
    peer reader reads what the original said. A file is written only when its
    content changes, and never when the reader reports an error in it (a value
    or section it cannot read, which the canonical form could not carry; exit
    1), but for a section or key given twice, which it writes once, and a
    $NODEID formula in another order, written $NODEID+n; the errors of lint's
    rules are lint's to report. A file that cannot be
    read is reported (exit 2) and every other file still formatted."""
    from ..lint.config import load_int_style

    tasks = []
    for name in files:
        try:
            tasks.append(_Task(name, load_int_style(config_path(name, config), radix), check or show_diff, show_diff))
        except ValueError as error:
            click.echo(f"error: configuration: {error}", err=True)
            sys.exit(EXIT_USAGE)
    worst = EXIT_OK
    progress = Progress("fmt", len(tasks)) if len(tasks) > 1 else None
    for done in run_each(_format, tasks, jobs, progress, cost=lambda task: file_size(task.name)):
        sys.stdout.write(done.out)
        sys.stdout.flush()
        for line in done.err:
            click.echo(line, err=True)
        worst = max(worst, done.status)
    sys.exit(worst)


@dataclass(frozen=True)
class _Task:
    name: str
    int_style: IntStyle
    dry: bool  # --check or --diff: write nothing
    show_diff: bool


@dataclass
class _Done:
    status: int = EXIT_OK
    out: str = ""
    err: list[str] = field(default_factory=list)


def _format(task: _Task) -> _Done:
    """One file (in a worker process): its diagnostics, diff and verdict as text, the file written when due."""
    from ..api import dumps, format_for, load
    from ..eds.decode import mixed_encoding
    from ..files import CannotWrite, write_all
    from ..model.device import blocking_errors
    from ..model.source import capped
    from ..sniff import NotADeviceDescription
    from .common import errors_to_fix, guard, unreadable

    name = task.name
    try:
        device = load(name)
    except OSError as error:
        return _Done(EXIT_USAGE, err=[f"{name}: error: cannot read: {unreadable(error)}"])
    except NotADeviceDescription as error:
        return _Done(EXIT_USAGE, err=[f"{name}: error: {error} [{error.code}]"])
    shown, notes = capped(blocking_errors(device))
    done = _Done(err=[d.format() for d in shown] + notes)
    problems = errors_to_fix(device)
    if problems:
        # The canonical form of a file the reader could not fully make sense of could drop
        # what it did not understand: such a file is left as it is.
        done.err.append(f"{name}: error: not formatted: {problems}")
        done.status = EXIT_FINDINGS
        return done
    path = Path(name)
    original = path.read_bytes()
    mixed = mixed_encoding(original)
    if mixed is not None:  # read as Windows-1252, its UTF-8 letters are mojibake: never save that
        done.err.append(f"{name}: error: not formatted: {mixed}; save it as UTF-8 first")
        done.status = EXIT_FINDINGS
        return done
    formatted = dumps(device, format_for(path), style="canonical", int_style=task.int_style)
    if formatted == original:
        return done
    if task.show_diff:
        done.out = _diff(name, original, formatted, done.err)
    if task.dry:
        done.err.append(f"would reformat {name}")
        done.status = EXIT_FINDINGS
        return done
    try:
        write_all([(path, formatted)], guard(rewrites=[path], ours=None))
    except CannotWrite as error:
        done.err.append(f"error: {error}")
        done.status = EXIT_USAGE
        return done
    done.err.append(f"reformatted {name}")
    return done


def _diff(name: str, original: bytes, formatted: bytes, notes: list[str]) -> str:
    """A unified diff of the lines' text; a change of line ends alone is one note, not every line twice."""
    from ..eds.decode import decode_as

    before, after = decode_as(original)[0], decode_as(formatted)[0]  # each in the code page it is written in
    old_ends = {_ending(line) for line in before.splitlines(keepends=True)} - {"", "LF"}
    if old_ends:
        notes.append(f"{name}: note: line ends {'/'.join(sorted(old_ends))} become LF")
    lines = difflib.unified_diff(
        [line + "\n" for line in before.splitlines()],
        [line + "\n" for line in after.splitlines()],
        fromfile=name,
        tofile=name,
    )
    return "".join(lines)


def _ending(line: str) -> str:
    for end, shown in (("\r\n", "CRLF"), ("\r", "CR"), ("\n", "LF")):
        if line.endswith(end):
            return shown
    return ""
