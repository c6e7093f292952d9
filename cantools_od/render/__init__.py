"""Renderers: a DeviceView → files, through Jinja2 templates in templates/<target>/."""

from __future__ import annotations

import importlib
from collections.abc import Callable
from functools import cache

import jinja2

from ..resources import resource_dir
from . import escape, prose

# target name → module in this package with `render(view) -> dict[str, str]`
TARGETS = {"c": "c", "rust": "rust", "python": "python", "markdown": "markdown", "canopennode": "canopennode"}

Renderer = Callable[..., dict[str, str]]


@cache
def environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=jinja2.FileSystemLoader(str(resource_dir("templates"))),
        undefined=jinja2.StrictUndefined,
        trim_blocks=True,
        lstrip_blocks=True,
        keep_trailing_newline=True,
        autoescape=False,
    )
    env.filters.update(
        c_comment=escape.c_comment,
        c_string=escape.c_string,
        line_comment=escape.line_comment,
        rust_doc=escape.rust_doc,
        rust_string=escape.rust_string,
        python_string=escape.python_string,
        md=escape.markdown_text,
        md_cell=escape.markdown_cell,
        hex4=lambda n: f"{n:04X}",
        count=prose.count,
    )
    return env


def render_template(name: str, **context: object) -> str:
    """A template's text, joined in batches as it is generated: a large object dictionary's output is
    tens of MB, and holding all of Jinja's small pieces at once would take many times that."""
    whole: list[str] = []
    batch: list[str] = []
    for piece in environment().get_template(name).generate(**context):
        batch.append(piece)
        if len(batch) == 4096:
            whole.append("".join(batch))
            batch.clear()
    whole.append("".join(batch))
    return "".join(whole)


def renderer(target: str) -> Renderer:
    module = importlib.import_module(f"{__name__}.{TARGETS[target]}")
    render: Renderer = module.render
    return render
