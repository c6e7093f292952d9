"""`cantools-od lsp`: the language server, on stdin and stdout."""

from __future__ import annotations

import signal
from types import FrameType

import click


@click.command(name="lsp")
@click.option("--stdio", is_flag=True, help="Talk over stdin/stdout (the only transport; editors pass it).")
def command(stdio: bool) -> None:
    """Serve the Language Server Protocol for EDS, DCF and XDD/XDC files: diagnostics as `lint`
    reports them, hover, go to definition, references, fixes, formatting as `fmt`, outline and
    completion. An editor starts it; see docs/editors.md."""
    from ..lsp.app import serve

    interrupted: list[int] = []

    def on_interrupt(signum: int, frame: FrameType | None) -> None:
        interrupted.append(signum)
        signal.default_int_handler(signum, frame)

    signal.signal(signal.SIGINT, on_interrupt)
    serve()
    if interrupted:  # pygls ends quietly on Ctrl-C; it is still an interruption (exit 130, as every command)
        raise KeyboardInterrupt
