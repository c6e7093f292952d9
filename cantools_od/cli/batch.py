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
        help="Files to check at once, each in a process of its own (default: the number of cores); the output is "
        "the same as with --jobs 1.",
    )(function)


def config_option(function: click.decorators.FC) -> click.decorators.FC:
    return click.option(
        "--config",
        "config",
        type=click.Path(dir_okay=False),
        help="Configuration file for every file (a pyproject.toml with [tool.cantools-od], or a cantools-od.toml); "
        "default: the nearest one from each file's folder upwards.",
    )(function)


def run_each(
    work: Callable[[Item], Result], items: Sequence[Item], jobs: int | None, progress: Progress | None = None
) -> list[Result]:
    """`work` on every item, in up to `jobs` processes (default: one a core), the results in the items' order.
    One item, or one job, runs here: no process is started for it. `progress` counts the items as they end."""
    workers = min(jobs or os.cpu_count() or 1, len(items))
    results: list[Result] = []
    if workers <= 1:
        for item in items:
            results.append(work(item))
            _step(progress, item)
    else:
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(max_workers=workers) as pool:
            for item, result in zip(items, pool.map(work, items), strict=True):
                results.append(result)
                _step(progress, item)
    if progress is not None:
        progress.clear()
    return results


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
