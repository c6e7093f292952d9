"""`cantools-od simulate`: serve the node a description describes on a CAN bus until Ctrl-C."""

from __future__ import annotations

import sys
import threading
from typing import TYPE_CHECKING, Any

import click

from .canbus import bus_options, connected, terminate_as_interrupt
from .common import EXIT_OK, EXIT_USAGE, node_id_option, read_device

if TYPE_CHECKING:
    from ..live.bus import BusOptions
    from ..live.simulator import Simulator

POLL = 0.5  # how often the bus is checked for a failure of its receiving thread


@click.command(name="simulate")
@click.argument("file", type=click.Path(dir_okay=False))
@node_id_option
@bus_options
@click.option(
    "--script",
    type=click.Path(dir_okay=False, exists=True),
    help="Python file whose setup(node) is called once the node runs (see docs/simulate.md).",
)
@click.option("--duration", type=click.FloatRange(0, min_open=True), help="Stop after this many seconds.")
def command(
    file: str,
    node_id: int | None,
    bus: BusOptions,
    script: str | None,
    duration: float | None,
) -> None:
    """Serve the node FILE (EDS, DCF, XDD, XDC or JSON) describes on a CAN bus: boot-up, NMT, heartbeat (1017h),
    SDO server with CiA 301 abort codes, PDOs, EMCY from a script. Values are ParameterValue (a DCF), else
    DefaultValue. Runs until Ctrl-C (exit 0); exit 2 when the bus cannot be used."""
    from ..live.simulator import CannotServe, Simulator

    device = read_device(file, node_id)
    nid = node_id if node_id is not None else device.node_id
    if nid is None:
        click.echo(f"{file}: error: no node-ID: give --node-id", err=True)
        sys.exit(EXIT_USAGE)
    setup = _script_setup(script) if script else None
    try:
        with terminate_as_interrupt(), connected(bus, "simulate") as network:
            try:
                simulator = Simulator(device, nid, network)
            except CannotServe as error:
                click.echo(f"{file}: error: {error}", err=True)
                sys.exit(EXIT_USAGE)
            objects, entries = simulator.served()
            serving = f"node {nid} from {file} ({objects} objects, {entries} entries) on {bus.describe()}"
            status = _serve(simulator, setup, duration, serving)
    except KeyboardInterrupt:  # before the node ran, or while the bus closed: nothing more to stop
        status = EXIT_OK
    if status == EXIT_OK:
        click.echo("simulate: stopped", err=True)
    sys.exit(status)


def _serve(simulator: Simulator, setup: Any, duration: float | None, serving: str) -> int:
    """Boot the node, say what it serves, and serve until Ctrl-C, the duration, or a failure of the bus or the
    script (exit 2)."""
    stopped = threading.Event()
    try:
        simulator.start()
        if setup is not None:
            setup(simulator)
        click.echo(f"simulate: {serving}; Ctrl-C stops", err=True)
        waited = 0.0
        while duration is None or waited < duration:
            step = POLL if duration is None else min(POLL, duration - waited)
            stopped.wait(step)
            waited += step
            simulator.network.check()
    except KeyboardInterrupt:
        return EXIT_OK
    except Exception as error:  # the bus or the script failed: one line, never a traceback
        click.echo(f"simulate: error: {_reason(error)}", err=True)
        return EXIT_USAGE
    finally:
        simulator.stop()
    return EXIT_OK


def _script_setup(path: str) -> Any:
    """The script's setup(node) function; a script that cannot run exits 2 with one line."""
    import runpy

    try:
        names = runpy.run_path(path)
    except Exception as error:
        click.echo(f"{path}: error: the script failed: {_reason(error)}", err=True)
        sys.exit(EXIT_USAGE)
    setup = names.get("setup")
    if not callable(setup):
        click.echo(f"{path}: error: the script defines no setup(node) function", err=True)
        sys.exit(EXIT_USAGE)
    return setup


def _reason(error: BaseException) -> str:
    return " ".join(str(error).split()) or type(error).__name__
