"""Wheel build step: the Jinja templates compiled to Python modules, so that `gen` does not compile them in
every process (jinja2's `ModuleLoader` loads them; pip byte-compiles them at install like any module).

Runs in the build environment, where the package's own dependencies are absent: only jinja2 is imported.
The renderer uses the compiled templates only with the jinja2 version that compiled them (JINJA2_VERSION).
The options that change how a template compiles are the renderer's (cantools_od/render/__init__.py:
`environment()`); the golden tests of `gen` run the installed wheel, so a difference would show there.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path
from typing import Any

import jinja2
from hatchling.builders.hooks.plugin.interface import BuildHookInterface


def _plain(value: object, *args: object) -> object:
    return value


class _KnownFilters(dict[str, Any]):
    """Jinja's own filters (some take the environment or context: that changes the code), and for the
    renderer's own filters, plain functions like them: compiling needs only their names and kind."""

    def get(self, key: str, default: Any = None) -> Any:
        return super().get(key, _plain)


class TemplatesHook(BuildHookInterface):  # type: ignore[type-arg]
    PLUGIN_NAME = "templates"
    _out: Path | None = None

    def initialize(self, version: str, build_data: dict[str, Any]) -> None:
        if self.target_name != "wheel":
            return
        out = self._out = Path(tempfile.mkdtemp(prefix="cantools-od-templates-"))
        env = jinja2.Environment(
            loader=jinja2.FileSystemLoader(str(Path(self.root) / "templates")),
            trim_blocks=True,
            lstrip_blocks=True,
            keep_trailing_newline=True,
            autoescape=False,
        )
        env.filters = _KnownFilters(env.filters)
        env.compile_templates(str(out), extensions=["j2"], zip=None, ignore_errors=False)
        # the compiled code calls into the jinja2 that compiled it: `render` uses it only with that version
        (out / "JINJA2_VERSION").write_text(jinja2.__version__, encoding="utf-8")
        build_data["force_include"][str(out)] = "cantools_od/templates_compiled"

    def finalize(self, version: str, build_data: dict[str, Any], artifact_path: str) -> None:
        if self._out is not None:
            shutil.rmtree(self._out, ignore_errors=True)
