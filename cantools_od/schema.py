"""The JSON Schema of the model, as checked in at schemas/od.schema.json.

Regenerate with `python -m cantools_od.schema > schemas/od.schema.json`.
"""

from __future__ import annotations

import json
from typing import Any

from .model import Device

SCHEMA_ID = "https://cantools-od.invalid/schemas/od.schema.json"


def model_schema() -> dict[str, Any]:
    schema = Device.model_json_schema(mode="serialization")
    return {"$schema": "https://json-schema.org/draft/2020-12/schema", "$id": SCHEMA_ID, **schema}


def schema_text() -> str:
    return json.dumps(model_schema(), indent=2, sort_keys=True) + "\n"


if __name__ == "__main__":
    print(schema_text(), end="")
