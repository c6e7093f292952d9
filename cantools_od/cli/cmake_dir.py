"""`cantools-od cmake-dir`: where the CMake package of cantools-od is."""

from __future__ import annotations

from pathlib import Path

import click


@click.command(name="cmake-dir")
def command() -> None:
    """Print the folder with cantools_odConfig.cmake and cantools_od.cmake, for
    `find_package(cantools_od CONFIG)` (as cantools_od_DIR or in CMAKE_PREFIX_PATH)
    or `include(<folder>/cantools_od.cmake)`."""
    click.echo(str(Path(__file__).resolve().parent.parent / "cmake"))
