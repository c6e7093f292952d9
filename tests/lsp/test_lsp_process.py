"""Large documents served by a process of their own (cantools_od/lsp/process.py): every feature answers there as in
the server itself, diagnostics equal `lint --format json`, and no such process outlives the document or the server,
whether the editor ends the session, just goes away, or the server is killed."""

from __future__ import annotations

import json
import os
import subprocess
import time
from pathlib import Path

import pytest
import pytest_lsp
from lspkit import SERVER, Lint, close_file, diagnostics_for, expected, open_file, seen, start, text_of
from lsprotocol import types
from pytest_lsp import LanguageClient

from support import CORPUS, EXAMPLES, cli_command

ASYNC = pytest.mark.asyncio(loop_scope="module")
EVERY_DOCUMENT = {"ownProcessAbove": 0}
"""Every document, however small, in a process of its own."""


def children_of(pid: int) -> list[int]:
    """The processes whose parent is `pid`."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            stat = (entry / "stat").read_text()
        except OSError:
            continue
        if int(stat.rpartition(")")[2].split()[1]) == pid:
            found.append(int(entry.name))
    return found


def alive(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()[0]
    except OSError:
        return False
    return state != "Z"


def wait_until(condition: object, seconds: float = 20) -> bool:
    deadline = time.monotonic() + seconds
    while time.monotonic() < deadline:
        if condition():  # type: ignore[operator]
            return True
        time.sleep(0.05)
    return False


def server_pid(client: LanguageClient) -> int:
    process = client._server
    assert process is not None
    return process.pid


@pytest_lsp.fixture(config=SERVER, scope="module")
async def client(lsp_client: LanguageClient):
    await start(lsp_client, EVERY_DOCUMENT)
    yield
    await lsp_client.shutdown_session()


def _corpus(names: tuple[str, ...]) -> list[Path]:
    found = [CORPUS / name for name in names if (CORPUS / name).is_file()]
    if not found:
        pytest.skip("../shared/eds-corpus is absent")
    return found


@ASYNC
async def test_a_document_in_its_own_process_is_checked_as_lint_checks_it(client: LanguageClient) -> None:
    files = _corpus(("canopendemo__demoDevice.eds", "faulhaber__605.3150.71-A-EK-3-60.eds"))
    lint = Lint(files)
    before = set(children_of(server_pid(client)))
    found = [await open_file(client, path) for path in files]
    findings = lint.result()
    for path, diagnostics in zip(files, found, strict=True):
        mine = [f for f in findings if Path(str(f["file"])).name == path.name]
        assert sorted(seen(diagnostics)) == sorted(expected(mine, text_of(path))), path.name
    assert len(set(children_of(server_pid(client))) - before) == len(files)  # one process for each
    for path in files:
        close_file(client, path)
    assert wait_until(lambda: set(children_of(server_pid(client))) <= before)


def _example(folder: Path) -> Path:
    path = folder / "device.eds"
    path.write_bytes((EXAMPLES / "cia402_drive.eds").read_bytes())
    return path


async def _opened(client: LanguageClient, folder: Path) -> tuple[Path, str, int]:
    """A copy of an example opened: its path, its URI and the process serving it (the only one)."""
    path = _example(folder)
    await open_file(client, path)
    (pid,) = children_of(server_pid(client))
    return path, path.resolve().as_uri(), pid


@ASYNC
async def test_every_feature_answers_from_the_documents_process(client: LanguageClient, tmp_path: Path) -> None:
    path, uri, pid = await _opened(client, tmp_path)
    lines = text_of(path).splitlines()
    header = lines.index("[1000]")
    document = types.TextDocumentIdentifier(uri)
    hover = await client.text_document_hover_async(types.HoverParams(document, types.Position(header + 1, 3)))
    assert hover is not None and "1000" in str(hover.contents)
    symbols = await client.text_document_document_symbol_async(types.DocumentSymbolParams(document))
    assert symbols and any("1000" in symbol.name for symbol in symbols)
    folding = await client.text_document_folding_range_async(types.FoldingRangeParams(document))
    assert folding
    everywhere = await client.workspace_symbol_async(types.WorkspaceSymbolParams(query="1018"))
    assert everywhere and all(symbol.location.uri == uri for symbol in everywhere)  # type: ignore[union-attr]
    formatted = await client.text_document_formatting_async(
        types.DocumentFormattingParams(document, types.FormattingOptions(4, True))
    )
    assert formatted is not None
    # An edit, checked in the document's process: the diagnostics of the new version equal lint's of the new text.
    line = next(n for n, text in enumerate(lines) if text.startswith("DataType=") and n > header)
    change = types.TextDocumentContentChangePartial(
        range=types.Range(types.Position(line, 0), types.Position(line + 1, 0)), text="DataType=0x0099\n"
    )
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version=2, uri=uri), [change])
    )
    diagnostics = await diagnostics_for(client, uri, 2)
    path.write_text("\n".join([*lines[:line], "DataType=0x0099", *lines[line + 1 :]]) + "\n")
    assert sorted(seen(diagnostics)) == sorted(expected(Lint([path]).result(), text_of(path)))
    close_file(client, path)
    assert wait_until(lambda: not alive(pid))


def _message(body: dict[str, object]) -> bytes:
    data = json.dumps({"jsonrpc": "2.0", **body}).encode()
    return b"Content-Length: %d\r\n\r\n" % len(data) + data


def _session(folder: Path) -> tuple[subprocess.Popen[bytes], int]:
    """A server started as an editor starts it, with one document open in a process of its own: (server, child)."""
    path = _example(folder)
    server = subprocess.Popen([*cli_command(), "lsp", "--stdio"], stdin=subprocess.PIPE, stdout=subprocess.DEVNULL)
    assert server.stdin is not None
    options = {"processId": os.getpid(), "rootUri": None, "capabilities": {}, "initializationOptions": EVERY_DOCUMENT}
    document = {"uri": path.as_uri(), "languageId": "eds", "version": 1, "text": text_of(path)}
    server.stdin.write(_message({"id": 1, "method": "initialize", "params": options}))
    server.stdin.write(_message({"method": "initialized", "params": {}}))
    server.stdin.write(_message({"method": "textDocument/didOpen", "params": {"textDocument": document}}))
    server.stdin.flush()
    assert wait_until(lambda: children_of(server.pid)), "no process of its own for the document"
    (child,) = children_of(server.pid)
    return server, child


@pytest.mark.parametrize("ending", ["shutdown and exit", "stdin closed", "server killed"])
def test_no_process_outlives_the_server(tmp_path: Path, ending: str) -> None:
    server, child = _session(tmp_path)
    assert server.stdin is not None
    if ending == "shutdown and exit":
        server.stdin.write(_message({"id": 2, "method": "shutdown"}) + _message({"method": "exit"}))
        server.stdin.flush()
    elif ending == "stdin closed":
        server.stdin.close()
    else:
        server.kill()
    server.wait(30)
    assert wait_until(lambda: not alive(child)), f"{ending}: the document's process {child} is still running"


@ASYNC
async def test_a_document_whose_process_stops_says_so(client: LanguageClient, tmp_path: Path) -> None:
    path, uri, pid = await _opened(client, tmp_path)
    os.kill(pid, 9)
    said = await diagnostics_for(client, uri, None)  # type: ignore[arg-type]
    assert [d.message for d in said] == [
        "the process checking this document stopped (exit code -9); close and reopen it"
    ]
    hover = await client.text_document_hover_async(
        types.HoverParams(types.TextDocumentIdentifier(uri), types.Position(1, 1))
    )
    assert hover is None  # the server answers (it has no such document), it does not wait for the dead process
    close_file(client, path)


def cpu_seconds(pid: int) -> float:
    """The CPU time a process has spent so far, all its threads (user and system)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


