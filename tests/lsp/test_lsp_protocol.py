"""What editors send besides text: settings that change, a change to a document never opened, messages that
do not fit, code actions resolved when chosen, completion in a header the editor closed itself."""

from __future__ import annotations

import asyncio
import json
import re
import shutil
import subprocess
from pathlib import Path

import pytest
import pytest_lsp
from lspkit import SERVER, Lint, close_file, diagnostics_for, expected, open_file, seen, start
from lsprotocol import types
from pytest_lsp import LanguageClient

from cantools_od.lsp.edits import apply

from support import EXAMPLES, ROOT, cli_command

pytestmark = pytest.mark.asyncio(loop_scope="module")
DRIVE = EXAMPLES / "cia402_drive.eds"


@pytest_lsp.fixture(config=SERVER, scope="module")
async def client(lsp_client: LanguageClient):
    await start(lsp_client)
    yield
    await lsp_client.shutdown_session()


async def test_a_changed_setting_checks_every_open_document_again(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "drive.eds"
    shutil.copyfile(DRIVE, path)
    first = await open_file(client, path)
    assert sorted(seen(first)) == sorted(expected(Lint([path]).result(), path.read_text()))
    settings = {"cantools-od": {"profile": "canopennode", "nodeId": None, "command": ["cantools-od", "lsp"]}}
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams(settings))
    uri = path.resolve().as_uri()
    while True:  # republished for the same version, with the profile's findings
        client.arrived.clear()  # type: ignore[attr-defined]
        await asyncio.wait_for(client.arrived.wait(), 60)  # type: ignore[attr-defined]
        again = client.published.pop((uri, 1), None)  # type: ignore[attr-defined]
        if again is not None:
            break
    profiled = Lint([path], "--profile", "canopennode").result()
    assert any(str(f["code"]).startswith("CNO") for f in profiled)
    assert sorted(seen(again)) == sorted(expected(profiled, path.read_text()))
    client.workspace_did_change_configuration(types.DidChangeConfigurationParams({"cantools-od": {"profile": None}}))
    close_file(client, path)


def test_every_server_setting_is_a_vscode_setting() -> None:
    package = json.loads((ROOT / "editors" / "vscode" / "package.json").read_text(encoding="utf-8"))
    names = set(package["contributes"]["configuration"]["properties"])
    assert {"cantools-od.nodeId", "cantools-od.canFd", "cantools-od.profile"} <= names
    extension = (ROOT / "editors" / "vscode" / "src" / "extension.ts").read_text(encoding="utf-8")
    assert 'configurationSection: "cantools-od"' in extension
    for setting in ("nodeId", "canFd", "profile"):
        assert "settings.get<" in extension and f'("{setting}"' in extension, setting


async def test_a_change_to_a_document_never_opened_shows_no_error(client: LanguageClient, tmp_path: Path) -> None:
    shown = len(client.messages)
    uri = (tmp_path / "never.eds").as_uri()
    change = types.TextDocumentContentChangePartial(types.Range(types.Position(0, 0), types.Position(0, 0)), "x")
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(2, uri), [change])
    )
    path = tmp_path / "drive.eds"
    shutil.copyfile(DRIVE, path)
    await open_file(client, path)  # the server went on, and has answered what followed
    assert client.messages[shown:] == []
    close_file(client, path)


def _frame(body: bytes) -> bytes:
    return b"Content-Length: %d\r\n\r\n" % len(body) + body


def test_messages_that_do_not_fit_are_answered_and_logged_in_one_line() -> None:
    initialize = {"jsonrpc": "2.0", "id": 1, "method": "initialize", "params": {"capabilities": {}}}
    hover = {"jsonrpc": "2.0", "id": 7, "method": "textDocument/hover", "params": {"textDocument": 5}}
    shutdown = {"jsonrpc": "2.0", "id": 2, "method": "shutdown"}
    sent = (
        _frame(b"{not json")
        + _frame(json.dumps([1, 2]).encode())
        + _frame(json.dumps(initialize).encode())
        + _frame(json.dumps(hover).encode())
        + _frame(json.dumps(shutdown).encode())
        + _frame(json.dumps({"jsonrpc": "2.0", "method": "exit"}).encode())
    )
    done = subprocess.run([*cli_command(), "lsp"], input=sent, capture_output=True, timeout=60)
    answers = [
        json.loads(body) for body in re.split(rb"Content-Length: \d+\r\n(?:[^\r\n]+\r\n)*\r\n", done.stdout) if body
    ]
    assert any(a.get("error", {}).get("code") == -32700 and "id" in a and a["id"] is None for a in answers), answers
    assert any(a.get("id") == 1 and "result" in a for a in answers), answers
    assert any(a.get("id") == 7 and a.get("error", {}).get("code") == -32602 for a in answers), answers
    errors = done.stderr.decode()
    assert "Traceback" not in errors and all(line.startswith("cantools-od lsp: ") for line in errors.splitlines())


