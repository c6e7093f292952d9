"""Property: for random files and random fix sets, the preserving writer changes only the lines the
applied fixes name (a value rewritten, a name respelled); every other line, empty keys included,
stays byte for byte, and the written file reads back as the fixed model."""

from __future__ import annotations

from dataclasses import dataclass

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from cantools_od import dumps, loads
from cantools_od.eds.preserve import respell
from cantools_od.model import Device

KEYS = ("ParameterName", "DataType", "AccessType", "DefaultValue", "LowLimit", "HighLimit", "PDOMapping", "ObjFlags")


@dataclass(frozen=True)
class Key:
    name: str  # canonical
    written: str  # as the file spells it
    value: str  # "" for an empty key


@dataclass(frozen=True)
class Var:
    index: int
    keys: tuple[Key, ...]
    comment: bool


def _case(name: str, flips: list[bool]) -> str:
    return "".join(c.swapcase() if flip else c for c, flip in zip(name, flips + [False] * len(name), strict=False))


@st.composite
def variables(draw: st.DrawFn, index: int) -> Var:
    keys = [Key("ParameterName", "ParameterName", f"Object {index:X}"), Key("DataType", "DataType", "0x0006")]
    keys.append(Key("AccessType", "AccessType", draw(st.sampled_from(["ro", "rw"]))))
    for name in ("DefaultValue", "LowLimit", "HighLimit", "PDOMapping", "ObjFlags"):
        kind = draw(st.sampled_from(["absent", "empty", "value"]))
        if kind == "absent":
            continue
        value = {"PDOMapping": "0", "ObjFlags": "0"}.get(name, str(draw(st.integers(0, 100))))
        if name == "HighLimit":
            value = "1000"
        keys.append(Key(name, name, "" if kind == "empty" else value))
    keys = [Key(k.name, _case(k.name, draw(st.lists(st.booleans(), max_size=3))), k.value) for k in keys]
    return Var(index, tuple(draw(st.permutations(keys))), draw(st.booleans()))


@st.composite
def files(draw: st.DrawFn) -> list[Var]:
    count = draw(st.integers(1, 5))
    return [draw(variables(0x2000 + n)) for n in range(count)]


def render(objects: list[Var], eol: str) -> str:
    lines: list[str] = []
    for var in objects:
        if var.comment:
            lines.append("; a comment")
        lines.append(f"[{var.index:04X}]")
        lines.extend(f"{key.written}={key.value}" for key in var.keys)
        lines.append("")
    return eol.join(lines) + eol


@dataclass(frozen=True)
class Change:
    index: int
    key: str  # canonical
    respell: bool  # respell the key, else set a new DefaultValue/LowLimit


def apply(device: Device, objects: list[Var], text: str, changes: list[Change]) -> set[int]:
    """Applies the changes as lint fixes do; returns the lines they name."""
    named: set[int] = set()
    by_index = {var.index: var for var in objects}
    for change in changes:
        obj = device.objects[change.index]
        assert obj.origin is not None
        where = obj.origin.where(change.key)
        assert where is not None
        line, column, _ = where
        written = next(k.written for k in by_index[change.index].keys if k.name == change.key)
        if change.respell:
            if written != change.key:
                respell(device, line, column, written, change.key)
                named.add(line)
        elif change.key == "DefaultValue":
            obj.default = 4242
            named.add(line)
        elif change.key == "LowLimit":
            obj.low_limit = 999
            named.add(line)
    return named


@st.composite
def fix_sets(draw: st.DrawFn, objects: list[Var]) -> list[Change]:
    candidates = [
        Change(var.index, key.name, respell)
        for var in objects
        for key in var.keys
        for respell in (True, False)
        if respell or (key.name in ("DefaultValue", "LowLimit") and key.value)
    ]
    return draw(st.lists(st.sampled_from(candidates), max_size=6, unique=True)) if candidates else []


def changed(before: str, after: str) -> set[int]:
    """The numbers of the lines that differ. No fix here adds or removes a line, so lines are compared
    by position: a diff would align look-alike sections wrongly and blame lines that did not change."""
    old, new = before.splitlines(), after.splitlines()
    assert len(new) == len(old), "no fix here adds or removes a line"
    return {number for number, (a, b) in enumerate(zip(old, new, strict=True), 1) if a != b}


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.data(), st.sampled_from(["\n", "\r\n"]))
def test_preserve_changes_only_the_lines_the_fixes_name(data: st.DataObject, eol: str) -> None:
    objects = data.draw(files())
    text = render(objects, eol)
    device = loads(text, source="t.eds")
    changes = data.draw(fix_sets(objects))
    named = apply(device, objects, text, changes)
    out = dumps(device).decode()
    assert changed(text, out) <= named
    assert changed(text, out) == named or not changes  # each named line did change
    again = loads(out, source="t.eds")
    for change in changes:
        if not change.respell:
            obj = again.objects[change.index]
            assert (obj.default if change.key == "DefaultValue" else obj.low_limit) in (4242, 999)
    respelled = {(c.index, c.key) for c in changes if c.respell}
    for var in objects:
        for key in var.keys:
            if key.value == "":  # an empty key stays, respelled only when a fix says so
                spelling = key.name if (var.index, key.name) in respelled else key.written
                assert f"{eol}{spelling}={eol}" in out
