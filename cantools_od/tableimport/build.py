"""Merged objects → an ordinary Device, with provenance in origins and in EDS comments."""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass, field
from pathlib import Path

from ..model import (
    AccessType,
    Device,
    DeviceInfo,
    Diagnostic,
    DummyUsage,
    FileInfo,
    NodeIdExpr,
    Object,
    ObjectKind,
    Origin,
    Severity,
    SubObject,
    Value,
    Variable,
    standard_type,
)
from ..model.cia301.cobid import ALL_NODE_IDS, BASE_11BIT
from ..model.cia301.connections import predefined_cob_base
from ..model.cia301.objects import (
    FIRST_SDO_SERVER,
    IDENTITY,
    IDENTITY_PRODUCT_CODE,
    IDENTITY_REVISION,
    IDENTITY_VENDOR_ID,
    SDO_SERVERS,
)
from ..model.cia301.pdo import RX, TX, count_pdos, is_mapping
from ..model.datatypes import DOMAIN
from ..model.device import OBJECT_LISTS, object_lists_of
from .capacity import PROSE_CAPACITY
from .entries import loc
from .facts import Norm, Source
from .merge import Candidate, MergedEntry, MergedObject, MergeResult, Resolved, display

# canonical EDS key → merged field
KEY_FIELDS = {
    "ParameterName": "name",
    "ObjectType": "object_code",
    "DataType": "data_type",
    "AccessType": "access",
    "DefaultValue": "default",
    "LowLimit": "low",
    "HighLimit": "high",
    "PDOMapping": "pdo_mapping",
}


@dataclass
class BuildInfo:
    vendor_name: str | None = None
    product_name: str | None = None
    description: str = ""
    file_name: str = ""
    sources: list[str] = field(default_factory=list)
    comments: bool = True
    dummy_usage: dict[int, bool] | None = None
    baud_rates: dict[int, bool] = field(default_factory=dict)


def build(merged: MergeResult, info: BuildInfo) -> tuple[Device, list[Diagnostic]]:
    """The device, and diagnostics for values that could not go into an EDS."""
    problems: list[Diagnostic] = []
    device = Device()
    for index, obj in sorted(merged.objects.items()):
        built = _object(obj, info, problems)
        if built is not None:
            device.objects[index] = built
    _lists(device)
    device.file_info = FileInfo(
        file_name=info.file_name or None,
        file_version=1,
        file_revision=0,
        eds_version="4.0",
        description=(info.description or "Imported from vendor documentation")[:243],
        created_by="cantools-od import-table",
    )
    identity = device.objects.get(IDENTITY)
    name_obj = device.objects.get(0x1008)
    product = info.product_name
    if product is None and name_obj is not None and isinstance(name_obj.default, str):
        product = name_obj.default
    device.device_info = DeviceInfo(
        vendor_name=info.vendor_name,
        vendor_number=_identity(identity, IDENTITY_VENDOR_ID),
        product_name=product,
        product_number=_identity(identity, IDENTITY_PRODUCT_CODE),
        revision_number=_identity(identity, IDENTITY_REVISION),
        simple_boot_up_master=False,
        simple_boot_up_slave=True,
        granularity=8 if _dynamic_mapping(device) else 0,
        group_messaging=False,
        nr_of_rx_pdo=count_pdos(device.objects, RX),
        nr_of_tx_pdo=count_pdos(device.objects, TX),
        lss_supported=False,
    )
    device.device_info.baud_rates = dict(info.baud_rates)
    stated = info.dummy_usage is not None
    device.dummy_usage = DummyUsage(enabled={n: bool((info.dummy_usage or {}).get(n)) for n in range(1, 8)})
    if info.comments and not stated:
        device.dummy_usage.comments[""] = [
            "; dummy mapping support is not taken from the sources: set it in the overrides"
        ]
    if info.comments and info.sources:
        device.file_info.comments[""] = ["; Imported by cantools-od import-table from:"] + [
            f";   {source}" for source in info.sources
        ]
    return device, problems


