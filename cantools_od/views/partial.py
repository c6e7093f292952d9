"""What `gen --keep-going` generates when the input has errors: everything but what they touch."""

from __future__ import annotations

from dataclasses import replace

from ..model import Device
from .codegen import DeviceView


def without(device: Device, indices: set[int]) -> Device:
    """A shallow copy of `device` without the objects `indices`."""
    if not indices:
        return device
    kept = {index: obj for index, obj in device.objects.items() if index not in indices}
    return device.model_copy(update={"objects": kept})


def left_out_objects(device: Device, indices: set[int]) -> list[str]:
    """One line per object left out, `2000h Name`, for the output's header and the user."""
    lines = []
    for index in sorted(indices):
        obj = device.objects.get(index)
        lines.append(f"{index:04X}h {obj.name}" if obj is not None and obj.name else f"{index:04X}h")
    return lines


def without_failed_pdos(view: DeviceView) -> tuple[DeviceView, list[str]]:
    """The view without the PDOs it cannot generate code for, and one line per PDO left out."""
    kept = tuple(p for p in view.pdos if p.pdo.name not in view.failed_pdos)
    lines = [f"{name} (its packing code)" for name in sorted(view.failed_pdos)]
    return replace(view, pdos=kept, problems=(), failed_pdos=frozenset()), lines
