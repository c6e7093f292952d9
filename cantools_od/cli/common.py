"""What the subcommands share: reading inputs, printing diagnostics, exit codes."""

from __future__ import annotations

import sys
from collections.abc import Iterable
from typing import TYPE_CHECKING

import click

from ..model import Device, Diagnostic, Severity

if TYPE_CHECKING:
    from ..identifiers import Identifiers

EXIT_OK = 0
EXIT_FINDINGS = 1
EXIT_USAGE = 2


def read_device(path: str, node_id: int | None = None) -> Device:
    """Load a file; an unreadable path exits with code 2 and a message."""
    from ..api import load

    try:
        return load(path, node_id=node_id)
    except OSError as error:
        click.echo(f"{path}: error: cannot read: {error.strerror or error}", err=True)
        sys.exit(EXIT_USAGE)
    except ValueError as error:  # JSON that is not a model
        click.echo(f"{path}:1:1: error: not a cantools-od model: {error} [JSN001]", err=True)
        sys.exit(EXIT_USAGE)


def report(diagnostics: Iterable[Diagnostic], minimum: Severity = Severity.WARNING) -> bool:
    """Print diagnostics at or above `minimum` to stderr; True when one is an error."""
    order = [Severity.ERROR, Severity.WARNING, Severity.INFO]
    errors = False
    for diagnostic in diagnostics:
        if order.index(diagnostic.severity) <= order.index(minimum):
            click.echo(diagnostic.format(), err=True)
        errors = errors or diagnostic.severity is Severity.ERROR
    return errors


def node_id_option(function: click.decorators.FC) -> click.decorators.FC:
    return click.option(
        "--node-id",
        type=click.IntRange(1, 127),
        help="Node-ID that $NODEID stands for (1-127); a DCF's own NodeID otherwise.",
    )(function)


def pins_option(function: click.decorators.FC) -> click.decorators.FC:
    return click.option(
        "--pins",
        "pin_file",
        type=click.Path(dir_okay=False),
        help="Pin file of identifiers (from `cantools-od ids`); default: FILE's stem + .ids.toml beside it.",
    )(function)


def identifiers_for(device: Device, file: str, pin_file: str | None) -> Identifiers:
    """The device's identifiers with its pins; a bad pin file exits with code 2."""
    from ..identifiers import assign, load_pins, pin_file_for

    path = pin_file_for(file, pin_file)
    try:
        return assign(device, load_pins(path) if path is not None else None)
    except OSError as error:
        click.echo(f"{path}: error: cannot read: {error.strerror or error}", err=True)
    except ValueError as error:
        click.echo(f"{path}: error: {error}", err=True)
    sys.exit(EXIT_USAGE)
