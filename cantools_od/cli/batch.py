"""Many files, one report: per-file work run in processes (`--jobs`), results in the order the files were given,
and each file's configuration found from its own folder (`--config` overrides it)."""

from __future__ import annotations

import os
from collections.abc import Callable, Sequence
from functools import cache
from pathlib import Path
from typing import TypeVar

import click

from .common import Progress

Item = TypeVar("Item")
Result = TypeVar("Result")


def jobs_option(function: click.decorators.FC) -> click.decorators.FC:
    return click.option(
        "--jobs",
        "-j",
        type=click.IntRange(min=1),
        help="Files to check at once, each in a process of its own (default: the number of cores, or one when the "
        "files total under 128 KB); the output is the same as with --jobs 1.",
    )(function)


def config_option(function: click.decorators.FC) -> click.decorators.FC:
    return click.option(
        "--config",
        "config",
        type=click.Path(dir_okay=False),
        help="Configuration file for every file (a pyproject.toml with [tool.cantools-od], or a cantools-od.toml); "
        "default: the nearest one from each file's folder upwards.",
    )(function)


SMALL_WORK = 128 * 1024
"""Bytes of files below which the default is to work in this process: starting processes costs about as much as
half the work on 100-200 KB of device descriptions saves (measured on two cores)."""


def run_each(
    work: Callable[[Item], Result],
    items: Sequence[Item],
    jobs: int | None,
    progress: Progress | None = None,
    cost: Callable[[Item], int] | None = None,
) -> list[Result]:
    """`work` on every item, in up to `jobs` processes (default: one a core, or none below SMALL_WORK of `cost`),
    the results in the items' order. One item, or one job, runs here: no process is started for it. `progress`
    counts the items as they end. With `cost` (a guess of each item's work, such as its size), the costliest start
    first: a large file left to the end would keep one process busy while the others wait."""
    workers = min(jobs or os.cpu_count() or 1, len(items))
    costs = [cost(item) for item in items] if cost is not None else None  # a stat per file: asked once
    if jobs is None and costs is not None and sum(costs) < SMALL_WORK:
        workers = 1
    if workers <= 1:
        results: list[Result] = []
        for item in items:
            results.append(work(item))
            _step(progress, item)
    else:
        results = _in_processes(work, items, workers, progress, costs)
    if progress is not None:
        progress.clear()
    return results


def _in_processes(
    work: Callable[[Item], Result],
    items: Sequence[Item],
    workers: int,
    progress: Progress | None,
    costs: list[int] | None,
) -> list[Result]:
    from concurrent.futures import ProcessPoolExecutor, as_completed

    ended: dict[int, Result] = {}
    with ProcessPoolExecutor(max_workers=workers) as pool:
        futures = {
            pool.submit(_each, work, [items[i] for i in batch]): batch for batch in _batches(len(items), workers, costs)
        }
        for future in as_completed(futures):
            for index, result in zip(futures[future], future.result(), strict=True):
                ended[index] = result
                _step(progress, items[index])
    return [ended[i] for i in range(len(items))]


def _batches(count: int, workers: int, costs: list[int] | None) -> list[list[int]]:
    """The items' indices, costliest first, in batches: a process takes a batch at a time, as each item sent alone
    costs a round trip between the processes (about half a millisecond). A batch holds at most an eighth of a
    process's share of the items and of the cost, so that no process is left working alone at the end."""
    if costs is None:
        return [[i] for i in range(count)]
    most, limit = max(1, count // (workers * 8)), sum(costs) // (workers * 8)
    batches: list[list[int]] = []
    batch: list[int] = []
    held = 0
    for index in sorted(range(count), key=lambda i: -costs[i]):
        batch.append(index)
        held += costs[index]
        if len(batch) >= most or held >= limit:
            batches.append(batch)
            batch, held = [], 0
    return [*batches, batch] if batch else batches


def _each(work: Callable[[Item], Result], batch: list[Item]) -> list[Result]:
    """A batch's work, in the process that took it."""
    return [work(item) for item in batch]


def file_size(path: str) -> int:
    """A file's size as the cost of its work; 0 when it cannot be read (it then fails fast)."""
    try:
        return os.stat(path).st_size
    except (OSError, ValueError):
        return 0


def _step(progress: Progress | None, item: object) -> None:
    if progress is not None:
        progress.step(str(getattr(item, "name", item)))


@cache
def config_of_folder(folder: Path) -> Path | None:
    """The configuration file for the files in `folder` (looked up once a folder)."""
    from ..lint.config import find_config

    return find_config(folder)


def config_path(file: str, explicit: str | None) -> Path | None:
    """The configuration that holds for `file`: --config, else the nearest from its folder upwards."""
    if explicit is not None:
        return Path(explicit)
    return config_of_folder(Path(file).resolve().parent)
