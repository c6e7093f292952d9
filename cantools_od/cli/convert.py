"""`cantools-od convert`: between EDS, DCF, XDD, XDC and JSON, by file extension."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, node_id_option, read_device, report


@click.command(name="convert")
@click.argument("source", type=click.Path(dir_okay=False))
@click.option(
    "-o",
    "--output",
    required=True,
    type=click.Path(dir_okay=False),
    help="File to write (.eds, .dcf, .xdd, .xpd, .xdc, .json).",
)
@node_id_option
def command(source: str, output: str, node_id: int | None) -> None:
    """Convert SOURCE to OUTPUT. The same format in and out keeps the original
    layout; a DCF made from an EDS (an XDC from an XDD) needs --node-id."""
    from ..api import dumps, format_for, write_if_changed

    device = read_device(source, node_id)
    errors = report(device.diagnostics)
    fmt_in, fmt_out = format_for(Path(source)), format_for(Path(output))
    try:
        data = dumps(device, fmt_out, style="preserve" if fmt_in == fmt_out else "canonical")
    except ValueError as error:
        click.echo(f"{source}: error: {error}", err=True)
        sys.exit(EXIT_USAGE)
    write_if_changed(Path(output), data)
    sys.exit(EXIT_FINDINGS if errors else EXIT_OK)