def _identity(identity: Object | None, sub: int) -> int | None:
    if identity is None or sub not in identity.subs:
        return None
    value = identity.subs[sub].default
    return value if isinstance(value, int) and not isinstance(value, bool) and 0 <= value < 1 << 32 else None


def _dynamic_mapping(device: Device) -> bool:
    for index, obj in device.objects.items():
        if is_mapping(index) and any(sub.access is not None and sub.access.writable for sub in obj.subs.values()):
            return True
    return False


def _lists(device: Device) -> None:
    for name, listed in object_lists_of(device.objects).items():
        setattr(device, OBJECT_LISTS[name], listed)


def _object(obj: MergedObject, info: BuildInfo, problems: list[Diagnostic]) -> Object | None:
    name = _name(obj.fields.get("name"), f"Object {obj.index:04X}h")
    result = Object(index=obj.index, name=name, object_type=obj.kind)
    primary = _primary(obj.sources)
    if obj.kind in (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT):
        for sub, entry in sorted(obj.entries.items()):
            if sub > 254:
                problems.append(
                    _problem(
                        obj,
                        entry,
                        "IMP032",
                        f"{obj.index:04X}h sub-index {sub} is reserved "
                        "(FFh holds the object structure); not written to the EDS",
                    )
                )
                continue
            sub_obj = SubObject(name=_name(entry.fields.get("name"), f"Sub-index {sub}"))
            _fill(sub_obj, entry, obj, problems)
            sub_obj.origin = _origin(entry.fields, primary)
            if info.comments:
                sub_obj.comments = _comments(entry.fields, entry, None)
            result.subs[sub] = sub_obj
        result.sub_number = len(result.subs)
        result.origin = _origin({k: v for k, v in obj.fields.items() if k in ("name", "object_code")}, primary)
        if info.comments:
            result.comments = _comments(obj.fields, None, obj)
        return result
    entry = obj.entries.get(0, MergedEntry(0))
    _fill(result, entry, obj, problems)
    fields = {**entry.fields, **{k: v for k, v in obj.fields.items() if k in ("name", "object_code")}}
    result.origin = _origin(fields, primary)
    if info.comments:
        result.comments = _comments(fields, entry, obj)
    if obj.kind is ObjectKind.DOMAIN:
        result.data_type = DOMAIN.index
        result.default = None
        result.pdo_mapping = None
    return result


_ASCII = str.maketrans({"→": "->", "←": "<-", "μ": "u", "µ": "u", "°": "deg", "²": "2", "³": "3", "¹": "1"})


def _name(resolved: Resolved | None, fallback: str) -> str:
    if resolved is None or not isinstance(resolved.value, str) or not resolved.value.strip():
        return fallback
    text = resolved.value.strip().translate(_ASCII)
    text = text.encode("ascii", "replace").decode("ascii").replace("?", "_") if not text.isascii() else text
    return text[:241]


def _fill(var: Variable, entry: MergedEntry, obj: MergedObject, problems: list[Diagnostic]) -> None:
    dtype_res = entry.fields.get("data_type")
    if dtype_res is not None and isinstance(dtype_res.value, int) and not isinstance(dtype_res.value, bool):
        var.data_type = dtype_res.value
    elif obj.kind not in (ObjectKind.DOMAIN,):
        problems.append(
            _problem(obj, entry, "IMP031", f"{_where(obj, entry)}: no data type in any source; DataType left out")
        )
    access = entry.fields.get("access")
    if access is not None and isinstance(access.value, AccessType):
        var.access = access.value
    elif obj.kind is not ObjectKind.DOMAIN:
        problems.append(
            _problem(obj, entry, "IMP031", f"{_where(obj, entry)}: no access type in any source; AccessType left out")
        )
    mapping = entry.fields.get("pdo_mapping")
    if mapping is not None and isinstance(mapping.value, bool):
        var.pdo_mapping = mapping.value
    for field_name in ("default", "low", "high"):
        resolved = entry.fields.get(field_name)
        if resolved is None:
            continue
        value = _typed(resolved.value, var.data_type)
        if field_name == "default" and isinstance(value, int) and not isinstance(value, bool):
            relative = _node_relative(obj.index, entry.sub, value)
            if relative is not None:
                message = (
                    f"{_where(obj, entry)}: default 0x{value:X} is the COB-ID for node {value - relative.offset}; "
                    f"written as {relative.canonical()}"
                )
                problems.append(_problem(obj, entry, "IMP051", message, resolved.source))
                value = relative
        if value is None:
            problems.append(
                _problem(
                    obj,
                    entry,
                    "IMP050",
                    f"{_where(obj, entry)}: {field_name} {display(resolved.value, field_name)} does not fit "
                    f"{display(var.data_type, 'data_type') if var.data_type else 'an unknown type'}; left out",
                    resolved.source,
                )
            )
            continue
        setattr(var, {"default": "default", "low": "low_limit", "high": "high_limit"}[field_name], value)
    if var.low_limit is not None and var.high_limit is not None:
        dtype = standard_type(var.data_type)
        if dtype is None or not dtype.is_numeric:
            var.low_limit = var.high_limit = None


