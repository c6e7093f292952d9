"""The JSON report and its schema, checked in at schemas/diff.schema.json.

Regenerate the schema with `python -m cantools_od.changes.jsonout > schemas/diff.schema.json`.
"""

from __future__ import annotations

import json
from typing import Any

from pydantic import BaseModel, ConfigDict

from .records import DeviceDiff, Impact

SCHEMA_ID = "https://cantools-od.invalid/schemas/diff.schema.json"


class Summary(BaseModel):
    """Number of changes per impact class."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    breaking: int
    compatible: int
    value: int
    cosmetic: int


class DiffReport(DeviceDiff):
    """`cantools-od diff --format json`: the change records with a summary."""

    summary: Summary


def report(diff: DeviceDiff) -> DiffReport:
    counts = diff.counts()
    # The records as they are: dumped to Python and validated again, typed values ($NODEID sums,
    # raw text) would come back as the plain dicts of their fields, which no value type reads.
    records = {name: getattr(diff, name) for name in DeviceDiff.model_fields}
    return DiffReport(**records, summary=Summary(**{impact.value: counts[impact] for impact in Impact}))


def render(diff: DeviceDiff) -> str:
    return report(diff).model_dump_json(indent=2)


def schema() -> dict[str, Any]:
    body = DiffReport.model_json_schema(mode="serialization")
    return {"$schema": "https://json-schema.org/draft/2020-12/schema", "$id": SCHEMA_ID, **body}


def schema_text() -> str:
    return json.dumps(schema(), indent=2, sort_keys=True) + "\n"


if __name__ == "__main__":
    print(schema_text(), end="")