@pytest_lsp.fixture(config=SERVER, scope="module")
async def resolving(lsp_client: LanguageClient):
    capabilities = types.ClientCapabilities(
        text_document=types.TextDocumentClientCapabilities(
            code_action=types.CodeActionClientCapabilities(
                resolve_support=types.ClientCodeActionResolveOptions(properties=["edit"])
            )
        )
    )
    await lsp_client.initialize_session(types.InitializeParams(capabilities=capabilities))
    yield
    await lsp_client.shutdown_session()


async def test_a_fix_is_computed_when_chosen(resolving: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "bad.eds"
    original = DRIVE.read_text().replace("SupportedObjects=3", "SupportedObjects=7", 1)
    path.write_text(original)
    diagnostics = await open_file(resolving, path)
    fixable = [d for d in diagnostics if d.data and d.data.get("safe")]
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    offered = await resolving.text_document_code_action_async(
        types.CodeActionParams(document, fixable[0].range, types.CodeActionContext(diagnostics=fixable[:1]))
    )
    actions = [a for a in offered or [] if isinstance(a, types.CodeAction)]
    assert actions and all(a.edit is None for a in actions)  # offered without the work of making the edit
    fix_all = next(a for a in actions if a.kind == types.CodeActionKind.SourceFixAll)
    chosen = await resolving.code_action_resolve_async(fix_all)
    assert chosen.edit is not None and chosen.edit.changes is not None
    fixed = apply(original, list(chosen.edit.changes[document.uri]))
    copy = tmp_path / "copy" / "bad.eds"
    copy.parent.mkdir()
    copy.write_text(original)
    Lint([copy], "--fix").wait()
    assert fixed == copy.read_text() != original
    close_file(resolving, path)


async def test_completing_a_header_the_editor_closed_writes_one_bracket(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "new.eds"
    text = DRIVE.read_text() + "\n[Fi]\n"
    path.write_text(text)
    await open_file(client, path)
    number = text.splitlines().index("[Fi]")
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    found = await client.text_document_completion_async(
        types.CompletionParams(document, types.Position(number, 3))  # after "[Fi", before the editor's "]"
    )
    items = found.items if isinstance(found, types.CompletionList) else found or []
    item = next(i for i in items if i.label == "FileInfo")
    if isinstance(item.text_edit, types.TextEdit):
        after = apply(text, [item.text_edit])
    else:  # no range: the editor replaces the word before the cursor
        word = types.Range(types.Position(number, 1), types.Position(number, 3))
        after = apply(text, [types.TextEdit(word, item.insert_text or item.label)])
    assert after.splitlines()[number] == "[FileInfo]"
    close_file(client, path)


async def test_the_outline_of_an_xdd_names_objects_and_spans_their_elements(client: LanguageClient) -> None:
    from lspkit import XDD_CORPUS, text_of

    path = XDD_CORPUS / "canopendemo__demoDevice.xdd"
    if not path.is_file():
        pytest.skip("../shared/eds-corpus/xdd is absent")
    await open_file(client, path)
    lines = text_of(path).splitlines()
    found = await client.text_document_document_symbol_async(
        types.DocumentSymbolParams(types.TextDocumentIdentifier(path.resolve().as_uri()))
    )
    symbols = [s for s in found or [] if isinstance(s, types.DocumentSymbol)]
    assert all("<" not in s.name and "=" not in s.name for s in symbols), [s.name for s in symbols]
    assert {"FileInfo", "DeviceInfo"} <= {s.name for s in symbols}
    for symbol in symbols:
        start, end = symbol.range.start, symbol.range.end
        assert lines[start.line][start.character] == "<", symbol.name
        assert lines[end.line][: end.character].endswith(">"), symbol.name
        if re.match(r"[0-9A-F]{4} ", symbol.name):
            assert f'index="{symbol.name[:4]}"' in lines[start.line], symbol.name
            closing = lines[end.line][: end.character]
            assert closing.endswith(("/>", "</CANopenObject>")), symbol.name
    close_file(client, path)


async def test_each_section_folds(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "drive.eds"
    shutil.copyfile(DRIVE, path)
    await open_file(client, path)
    lines = DRIVE.read_text().splitlines()
    found = await client.text_document_folding_range_async(
        types.FoldingRangeParams(types.TextDocumentIdentifier(path.resolve().as_uri()))
    )
    folds = {(f.start_line, f.end_line) for f in found or []}
    headers = [n for n, line in enumerate(lines) if line.startswith("[")]
    for header, following in zip(headers, [*headers[1:], len(lines)], strict=True):
        last = max(n for n in range(header, following) if lines[n].strip())  # its last key
        if last > header:
            assert (header, last) in folds, lines[header]
    close_file(client, path)


async def _hover(client: LanguageClient, path: Path, line: int) -> str:
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    found = await client.text_document_hover_async(types.HoverParams(document, types.Position(line, 1)))
    assert found is not None and isinstance(found.contents, types.MarkupContent)
    return found.contents.value


async def test_hover_on_a_device_info_key_and_on_a_mapping_header(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "drive.eds"
    shutil.copyfile(DRIVE, path)
    await open_file(client, path)
    lines = DRIVE.read_text().splitlines()
    rates = {line.split("=")[0]: line.split("=")[1] for line in lines if line.startswith("BaudRate_")}
    for key, value in rates.items():
        said = await _hover(client, path, lines.index(f"{key}={value}"))
        rate = key.removeprefix("BaudRate_")
        assert f"{rate} kbit/s: {'supported' if value == '1' else 'not supported'}" in said, said
    header = lines.index("[1A00]")
    mapped = [line.split("=")[1] for line in lines[header:] if line.startswith("DefaultValue=0x6")][:2]
    said = await _hover(client, path, header)
    offset = 0
    for raw in mapped:  # each mapping entry's bits follow the one before
        value = int(raw, 16)
        bits = value & 0xFF
        assert f"| {offset}-{offset + bits - 1} | {value >> 16:04X}h sub{(value >> 8) & 0xFF:X} |" in said, said
        offset += bits
    close_file(client, path)


async def test_workspace_symbols_find_objects_of_every_open_document(client: LanguageClient, tmp_path: Path) -> None:
    first, second = tmp_path / "drive.eds", tmp_path / "io.eds"
    shutil.copyfile(DRIVE, first)
    shutil.copyfile(EXAMPLES / "io_device.eds", second)
    await open_file(client, first)
    await open_file(client, second)
    found = await client.workspace_symbol_async(types.WorkspaceSymbolParams(query="1018 identity"))
    places = {(s.name.split(" ")[0], s.location.uri) for s in found or [] if isinstance(s.location, types.Location)}
    assert places == {("1018", first.resolve().as_uri()), ("1018", second.resolve().as_uri())}
    for symbol in found or []:
        assert isinstance(symbol.location, types.Location)
        path = first if symbol.location.uri == first.resolve().as_uri() else second
        assert path.read_text().splitlines()[symbol.location.range.start.line] == "[1018]"
    close_file(client, first)
    close_file(client, second)


async def test_an_outline_cancelled_before_it_starts_is_not_made(client: LanguageClient, tmp_path: Path) -> None:
    from pygls.exceptions import JsonRpcRequestCancelled

    from support import CORPUS

    source = max(CORPUS.glob("*.eds"), key=lambda p: p.stat().st_size, default=DRIVE)  # a check that takes a while
    path = tmp_path / source.name
    shutil.copyfile(source, path)
    await open_file(client, path)
    uri = path.resolve().as_uri()
    change = types.TextDocumentContentChangePartial(types.Range(types.Position(0, 0), types.Position(0, 0)), "; x\n")
    client.text_document_did_change(  # a header line moves every section: the whole text is read again
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(2, uri), [change])
    )
    await asyncio.sleep(0.05)  # the check has started in the document's queue; the outline waits behind it
    params = types.DocumentSymbolParams(types.TextDocumentIdentifier(uri))
    request = client.protocol.send_request(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL, params, msg_id="outline-1")
    client.protocol.notify(types.CANCEL_REQUEST, types.CancelParams(id="outline-1"))
    with pytest.raises(JsonRpcRequestCancelled):
        await asyncio.wait_for(asyncio.wrap_future(request), 60)
    await diagnostics_for(client, uri, 2)
    close_file(client, path)
