"""`cantools-od convert`: between EDS, DCF, XDD, XDC and JSON, by file extension."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .common import (
    EXIT_FINDINGS,
    EXIT_OK,
    EXIT_USAGE,
    Output,
    check_extension,
    errors_to_fix,
    node_id_option,
    read_device,
    report,
    write_outputs,
)


@click.command(name="convert")
@click.argument("source", type=click.Path(dir_okay=False))
@click.option(
    "-o",
    "--output",
    required=True,
    type=Output(dir_okay=False),
    help="File to write (.eds, .dcf, .xdd, .xpd, .xdc, .json).",
)
@node_id_option
def command(source: str, output: str, node_id: int | None) -> None:
    """Convert SOURCE to OUTPUT between EDS, DCF, XDD (.xdd, .xpd), XDC and JSON, by their
    extensions. The same format in and out keeps the original
    layout; a DCF made from an EDS (an XDC from an XDD) needs --node-id. A SOURCE
    the reader reports an error in (a value or section it cannot read) is not
    converted (exit 1); the errors of lint's rules are lint's to report."""
    from ..api import dumps, format_for, loads

    check_extension(source, "input")
    check_extension(output, "output")
    device = read_device(source, node_id)
    report(device.diagnostics)
    problems = errors_to_fix(device)
    if problems:
        click.echo(f"{source}: error: not converted: {problems}", err=True)
        sys.exit(EXIT_FINDINGS)
    _refuse_other_node_id(source, device.commissioning.node_id if device.commissioning else None, node_id)
    fmt_in, fmt_out = format_for(Path(source)), format_for(Path(output))
    if fmt_out in ("dcf", "xdc") and not device.is_dcf and device.node_id is None:
        made = "a DCF" if fmt_out == "dcf" else "an XDC"
        kind = {"eds": "an EDS", "xdd": "an XDD", "json": "a JSON model"}.get(fmt_in, "a device description")
        click.echo(
            f"{source}: error: {made} describes one node: give its node-ID (--node-id N) to make one from {kind}",
            err=True,
        )
        sys.exit(EXIT_USAGE)
    try:
        data = dumps(device, fmt_out, style="preserve" if fmt_in == fmt_out else "canonical")
    except ValueError as error:
        click.echo(f"{source}: error: {error}", err=True)
        sys.exit(EXIT_USAGE)
    if fmt_in != fmt_out:  # what the target has no place for is said, section by section
        from ..losses import losses

        for lost in losses(device, loads(data, fmt=fmt_out, node_id=node_id), fmt_out):
            click.echo(f"{source}: warning: {lost}", err=True)
    write_outputs({Path(output): data})
    sys.exit(EXIT_OK)


def _refuse_other_node_id(source: str, commissioned: int | None, given: int | None) -> None:
    """A file commissioned for one node is not silently written for another: its values may already be
    resolved for the node-ID it names, so --node-id must agree with it (or be left out)."""
    if given is None or commissioned is None or given == commissioned:
        return
    click.echo(
        f"{source}: error: the file is commissioned for node-ID {commissioned}, not {given}:"
        " leave out --node-id or change the node-ID in the file",
        err=True,
    )
    sys.exit(EXIT_USAGE)
