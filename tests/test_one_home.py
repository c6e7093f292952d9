"""Each piece of CiA 301 knowledge lives in one module, and every module imports on its own.

The numbers of the communication profile (PDO record ranges, SDO ranges, pre-defined COB-IDs, the
mandatory objects) live in `cantools_od/model/cia301/`, the data-type indices in
`cantools_od/model/datatypes.py`. Any other module names them through those modules; a copy
elsewhere is how two commands came to read one PDO three ways. The sweep looks at integer
constants written in hex, as CANopen writes indices and COB-IDs: decimal counts and sizes (128
node-IDs, a 4096-byte batch) are other numbers that happen to be equal.
"""

from __future__ import annotations

import ast
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

from support import ROOT

PACKAGE = ROOT / "cantools_od"
CIA301_HOME = "model/cia301/"
TYPES_HOME = "model/datatypes.py"

PDO_RECORDS = {0x1400, 0x15FF, 0x1600, 0x17FF, 0x1800, 0x19FF, 0x1A00, 0x1BFF}
SDO_RECORDS = {0x1200, 0x127F, 0x1280, 0x12FF}
MANDATORY = {0x1000, 0x1001, 0x1018}
COB_ID_BASES = {0x080, 0x100, 0x180, 0x200, 0x280, 0x300, 0x380, 0x400, 0x480, 0x500, 0x580, 0x600, 0x700}
PROFILE_NUMBERS = PDO_RECORDS | SDO_RECORDS | MANDATORY | COB_ID_BASES
# A type index is written with four hex digits (DataType=0x0007): 0001h-001Bh basic, 0020h-0023h records.
TYPE_INDICES = set(range(0x0001, 0x001C)) | set(range(0x0020, 0x0024))

# Modules that may spell these numbers, each with its reason.
ALLOWED = {
    "lint/examples.py": "builds the EDS text of rule examples: documentation, not knowledge",
    "render/pyruntime.py": "copied verbatim into each generated Python module, which cannot import cantools_od",
}
# Single numbers that are equal to a profile number by chance, each with its reason.
ALLOWED_NUMBERS = {
    ("render/py_text.py", 0x100): "a character code (the \\xNN escape ends below 100h), not a COB-ID",
}


def example_calls(tree: ast.AST) -> set[int]:
    """ids of constants inside calls of the rule-example builder (`ex.record(0x1A00, ...)`)."""
    inside: set[int] = set()
    for node in ast.walk(tree):
        func = node.func if isinstance(node, ast.Call) else None
        if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name) and func.value.id == "ex":
            inside.update(id(sub) for sub in ast.walk(node))
    return inside


def misplaced(relative: str, source: str) -> list[str]:
    """`file:line: 0xNNNN` for every profile or type number written in hex outside its home."""
    if relative.startswith(CIA301_HOME) or relative in ALLOWED:
        return []
    tree = ast.parse(source)
    examples = example_calls(tree)
    found = []
    for node in ast.walk(tree):
        if not isinstance(node, ast.Constant) or type(node.value) is not int or id(node) in examples:
            continue
        written = ast.get_source_segment(source, node) or ""
        if not written.lower().startswith("0x"):
            continue
        if (relative, node.value) in ALLOWED_NUMBERS:
            continue
        profile = node.value in PROFILE_NUMBERS
        type_index = node.value in TYPE_INDICES and len(written) == 6 and relative != TYPES_HOME
        if profile or type_index:
            found.append(f"cantools_od/{relative}:{node.lineno}: {written}")
    return found


def modules() -> list[Path]:
    return sorted(PACKAGE.rglob("*.py"))


def test_profile_numbers_live_in_their_home() -> None:
    found = [
        line
        for path in modules()
        for line in misplaced(path.relative_to(PACKAGE).as_posix(), path.read_text(encoding="utf-8"))
    ]
    assert not found, "CiA 301 numbers outside model/cia301, type indices outside model/datatypes.py:\n" + "\n".join(
        found
    )


PROBE = "RPDO = 0x1400\nSDO_TX = 0x580\nSIZE = 512\nTYPE = 0x0007\nSMALL = 0x07\nEXAMPLE = ex.record(0x1A00)\n"


def test_the_sweep_finds_a_copy() -> None:
    """The sweep is not blind: a PDO base, a COB-ID base and a type index written in hex are caught, in
    any module but their home; decimal sizes and rule-example builders are not numbers of the profile."""
    assert [line.split(": ", 1)[1] for line in misplaced("lint/probe.py", PROBE)] == ["0x1400", "0x580", "0x0007"]
    assert misplaced("model/cia301/probe.py", PROBE) == []
    assert [line.split(": ", 1)[1] for line in misplaced(TYPES_HOME, PROBE)] == ["0x1400", "0x580"]


