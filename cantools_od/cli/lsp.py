"""`cantools-od lsp`: the language server, on stdin and stdout."""

from __future__ import annotations

import click


@click.command(name="lsp")
@click.option("--stdio", is_flag=True, help="Talk over stdin/stdout (the only transport; editors pass it).")
def command(stdio: bool) -> None:
    """Serve the Language Server Protocol for EDS, DCF and XDD/XDC files: diagnostics as `lint`
    reports them, hover, go to definition, references, fixes, formatting as `fmt`, outline and
    completion. An editor starts it; see README, "Editors"."""
    from ..lsp.server import serve

    serve()
