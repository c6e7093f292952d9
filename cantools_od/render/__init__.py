"""Renderers: a DeviceView → files, through Jinja2 templates in templates/<target>/."""

from __future__ import annotations

import importlib
from collections.abc import Callable, Iterable, Iterator
from functools import cache
from typing import Generic, TypeVar

import jinja2

from ..resources import resource_dir
from . import escape, prose

# target name → module in this package with `stream(view) -> dict[str, Iterable[str]]` (file name → its text
# in pieces, produced as they are read) and `render(view) -> dict[str, str]` (the same, whole)
TARGETS = {
    "c": "c",
    "rust": "rust",
    "python": "python",
    "markdown": "markdown",
    "canopennode": "canopennode",
    "html": "html",
}

Renderer = Callable[..., dict[str, str]]
Streamer = Callable[..., dict[str, Iterable[str]]]
T = TypeVar("T")


class Each(Generic[T]):
    """Items made each time they are iterated, one object at a time: the per-entry parts of a large
    object dictionary's files would take many times its size if all were held at once."""

    def __init__(self, make: Callable[[], Iterator[T]], length: int | None = None) -> None:
        self._make = make
        self._length = length

    def __iter__(self) -> Iterator[T]:
        return self._make()

    def __bool__(self) -> bool:
        return bool(self._length) if self._length is not None else next(self._make(), None) is not None

    def __len__(self) -> int:
        if self._length is None:
            raise TypeError("the number of items is not known before they are made")
        return self._length


def _loader() -> jinja2.BaseLoader:
    """The templates as the wheel's build compiled them (hatch_build.py), when this jinja2 compiled them:
    compiling them took 25-115 ms of every `gen`; their sources otherwise (a checkout, another jinja2)."""
    compiled = resource_dir("templates_compiled")
    try:
        built_with = (compiled / "JINJA2_VERSION").read_text(encoding="utf-8")
    except OSError:
        built_with = None
    if built_with == jinja2.__version__:
        return jinja2.ModuleLoader(str(compiled))
    return jinja2.FileSystemLoader(str(resource_dir("templates")))


@cache
def environment() -> jinja2.Environment:
    env = jinja2.Environment(
        loader=_loader(),
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
        xml=escape.xml_text,
        xml_comment=escape.xml_comment,
        hex4=lambda n: f"{n:04X}",
        count=prose.count,
    )
    return env


def stream_template(name: str, **context: object) -> Iterator[str]:
    """A template's text in pieces of a few thousand of Jinja's, as it is generated: a large object
    dictionary's output is hundreds of MB, which need never be held at once."""
    batch: list[str] = []
    for piece in environment().get_template(name).generate(**context):
        batch.append(piece)
        if len(batch) == 4096:
            yield "".join(batch)
            batch.clear()
    yield "".join(batch)


def render_template(name: str, **context: object) -> str:
    """A template's text."""
    return "".join(stream_template(name, **context))


def whole(files: dict[str, Iterable[str]]) -> dict[str, str]:
    """Streamed files, each joined into one text."""
    return {name: "".join(pieces) for name, pieces in files.items()}


def renderer(target: str) -> Renderer:
    """The target's `render`: every file's whole text."""
    module = importlib.import_module(f"{__name__}.{TARGETS[target]}")
    render: Renderer = module.render
    return render


def streamer(target: str) -> Streamer:
    """The target's `stream`: every file's text in pieces, rendered as they are read."""
    module = importlib.import_module(f"{__name__}.{TARGETS[target]}")
    stream: Streamer = module.stream
    return stream
