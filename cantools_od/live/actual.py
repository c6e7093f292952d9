"""The device as read: its description with each value read as ParameterValue, as a DCF for its node-ID
(`probe -o actual.dcf`: a commissioning backup, or the newer side of a `diff`)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..model.cia301.slots import slot
from ..model.device import Commissioning
from ..model.wire import decoded

if TYPE_CHECKING:
    from ..model import Device
    from .judge import Reading


def actual_device(device: Device, node_id: int, readings: list[Reading]) -> Device:
    """A copy of `device` holding the values read (the entries not read keep what the file gives)."""
    actual = device.model_copy(deep=True)
    actual._original = device._original
    for reading in readings:
        found = slot(actual, reading.index, reading.subindex)
        if reading.data is None or found is None:
            continue
        dtype = actual.entry_type(found.var, found.owner)
        if dtype is not None:
            found.var.parameter_value = decoded(dtype.kind, reading.data)
    actual.node_id = node_id
    if actual.commissioning is None:
        actual.commissioning = Commissioning()
    actual.commissioning.node_id = node_id
    return actual
