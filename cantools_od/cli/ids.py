"""`cantools-od ids`: the identifiers generated code uses, as a TOML pin file."""

from __future__ import annotations

from pathlib import Path

import click

from ..model import Severity
from .common import identifiers_for, pins_option, read_device, report


@click.command(name="ids")
@click.argument("file", type=click.Path(dir_okay=False))
@pins_option
@click.option(
    "-o", "--output", type=click.Path(dir_okay=False), help="Write the pin file here (atomically) instead of to stdout."
)
def command(file: str, pin_file: str | None, output: str | None) -> None:
    """Print the identifier of every object and sub-object of FILE as a TOML
    pin file. Save it as FILE's stem + .ids.toml (or pass it with --pins) to
    freeze names: generators then keep them when display names change.
    Pins already in that file are kept, so `ids FILE -o FILE.ids.toml` updates it."""
    from ..api import write_if_changed

    device = read_device(file)
    report(device.diagnostics, minimum=Severity.ERROR)
    text = identifiers_for(device, file, pin_file).to_toml()
    if output is None:
        click.echo(text, nl=False)
    else:
        write_if_changed(Path(output), text.encode("utf-8"))
