"""What `gen --keep-going` generates when the input has errors: everything but what they touch."""

from __future__ import annotations

from dataclasses import replace

from ..model import Device, Diagnostic, Location, NodeIdExpr, Object, Severity, Variable
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


def unfit_values(device: Device) -> dict[int, list[Diagnostic]]:
    """The objects with a default, DCF value or limit their data type cannot hold (70000 for an
    UNSIGNED16, 1e39 for a REAL32), each with GEN001 errors saying what: generated code has no
    spelling for such a value, so it is left out with an error, never as a silent gap."""
    found: dict[int, list[Diagnostic]] = {}
    for index, obj in device.objects.items():
        for subindex, var in obj.subs.items() if obj.has_subs else [(0, obj)]:
            for key, problem in _unfit(device, obj, var):
                label = f"{index:04X}h" + (f"sub{subindex}" if obj.has_subs else "")
                origin = var.origin or obj.origin
                at = origin.where(key) if origin is not None else None
                where = Location(file=device.source, line=at[0], column=at[2]) if at else Location(file=device.source)
                message = f"cannot generate {label} {key}: {problem}"
                found.setdefault(index, []).append(
                    Diagnostic(code="GEN001", severity=Severity.ERROR, message=message, location=where)
                )
    return found


def _unfit(device: Device, obj: Object, var: Variable) -> list[tuple[str, str]]:
    dtype = device.entry_type(var, obj)
    if dtype is None or not dtype.is_numeric:
        return []
    problems = []
    keys = ("DefaultValue", "ParameterValue", "LowLimit", "HighLimit")
    for key, value in zip(keys, (var.default, var.parameter_value, var.low_limit, var.high_limit), strict=True):
        # $NODEID values are checked at the node-IDs 1 and 127 that bound them
        numbers = [value.resolve(1), value.resolve(127)] if isinstance(value, NodeIdExpr) else [value]
        for number in numbers:
            problem = dtype.number_problem(number) if isinstance(number, (int, float)) else None
            if problem is not None:
                problems.append((key, problem))
                break
    return problems
