"""The packages' order, held: data flows one way (sources → model → checks, views, changes, network → renderers →
editor and command line), so no module imports one of a later layer, and no modules import each other in a circle.

Every import counts, wherever it stands (inside a function or under TYPE_CHECKING too): a late import hides a
cycle from Python, not from a reader. The order is written here once; docs/architecture.md explains it.
"""

from __future__ import annotations

import ast
from collections import defaultdict
from pathlib import Path

import pytest

from support import ROOT

PACKAGE = ROOT / "cantools_od"

# Lowest first. A module may import its own layer's modules and those of lower layers. The package itself
# (cantools_od/__init__.py, lazy re-exports and __version__) stands outside the order: anyone may read the version.
LAYERS: tuple[tuple[str, ...], ...] = (
    ("model", "canopennode", "names", "resources", "collector", "files"),
    ("sniff", "eds", "xdd", "tableimport", "schema", "api"),
    ("identifiers", "interop", "losses", "views"),
    ("lint", "changes", "network", "live"),
    ("render",),
    ("lsp",),
    ("cli", "__main__"),
)


def layer_of(module: str) -> int | None:
    """The layer of a module `cantools_od.<top>...`; None for the package itself."""
    parts = module.split(".")
    if len(parts) == 1:
        return None
    for number, tops in enumerate(LAYERS):
        if parts[1] in tops:
            return number
    raise AssertionError(f"{module}: its package {parts[1]!r} has no place in LAYERS")


def modules(package: Path = PACKAGE) -> dict[str, Path]:
    found = {}
    for path in package.rglob("*.py"):
        parts = list(path.relative_to(package.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts = parts[:-1]
        found[".".join(parts)] = path
    return found


def _target(module: str, node: ast.ImportFrom, is_package: bool) -> str:
    base = module.split(".") if is_package else module.split(".")[:-1]
    if node.level > 1:
        base = base[: len(base) - (node.level - 1)]
    if not node.level:
        return node.module or ""
    return ".".join(base + ([node.module] if node.module else []))


def imports(package: Path = PACKAGE) -> dict[str, set[str]]:
    """Module → the modules of the package it imports (a `from x import name` of a submodule counts as that one)."""
    known = modules(package)
    found: dict[str, set[str]] = defaultdict(set)
    for module, path in known.items():
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            names: list[str] = []
            if isinstance(node, ast.ImportFrom):
                base = _target(module, node, path.name == "__init__.py")
                names = [f"{base}.{alias.name}" if f"{base}.{alias.name}" in known else base for alias in node.names]
            elif isinstance(node, ast.Import):
                names = [alias.name for alias in node.names]
            for name in names:
                while name and name not in known:
                    name = name.rpartition(".")[0]
                if name and name != module:
                    found[module].add(name)
    return found


def upward(graph: dict[str, set[str]]) -> list[str]:
    wrong = []
    for module, targets in sorted(graph.items()):
        mine = layer_of(module)
        for target in sorted(targets):
            theirs = layer_of(target)
            if mine is not None and theirs is not None and theirs > mine:
                wrong.append(f"{module} imports {target}, a later layer")
    return wrong


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The strongly connected groups of more than one module (Tarjan's algorithm, without recursion)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on_stack: set[str] = set()
    found: list[list[str]] = []
    for start in sorted(graph):
        if start in index:
            continue
        work = [(start, iter(sorted(graph.get(start, ()))))]
        index[start] = low[start] = len(index)
        stack.append(start)
        on_stack.add(start)
        while work:
            node, children = work[-1]
            child = next(children, None)
            if child is not None:
                if child not in index:
                    index[child] = low[child] = len(index)
                    stack.append(child)
                    on_stack.add(child)
                    work.append((child, iter(sorted(graph.get(child, ())))))
                elif child in on_stack:
                    low[node] = min(low[node], index[child])
                continue
            work.pop()
            if work:
                low[work[-1][0]] = min(low[work[-1][0]], low[node])
            if low[node] == index[node]:
                group = []
                while True:
                    member = stack.pop()
                    on_stack.discard(member)
                    group.append(member)
                    if member == node:
                        break
                if len(group) > 1:
                    found.append(sorted(group))
    return found


def test_no_module_imports_a_later_layer() -> None:
    assert upward(imports()) == []


def test_no_import_cycles() -> None:
    assert cycles(imports()) == []


def test_every_package_has_a_layer() -> None:
    for module in modules():
        layer_of(module)


@pytest.mark.parametrize(
    ("files", "wrong"),
    [
        ({"model/__init__.py": "", "model/a.py": "from ..cli import b\n", "cli/__init__.py": "", "cli/b.py": ""},
         "upward"),
        ({"model/__init__.py": "", "model/a.py": "from . import b\n", "model/b.py": "def f():\n    from . import a\n"},
         "cycle"),
    ],
)  # fmt: skip
def test_the_checks_catch_what_they_are_for(tmp_path: Path, files: dict[str, str], wrong: str) -> None:
    """Both ways: an upward import and a cycle (here hidden in a function) are found in a package made for it."""
    package = tmp_path / "cantools_od"
    for name, text in {"__init__.py": "", **files}.items():
        (package / name).parent.mkdir(parents=True, exist_ok=True)
        (package / name).write_text(text, encoding="utf-8")
    graph = imports(package)
    assert bool(upward(graph)) == (wrong == "upward")
    assert bool(cycles(graph)) == (wrong == "cycle")
