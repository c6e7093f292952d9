"""The language server put together: document synchronisation on the server's state (server.py) and every
request's handler (features.py); `serve` runs it on stdin/stdout."""

from __future__ import annotations

import contextlib
import os
import sys

from lsprotocol import types

from . import features
from .document import Encoding, path_of
from .process import PARENT, watch_parent
from .rpc import log_in_one_line
from .server import OdServer, Open
from .text import faster


def _resolves(capabilities: types.ClientCapabilities) -> bool:
    document = capabilities.text_document
    support = document.code_action.resolve_support if document and document.code_action else None
    return support is not None and "edit" in support.properties


def build() -> OdServer:
    server = OdServer()

    @server.feature(types.INITIALIZE)
    def initialize(ls: OdServer, params: types.InitializeParams) -> None:
        ls.resolves = _resolves(params.capabilities)
        faster(ls.workspace)
        ls.configure(params.initialization_options)

    @server.feature(types.WORKSPACE_DID_CHANGE_CONFIGURATION)
    def did_change_configuration(ls: OdServer, params: types.DidChangeConfigurationParams) -> None:
        ls.configure(params.settings)
        ls.recheck_all()

    @server.feature(types.SHUTDOWN)
    def shutdown(ls: OdServer, params: None) -> None:
        ls.children.close_all()

    @server.feature(types.TEXT_DOCUMENT_DID_OPEN)
    def did_open(ls: OdServer, params: types.DidOpenTextDocumentParams) -> None:
        uri = params.text_document.uri
        _closed(ls.open.pop(uri, None))
        ls.open[uri] = Open.of(uri)
        ls.schedule(uri, 0)

    @server.feature(types.TEXT_DOCUMENT_DID_CHANGE)
    def did_change(ls: OdServer, params: types.DidChangeTextDocumentParams) -> None:
        ls.edited(params.text_document.uri)

    @server.feature(types.TEXT_DOCUMENT_DID_SAVE)
    def did_save(ls: OdServer, params: types.DidSaveTextDocumentParams) -> None:
        uri = params.text_document.uri
        state = ls.open.get(uri)
        encoding = Encoding.of_file(path_of(uri))
        if state is not None and encoding != state.encoding:  # the file's bytes are the editor's now
            state.encoding, state.whole = encoding, True
        ls.schedule(uri, 0)  # the configuration beside it may have changed

    @server.feature(types.TEXT_DOCUMENT_DID_CLOSE)
    def did_close(ls: OdServer, params: types.DidCloseTextDocumentParams) -> None:
        uri = params.text_document.uri
        _closed(ls.open.pop(uri, None))
        ls.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri, []))

    features.register(server)
    return server


def _closed(state: Open | None) -> None:
    if state is None:
        return
    if state.pending is not None:
        state.pending.cancel()
    state.worker.shutdown(wait=False, cancel_futures=True)


def serve() -> None:
    """Serve on stdin/stdout until the client says exit or stdin ends; then no process of ours is left running.
    A child (process.py) ends at once then, even in the middle of a check: nobody waits for it."""
    log_in_one_line()
    server = build()
    child = PARENT in os.environ
    if child:
        server.children.above = None
        watch_parent()
    stdin = server.children.record(sys.stdin.buffer)
    server.start_io(stdin)  # type: ignore[arg-type]  # read as a file: lines, then bodies
    server.children.end()
    if child:
        with contextlib.suppress(ValueError, OSError):  # pygls may have closed stdout
            sys.stdout.flush()
        os._exit(0)
