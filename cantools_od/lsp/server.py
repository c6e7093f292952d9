"""The server's wiring: documents in, analyses out, one feature module per kind of request."""

from __future__ import annotations

import asyncio
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass, field
from typing import Any, TypeVar

from lsprotocol import types
from pygls.lsp.server import LanguageServer

from .. import __version__
from ..lint import LintOptions
from ..model.cia301.cobid import ALL_NODE_IDS
from .diagnostics import diagnostics
from .document import Analysis, Encoding, analyse, path_of
from .incremental import reanalyse
from .positions import Lines
from .process import Children
from .quick import quick_findings
from .rpc import OdProtocol, is_parse_error, say
from .where import Index

DEBOUNCE = 0.1
"""Seconds of quiet after an edit before the document is read and linted again, when the edit follows another
within that time (a burst: typing, a paste in steps, an undo); an edit after a quiet spell is checked at once."""

EAGER_INDEX = 2_000_000
"""Characters up to which a document's index (where hover and navigation look keys up) is made after each check,
in its queue; a larger one's is made at the first request that needs it (seconds of work for 20 MB, for nothing
when nobody hovers)."""


@dataclass
class Open:
    """An open document: its encoding on disk, its queue of work, its last analysis and the re-check waiting."""

    encoding: Encoding
    worker: ThreadPoolExecutor = field(
        default_factory=lambda: ThreadPoolExecutor(max_workers=1, thread_name_prefix="lint")
    )
    """This document's queue: checks, fixes, outline and formatting of one document run one after another,
    beside (not behind) those of every other document."""
    analysis: Analysis | None = None
    lines: Lines | None = None
    pending: asyncio.TimerHandle | None = None
    changed: float = float("-inf")
    """When (the event loop's clock) the text last changed."""
    latest: Analysis | None = None
    """The worker's newest analysis, published or not yet: what the next check starts from (the worker runs
    checks one after another, so an edit made while one runs is checked from its result)."""
    cache: dict[str, Any] = field(default_factory=dict)
    """What the features derive from the analysis (indexes of lines), dropped with it."""
    whole: bool = False
    """The next check reads the whole text (the settings changed: nothing of the last check is kept)."""
    told: bool = False
    """The user was shown once why a range is not formatted (format on paste would show it at every paste)."""

    @staticmethod
    def of(uri: str) -> Open:
        return Open(Encoding.of_file(path_of(uri)))


R = TypeVar("R")


