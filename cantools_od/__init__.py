"""cantools-od: read, check and generate code from CANopen object dictionaries."""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

__version__ = "0.1.0"

if TYPE_CHECKING:
    from .api import dumps, load, loads, save
    from .changes import diff
    from .interop import to_canopen
    from .model import Device

__all__ = ["Device", "__version__", "diff", "dumps", "load", "loads", "save", "to_canopen"]


def __getattr__(name: str) -> Any:
    # Lazy, so that `cantools-od --version` does not pay for pydantic.
    if name in ("dumps", "load", "loads", "save"):
        from . import api

        return getattr(api, name)
    if name == "to_canopen":
        from .interop import to_canopen

        return to_canopen
    if name == "diff":
        from .changes import diff

        return diff
    if name == "Device":
        from .model import Device

        return Device
    raise AttributeError(name)
