"""`cantools-od probe`: read a live node over SDO against its description, report as lint does."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING, NoReturn

import click

from .canbus import EXIT_INTERRUPTED, bus_options, connected, terminate_as_interrupt
from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Output, Progress, node_id_option, read_device, write_outputs

if TYPE_CHECKING:
    from ..lint import Finding
    from ..live.bus import BusOptions
    from ..live.probe import Prober, ProbeResult
    from ..model import Device


@click.command(name="probe")
@click.argument("file", type=click.Path(dir_okay=False))
@node_id_option
@bus_options
@click.option(
    "--format", "fmt", type=click.Choice(["text", "json", "sarif", "github"]), default="text", show_default=True
)
@click.option(
    "--timeout", type=click.FloatRange(0, min_open=True), default=1.0, show_default=True,
    help="Seconds each SDO request waits for its response.",
)  # fmt: skip
@click.option(
    "--wait", type=click.FloatRange(0), default=0.0, show_default=True,
    help="Seconds to wait for the node to answer at all (a node still booting).",
)  # fmt: skip
@click.option("--check-writes", is_flag=True, help="Write each writable entry back with the value just read.")
@click.option("-o", "--output", type=Output(dir_okay=False), help="Write the values read as a DCF (or .json).")
def command(
    file: str,
    node_id: int | None,
    bus: BusOptions,
    fmt: str,
    timeout: float,
    wait: float,
    check_writes: bool,
    output: str | None,
) -> None:
    """Read every entry FILE (EDS, DCF, XDD, XDC or JSON) lists from the live node over SDO and report where they
    differ (the PRB codes of `cantools-od rules`). Writes nothing unless --check-writes (the value just
    read, back). Exit 0 without errors, 1 with errors, 2 when the bus cannot be used or the node does not
    answer, 130 on Ctrl-C."""
    from ..live.probe import ProbeOptions, Prober

    device = read_device(file, node_id)
    nid = node_id if node_id is not None else device.node_id
    if nid is None:
        click.echo(f"{file}: error: no node-ID: give --node-id", err=True)
        sys.exit(EXIT_USAGE)
    options = ProbeOptions(timeout=timeout, wait=wait, check_writes=check_writes)
    try:
        with terminate_as_interrupt(), connected(bus, "probe") as network:
            result = _run(Prober(device, nid, network, options))
    except KeyboardInterrupt:  # before the first read, or while the bus closed: nothing was read or changed
        click.echo("probe: interrupted; nothing was changed", err=True)
        sys.exit(EXIT_INTERRUPTED)
    findings = result.findings
    from ..lint.output import render

    click.echo(render(fmt, findings, 1), nl=False)
    click.echo(_summary(nid, result, findings), err=True)
    if output:
        _write(device, nid, result, Path(output))
    from ..lint import has_errors

    sys.exit(EXIT_FINDINGS if has_errors(findings) else EXIT_OK)


def _run(prober: Prober) -> ProbeResult:
    """The probe, with a count on a terminal; no answer, a bus failure or Ctrl-C end it with one line."""
    import can

    from ..live.probe import NoAnswer

    entries = len(prober.entries())
    progress = Progress("probe", entries)
    try:
        result = prober.run(lambda label: progress.step(label))
    except KeyboardInterrupt:
        prober.interrupted()
        progress.clear()
        done = len(prober.result.readings)
        click.echo(f"probe: interrupted after {done} of {entries} entries; nothing was changed", err=True)
        sys.exit(EXIT_INTERRUPTED)
    except NoAnswer as error:
        progress.clear()
        _bus_failed(prober)  # no answers because nothing is received any more
        click.echo(f"probe: error: {error}", err=True)
        sys.exit(EXIT_USAGE)
    except (can.CanError, OSError) as error:
        progress.clear()
        _say_bus_failed(error)
    progress.clear()
    return result


def _bus_failed(prober: Prober) -> None:
    """When python-can's receiving thread failed: say so (one line, exit 2)."""
    try:
        prober.node.network.check()
    except Exception as error:
        _say_bus_failed(error)


def _say_bus_failed(error: BaseException) -> NoReturn:
    reason = " ".join(str(error).split()) or type(error).__name__
    click.echo(f"probe: error: the CAN bus failed: {reason}", err=True)
    sys.exit(EXIT_USAGE)


def _summary(node_id: int, result: ProbeResult, findings: list[Finding]) -> str:
    skipped = f", {result.skipped} not read (write-only or DOMAIN)" if result.skipped else ""
    return (
        f"probe: node {node_id}: {result.read} entries read in {result.seconds:.1f} s "
        f"({result.transfers} SDO transfers{skipped}), {len(findings)} finding{'s' if len(findings) != 1 else ''}"
    )


def _write(device: Device, node_id: int, result: ProbeResult, path: Path) -> None:
    from ..api import dumps, format_for
    from ..live.actual import actual_device

    actual = actual_device(device, node_id, result.readings)
    written = write_outputs([(path, dumps(actual, format_for(path), style="canonical"))])
    if written:
        click.echo(f"probe: wrote {path}", err=True)
