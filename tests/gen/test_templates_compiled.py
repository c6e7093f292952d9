"""The wheel carries the templates compiled (hatch_build.py), so that `gen` does not compile them in every
process; the output through them is the golden tests' (they run the installed wheel)."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

from support import ROOT

_LOADED = """
import sys
import jinja2
if sys.argv[1] != "-":
    jinja2.__version__ = sys.argv[1]
from cantools_od.render import environment
env = environment()
for name in sys.argv[2:]:
    env.get_template(name)
print(type(env.loader).__name__)
"""


def _loader(tmp_path: Path, jinja_version: str) -> str:
    names = sorted(path.relative_to(ROOT / "templates").as_posix() for path in (ROOT / "templates").rglob("*.j2"))
    run = subprocess.run(
        [sys.executable, "-c", _LOADED, jinja_version, *names], capture_output=True, text=True, cwd=tmp_path
    )
    assert run.returncode == 0, run.stderr
    return run.stdout.strip()


def test_installed_wheel_loads_every_template_compiled(tmp_path: Path) -> None:
    assert _loader(tmp_path, "-") == "ModuleLoader"


def test_another_jinja2_compiles_the_sources(tmp_path: Path) -> None:
    # the compiled code calls into the jinja2 that compiled it: with another version, the sources are compiled
    assert _loader(tmp_path, "0.0") == "FileSystemLoader"
