"""`cantools-od ids`: the identifiers generated code uses, as a TOML pin file."""

from __future__ import annotations

import sys

import click

from ..model import Severity
from .common import EXIT_USAGE, read_device, report


@click.command(name="ids")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option(
    "--pins",
    "pin_file",
    type=click.Path(dir_okay=False),
    help="A pin file whose identifiers take precedence (the output of an earlier run).",
)
def command(file: str, pin_file: str | None) -> None:
    """Print the identifier of every object and sub-object of FILE as a TOML
    pin file. Keep it and pass it with --pins to generators to freeze names."""
    from ..identifiers import assign, load_pins

    device = read_device(file)
    report(device.diagnostics, minimum=Severity.ERROR)
    try:
        pins = load_pins(pin_file) if pin_file is not None else None
        identifiers = assign(device, pins)
    except OSError as error:
        click.echo(f"{pin_file}: error: cannot read: {error.strerror or error}", err=True)
        sys.exit(EXIT_USAGE)
    except ValueError as error:
        click.echo(f"{pin_file}: error: {error}", err=True)
        sys.exit(EXIT_USAGE)
    click.echo(identifiers.to_toml(), nl=False)
