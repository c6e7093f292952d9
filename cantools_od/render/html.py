"""One self-contained HTML reference page a device: `<name>.html`, from a DeviceView.

The page needs nothing beyond itself (styles, the filter script and the PDO pictures are inside it), so it
opens from a file, a build artefact or an e-mail with no network. Anchors are those of every reference document
(render/anchors.py): `#1400` for an object, `#1400-1` for its sub-index 1, and `#tpdo1` for a PDO's picture.
"""

from __future__ import annotations

from collections.abc import Iterable

from ..model import Object
from ..views.bitfield import diagram
from ..views.codegen import DeviceView, EntryView, ObjectView
from ..views.pdo import Pdo
from ..views.reference import (
    NONE,
    TYPE_KINDS,
    header_where,
    kind_text,
    limits_text,
    mapped_by,
    source_name,
    summary,
    type_definition,
    type_text,
    value_text,
    where_text,
)
from . import Each, stream_template, whole
from .anchors import object_anchor
from .svg import sheet


def stream(view: DeviceView) -> dict[str, Iterable[str]]:
    """`<name>.html`, rendered as it is read."""
    return {f"{view.name}.html": stream_template("html/reference.html.j2", d=_document(view))}


def render(view: DeviceView) -> dict[str, str]:
    return whole(stream(view))


def _document(view: DeviceView) -> dict[str, object]:
    mapped = mapped_by(view)
    info = view.device.device_info
    return {
        "title": info.product_name or view.name,
        "source": source_name(view),
        "summary": summary(view),
        "pdos": [_pdo(view, pdo.pdo) for pdo in view.pdos],
        "types": [_type_row(view, obj) for obj in view.device.objects.values() if obj.kind in TYPE_KINDS],
        "objects": Each(lambda: (_object(view, obj, mapped) for obj in view.objects), len(view.objects)),
    }


def _pdo(view: DeviceView, pdo: Pdo) -> dict[str, object]:
    return {
        "anchor": pdo.name.lower(),
        "name": pdo.name,
        "comm": object_anchor(pdo.comm_index),
        "mapping": object_anchor(pdo.map_index),
        "svg": sheet([diagram(pdo, view.node_id)]),
    }


def _type_row(view: DeviceView, obj: Object) -> list[str]:
    type_name, value = type_definition(obj)
    where = f"{source_name(view)}:{obj.origin.line}" if obj.origin is not None and obj.origin.line else NONE
    return [f"{obj.index:04X}h", obj.name or NONE, obj.kind.name, type_name, value, where]


def _object(view: DeviceView, obj: ObjectView, mapped: dict[tuple[int, int], list[str]]) -> dict[str, object]:
    rows = [_row(view, entry, mapped) for entry in obj.entries]
    words = [f"{obj.index:04X}", f"{obj.index:04X}h", f"0x{obj.index:04X}", obj.name, obj.identifier]
    words += [text for entry in obj.entries for text in (entry.name, entry.flat)]
    return {
        "anchor": object_anchor(obj.index),
        "index": f"{obj.index:04X}h",
        "name": obj.name,
        "kind": kind_text(obj),
        "identifier": obj.identifier,
        "where": header_where(view, obj),
        "search": " ".join(words).lower(),
        "rows": rows,
    }


def _row(view: DeviceView, entry: EntryView, mapped: dict[tuple[int, int], list[str]]) -> dict[str, object]:
    pdos = mapped.get((entry.index, entry.subindex), [])
    return {
        "anchor": object_anchor(entry.index, entry.subindex),
        "cells": [
            f"{entry.subindex:X}h",
            entry.name or NONE,
            type_text(view.device, entry),
            entry.access.value if entry.access else NONE,
            ", ".join(pdos) or ("mappable" if entry.pdo_mappable else "no"),
            value_text(view, entry),
            limits_text(entry),
            entry.flat,
            where_text(view, entry) or NONE,
        ],
    }
