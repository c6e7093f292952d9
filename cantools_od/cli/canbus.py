"""The CAN bus options `probe` and `simulate` share, named as python-can names them."""

from __future__ import annotations

import contextlib
import functools
import signal
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import TYPE_CHECKING, Any

import click

from .common import EXIT_USAGE

if TYPE_CHECKING:
    import canopen

    from ..live.bus import BusOptions

RECEIVE_CYCLE = 0.1  # seconds the receiving thread waits per turn: how long stopping it takes at most
EXIT_INTERRUPTED = 130  # 128 + SIGINT, as a shell reports a command Ctrl-C stopped


def bus_options(function: Callable[..., None]) -> Callable[..., None]:
    """--interface, --channel, --bitrate, given to the command as one `bus` (BusOptions); what is not given
    comes from python-can's configuration."""

    @functools.wraps(function)
    def command(interface: str | None, channel: str | None, bitrate: int | None, **rest: Any) -> None:
        from ..live.bus import BusOptions

        function(bus=BusOptions(interface, channel, bitrate), **rest)

    options = (
        click.option("-i", "--interface", help="python-can interface: socketcan, pcan, kvaser, vector, slcan, ..."),
        click.option("-c", "--channel", help="Channel of the interface: can0, PCAN_USBBUS1, ..."),
        click.option("-b", "--bitrate", type=click.IntRange(1), help="Bit rate in bit/s (500000)."),
    )
    for option in reversed(options):
        command = option(command)
    return command


@contextmanager
def connected(options: BusOptions, command: str) -> Iterator[canopen.Network]:
    """A python-canopen network on the bus; a bus that cannot be opened exits 2 with one line. Disconnected
    on the way out, however the command ends."""
    import canopen

    from ..live.bus import BusError, open_bus

    try:
        bus = open_bus(options)
    except BusError as error:
        click.echo(f"{command}: error: {error}", err=True)
        sys.exit(EXIT_USAGE)
    network = canopen.Network(bus)
    network.NOTIFIER_CYCLE = RECEIVE_CYCLE
    listeners: list[Any] = network.listeners  # python-can's listeners; python-canopen annotates its own only
    listeners.append(_ReceiveFailure())
    try:
        network.connect()
        yield network
    finally:
        _disconnect(network)


class _ReceiveFailure:
    """Told when python-can's receiving thread fails: the failure is kept for `Network.check`, which the
    commands call and report in one line, instead of python-can raising it again in its thread (a traceback)."""

    def on_message_received(self, message: object) -> None:
        """Frames are python-canopen's listener's business."""

    __call__ = on_message_received  # what python-can's notifier calls, as its own Listener class does

    def on_error(self, error: Exception) -> None:
        """Handled: the notifier keeps it as its `exception`."""

    def stop(self) -> None:
        """Nothing to release."""


def _disconnect(network: canopen.Network) -> None:
    network.NOTIFIER_SHUTDOWN_TIMEOUT = 2.0
    with contextlib.suppress(Exception):  # the bus already failed: the command said why, nothing left to release
        network.disconnect()


@contextmanager
def terminate_as_interrupt() -> Iterator[None]:
    """SIGTERM (a service manager, `kill`) ends the command as Ctrl-C does: cleanly, through KeyboardInterrupt."""

    def interrupt(signum: int, frame: object) -> None:
        raise KeyboardInterrupt

    previous = signal.signal(signal.SIGTERM, interrupt)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, previous)