class OdServer(LanguageServer):
    def __init__(self) -> None:
        super().__init__(
            "cantools-od",
            __version__,
            text_document_sync_kind=types.TextDocumentSyncKind.Incremental,
            protocol_cls=OdProtocol,
        )
        self.open: dict[str, Open] = {}
        self.options = LintOptions()
        self.rules_url: str | None = None
        self.settings: dict[str, Any] = {}
        self.resolves = False
        """The client asks for a code action's edit when the user picks it (codeAction/resolve)."""
        self.tasks: set[asyncio.Task[None]] = set()
        self.children = Children(self._relay, self._child_stopped)
        """The processes that serve the large documents (process.py)."""
        assert isinstance(self.protocol, OdProtocol)
        self.protocol.divert = self.children.take

    def _relay(self, data: bytes) -> None:
        """A child's message, framed, written to the editor as it came."""
        writer = self.protocol.writer
        if writer is not None:  # stdin/stdout, the only transport: a plain write
            writer.write(data)

    def _child_stopped(self, uri: str, reason: str) -> None:
        start = types.Range(types.Position(0, 0), types.Position(0, 0))
        found = [types.Diagnostic(start, reason, types.DiagnosticSeverity.Error, source="cantools-od")]
        self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri, found))
        say(f"{uri}: {reason}")

    def configure(self, settings: object) -> None:
        """initializationOptions or workspace/didChangeConfiguration's settings (those under "cantools-od" when
        given so, as VS Code sends them): {"nodeId": 5, "canFd": true, "profile": "canopennode", "rulesUrl": "...",
        "ownProcessAbove": 2000000}; a setting not given keeps its value."""
        if isinstance(settings, dict) and isinstance(settings.get("cantools-od"), dict):
            settings = settings["cantools-od"]
        if not isinstance(settings, dict):
            return
        self.settings.update(settings)
        settings = self.settings
        self.children.configure(settings)
        node_id = settings.get("nodeId")
        profile = settings.get("profile")
        self.options = LintOptions(
            can_fd=settings.get("canFd") is True,
            node_id=node_id if isinstance(node_id, int) and node_id in ALL_NODE_IDS else None,
            profile=profile if profile == "canopennode" else None,
        )
        url = settings.get("rulesUrl")
        self.rules_url = url if isinstance(url, str) and url else None

    def report_server_error(self, error: Exception, source: Any) -> None:
        """An error outside a request: one line in the log, never a pop-up with a Python exception's name."""
        if is_parse_error(error):  # pygls has logged it
            assert isinstance(self.protocol, OdProtocol)
            self.protocol.parse_error(error)
            return
        say(f"{type(error).__name__}: {error}")

    def recheck_all(self) -> None:
        """Check every open document again from its whole text (the settings changed)."""
        for uri, state in self.open.items():
            state.whole = True
            self.schedule(uri, 0)

    async def in_worker(self, uri: str, function: Callable[..., R], *args: Any) -> R:
        """`function(*args)` in the document's queue; cancelled (not started) when the request is."""
        state = self.open[uri]
        return await asyncio.get_running_loop().run_in_executor(state.worker, function, *args)

    def text(self, uri: str) -> str:
        return self.workspace.get_text_document(uri).source

    def current(self, uri: str) -> tuple[Analysis, Lines, Open] | None:
        """The last analysis of an open document, with its lines."""
        state = self.open.get(uri)
        if state is None or state.analysis is None or state.lines is None:
            return None
        return state.analysis, state.lines, state

    def schedule(self, uri: str, delay: float) -> None:
        state = self.open.get(uri)
        if state is None:
            return
        if state.pending is not None:
            state.pending.cancel()
        state.pending = asyncio.get_running_loop().call_later(delay, self._start_check, uri)

    def edited(self, uri: str) -> None:
        """Check the text after an edit: at once after a quiet spell, else when the burst of edits pauses."""
        state = self.open.get(uri)
        if state is None:
            return
        now = asyncio.get_running_loop().time()
        burst = state.pending is not None or now - state.changed < DEBOUNCE
        state.changed = now
        self.schedule(uri, DEBOUNCE if burst else 0)

    def _start_check(self, uri: str) -> None:
        task = asyncio.get_running_loop().create_task(self.check(uri))
        self.tasks.add(task)  # the loop keeps only a weak reference to a task
        task.add_done_callback(self.tasks.discard)

    async def check(self, uri: str) -> None:
        """Read and lint the document's current text in the worker, then publish, unless it changed meanwhile."""
        state = self.open.get(uri)
        if state is None:
            return
        state.pending = None
        document = self.workspace.get_text_document(uri)
        text, version = document.source, document.version
        analysis = await self.analysed(uri, state, text, version)
        try:  # the lines of a large text take a while to find: not on the loop that answers every document
            lines, found = await self.in_worker(uri, self._published, analysis, text)
        except RuntimeError:  # closed meanwhile
            return
        if self.open.get(uri) is not state or self.workspace.get_text_document(uri).version != version:
            return
        state.analysis, state.lines, state.cache = analysis, lines, {}
        self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri, found, version))
        if analysis.device is not None and len(text) <= EAGER_INDEX:  # made beside the loop, not at the first hover
            try:
                index = await self.in_worker(uri, Index, analysis.device)
            except RuntimeError:  # closed meanwhile
                return
            if state.analysis is analysis:
                state.cache.setdefault("index", index)

    def _published(self, analysis: Analysis, text: str) -> tuple[Lines, list[types.Diagnostic]]:
        lines = Lines(text)
        return lines, diagnostics(analysis, lines, self.rules_url)

    async def analysed(self, uri: str, state: Open, text: str, version: int | None) -> Analysis:
        """The text read and linted in the worker: after an edit inside one object, only that object read
        again (incremental.py); otherwise the quick findings published first, then the whole text read."""
        loop = asyncio.get_running_loop()
        if state.whole:
            state.whole, state.latest = False, None
        elif state.analysis is not None:
            try:
                found = await loop.run_in_executor(state.worker, self._reanalysed, uri, state, text, version)
            except Exception as error:  # the whole text read answers all the same
                say(f"{uri}: incremental check: {type(error).__name__}: {error}")
                found = None
            if found is not None:
                return found
            await self.publish_quick(uri, state.analysis, text, version)
        try:
            return await loop.run_in_executor(state.worker, self._analysed, uri, state, text, version)
        except Exception as error:  # a bug must not stop the server: say it in one line
            say(f"{uri}: {type(error).__name__}: {error}")
            return Analysis(version, text, None, refusal=("LNT001", f"cannot check: {type(error).__name__}: {error}"))

    def _reanalysed(self, uri: str, state: Open, text: str, version: int | None) -> Analysis | None:
        """In the worker: `reanalyse` from the worker's newest analysis."""
        base = state.latest or state.analysis
        found = reanalyse(base, uri, text, version, state.encoding, self.options) if base is not None else None
        if found is not None:
            state.latest = found
        return found

    def _analysed(self, uri: str, state: Open, text: str, version: int | None) -> Analysis:
        """In the worker: `analyse`, kept as the worker's newest analysis."""
        state.latest = analyse(uri, text, version, state.encoding, self.options)
        return state.latest

    async def publish_quick(self, uri: str, before: Analysis, text: str, version: int | None) -> None:
        """Publish the quick findings of an edit inside one object (quick.py), without a version: the
        exact ones, published with the version, follow."""
        state = self.open[uri]
        try:
            found = await asyncio.get_running_loop().run_in_executor(
                state.worker, self._quick, uri, before, text, state.encoding
            )
        except Exception as error:  # the full check answers all the same
            say(f"{uri}: quick check: {type(error).__name__}: {error}")
            return
        if found is None or self.open.get(uri) is not state or self.workspace.get_text_document(uri).version != version:
            return
        self.text_document_publish_diagnostics(types.PublishDiagnosticsParams(uri, found))

    def _quick(self, uri: str, before: Analysis, text: str, encoding: Encoding) -> list[types.Diagnostic] | None:
        """In the worker: the quick findings as diagnostics."""
        found = quick_findings(before, text, uri, encoding, self.options)
        if found is None:
            return None
        return diagnostics(Analysis(None, text, None, found), Lines(text), self.rules_url)
