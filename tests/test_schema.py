"""The checked-in JSON Schema matches the model, and model JSON validates against it."""

from __future__ import annotations

import json

from cantools_od import dumps, load
from cantools_od.resources import resource_dir
from cantools_od.schema import schema_text

from support import EXAMPLES


def test_checked_in_schema_has_not_drifted() -> None:
    checked_in = (resource_dir("schemas") / "od.schema.json").read_text()
    assert checked_in == schema_text(), "regenerate: python -m cantools_od.schema > schemas/od.schema.json"


def test_example_json_has_the_schema_shape() -> None:
    schema = json.loads(schema_text())
    data = json.loads(dumps(load(EXAMPLES / "cia402_drive.eds"), "json"))
    assert set(data) <= set(schema["properties"])
    object_props = set(schema["$defs"]["Object"]["properties"])
    for obj in data["objects"].values():
        assert set(obj) <= object_props