def module_names() -> list[str]:
    names = []
    for path in modules():
        parts = path.relative_to(ROOT).with_suffix("").parts
        if parts[-1] == "__main__":
            continue
        names.append(".".join(parts[:-1] if parts[-1] == "__init__" else parts))
    return names


# Imports each named module in a fork of an interpreter that has loaded only third-party libraries: for our
# modules, as fresh as a new interpreter, without paying each time for the interpreter and pydantic to start.
_FORKING_IMPORTER = """
import os, sys
import click, jinja2, pydantic
for name in sys.argv[1:]:
    pid = os.fork()
    if pid == 0:
        try:
            __import__(name)
        except BaseException as error:
            print(f"{name}: {type(error).__name__}: {error}", flush=True)
            os._exit(1)
        os._exit(0)
    status = os.waitstatus_to_exitcode(os.waitpid(pid, 0)[1])
    if status not in (0, 1):  # 1: the child said why
        print(f"{name}: ended with {status}", flush=True)
"""


def _import_each_alone(names: list[str]) -> list[str]:
    run = subprocess.run([sys.executable, "-c", _FORKING_IMPORTER, *names], capture_output=True, text=True, timeout=600)
    assert run.returncode == 0, run.stderr
    return run.stdout.splitlines()


def imports_failing(names: list[str]) -> list[str]:
    """`module: error` for each module that does not import first thing in a fresh interpreter; two at a time."""
    with ThreadPoolExecutor(max_workers=2) as pool:
        return [line for lines in pool.map(_import_each_alone, [names[0::2], names[1::2]]) for line in lines]


def test_every_module_imports_alone() -> None:
    """No import cycle: each module imports first thing in a fresh interpreter (a cycle shows as an
    ImportError about a partially initialised module when it is entered from the wrong end)."""
    names = module_names()
    assert len(names) > 150
    failed = imports_failing(names)
    assert not failed, "\n".join(failed)


def test_a_module_that_fails_to_import_is_named() -> None:
    failed = imports_failing(["cantools_od.model", "cantools_od.no_such_module", "json", "cantools_od.lint.nowhere"])
    assert [line.split(":")[0] for line in failed] == ["cantools_od.no_such_module", "cantools_od.lint.nowhere"]


def _module_of(path: Path) -> str:
    parts = path.relative_to(ROOT).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


def import_graph() -> dict[str, set[str]]:
    """module → the package modules it imports when it is loaded (top-level imports; imports inside
    functions and under TYPE_CHECKING run later or never, so they cannot close a cycle at load time)."""
    paths = {_module_of(path): path for path in modules()}
    graph: dict[str, set[str]] = {name: set() for name in paths}
    for name, path in paths.items():
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.parse(path.read_text(encoding="utf-8")).body:
            if isinstance(node, ast.Import):
                graph[name].update(alias.name for alias in node.names if alias.name in paths)
            elif isinstance(node, ast.ImportFrom):
                base = package
                for _ in range(node.level - 1):
                    base = base.rpartition(".")[0]
                target = (f"{base}.{node.module}" if node.module else base) if node.level else node.module or ""
                for alias in node.names:
                    found = f"{target}.{alias.name}" if f"{target}.{alias.name}" in paths else target
                    if found in paths and found != name:
                        graph[name].add(found)
    return graph


def cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """The import cycles, each as the sorted modules that reach one another."""
    found = set()
    for start in graph:
        reach = _reach(graph, start)
        if start in reach:
            found.add(tuple(sorted(other for other in reach if start in _reach(graph, other))))
    return [list(cycle) for cycle in sorted(found)]


def _reach(graph: dict[str, set[str]], start: str) -> set[str]:
    seen, todo = set(), list(graph[start])
    while todo:
        name = todo.pop()
        if name not in seen:
            seen.add(name)
            todo.extend(graph[name])
    return seen


def test_no_import_cycle() -> None:
    graph = import_graph()
    assert sum(map(len, graph.values())) > 300  # the graph is read, not empty
    assert cycles(graph) == []


def test_a_cycle_is_found() -> None:
    graph = {"a": {"b"}, "b": {"c"}, "c": {"a"}, "d": {"a"}}
    assert cycles(graph) == [["a", "b", "c"]]
