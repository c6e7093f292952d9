"""Every real file of ../shared/eds-corpus: loads, round-trips, formats stably, loses nothing."""

from __future__ import annotations

from pathlib import Path

import pytest

from cantools_od import dumps, load, loads
from cantools_od.model import Device

from support import corpus_file, corpus_files, corpus_params


def file_format(device: Device) -> str:
    return "dcf" if device.is_dcf else "eds"


@pytest.mark.parametrize("path", corpus_params())
def test_corpus_file(path: Path) -> None:
    device = load(path)
    fmt = file_format(device)
    assert dumps(device, fmt, "preserve") == path.read_bytes()
    canonical = dumps(device, fmt, "canonical")
    reloaded = loads(canonical, fmt=fmt, source="canonical")  # type: ignore[arg-type]
    assert dumps(reloaded, fmt, "canonical") == canonical
    content = device.content()
    assert reloaded.content() == content
    assert loads(dumps(device, "json")).content() == content


def _compact_facts(device: Device) -> dict[str, object]:
    """What python-canopen's export loses, gathered for comparison."""
    return {
        "compact": {
            i: {s: (sub.name, sub.parameter_value, sub.denotation) for s, sub in o.subs.items()}
            for i, o in device.objects.items()
            if o.compact_sub_obj
        },
        "flags": {
            (i, s): v.obj_flags for i, o in device.objects.items() for s, v in [(0, o), *o.subs.items()] if v.obj_flags
        },
        "denotations": {
            (i, s): v.denotation
            for i, o in device.objects.items()
            for s, v in [(0, o), *o.subs.items()]
            if v.denotation
        },
        "dummy": device.dummy_usage.enabled if device.dummy_usage else None,
    }


def _compact_specimens() -> list[str]:
    """python-canopen's sample and every lely DCF (CompactSubObj records with [xxxxValue])."""
    return ["python-canopen__sample.eds", *(p.name for p in corpus_files() if p.name.startswith("lely-"))]


@pytest.mark.parametrize("name", _compact_specimens())
def test_compact_data_survives_canonical(name: str) -> None:
    device = load(corpus_file(name))
    facts = _compact_facts(device)
    fmt = file_format(device)
    again = loads(dumps(device, fmt, "canonical"), fmt=fmt)  # type: ignore[arg-type]
    assert _compact_facts(again) == facts


def test_sample_specimen_details() -> None:
    device = load(corpus_file("python-canopen__sample.eds"))
    compact = [o for o in device.objects.values() if o.compact_sub_obj]
    assert compact, "sample.eds has CompactSubObj objects"
    assert any(s.name != f"{o.name}{i}" for o in compact for i, s in o.subs.items() if i)  # [xxxxName] applied
    assert device.dialect.value == "python-canopen"


def test_lely_dcf_keeps_values_and_dummy_usage() -> None:
    assert load(corpus_file("lely-core__coapp-fiber-master.dcf")).dummy_usage is not None
    device = load(corpus_file("lely-core__co-pdo-transmit.dcf"))
    values = [s.parameter_value for o in device.objects.values() if o.compact_sub_obj for s in o.subs.values()]
    assert any(v is not None for v in values)
