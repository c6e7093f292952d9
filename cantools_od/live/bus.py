"""The CAN bus, opened as python-can users configure one: the options given, else python-can's own
configuration file (~/.canrc, can.ini) and environment (CAN_INTERFACE, CAN_CHANNEL, CAN_BITRATE)."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any, NamedTuple

if TYPE_CHECKING:
    import can


class BusError(Exception):
    """The bus cannot be opened or used; the message is one line saying why."""


class BusOptions(NamedTuple):
    interface: str | None = None
    channel: str | None = None
    bitrate: int | None = None

    def arguments(self) -> dict[str, Any]:
        """What python-can is given: only the options set, so that its configuration supplies the rest."""
        return {key: value for key, value in self._asdict().items() if value is not None}

    def describe(self) -> str:
        given = self.arguments()
        return " ".join(f"{key}={value}" for key, value in given.items()) or "python-can's configuration"


def open_bus(options: BusOptions) -> can.BusABC:
    """The bus; `BusError` with python-can's reason when it cannot be opened."""
    import can

    try:
        bus: can.BusABC = can.Bus(**options.arguments())
    except can.CanInterfaceNotImplementedError as error:
        if "interface" not in options.arguments() and "None" in str(error):
            raise BusError(
                "no CAN interface: give --interface (and --channel), or configure python-can (CAN_INTERFACE, ~/.canrc)"
            ) from error
        raise BusError(f"cannot open the CAN bus ({options.describe()}): {_reason(error)}") from error
    except (can.CanError, OSError, ValueError, ImportError, NotImplementedError, RuntimeError, TypeError) as error:
        raise BusError(f"cannot open the CAN bus ({options.describe()}): {_reason(error)}") from error
    return bus


def _reason(error: BaseException) -> str:
    text = " ".join(str(error).split())
    return text or type(error).__name__
