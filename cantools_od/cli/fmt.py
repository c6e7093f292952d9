"""`cantools-od fmt`: canonical form in place, or a check/diff for pre-commit and CI."""

from __future__ import annotations

import difflib
import sys
from pathlib import Path

import click

from ..model import Severity
from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Progress, errors_to_fix, read_device, report, write_outputs

RADIXES = ("canonical", "as-written", "hex", "decimal")


@click.command(name="fmt")
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False))
@click.option("--check", is_flag=True, help="Change nothing; exit 1 when a file would change.")
@click.option("--diff", "show_diff", is_flag=True, help="Change nothing; print what would change as a diff.")
@click.option(
    "--radix",
    type=click.Choice(RADIXES),
    help="How integers are spelled; replaces integer-radix of [tool.cantools-od] (default: canonical).",
)
def command(files: tuple[str, ...], check: bool, show_diff: bool, radix: str | None) -> None:
    """Rewrite FILES in canonical form (CiA 306 key order and spelling, sorted
    sections, integers by the radix style, LF line ends), spelled so that every
    peer reader reads what the original said. A file is written only when its
    content changes, and never when it has errors (exit 1)."""
    from ..api import dumps, format_for
    from ..eds.decode import mixed_encoding
    from ..lint.config import load_int_style

    try:
        int_style = load_int_style(Path.cwd(), radix)
    except ValueError as error:
        click.echo(f"error: configuration: {error}", err=True)
        sys.exit(EXIT_USAGE)

    changed = refused = 0
    progress = Progress("fmt", len(files))
    for name in files:
        progress.step(name)
        device = read_device(name)
        progress.clear()
        report(device.diagnostics, minimum=Severity.ERROR)
        problems = errors_to_fix(device)
        if problems:
            # The canonical form of a file the reader could not fully make sense of could drop
            # what it did not understand: such a file is left as it is.
            click.echo(f"{name}: error: not formatted: {problems}", err=True)
            refused += 1
            continue
        path = Path(name)
        original = path.read_bytes()
        mixed = mixed_encoding(original)
        if mixed is not None:  # read as Windows-1252, its UTF-8 letters are mojibake: never save that
            click.echo(f"{name}: error: not formatted: {mixed}; save it as UTF-8 first", err=True)
            refused += 1
            continue
        formatted = dumps(device, format_for(path), style="canonical", int_style=int_style)
        if formatted == original:
            continue
        changed += 1
        if show_diff:
            _show_diff(name, original, formatted)
        if check or show_diff:
            click.echo(f"would reformat {name}", err=True)
        else:
            write_outputs({path: formatted})
            click.echo(f"reformatted {name}", err=True)
    sys.exit(EXIT_FINDINGS if refused or (changed and (check or show_diff)) else EXIT_OK)


def _show_diff(name: str, original: bytes, formatted: bytes) -> None:
    """A unified diff of the lines' text; a change of line ends alone is one note, not every line twice."""
    before = original.decode("utf-8", "replace")
    after = formatted.decode("utf-8")
    old_ends = {_ending(line) for line in before.splitlines(keepends=True)} - {"", "LF"}
    if old_ends:
        click.echo(f"{name}: note: line ends {'/'.join(sorted(old_ends))} become LF", err=True)
    sys.stdout.writelines(
        difflib.unified_diff(
            [line + "\n" for line in before.splitlines()],
            [line + "\n" for line in after.splitlines()],
            fromfile=name,
            tofile=name,
        )
    )


def _ending(line: str) -> str:
    for end, shown in (("\r\n", "CRLF"), ("\r", "CR"), ("\n", "LF")):
        if line.endswith(end):
            return shown
    return ""
