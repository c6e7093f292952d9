"""Large documents served by a process of their own: a second `cantools-od lsp` per document, spoken to over a pipe.

The server is one Python process: while a thread of it reads and checks a 20 MB document, it holds the interpreter
lock through long calls in C (scanning the text, building the model), and a hover on another document waits for
them, seconds on a busy machine. A document whose text at opening is longer than `ownProcessAbove` characters is
therefore handed whole to a child server: every message about it (opening, edits, saving, closing, each request
and its cancellation) is passed on as it came, and the child's messages (diagnostics, answers, log lines) are
written to the editor as bytes, never decoded here, so nothing of the large document is read, checked or
converted in this process. The child is the same server (a document's features all work there as here) told
to keep its documents in process. It ends with the document, when this process ends (its stdin closes), and on
its own when its parent is gone (a watchdog: a killed server leaves no checker behind).
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import os
import re
import signal
import sys
import threading
import time
from collections.abc import Callable
from typing import Any, BinaryIO

from .rpc import say

PARENT = "CANTOOLS_OD_LSP_PARENT"
"""Set in a child's environment to its parent's process id: the child watches it and keeps every document."""
OWN_PROCESS_ABOVE = 2_000_000
"""Default of the `ownProcessAbove` setting: characters of a document's text at opening."""
SETTING = "ownProcessAbove"
SYMBOLS_WAIT = 2.0
"""Seconds a workspace symbol search waits for each child; one still busy (reading its document) adds nothing."""
_OWN = "cantools-od/"
"""Prefix of the ids of this server's own requests to a child (the editor's ids are passed on unchanged)."""
_ID = re.compile(rb'\{\s*"id":\s*("(?:[^"\\]|\\.)*"|-?\d+)')
STAND_IN = "cantools-od/standIn"
"""The method of the message pygls decodes in place of a large one (Recording); never seen by pygls' handlers."""
_HEAD = 4096
_METHOD = re.compile(rb'"method"\s*:\s*"(textDocument/did(?:Open|Change))"')
_URI = re.compile(rb'"uri"\s*:\s*("(?:[^"\\]|\\.)*")')
_ID_MEMBER = re.compile(rb'"id"\s*:')
_STOPPED = -32603


def _framed(body: bytes) -> bytes:
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def _frame(message: dict[str, Any]) -> bytes:
    return _framed(json.dumps(message).encode("utf-8"))


def _member(pattern: re.Pattern[bytes], body: bytes) -> re.Match[bytes] | None:
    """A member in the first or last bytes of a message, where all but its one large member are. A match cannot
    start inside a string: its second quote is unescaped, so it closes a string, and a colon follows only a key."""
    return pattern.search(body, 0, _HEAD) or pattern.search(body, max(len(body) - _HEAD, 0))


def _document_of(body: bytes) -> tuple[str, str] | None:
    """The method and document of a didOpen or didChange notification (the document's URI comes before its text in
    the message), else None."""
    method, uri = _member(_METHOD, body), _URI.search(body, 0, _HEAD)
    if method is None or uri is None or _member(_ID_MEMBER, body) is not None:
        return None
    try:
        found = json.loads(uri.group(1))
    except ValueError:
        return None
    return (method.group(1).decode(), found) if isinstance(found, str) else None


class Recording:
    """stdin as pygls reads it (a header line at a time, then a body), keeping the last body: the message pygls
    is reading, passed on to a child as it came (writing 20 MB of JSON again would hold this process).

    pygls reads in a thread of its pool, then decodes the body on the loop, all of it, before it reads the next
    message. A body longer than `above` bytes that opens or changes a document is therefore given to pygls as a
    stand-in of a few bytes naming the document (`STAND_IN`), and `Children.take` passes the body kept here on
    to the document's child, on the loop and in the order the messages came; the 20 MB are never decoded here."""

    def __init__(self, stream: BinaryIO, above: Callable[[], int | None] = lambda: None) -> None:
        self.stream, self.last, self.above = stream, b"", above

    def readline(self) -> bytes:
        return self.stream.readline()

    def read(self, size: int = -1) -> bytes:
        self.last = self.stream.read(size)
        above = self.above()
        found = _document_of(self.last) if above is not None and len(self.last) > above else None
        if found is None:
            return self.last
        method, uri = found
        return json.dumps({"jsonrpc": "2.0", "method": STAND_IN, "params": {"method": method, "uri": uri}}).encode()


def _uri_of(params: object) -> str | None:
    """The document a message is about: its textDocument, or a code action's (codeAction/resolve)."""
    if not isinstance(params, dict):
        return None
    document, data = params.get("textDocument"), params.get("data")
    uri = document.get("uri") if isinstance(document, dict) else data.get("uri") if isinstance(data, dict) else None
    return uri if isinstance(uri, str) else None


def kept_in_process(settings: object) -> object:
    """The settings as a child gets them: it keeps its documents (it never starts a child of its own)."""
    if not isinstance(settings, dict):
        return {SETTING: None}
    if isinstance(settings.get("cantools-od"), dict):
        return {**settings, "cantools-od": {**settings["cantools-od"], SETTING: None}}
    return {**settings, SETTING: None}


