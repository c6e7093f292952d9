"""The bus description as ros2_canopen's build installs it: its `cogen` copies `defaults` over each of
`nodes` and writes `options`, `master` and the nodes with `yaml.dump` (keys sorted), then `@NAME@`
placeholders are replaced in the text. ros2_canopen's nodes read that file at run time, so a
configuration package built without cogen installs it too (`network --write-bus`). A file without
`nodes` is installed as written, its placeholders replaced."""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

import yaml

_PLACEHOLDER = re.compile(r"@([A-Za-z_][A-Za-z0-9_]*)@")


def with_defaults(node: Mapping[Any, Any], defaults: Mapping[Any, Any]) -> dict[Any, Any]:
    """A node as cogen expands it: each key of `defaults` copied over the node's own
    (`nodes[node_name][entry_name] = defaults[entry_name]`)."""
    return {**node, **defaults}


def expanded(text: str, defines: Mapping[str, str]) -> str:
    """`text` (a bus description that read_network accepted) as cogen and the placeholder step make it."""
    data: Any = yaml.safe_load(text)
    if isinstance(data, dict) and "nodes" in data and "master" in data:
        defaults = data.get("defaults") or {}
        result: dict[str, Any] = {"options": data.get("options") or {}, "master": data["master"]}
        for name, node in (data["nodes"] or {}).items():
            result[name] = with_defaults(node or {}, defaults)
        text = yaml.dump(result)
    return _PLACEHOLDER.sub(lambda match: defines.get(match.group(1), match.group(0)), text)