def _cob_base(index: int, sub: int) -> int | None:
    """The pre-defined connection set's base; every SDO server is read like the default one."""
    return predefined_cob_base(FIRST_SDO_SERVER if index in SDO_SERVERS else index, sub)


def _node_relative(index: int, sub: int, value: int) -> NodeIdExpr | None:
    """A default COB-ID printed for node 1 or node 127 (`0x601`, `0x27F`, `0x400001FF`) is `$NODEID+base`."""
    base = _cob_base(index, sub)
    if base is None:
        return None
    flags = value & ~BASE_11BIT
    for node in (ALL_NODE_IDS[-1], ALL_NODE_IDS[0]):
        if value & BASE_11BIT == base + node:
            return NodeIdExpr(offset=flags + base, text=f"0x{value:X}")
    return None


def _typed(value: Norm, type_index: int | None) -> Value | None:
    """The value as the entry's type holds it, or None when it cannot be."""
    dtype = standard_type(type_index)
    if isinstance(value, NodeIdExpr):
        return value if dtype is None or dtype.is_integer else None
    if dtype is None:
        return value if isinstance(value, (int, str)) and not isinstance(value, bool) else None
    kind = dtype.kind.value
    if kind in ("unsigned", "signed", "bool"):
        if isinstance(value, float) and value.is_integer():
            value = int(value)
        if not isinstance(value, int) or isinstance(value, bool):
            return None
        limits = dtype.int_range()
        if limits is not None and not limits[0] <= value <= limits[1]:
            return None
        return value
    if kind == "real":
        if isinstance(value, (int, float)) and not isinstance(value, bool) and math.isfinite(float(value)):
            return float(value)
        return None
    if kind == "string":
        text = str(value) if not isinstance(value, bytes) else None
        return text if text is not None and text.isascii() and text.isprintable() else None
    if kind == "octets":
        return value if isinstance(value, bytes) else None
    return None


def _where(obj: MergedObject, entry: MergedEntry | None) -> str:
    if entry is None or obj.kind not in (ObjectKind.ARRAY, ObjectKind.RECORD, ObjectKind.DEFSTRUCT):
        return f"{obj.index:04X}h"
    return f"{obj.index:04X}h sub {entry.sub}"


def _problem(
    obj: MergedObject, entry: MergedEntry | None, code: str, message: str, source: Source | None = None
) -> Diagnostic:
    where = source or _primary(obj.sources)
    location = loc(where.file, where.line) if where is not None else loc("", 0)
    severity = Severity.INFO if code == "IMP051" else Severity.WARNING
    return Diagnostic(code=code, severity=severity, message=message, location=location)


def _primary(sources: list[Source]) -> Source | None:
    real = [s for s in sources if s.line > 0]
    if not real:
        return None
    return max(real, key=lambda s: (int(s.kind), -s.line))