class Child:
    """One document's server process, its pipe, and the editor's requests it has not answered yet."""

    def __init__(self, uri: str, initialize: dict[str, Any], relay: Callable[[bytes], None]) -> None:
        self.uri, self.relay = uri, relay
        self.outbox: list[bytes] = [_frame({"jsonrpc": "2.0", "id": f"{_OWN}0", "method": "initialize",
                                            "params": initialize}),
                                    _frame({"jsonrpc": "2.0", "method": "initialized", "params": {}})]  # fmt: skip
        self.process: asyncio.subprocess.Process | None = None
        self.pending: set[str | int] = set()
        self.answers: dict[str, asyncio.Future[Any]] = {}
        self.closing = False
        self.numbers = 0
        self.on_stop: Callable[[Child, int | None], None] = lambda child, code: None
        self.task = asyncio.get_running_loop().create_task(self._run())

    def send(self, message: dict[str, Any] | bytes) -> None:
        """A message, or a message's frame as it came."""
        frame = message if isinstance(message, bytes) else _frame(message)
        if self.process is None or self.process.stdin is None:
            self.outbox.append(frame)
        elif not self.process.stdin.is_closing():
            self.process.stdin.write(frame)  # buffered by the loop: never waits for the child to read

    def request(self, method: str, params: object) -> asyncio.Future[Any]:
        """This server's own request to the child; its answer's result (None when the child stops first)."""
        self.numbers += 1
        number = f"{_OWN}{self.numbers}"
        found = self.answers[number] = asyncio.get_running_loop().create_future()
        self.send({"jsonrpc": "2.0", "id": number, "method": method, "params": params})
        return found

    def close(self) -> None:
        """The document is closed: the child ends once it has answered what it was sent (its stdin closes)."""
        self.closing = True
        self.send({"jsonrpc": "2.0", "id": f"{_OWN}shutdown", "method": "shutdown"})
        self.send({"jsonrpc": "2.0", "method": "exit"})
        if self.process is not None and self.process.stdin is not None:
            self.process.stdin.close()

    async def _run(self) -> None:
        environment = {**os.environ, PARENT: str(os.getpid())}
        command = (sys.executable, "-m", "cantools_od", "lsp", "--stdio")
        try:
            self.process = await asyncio.create_subprocess_exec(
                *command, stdin=asyncio.subprocess.PIPE, stdout=asyncio.subprocess.PIPE, env=environment
            )
        except OSError as error:
            say(f"{self.uri}: cannot start a process for it: {error}")
            self._stopped(None)
            return
        assert self.process.stdin is not None and self.process.stdout is not None
        for frame in self.outbox:
            self.process.stdin.write(frame)
        self.outbox = []
        if self.closing:
            self.process.stdin.close()
        try:
            await self._read(self.process.stdout)
        except asyncio.CancelledError:  # the server's loop is ending: the child ends with it
            if self.process.returncode is None:
                self.process.kill()
            raise
        self._stopped(await self.process.wait())

    async def _read(self, stdout: asyncio.StreamReader) -> None:
        while True:
            length = None
            while True:
                header = await stdout.readline()
                if not header:
                    return
                if header in (b"\r\n", b"\n"):
                    break
                name, _, value = header.partition(b":")
                if name.strip().lower() == b"content-length":
                    length = int(value)
            if length is None:
                continue
            self._received(await stdout.readexactly(length))

    def _received(self, body: bytes) -> None:
        """A message of the child's: an answer to this server's own request, else the editor's, as it came."""
        found = _ID.match(body)
        number: str | int | None = json.loads(found.group(1)) if found is not None else None
        if isinstance(number, str) and number.startswith(_OWN):
            answer = self.answers.pop(number, None)
            if answer is not None and not answer.done():
                answer.set_result(json.loads(body).get("result"))
            return
        if number is not None:
            self.pending.discard(number)
        self.relay(_framed(body))

    def _stopped(self, code: int | None) -> None:
        for answer in self.answers.values():
            if not answer.done():
                answer.set_result(None)
        self.answers = {}
        self.on_stop(self, code)


