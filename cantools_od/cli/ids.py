"""`cantools-od ids`: the identifiers generated code uses, as a TOML pin file."""

from __future__ import annotations

import click

from ..model import Severity
from .common import identifiers_for, pins_option, read_device, report


@click.command(name="ids")
@click.argument("file", type=click.Path(dir_okay=False))
@pins_option
def command(file: str, pin_file: str | None) -> None:
    """Print the identifier of every object and sub-object of FILE as a TOML
    pin file. Save it as FILE's stem + .ids.toml (or pass it with --pins) to
    freeze names: generators then keep them when display names change."""
    device = read_device(file)
    report(device.diagnostics, minimum=Severity.ERROR)
    click.echo(identifiers_for(device, file, pin_file).to_toml(), nl=False)
