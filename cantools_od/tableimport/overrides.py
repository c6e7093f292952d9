"""The overrides file (TOML): resolve conflicts, correct values, exclude objects, explain lint findings.

[policy]
prefer = "detail"              # detail | summary | first | last

[device]
vendor_name = "Elmo Motion Control"
product_name = "SimplIQ"

[exclude]
"0x2030" = "the manual removed it from its EDS (000:2746)"

[objects."0x1000"]              # the object, or a VAR's value
default = "0x00020192"
reason = "SDO example reads 0x00020192 (000:768)"

[objects."0x1A00-0x1A03".sub.0] # an entry; index and sub-index ranges allowed
access = "rw"
reason = "the remapping procedure writes sub-index 0 (000:988)"

[objects."0x1400-0x1403"]
prefer = "summary"             # this object's conflicts by another policy

[lint]                          # why remaining lint findings are acceptable
PDO012 = "..."
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass, field
from typing import Any

from ..model import Diagnostic, Severity
from .entries import Kind, loc
from .facts import Norm, Source
from .merge import POLICIES, MergeOptions, Override, Policy
from .notation import parse_access, parse_index, parse_mapping, parse_object_code, parse_sub, parse_type

ENTRY_FIELDS = ("data_type", "access", "pdo_mapping", "default", "low", "high")
OBJECT_FIELDS = ("name", "object_code")
ALIASES = {
    "type": "data_type",
    "datatype": "data_type",
    "accesstype": "access",
    "pdomapping": "pdo_mapping",
    "mapping": "pdo_mapping",
    "defaultvalue": "default",
    "lowlimit": "low",
    "highlimit": "high",
    "objecttype": "object_code",
    "parametername": "name",
}


@dataclass
class Overrides:
    options: MergeOptions = field(default_factory=MergeOptions)
    vendor_name: str | None = None
    product_name: str | None = None
    lint: dict[str, str] = field(default_factory=dict)
    dummy_usage: dict[int, bool] | None = None
    baud_rates: dict[int, bool] = field(default_factory=dict)
    diagnostics: list[Diagnostic] = field(default_factory=list)
    path: str = ""

    @property
    def ok(self) -> bool:
        return not any(d.severity is Severity.ERROR for d in self.diagnostics)


def load_overrides(path: str, data: bytes) -> Overrides:
    out = Overrides(path=path)
    try:
        doc = tomllib.loads(data.decode("utf-8"))
    except (tomllib.TOMLDecodeError, UnicodeDecodeError) as error:
        line = _error_line(str(error))
        out.diagnostics.append(_diag(path, line, "IMP003", f"overrides file is not valid TOML: {error}"))
        return out
    lines = _line_index(data.decode("utf-8"))
    policy = doc.get("policy", {})
    if isinstance(policy, dict) and "prefer" in policy:
        if policy["prefer"] in POLICIES:
            out.options.policy = policy["prefer"]
        else:
            out.diagnostics.append(
                _diag(path, lines.get("prefer", 0), "IMP003", f"[policy] prefer must be one of {', '.join(POLICIES)}")
            )
    device = doc.get("device", {})
    if isinstance(device, dict):
        out.vendor_name = _str(device.get("vendor_name"))
        out.product_name = _str(device.get("product_name"))
        dummies = device.get("dummy_usage")
        if isinstance(dummies, list):
            out.dummy_usage = {n: n in [int(str(d), 0) for d in dummies] for n in range(1, 8)}
        rates = device.get("baud_rates")
        if isinstance(rates, list):
            out.baud_rates = {
                rate: int(rate) in [int(r) for r in rates] for rate in (10, 20, 50, 125, 250, 500, 800, 1000)
            }
    lint = doc.get("lint", {})
    if isinstance(lint, dict):
        out.lint = {str(k): str(v) for k, v in lint.items()}
    exclude = doc.get("exclude", {})
    if isinstance(exclude, dict):
        for key, reason in exclude.items():
            spec = parse_index(key, bare=True)
            if spec is None:
                out.diagnostics.append(_diag(path, lines.get(key, 0), "IMP003", f"[exclude] {key!r} is not an index"))
                continue
            for index in spec.indices():
                out.options.exclude[index] = str(reason)
    objects = doc.get("objects", {})
    if isinstance(objects, dict):
        for key, table in objects.items():
            _object_table(out, path, lines, key, table)
    return out


def _object_table(out: Overrides, path: str, lines: dict[str, int], key: str, table: Any) -> None:
    where = f"objects.{key}".replace(" ", "")
    line = lines.get(where, lines.get(key, 0))
    spec = parse_index(key, bare=True)
    if spec is None or not isinstance(table, dict):
        out.diagnostics.append(_diag(path, line, "IMP003", f"[objects.{key!r}] does not name an index"))
        return
    reason = str(table.get("reason", ""))
    prefer = table.get("prefer")
    if prefer is not None:
        if prefer not in POLICIES:
            out.diagnostics.append(_diag(path, line, "IMP003", f"prefer must be one of {', '.join(POLICIES)}"))
        else:
            for index in spec.indices():
                out.options.object_policy[index] = prefer
    for name, value in table.items():
        field_name = ALIASES.get(name.lower().replace("_", ""), name)
        if name in ("reason", "prefer", "sub"):
            continue
        if field_name not in ENTRY_FIELDS + OBJECT_FIELDS:
            out.diagnostics.append(_diag(path, lines.get(name, line), "IMP003", f"unknown override field {name!r}"))
            continue
        sub = None if field_name in OBJECT_FIELDS else 0
        _add(out, path, lines.get(f"{where}/{name}", line), spec.indices(), [sub], field_name, value, reason)
    subs = table.get("sub", {})
    if not isinstance(subs, dict):
        return
    for sub_key, sub_table in subs.items():
        sub_spec = parse_sub(str(sub_key))
        if sub_spec is None or not isinstance(sub_table, dict):
            out.diagnostics.append(_diag(path, line, "IMP003", f"[objects.{key!r}.sub.{sub_key!r}] is not a sub-index"))
            continue
        sub_where = f"{where}.sub.{sub_key}".replace(" ", "")
        sub_line = lines.get(sub_where, line)
        sub_reason = str(sub_table.get("reason", reason))
        if sub_table.get("exclude") is True:
            for index in spec.indices():
                for sub in sub_spec.subs:
                    out.options.exclude_entries[(index, sub)] = sub_reason
            continue
        for name, value in sub_table.items():
            field_name = ALIASES.get(name.lower().replace("_", ""), name)
            if name == "reason":
                continue
            if field_name not in (*ENTRY_FIELDS, "name"):
                out.diagnostics.append(_diag(path, lines.get(name, line), "IMP003", f"unknown override field {name!r}"))
                continue
            field_line = lines.get(f"{sub_where}/{name}", sub_line)
            _add(out, path, field_line, spec.indices(), list(sub_spec.subs), field_name, value, sub_reason)


def _add(
    out: Overrides,
    path: str,
    line: int,
    indices: range,
    subs: list[int | None],
    field_name: str,
    value: Any,
    reason: str,
) -> None:
    raw = str(value).lower() if isinstance(value, bool) else str(value)
    normalised = _normalise(field_name, value)
    if normalised is None and field_name not in ("default", "low", "high"):
        out.diagnostics.append(_diag(path, line, "IMP003", f"{field_name} = {value!r} is not understood"))
        return
    source = Source(path, line, "overrides", Kind.OVERRIDE)
    for index in indices:
        for sub in subs:
            out.options.overrides.append(Override(index, sub, field_name, raw, normalised, reason, source))


def _normalise(field_name: str, value: Any) -> Norm | None:
    if field_name == "name":
        return str(value)
    if field_name == "object_code":
        return parse_object_code(str(value))
    if field_name == "data_type":
        if isinstance(value, int):
            return value
        spec = parse_type(str(value))
        return spec.index if spec is not None else None
    if field_name == "access":
        spec_a = parse_access(str(value))
        return spec_a.access if spec_a is not None else None
    if field_name == "pdo_mapping":
        if isinstance(value, bool):
            return value
        spec_m = parse_mapping(str(value))
        return spec_m.mappable if spec_m is not None else None
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, (int, float)):
        return value
    return str(value)  # parsed with the entry's type when merged


def _str(value: object) -> str | None:
    return str(value) if value is not None else None


def _line_index(text: str) -> dict[str, int]:
    """Lines for messages and provenance: `table` → its header line, `table/key` → the key's line,
    tables written with quotes removed (`objects.0x1800.sub.2`); a bare `key` → its last line."""
    out: dict[str, int] = {}
    table = ""
    for number, raw in enumerate(text.splitlines(), start=1):
        stripped = raw.strip()
        if stripped.startswith("[") and not stripped.startswith("[["):
            table = stripped.strip("[]").replace('"', "").replace(" ", "")
            out.setdefault(table, number)
            for part in table.split("."):
                out.setdefault(part, number)
        elif "=" in stripped and not stripped.startswith("#"):
            key = stripped.split("=", 1)[0].strip().strip('"')
            out[f"{table}/{key}"] = number
            out[key] = number
    return out


def _error_line(message: str) -> int:
    import re

    match = re.search(r"line (\d+)", message)
    return int(match.group(1)) if match else 0


def _diag(path: str, line: int, code: str, message: str) -> Diagnostic:
    return Diagnostic(code=code, severity=Severity.ERROR, message=message, location=loc(path, line))


def policy_of(value: str) -> Policy | None:
    for policy in POLICIES:
        if policy == value:
            return policy
    return None
