"""A real LSP client talking to `cantools-od lsp` in a process of its own (pytest-lsp), and what the tests share."""

from __future__ import annotations

import asyncio
import json
import subprocess
import threading
from pathlib import Path

from lsprotocol import types
from pygls.protocol import default_converter
from pytest_lsp import ClientServerConfig, LanguageClient
from pytest_lsp.client import DEFAULT_CLIENT_FEATURES, register_lsp_features

from cantools_od.eds.decode import decode_as

from support import CORPUS, cli_command


class Client(LanguageClient):
    """pytest-lsp's client, keeping every diagnostics notification with its version, so that none is
    missed between two waits."""

    published: dict[tuple[str, int | None], list[types.Diagnostic]]
    arrived: asyncio.Event


def _client() -> Client:
    client = Client(converter_factory=default_converter)
    client.published = {}
    client.arrived = asyncio.Event()
    features = dict(DEFAULT_CLIENT_FEATURES)

    def publish(client: Client, params: types.PublishDiagnosticsParams) -> None:
        client.diagnostics[params.uri] = params.diagnostics
        client.published[params.uri, params.version] = list(params.diagnostics)
        client.arrived.set()

    features[types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS] = publish
    register_lsp_features(client, features)
    return client


SERVER = ClientServerConfig(server_command=[*cli_command(), "lsp", "--stdio"], client_factory=_client)
XDD_CORPUS = CORPUS.parent / "xdd"
LANGUAGES = {".eds": "eds", ".dcf": "dcf", ".xdd": "xml", ".xdc": "xml", ".xpd": "xml"}


async def start(client: LanguageClient, options: dict[str, object] | None = None) -> None:
    capabilities = types.ClientCapabilities(
        text_document=types.TextDocumentClientCapabilities(
            hover=types.HoverClientCapabilities(content_format=[types.MarkupKind.Markdown]),
            code_action=types.CodeActionClientCapabilities(
                code_action_literal_support=types.ClientCodeActionLiteralOptions(
                    types.ClientCodeActionKindOptions(value_set=[types.CodeActionKind.QuickFix])
                )
            ),
            document_symbol=types.DocumentSymbolClientCapabilities(hierarchical_document_symbol_support=True),
        )
    )
    await client.initialize_session(types.InitializeParams(capabilities=capabilities, initialization_options=options))


def text_of(path: Path) -> str:
    """The file's text as an editor shows it: UTF-8, else Windows-1252, without a BOM."""
    return decode_as(path.read_bytes())[0]


async def diagnostics_for(client: LanguageClient, uri: str, version: int) -> list[types.Diagnostic]:
    """The diagnostics the server publishes for that version of `uri` (taken: a reopened document counts again)."""
    assert isinstance(client, Client)
    while (uri, version) not in client.published:
        client.arrived.clear()
        await asyncio.wait_for(client.arrived.wait(), 120)
    return client.published.pop((uri, version))


async def open_file(client: LanguageClient, path: Path, text: str | None = None) -> list[types.Diagnostic]:
    """Open `path` (with `text`, else its content) and wait for its first diagnostics."""
    uri = path.resolve().as_uri()
    document = types.TextDocumentItem(
        uri, LANGUAGES.get(path.suffix.lower(), "eds"), 1, text_of(path) if text is None else text
    )
    client.text_document_did_open(types.DidOpenTextDocumentParams(document))
    return await diagnostics_for(client, uri, 1)


def close_file(client: LanguageClient, path: Path) -> None:
    client.text_document_did_close(
        types.DidCloseTextDocumentParams(types.TextDocumentIdentifier(path.resolve().as_uri()))
    )


class Lint:
    """`cantools-od lint --format json FILES` running beside the server in the files' folder (where the server
    looks for configuration), read by a thread of its own so that it never waits on a full pipe."""

    def __init__(self, files: list[Path], *args: str, command: str = "lint") -> None:
        options = ["--format", "json"] if command == "lint" else []
        command_line = [*cli_command(), command, *options, *args, *(path.name for path in files)]
        self.done: list[subprocess.CompletedProcess[str]] = []

        def run() -> None:
            self.done.append(subprocess.run(command_line, cwd=files[0].parent, capture_output=True, text=True))

        self.thread = threading.Thread(target=run)
        self.thread.start()

    def wait(self) -> subprocess.CompletedProcess[str]:
        self.thread.join()
        return self.done[0]

    def result(self) -> list[dict[str, object]]:
        self.wait()
        process = self.done[0]
        assert process.returncode in (0, 1), process.stderr
        found: list[dict[str, object]] = json.loads(process.stdout)
        return found


def expected(findings: list[dict[str, object]], text: str) -> list[tuple[int, int, str, str, str]]:
    """lint's findings as the LSP positions (from 0, UTF-16 units) and fields a diagnostic carries."""
    lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    out = []
    for f in findings:
        line, column = max(int(str(f["line"])) - 1, 0), max(int(str(f["column"])) - 1, 0)
        before = lines[line][:column] if line < len(lines) else ""
        units = len(before.encode("utf-16-le")) // 2
        severity = {"error": 1, "warning": 2, "info": 3}[str(f["severity"])]
        out.append((line, units, str(f["code"]), str(severity), str(f["message"])))
    return out


def seen(diagnostics: list[types.Diagnostic]) -> list[tuple[int, int, str, str, str]]:
    return [
        (d.range.start.line, d.range.start.character, str(d.code), str(int(d.severity or 0)), d.message)
        for d in diagnostics
    ]
