"""`cantools-od convert`: between EDS, DCF, XDD, XDC and JSON, by file extension."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from ..model.source import capped
from .batch import file_selection
from .common import (
    EXIT_FINDINGS,
    EXIT_OK,
    EXIT_USAGE,
    check_extension,
    lint_errors,
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
    type=click.Path(dir_okay=False),
    help="File to write (.eds, .dcf, .xdd, .xpd, .xdc, .json).",
)
@node_id_option
def command(source: str, output: str, node_id: int | None) -> None:
    """Convert SOURCE to OUTPUT between EDS, DCF, XDD (.xdd, .xpd), XDC and JSON, by their
    extensions. The same format in and out keeps the original
    layout; a DCF made from an EDS (an XDC from an XDD) needs --node-id. A SOURCE
    `lint` reports an error in is not converted (exit 1; a code its configuration
    ignores is no error)."""
    from ..api import dumps, format_for, loads

    check_extension(source, "input")
    check_extension(output, "output")
    device = read_device(source, node_id)
    report(device.diagnostics)
    errors = lint_errors(device, file_selection(source), node_id)
    if errors:  # an error in the input fails the command; the configuration's `ignore` opts out
        said = {d.code for d in device.diagnostics}  # the reader's, reported above
        shown, notes = capped([error for error in errors if error.code not in said])
        for line in [error.format() for error in shown] + notes:
            click.echo(line, err=True)
        count = f"{len(errors)} error{'s' if len(errors) != 1 else ''}"
        click.echo(
            f"{source}: error: not converted: {count} to fix first (as `cantools-od lint` reports them)", err=True
        )
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
