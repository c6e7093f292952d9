"""`cantools-od dump`: the object dictionary as a table, or the model as JSON."""

from __future__ import annotations

import sys

import click

from .common import EXIT_FINDINGS, EXIT_OK, node_id_option, read_device, report


@click.command(name="dump")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text", show_default=True)
@node_id_option
def command(file: str, fmt: str, node_id: int | None) -> None:
    """Show the object dictionary of FILE (EDS, DCF, XDD, XDC or JSON) as a table, or the whole
    model as JSON (--format json)."""
    from ..api import dumps
    from ..views.table import render_table

    device = read_device(file, node_id)
    errors = report(device.diagnostics)
    if fmt == "json":
        sys.stdout.write(dumps(device, "json").decode("utf-8"))
    else:
        click.echo(render_table(device))
    sys.exit(EXIT_FINDINGS if errors else EXIT_OK)
