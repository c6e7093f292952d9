"""Wheel build steps:
- the Jinja templates compiled to Python modules, so that `gen` does not compile them in every process
  (jinja2's `ModuleLoader` loads them; pip byte-compiles them at install like any module);
- the readers' compiled parts, each an extension module built by setuptools' `build_ext`, which knows each
  platform's compiler and flags: the EDS reader's per-line scanner (cantools_od/eds/_scan.c) and the XML reader's
  per-element byte work (cantools_od/xdd/_tags.c). Where they cannot be compiled (no C compiler), the wheel is
  built without them, says so, and the readers use the same code in Python (eds/ini.py, xdd/safe.py and
  xdd/locations.py).

Runs in the build environment, where the package's own dependencies are absent: only jinja2 and setuptools are
imported.
The renderer uses the compiled templates only with the jinja2 version that compiled them (JINJA2_VERSION).
The options that change how a template compiles are the renderer's (cantools_od/render/__init__.py:
`environment()`); the golden tests of `gen` run the installed wheel, so a difference would show there.
"""

from __future__ import annotations

import shutil
import sys
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


EXTENSIONS = ("cantools_od.eds._scan", "cantools_od.xdd._tags")
"""Module names; each is built from the C file of the same path."""


def compile_extensions(root: Path, out: Path) -> list[Path] | None:
    """The extension modules built into `out`; None, with a line on stderr, when they cannot be compiled here."""
    from setuptools import Distribution, Extension
    from setuptools.errors import CCompilerError, CompileError, ExecError, LinkError, PlatformError

    modules = [Extension(name, [str(root.joinpath(*name.split(".")).with_suffix(".c"))]) for name in EXTENSIONS]
    dist = Distribution({"name": "cantools-od", "ext_modules": modules})
    command = dist.get_command_obj("build_ext")
    command.build_lib = str(out / "lib")
    command.build_temp = str(out / "temp")
    try:
        command.ensure_finalized()
        command.run()
    except (CCompilerError, CompileError, ExecError, LinkError, PlatformError) as why:
        print(
            f"cantools-od: the readers' compiled parts were not built ({why}); the readers use their Python form",
            file=sys.stderr,
        )
        return None
    return [Path(command.get_ext_fullpath(name)) for name in EXTENSIONS]


class WheelHook(BuildHookInterface):  # type: ignore[type-arg]
    PLUGIN_NAME = "templates-and-extensions"
    _out: Path | None = None

    def initialize(self, version: str, build_data: dict[str, Any]) -> None:
        if self.target_name != "wheel":
            return
        out = self._out = Path(tempfile.mkdtemp(prefix="cantools-od-build-"))
        built = compile_extensions(Path(self.root), out / "extensions")
        if built is not None:
            for name, path in zip(EXTENSIONS, built, strict=True):
                folder = "/".join(name.split(".")[:-1])
                build_data["force_include"][str(path)] = f"{folder}/{path.name}"
            build_data["pure_python"] = False
            build_data["infer_tag"] = True  # the extension is for this interpreter and platform
        self._templates(out / "templates", build_data)

    def _templates(self, out: Path, build_data: dict[str, Any]) -> None:
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
