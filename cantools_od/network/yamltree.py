"""YAML read with the line of every key: the bus description's parts keep where they were written.

Mappings become `Located` dictionaries (a plain dict plus the line of the mapping and of each key);
a key written twice, a document that is not a mapping and YAML that does not parse are one-line
`NetworkError`s at `file:line`.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

import yaml
from yaml.constructor import ConstructorError
from yaml.nodes import MappingNode, Node


class NetworkError(ValueError):
    """The bus description cannot be turned into a network; the message is one line with `file:line`."""

    def __init__(self, file: str, line: int, message: str) -> None:
        super().__init__(f"{file}:{line}: error: {message}" if line else f"{file}: error: {message}")
        self.file = file
        self.line = line
        self.reason = message


class Located(dict[Any, Any]):
    """A YAML mapping with the line of the mapping itself and of each of its keys (from 1)."""

    line: int = 0
    lines: dict[Any, int]

    def line_of(self, key: Any) -> int:
        return self.lines.get(key, self.line)


class _Loader(yaml.SafeLoader):
    """SafeLoader whose mappings remember their lines and refuse a key written twice."""

    def construct_mapping(self, node: Node, deep: bool = False) -> Located:
        if not isinstance(node, MappingNode):
            raise ConstructorError(None, None, "expected a mapping", node.start_mark)
        self.flatten_mapping(node)
        result = Located()
        result.line = node.start_mark.line + 1
        result.lines = {}
        for key_node, value_node in node.value:
            key = self.construct_object(key_node, deep=True)
            try:
                hash(key)
            except TypeError:
                raise ConstructorError(None, None, "a key that is not a scalar", key_node.start_mark) from None
            if key in result:
                raise ConstructorError(
                    None, None, f"key {key!r} written twice (first on line {result.lines[key]})", key_node.start_mark
                )
            result[key] = self.construct_object(value_node, deep=True)
            result.lines[key] = key_node.start_mark.line + 1
        return result


_Loader.add_constructor("tag:yaml.org,2002:map", _Loader.construct_mapping)


def read_yaml(text: str, file: str) -> Located:
    """The document's top-level mapping; NetworkError when it is no YAML mapping."""
    try:
        data = yaml.load(text, Loader=_Loader)  # a SafeLoader
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        line = mark.line + 1 if mark is not None else 0
        raise NetworkError(file, line, f"not YAML: {error.problem or error.context}") from None
    except yaml.YAMLError as error:
        raise NetworkError(file, 0, f"not YAML: {' '.join(str(error).split())}") from None
    if not isinstance(data, Located):
        raise NetworkError(file, 1, "a bus description is a YAML mapping (master, nodes, ...)")
    return data


_PLACEHOLDER = re.compile(r"@([A-Za-z_][A-Za-z0-9_]*)@")


def substitute(value: Any, defines: Mapping[str, str], file: str, line: int) -> Any:
    """`value` with every `@NAME@` in its strings replaced from `defines` (as ros2_canopen's build does)."""
    if isinstance(value, str):

        def replace(match: re.Match[str]) -> str:
            name = match.group(1)
            if name not in defines:
                raise NetworkError(file, line, f"{match.group(0)} is not defined: give --define {name}=VALUE")
            return defines[name]

        return _PLACEHOLDER.sub(replace, value)
    if isinstance(value, Located):
        copy = Located({k: substitute(v, defines, file, value.line_of(k)) for k, v in value.items()})
        copy.line, copy.lines = value.line, value.lines
        return copy
    if isinstance(value, list):
        return [substitute(item, defines, file, line) for item in value]
    return value
