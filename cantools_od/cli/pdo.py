"""`cantools-od pdo`: the PDO map, drawn or as JSON."""

from __future__ import annotations

import json
import sys

import click

from .common import (
    EXIT_FINDINGS,
    EXIT_OK,
    EXIT_USAGE,
    identifiers_for,
    node_id_option,
    pins_option,
    read_device,
    report,
)


@click.command(name="pdo")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option("--format", "fmt", type=click.Choice(["text", "json"]), default="text", show_default=True)
@node_id_option
@pins_option
def command(file: str, fmt: str, node_id: int | None, pin_file: str | None) -> None:
    """Show the PDOs FILE configures, from its default (or DCF) values: drawn bit by bit, or as
    JSON (--format json)."""
    from ..model import NodeIdExpr
    from ..views.layout import draw
    from ..views.pdo import pdo_map

    device = read_device(file, node_id)
    errors = report(device.diagnostics)
    pdos = pdo_map(device, identifiers=identifiers_for(device, file, pin_file))
    if fmt == "json":
        symbolic = [p.name for p in pdos if isinstance(p.cob_id, NodeIdExpr)]
        if symbolic:
            click.echo(f"{file}: error: COB-IDs of {', '.join(symbolic)} use $NODEID: give --node-id", err=True)
            sys.exit(EXIT_USAGE)
        data = {
            "pdos": [
                {
                    "direction": p.direction,
                    "number": p.number,
                    "cob_id": p.cob_id,
                    "transmission_type": p.transmission_type,
                    "entries": [
                        {
                            "index": e.index,
                            "subindex": e.subindex,
                            "name": e.name,
                            "data_type": e.data_type_name,
                            "bit_offset": e.bit_offset,
                            "bit_length": e.bit_length,
                            "identifier": e.identifier,
                        }
                        for e in p.entries
                    ],
                }
                for p in pdos
            ]
        }
        click.echo(json.dumps(data, indent=2))
    else:
        for p in pdos:
            cob = (
                p.cob_id.canonical()
                if isinstance(p.cob_id, NodeIdExpr)
                else (f"0x{p.cob_id:X}" if p.cob_id is not None else "-")
            )
            click.echo(
                f"{p.name} ({p.comm_index:04X}/{p.map_index:04X})  COB-ID {cob}"
                f"  transmission type {p.transmission_type if p.transmission_type is not None else '-'}"
                f"  {p.bit_length} bits"
            )
            for e in p.entries:
                click.echo(
                    f"  {e.index:04X}sub{e.subindex:X}  bits {e.bit_offset:>3}-{e.bit_offset + e.bit_length - 1:<3}"
                    f"  {e.data_type_name:<14} {e.label}"
                )
            if p.entries:
                click.echo(draw(p))
            click.echo()
    sys.exit(EXIT_FINDINGS if errors else EXIT_OK)
