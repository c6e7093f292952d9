"""Whether `lint --fix` changes what a reader sees: every safe fix of a file applied (per code, and all together), the
written file read again by python-canopen, lely's dcfchk and our own reader, and each reading compared with the one
of the original. A safe fix may change no entry's name, type, access, default, value, limits or mapping flag in any
reader, nor make dcfchk refuse a file it accepted; [DeviceInfo] may change only to what 1018h states (EDS040).
An XDD is judged through its EDS form (python-canopen and dcfchk read no XDD)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

import canopen
from peermatrix import Dcfchk, canopen_od, canopen_reading, differences, quiet
from sharedcache import cached_for_file

from cantools_od.api import dumps, format_for, load
from cantools_od.lint import LintOptions, lint
from cantools_od.model import Device

_INFO = ("vendor_number", "product_number", "revision_number", "vendor_name", "product_name", "nr_of_RXPDO",
         "nr_of_TXPDO", "granularity")  # fmt: skip
_IDENTITY = {"vendor_number": 1, "product_number": 2, "revision_number": 3}
_MODEL = ("name", "data_type", "access", "default", "low_limit", "high_limit", "pdo_mapping", "parameter_value")


@dataclass(frozen=True)
class Change:
    file: str
    codes: str  # the fixes applied: one code, or "all"
    reader: str
    what: str

    def __str__(self) -> str:
        return f"{self.file}: fixes of {self.codes}: {self.reader}: {self.what}"


def _model(device: Device) -> dict[tuple[int, int, str], Any]:
    out: dict[tuple[int, int, str], Any] = {}
    for index, obj in device.objects.items():
        out[(index, -1, "name")] = obj.name
        for subindex, var in obj.subs.items() if obj.subs else [(0, obj)]:
            for name in _MODEL:
                out[(index, subindex, name)] = str(getattr(var, name))
    return out


def _info(path: Path) -> dict[str, Any] | None:
    """python-canopen's [DeviceInfo] and 1018h of the file; made once a run for the same bytes."""
    return cached_for_file("python-canopen-info", path, (canopen.__version__,), lambda: _read_info(path))


def _read_info(path: Path) -> dict[str, Any] | None:
    od = canopen_od(path)
    if isinstance(od, str):
        return None
    identity = od.get(0x1018) if 0x1018 in od else None
    out = {name: getattr(od.device_information, name, None) for name in _INFO}
    for name, subindex in _IDENTITY.items():
        sub = identity.subindices.get(subindex) if identity is not None and hasattr(identity, "subindices") else None
        truth = None if sub is None else sub.value  # a DCF's ParameterValue: the device's own
        out[f"1018h:{name}"] = truth
    return out


def _as_eds(path: Path, folder: Path, device: Device, name: str) -> Path:
    """The file a peer reads: the written file itself, or the EDS form of an XDD."""
    target = folder / name
    fmt = format_for(path)
    target.write_bytes(dumps(device, fmt) if fmt in ("eds", "dcf") else dumps(device, "eds"))
    return target


def _fixes(device: Device) -> tuple[dict[str, list[Any]], set[tuple[str, bool]]]:
    """The safe fixes of the device's findings by code, and every (code, safe) its fixes show."""
    by_code: dict[str, list[Any]] = {}
    seen: set[tuple[str, bool]] = set()
    for finding in lint(device, LintOptions()):
        if finding.fix is not None:
            seen.add((finding.code, finding.fix.safe))
            if finding.fix.safe:
                by_code.setdefault(finding.code, []).append(finding.fix)
    return by_code, seen


def judge_fixes(path: Path, folder: Path) -> tuple[list[Change], set[tuple[str, bool]]]:
    """Every change a reader sees after all the file's safe fixes (then, to name the culprit, after each code's
    alone), and the (code, safe) pairs its fixes show."""
    folder.mkdir(parents=True, exist_ok=True)
    device = load(path)
    groups, seen = _fixes(device)
    if not groups:
        return [], seen
    original = _as_eds(path, folder, device, "original" + (path.suffix if path.suffix in (".eds", ".dcf") else ".eds"))
    before = (_readings(original), _info(original), Dcfchk(original).verdict(), _model(device))
    changes = _changes(path, folder, before, "all", original.suffix)
    if changes and len(groups) > 1:
        changes = [c for code in sorted(groups) for c in _changes(path, folder, before, code, original.suffix)]
    return changes, seen


def _changes(path: Path, folder: Path, before: tuple[Any, ...], codes: str, suffix: str) -> list[Change]:
    fixed = load(path)
    chosen = _fixes(fixed)[0]
    for fix in chosen.get(codes, []) if codes != "all" else [f for fixes in chosen.values() for f in fixes]:
        fix.apply(fixed)
    return _compare(path.name, codes, before, _as_eds(path, folder, fixed, f"{codes}{suffix}"))


def _readings(path: Path) -> dict[int | None, Any]:
    """python-canopen's reading without a node-ID and with one ($NODEID values read then)."""
    return {node_id: canopen_reading(path, node_id) for node_id in (None, 5)}


def _compare(name: str, codes: str, before: tuple[Any, ...], written: Path) -> list[Change]:
    readings, info, verdict, model = before
    out: list[Change] = []
    for node_id, reading in readings.items():
        if isinstance(reading, str):
            continue
        peer = f"python-canopen (node-ID {node_id})"
        after = canopen_reading(written, node_id)
        if isinstance(after, str):
            out.append(Change(name, codes, peer, f"no longer reads the file: {after}"))
        else:
            out += [Change(name, codes, peer, str(d)) for d in differences(reading, after)]
    if info is not None:
        after_info = _info(written) or {}
        for key, value in info.items():
            new = after_info.get(key)
            truth = after_info.get(f"1018h:{key}")
            if new != value and not (key in _IDENTITY and new == truth):
                out.append(Change(name, codes, "python-canopen [DeviceInfo]", f"{key}: {value!r} -> {new!r}"))
    if verdict is None:
        with quiet():
            now = Dcfchk(written).verdict()
        if now is not None:
            out.append(Change(name, codes, "dcfchk", f"accepted the original, not this: {now}"))
    reread = load(written) if written.suffix in (".eds", ".dcf") else None
    if reread is not None:
        again = _model(reread)
        for key in sorted(model.keys() | again.keys(), key=str):
            if model.get(key) != again.get(key):
                out.append(Change(name, codes, "cantools-od", f"{key}: {model.get(key)} -> {again.get(key)}"))
    return out
