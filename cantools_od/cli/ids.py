"""`cantools-od ids`: the identifiers generated code uses, as a TOML pin file."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from ..model import Severity
from .common import (
    EXIT_FINDINGS,
    Output,
    errors_to_fix,
    identifiers_for,
    pins_option,
    read_device,
    report,
    write_outputs,
)


@click.command(name="ids")
@click.argument("file", type=click.Path(dir_okay=False))
@pins_option
@click.option(
    "-o", "--output", type=Output(dir_okay=False), help="Write the pin file here (atomically) instead of to stdout."
)
def command(file: str, pin_file: str | None, output: str | None) -> None:
    """Print the identifier of every object and sub-object of FILE as a TOML
    pin file. Save it as FILE's stem + .ids.toml (or pass it with --pins) to
    freeze names: generators then keep them when display names change.
    Pins already in that file are kept, so `ids FILE -o FILE.ids.toml` updates it."""
    device = read_device(file)
    report(device.diagnostics, minimum=Severity.ERROR)
    problems = errors_to_fix(device)
    if problems:  # identifiers of a file read only in part would pin the wrong names
        click.echo(f"{file}: error: no identifiers printed: {problems}", err=True)
        sys.exit(EXIT_FINDINGS)
    text = identifiers_for(device, file, pin_file).to_toml()
    if output is None:
        click.echo(text, nl=False)
    else:
        from ..identifiers import pin_file_for

        pins = pin_file_for(file, pin_file)  # the pin file read is updated by design: its pins are kept
        write_outputs({Path(output): text.encode("utf-8")}, rewrites=[pins] if pins is not None else [])