def _origin(fields: dict[str, Resolved], primary: Source | None) -> Origin | None:
    if primary is None:
        return None
    keys: dict[str, tuple[int, int, int]] = {}
    for key, field_name in KEY_FIELDS.items():
        resolved = fields.get(field_name)
        source = resolved.source if resolved is not None else None
        if source is not None and source.file == primary.file and source.line > 0:
            keys[key] = (source.line, 1, 1)
    return Origin(file=primary.file, line=primary.line, column=1, keys=keys)


def _comments(fields: dict[str, Resolved], entry: MergedEntry | None, obj: MergedObject | None) -> dict[str, list[str]]:
    """`; from manual.txt:1507 (layout)` above each key; conflicts and inferred values say so."""
    out: dict[str, list[str]] = {}
    if obj is not None:
        out[""] = [part for text in _places(obj.sources) for part in _wrap(f"; source: {text}")]
    for key, field_name in KEY_FIELDS.items():
        resolved = fields.get(field_name)
        if resolved is None:
            continue
        lines = []
        source = resolved.source
        if resolved.inferred and source is not None and source.layout == PROSE_CAPACITY:
            lines.append(f"; inferred from the capacity stated at {source.short()}")
        elif resolved.inferred:
            lines.append("; inferred from CiA 301 (no source states it)")
        else:
            where = _from(resolved)
            if where:
                lines.append(f"; from {where}")
            if resolved.conflict is not None:
                others = [
                    f"{display(c.value, field_name)} ({_sources(c)})"
                    for i, c in enumerate(resolved.conflict.candidates)
                    if i != resolved.conflict.chosen
                ]
                lines.append(
                    f"; conflict, resolved by {resolved.conflict.resolution}; also stated: {'; '.join(others)}"
                )
            elif resolved.note and resolved.facts and resolved.facts[0].source.kind.name == "OVERRIDE":
                lines.append(f"; override: {resolved.note}")
        if lines:
            out[key] = [part for line in lines for part in _wrap(line)]
    return out


def _wrap(comment: str) -> list[str]:
    """A comment as lines of at most 200 characters (CiA 306 allows 255 a line)."""
    text = " ".join(comment.split())
    parts = textwrap.wrap(text[1:].strip(), 196, break_long_words=True) or [""]
    return [f"; {parts[0]}"] + [f";   {part}" for part in parts[1:]]


def _sources(candidate: Candidate) -> str:
    shown = [f"{_short(s.file)}:{s.line}" for s in candidate.sources[:3] if s.line]
    return ", ".join(shown) or "structure"


def _from(resolved: Resolved) -> str:
    """`000_x.txt:1510,1517; 001_y.txt:2844`"""
    by_file: dict[str, set[int]] = {}
    for fact in resolved.facts:
        if fact.source.line > 0:
            by_file.setdefault(fact.source.file, set()).add(fact.source.line)
    parts = []
    for file, lines in by_file.items():
        shown = sorted(lines)
        text = ",".join(str(n) for n in shown[:8]) + (",..." if len(shown) > 8 else "")
        parts.append(f"{_short(file)}:{text}")
    return "; ".join(parts)


def _places(sources: list[Source]) -> list[str]:
    """`000_x.txt: 466 (table), 1496-1518 (object block)`, one line per file."""
    by_file: dict[str, dict[str, list[int]]] = {}
    for source in sources:
        if source.line > 0:
            layout = source.layout.replace(" heading", "")
            by_file.setdefault(source.file, {}).setdefault(layout, []).append(source.line)
    out = []
    for file, layouts in by_file.items():
        parts = [f"{_ranges(sorted(set(lines)))} ({layout})" for layout, lines in layouts.items()]
        out.append(f"{_short(file)}: {', '.join(parts)}")
    return out


def _ranges(lines: list[int]) -> str:
    spans: list[list[int]] = []
    for line in lines:
        if spans and line - spans[-1][1] <= 2:
            spans[-1][1] = line
        else:
            spans.append([line, line])
    return " ".join(f"{a}" if a == b else f"{a}-{b}" for a, b in spans)


def _short(file: str) -> str:
    return Path(file).name if file else "overrides"