class Children:
    """The server's children, one for each large open document, and what passes to them."""

    def __init__(self, relay: Callable[[bytes], None], stopped: Callable[[str, str], None]) -> None:
        self.relay, self.stopped = relay, stopped
        self.above: int | None = OWN_PROCESS_ABOVE
        self.initialize: dict[str, Any] = {}
        self.of: dict[str, Child] = {}
        self.spawned: list[Child] = []
        self.recording: Recording | None = None
        """The server's stdin, when it reads one: each message passed on as it came."""

    def _as_it_came(self, message: dict[str, Any]) -> dict[str, Any] | bytes:
        return _framed(self.recording.last) if self.recording is not None and self.recording.last else message

    def configure(self, settings: dict[str, Any]) -> None:
        if SETTING in settings:
            above = settings[SETTING]
            self.above = above if isinstance(above, int) and not isinstance(above, bool) and above >= 0 else None

    def record(self, stream: BinaryIO) -> Recording:
        """The server's stdin, read so that a large document's messages pass to its child undecoded."""
        self.recording = Recording(stream, lambda: self.above)
        return self.recording

    def take(self, message: dict[str, Any]) -> dict[str, Any] | None:
        """Pass the message on to the child it concerns: None when it is the child's alone, else the message for
        this server (the whole message a stand-in stood for, decoded now)."""
        method, params = message.get("method"), message.get("params")
        if method == STAND_IN and isinstance(params, dict):
            return self._stood_in(params)
        if method == "initialize" and isinstance(params, dict):
            self.initialize = {**params, "initializationOptions": kept_in_process(params.get("initializationOptions"))}
            return message
        if method == "workspace/didChangeConfiguration" and isinstance(params, dict):
            for each in self.of.values():
                each.send({**message, "params": {**params, "settings": kept_in_process(params.get("settings"))}})
            return message
        if method == "$/cancelRequest" and isinstance(params, dict):
            owner = next((child for child in self.of.values() if params.get("id") in child.pending), None)
            if owner is not None:
                owner.send(self._as_it_came(message))
            return message if owner is None else None
        if method == "textDocument/didOpen":
            return None if self._opened(message) else message
        child = self.of.get(_uri_of(params) or "")
        if child is None:
            return message
        child.send(self._as_it_came(message))
        if "id" in message:
            child.pending.add(message["id"])
        if method == "textDocument/didClose":
            del self.of[child.uri]
            child.close()
        return None

    def _stood_in(self, params: dict[str, Any]) -> dict[str, Any] | None:
        """A large didOpen or didChange (Recording): its body passed on as it came to the document's child (a new
        one for didOpen, as `_opened` makes); only when no child is to have it, decoded for this server."""
        uri, body = params.get("uri"), self.recording.last if self.recording is not None else b""
        large = self.above is not None and len(body) > self.above
        if params.get("method") == "textDocument/didOpen" and isinstance(uri, str) and large:
            old = self.of.pop(uri, None)
            if old is not None:
                old.close()
            self._spawn(uri).send(_framed(body))
            return None
        if params.get("method") == "textDocument/didChange" and uri in self.of:
            self.of[uri].send(_framed(body))
            return None
        whole = json.loads(body)
        return self.take(whole) if isinstance(whole, dict) else whole

    def _spawn(self, uri: str) -> Child:
        child = self.of[uri] = Child(uri, self.initialize, self.relay)
        child.on_stop = self._stopped
        self.spawned.append(child)
        return child

    def _opened(self, message: dict[str, Any]) -> bool:
        params = message.get("params")
        document = params.get("textDocument") if isinstance(params, dict) else None
        uri = document.get("uri") if isinstance(document, dict) else None
        text = document.get("text") if isinstance(document, dict) else None
        if not isinstance(uri, str) or not isinstance(text, str):
            return False
        old = self.of.pop(uri, None)
        if old is not None:
            old.close()
        if self.above is None or len(text) <= self.above:
            return False
        self._spawn(uri).send(self._as_it_came(message))
        return True

    def _stopped(self, child: Child, code: int | None) -> None:
        for number in child.pending:
            error = {"code": _STOPPED, "message": "the process checking this document stopped"}
            self.relay(_frame({"jsonrpc": "2.0", "id": number, "error": error}))
        self.spawned.remove(child)
        if child.closing or self.of.get(child.uri) is not child:
            return
        del self.of[child.uri]
        self.stopped(child.uri, f"the process checking this document stopped (exit code {code}); close and reopen it")

    async def symbols(self, query: str) -> list[Any]:
        """Workspace symbols of the children's documents."""
        asked = [child.request("workspace/symbol", {"query": query}) for child in self.of.values()]
        if not asked:
            return []
        done, _ = await asyncio.wait(asked, timeout=SYMBOLS_WAIT)
        found: list[Any] = []
        for answer in asked:
            result = answer.result() if answer in done else None
            found += result if isinstance(result, list) else []
        return found

    def close_all(self) -> None:
        for child in list(self.of.values()):
            child.close()
        self.of = {}

    def end(self) -> None:
        """When the server ends (its loop has stopped): every child still running killed."""
        for child in self.spawned:
            pid = child.process.pid if child.process is not None else None
            if pid is not None and child.process is not None and child.process.returncode is None:
                with contextlib.suppress(ProcessLookupError):
                    os.kill(pid, signal.SIGKILL)


def watch_parent() -> None:
    """In a child: end when the parent has gone (killed, crashed), even in the middle of a check."""
    parent = os.environ.get(PARENT)
    if parent is None or not parent.isdigit():
        return

    def watch() -> None:
        while os.getppid() == int(parent):
            time.sleep(0.5)
        os._exit(1)

    threading.Thread(target=watch, name="parent-watch", daemon=True).start()