PADDING = 3_000_000
"""Empty objects in a member of the opening message that no server reads (JSON-RPC lets a client add members):
12 MB whose decoding takes far more CPU than passing them on, so that the difference stands out of the noise."""


@ASYNC
async def test_a_large_document_passes_to_its_process_undecoded(client: LanguageClient, tmp_path: Path) -> None:
    """The server finds the document of a large didOpen in the first bytes of the message and passes the message
    on as it came: its own CPU time over the opening and an edit sent right after stays well below what decoding
    that JSON once takes (CPU time, not wall time: a loaded machine slows neither); the edit reaches the
    document's process after the opening, and its diagnostics equal lint's of the edited text."""
    path = _example(tmp_path)
    uri, text = path.resolve().as_uri(), text_of(path)
    lines = text.splitlines(keepends=True)
    line = next(n for n, each in enumerate(lines) if each.startswith("DataType=") and n > lines.index("[1000]\n"))
    document = {"uri": uri, "languageId": "eds", "version": 1, "text": text}
    # The method after the parameters, as pygls clients write it (VS Code writes it first: both are found).
    message = {"params": {"textDocument": document, "padding": [{}] * PADDING}, "method": "textDocument/didOpen",
               "jsonrpc": "2.0"}  # fmt: skip
    body = json.dumps(message)
    started = time.process_time()
    json.loads(body)
    decoding = time.process_time() - started
    change = types.TextDocumentContentChangePartial(
        range=types.Range(types.Position(line, 0), types.Position(line + 1, 0)), text="DataType=0x0099\n"
    )
    server = server_pid(client)
    before = cpu_seconds(server)
    client.protocol._send_data(message)
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version=2, uri=uri), [change])
    )
    diagnostics = await diagnostics_for(client, uri, 2)
    spent = cpu_seconds(server) - before
    path.write_text("".join([*lines[:line], "DataType=0x0099\n", *lines[line + 1 :]]), newline="")
    assert sorted(seen(diagnostics)) == sorted(expected(Lint([path]).result(), text_of(path)))
    assert spent < decoding / 2, f"the server spent {spent:.3f} s of CPU; decoding the message takes {decoding:.3f} s"
    close_file(client, path)
