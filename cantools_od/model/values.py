"""Typed values of DefaultValue, ParameterValue and the limits.

A value is a plain Python value chosen by the entry's data type (int, bool,
float, str, bytes) or one of the small classes below. In JSON, the values that
JSON cannot tell apart carry a one-key tag, so a model round-trips exactly.
"""

from __future__ import annotations

import math
from typing import Annotated, Any

from pydantic import BaseModel, ConfigDict, PlainSerializer, PlainValidator, WithJsonSchema


class NodeIdExpr(BaseModel):
    """`$NODEID` plus a constant, kept symbolic until a node-ID is known.

    `text` is the spelling found in the file (for diagnostics); two
    expressions are equal when their offsets are.
    """

    model_config = ConfigDict(frozen=True, defer_build=True)

    offset: int
    text: str = ""

    def resolve(self, node_id: int) -> int:
        return node_id + self.offset

    def canonical(self) -> str:
        if self.offset == 0:
            return "$NODEID"
        if self.offset < 0:
            return f"$NODEID-0x{-self.offset:X}"
        return f"$NODEID+0x{self.offset:X}"

    def __eq__(self, other: object) -> bool:
        return isinstance(other, NodeIdExpr) and other.offset == self.offset

    def __hash__(self) -> int:
        return hash(("nodeid", self.offset))


class TimeValue(BaseModel):
    """TIME_OF_DAY / TIME_DIFFERENCE: days since 1984-01-01 and ms after midnight."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    days: int
    ms: int

    @classmethod
    def from_bits(cls, bits: int) -> TimeValue:
        return cls(days=(bits >> 32) & 0xFFFF, ms=bits & 0x0FFFFFFF)


class RawValue(BaseModel):
    """Text that could not be read as the entry's data type, kept verbatim."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    text: str


Scalar = bool | int | float | str | bytes | NodeIdExpr | TimeValue | RawValue


def _to_json(value: Scalar) -> Any:
    if isinstance(value, bytes):
        return {"hex": value.hex()}
    if isinstance(value, float) and not math.isfinite(value):
        return {"real": repr(value)}
    if isinstance(value, float):
        return {"real": value}
    if isinstance(value, NodeIdExpr):
        return {"nodeid": value.offset, "text": value.text}
    if isinstance(value, TimeValue):
        return {"days": value.days, "ms": value.ms}
    if isinstance(value, RawValue):
        return {"raw": value.text}
    return value


def _from_json(data: Any) -> Scalar:
    if isinstance(data, (NodeIdExpr, TimeValue, RawValue, bool, int, float, str, bytes)):
        return data
    if isinstance(data, dict):
        if "hex" in data:
            return bytes.fromhex(data["hex"])
        if "real" in data:
            return float(data["real"])
        if "nodeid" in data:
            return NodeIdExpr(offset=data["nodeid"], text=data.get("text", ""))
        if "days" in data:
            return TimeValue(days=data["days"], ms=data["ms"])
        if "raw" in data:
            return RawValue(text=data["raw"])
    raise ValueError(f"not a typed value: {data!r}")


_VALUE_JSON_SCHEMA: dict[str, Any] = {
    "anyOf": [
        {"type": "boolean"},
        {"type": "integer"},
        {"type": "string"},
        {"type": "object", "properties": {"hex": {"type": "string"}}, "required": ["hex"]},
        {"type": "object", "properties": {"real": {"type": ["number", "string"]}}, "required": ["real"]},
        {
            "type": "object",
            "properties": {"nodeid": {"type": "integer"}, "text": {"type": "string"}},
            "required": ["nodeid"],
        },
        {
            "type": "object",
            "properties": {"days": {"type": "integer"}, "ms": {"type": "integer"}},
            "required": ["days", "ms"],
        },
        {"type": "object", "properties": {"raw": {"type": "string"}}, "required": ["raw"]},
    ]
}

Value = Annotated[
    Scalar,
    PlainValidator(_from_json),
    PlainSerializer(_to_json, return_type=Any, when_used="json"),
    WithJsonSchema(_VALUE_JSON_SCHEMA),
]
"""A typed value; see the module docstring for its JSON form."""
