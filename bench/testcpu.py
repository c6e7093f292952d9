"""Where the test suite's time goes: CPU per test, its own and its child processes', and how many processes it ran.

CPU time, unlike wall time, holds on a shared, loaded machine; `make test`'s wall time on an idle machine with
N workers is about max(total CPU / N, the longest xdist group). As a pytest plugin (works under pytest-xdist:
one file per worker):

    cd tests && PYTHONPATH=../bench TESTCPU_OUT=/tmp/cpu ../.venv/bin/python -m pytest -p testcpu ../tests/diff

then the sum per module, largest first, and per xdist group (a group runs on one worker: no group may be
longer than the wall time wanted):

    .venv/bin/python bench/testcpu.py /tmp/cpu

A test's own CPU includes its threads; its children's CPU counts processes that ended and were waited for
during the test (subprocess.run, process pools); a module fixture's set-up counts for the first test using it.
"""

from __future__ import annotations

import json
import os
import resource
import subprocess
import sys
import time
from collections.abc import Generator
from pathlib import Path
from typing import Any

import pytest

_started = [0]
_popen_init = subprocess.Popen.__init__


def _counting_init(self: subprocess.Popen[Any], *args: Any, **kwargs: Any) -> None:
    _started[0] += 1
    _popen_init(self, *args, **kwargs)


def _children() -> float:
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    return used.ru_utime + used.ru_stime


def pytest_configure(config: pytest.Config) -> None:
    subprocess.Popen.__init__ = _counting_init  # type: ignore[method-assign]


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_protocol(item: pytest.Item, nextitem: pytest.Item | None) -> Generator[None, None, None]:
    children, own, started, wall = _children(), time.process_time(), _started[0], time.perf_counter()
    yield
    mark = item.get_closest_marker("xdist_group")
    record = {
        "id": item.nodeid,
        "group": (mark.args[0] if mark.args else mark.kwargs.get("name")) if mark else None,
        "own": time.process_time() - own,
        "children": _children() - children,
        "processes": _started[0] - started,
        "wall": time.perf_counter() - wall,
    }
    prefix = os.environ.get("TESTCPU_OUT", "testcpu")
    with open(f"{prefix}.{os.environ.get('PYTEST_XDIST_WORKER', 'main')}.jsonl", "a", encoding="utf-8") as out:
        out.write(json.dumps(record) + "\n")


def summary(prefix: str) -> str:
    """CPU seconds per test module, largest first, from the files the plugin wrote under `prefix`; then the xdist
    groups (tests that run on one worker, one after another), the longest first."""
    folder, stem = Path(prefix).parent, Path(prefix).name
    rows: dict[str, list[float]] = {}
    groups: dict[str, list[float]] = {}
    for path in sorted(folder.glob(f"{stem}.*.jsonl")):
        for line in path.read_text(encoding="utf-8").splitlines():
            record = json.loads(line)
            row = rows.setdefault(record["id"].split("::")[0], [0, 0.0, 0.0, 0])
            row[0] += 1
            row[1] += record["own"]
            row[2] += record["children"]
            row[3] += record["processes"]
            if record.get("group"):
                group = groups.setdefault(record["group"], [0, 0.0, 0.0])
                group[0] += 1
                group[1] += record["own"] + record["children"]
                group[2] += record["wall"]
    lines = [f"{'module':56} {'tests':>5} {'own s':>8} {'children s':>10} {'CPU s':>8} {'processes':>9}"]
    total = [0.0, 0.0, 0.0, 0.0]
    for module, (tests, own, children, processes) in sorted(rows.items(), key=lambda kv: -(kv[1][1] + kv[1][2])):
        lines.append(f"{module:56} {tests:5.0f} {own:8.1f} {children:10.1f} {own + children:8.1f} {processes:9.0f}")
        total = [a + b for a, b in zip(total, (tests, own, children, processes), strict=True)]
    tests, own, children, processes = total
    lines.append(f"{'total':56} {tests:5.0f} {own:8.1f} {children:10.1f} {own + children:8.1f} {processes:9.0f}")
    lines.append(f"\n{'xdist group':56} {'tests':>5} {'CPU s':>8} {'wall s':>10}")
    for name, (tests, cpu, wall) in sorted(groups.items(), key=lambda kv: -kv[1][1])[:10]:
        lines.append(f"{name:56} {tests:5.0f} {cpu:8.1f} {wall:10.1f}")
    return "\n".join(lines)


if __name__ == "__main__":
    print(summary(sys.argv[1] if len(sys.argv) > 1 else "testcpu"))
