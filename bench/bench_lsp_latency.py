"""How fast `cantools-od lsp` answers what a user does by hand while another, large document is being checked.

    python bench/bench_lsp_latency.py                 # the largest corpus file and a 20 MB synthetic one
    python bench/bench_lsp_latency.py --big-size 5M --rounds 30

A pygls client (one that resolves code actions, as VS Code does) starts the server and opens the largest corpus
EDS (the Sevcon Nano, 524 kB) and a synthetic EDS of --big-size (bench/synthetic_eds.py). It then times, each
over --rounds requests, from the request to its answer:

- hover on the corpus file while the big file is opened (sent to the server and read);
- code actions at the cursor on successive lines of the corpus file, with the line's diagnostics (a cursor move);
- hover on the corpus file while the big file is re-checked after an edit of its header (a whole re-read);
- the corpus file's diagnostics after an edit of it while the big file is re-checked (one queue per document);
- resolving a quick fix of the corpus file (the edit `lint --fix` makes, computed when the action is chosen);
- the outline of the big file, and the same asked behind a re-check of it and cancelled ($/cancelRequest).

Goals (issue #40): cursor-move code actions <= 20 ms, hover <= 50 ms while another document re-checks.
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import logging
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

sys.path.insert(0, str(Path(__file__).resolve().parent))
import installed  # noqa: F401  (first: the installed package is measured, see bench/installed.py)
from bench_lsp import _largest
from synthetic_eds import parse_size, synthetic_eds

from cantools_od.eds.decode import decode_as


class Client(LanguageClient):
    def __init__(self) -> None:
        super().__init__("bench", "1")
        self.versions: dict[tuple[str, int], float] = {}
        self.diagnostics: dict[str, list[types.Diagnostic]] = {}
        self.arrived = asyncio.Event()

        @self.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def published(client: Client, params: types.PublishDiagnosticsParams) -> None:
            if params.version is not None:
                client.versions[params.uri, params.version] = time.perf_counter()
                client.diagnostics[params.uri] = list(params.diagnostics)
            client.arrived.set()

    async def published(self, uri: str, version: int) -> float:
        while (uri, version) not in self.versions:
            self.arrived.clear()
            await asyncio.wait_for(self.arrived.wait(), 900)
        return self.versions[uri, version]


def _ms(values: list[float]) -> str:
    if not values:
        return "none"
    return f"median {statistics.median(values):.1f} ms, worst {max(values):.1f} ms ({len(values)})"


async def _timed(request: asyncio.Future[object] | object) -> float:
    started = time.perf_counter()
    await request  # type: ignore[misc]
    return (time.perf_counter() - started) * 1000


def _capabilities() -> types.ClientCapabilities:
    resolve = types.ClientCodeActionResolveOptions(properties=["edit"])
    return types.ClientCapabilities(
        text_document=types.TextDocumentClientCapabilities(
            code_action=types.CodeActionClientCapabilities(resolve_support=resolve)
        )
    )


def _edit(uri: str, version: int, line: int, text: str) -> types.DidChangeTextDocumentParams:
    change = types.TextDocumentContentChangePartial(
        range=types.Range(types.Position(line, 0), types.Position(line + 1, 0)), text=text
    )
    return types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version=version, uri=uri), [change])


class Bench:
    def __init__(self, client: Client, small: Path, big: Path) -> None:
        self.client, self.small, self.big = client, small.resolve().as_uri(), big.resolve().as_uri()
        self.small_lines = decode_as(small.read_bytes())[0].splitlines()
        self.big_lines = decode_as(big.read_bytes())[0].splitlines()
        self.small_version = self.big_version = 1

    def recheck_big(self) -> None:
        """An edit of the big file's first line (a comment): dialect evidence may change, the whole text is read."""
        self.big_version += 1
        comment = f"; edit {self.big_version}\r\n"
        self.client.text_document_did_change(_edit(self.big, self.big_version, 0, comment))

    async def code_actions(self, rounds: int) -> list[float]:
        lines = [d.range.start.line for d in self.client.diagnostics.get(self.small, [])] or list(range(rounds))
        spent = []
        for round_ in range(rounds):
            line = lines[round_ % len(lines)]
            here = [d for d in self.client.diagnostics.get(self.small, []) if d.range.start.line == line]
            where = types.Range(types.Position(line, 0), types.Position(line, 0))
            params = types.CodeActionParams(types.TextDocumentIdentifier(self.small), where,
                                            types.CodeActionContext(diagnostics=here))  # fmt: skip
            spent.append(await _timed(self.client.text_document_code_action_async(params)))
        return spent

    async def hovers_until(self, uri: str, version: int, rounds: int) -> list[float]:
        """Hovers on the small file, one every 20 ms, until `uri`'s diagnostics of `version` arrive (at least
        `rounds`)."""
        spent: list[float] = []
        headers = [n for n, line in enumerate(self.small_lines) if line.startswith("DataType=")]
        while (uri, version) not in self.client.versions or len(spent) < rounds:
            line = headers[len(spent) % len(headers)]
            params = types.HoverParams(types.TextDocumentIdentifier(self.small), types.Position(line, 10))
            spent.append(await _timed(self.client.text_document_hover_async(params)))
            await asyncio.sleep(0.02)
        return spent

    async def hover_while_big_rechecks(self, rounds: int) -> list[float]:
        """Hovers on the small file from the moment the big one is edited until its diagnostics arrive."""
        self.recheck_big()
        return await self.hovers_until(self.big, self.big_version, rounds)

    async def small_edit_while_big_rechecks(self, rounds: int) -> list[float]:
        spent = []
        line = next(n for n, text in enumerate(self.small_lines) if text.startswith("DefaultValue="))
        for round_ in range(rounds):
            self.recheck_big()
            await asyncio.sleep(0.2)  # the big file's check is under way
            self.small_version += 1
            started = time.perf_counter()
            value = "1" if round_ % 2 else "2"
            self.client.text_document_did_change(_edit(self.small, self.small_version, line, f"DefaultValue={value}\n"))
            spent.append((await self.client.published(self.small, self.small_version) - started) * 1000)
        await self.client.published(self.big, self.big_version)
        return spent

    async def resolve(self, rounds: int) -> list[float]:
        spent = []
        for diagnostic in self.client.diagnostics.get(self.small, []):
            where = types.CodeActionParams(types.TextDocumentIdentifier(self.small), diagnostic.range,
                                           types.CodeActionContext(diagnostics=[diagnostic]))  # fmt: skip
            offered = await self.client.text_document_code_action_async(where) or []
            for action in offered:
                if isinstance(action, types.CodeAction) and action.kind == types.CodeActionKind.QuickFix:
                    spent.append(await _timed(self.client.code_action_resolve_async(action)))
            if len(spent) >= rounds:
                break
        return spent

    async def outline(self) -> tuple[float, float]:
        """The big file's outline, then the same asked behind a re-check of it and cancelled at once: the time
        to the server's answer ("request cancelled" when the work had not started)."""
        params = types.DocumentSymbolParams(types.TextDocumentIdentifier(self.big))
        whole = await _timed(self.client.text_document_document_symbol_async(params))
        self.recheck_big()
        await asyncio.sleep(0.2)
        started = time.perf_counter()
        request = self.client.protocol.send_request(types.TEXT_DOCUMENT_DOCUMENT_SYMBOL, params, msg_id="cancelled")
        self.client.protocol.notify(types.CANCEL_REQUEST, types.CancelParams(id="cancelled"))
        with contextlib.suppress(Exception):  # the server answers "request cancelled"
            await asyncio.wrap_future(request)
        answered = (time.perf_counter() - started) * 1000
        await self.client.published(self.big, self.big_version)
        return whole, answered


async def run(small: Path, big: Path, rounds: int) -> None:
    client = Client()
    await client.start_io(str(Path(sys.executable).parent / "cantools-od"), "lsp")
    await client.initialize_async(types.InitializeParams(capabilities=_capabilities()))
    client.initialized(types.InitializedParams())
    bench = Bench(client, small, big)
    opened = {}
    for path, uri in ((small, bench.small), (big, bench.big)):  # the small one first: hovered while the big opens
        started = time.perf_counter()
        item = types.TextDocumentItem(uri, "eds", 1, decode_as(path.read_bytes())[0])
        client.text_document_did_open(types.DidOpenTextDocumentParams(item))
        if uri == bench.big:
            hovers = await bench.hovers_until(bench.big, 1, 0)
        opened[uri] = (await client.published(uri, 1) - started) * 1000
    print(f"  open to diagnostics: small {opened[bench.small]:.0f} ms, big {opened[bench.big]:.0f} ms")
    print(f"  hover (small) while the big file opens: {_ms(hovers)}")
    print(f"  code actions at the cursor (small): {_ms(await bench.code_actions(rounds))}")
    print(f"  hover (small) while the big file re-checks: {_ms(await bench.hover_while_big_rechecks(rounds))}")
    print(f"  small file's edit to diagnostics while the big one re-checks: "
          f"{_ms(await bench.small_edit_while_big_rechecks(max(rounds // 10, 3)))}")  # fmt: skip
    print(f"  resolving a quick fix (small): {_ms(await bench.resolve(max(rounds // 5, 3)))}")
    whole, cancelled = await bench.outline()
    print(f"  outline of the big file: {whole:.0f} ms; asked behind a re-check and cancelled: answered in "
          f"{cancelled:.0f} ms")  # fmt: skip
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", nargs="?", type=Path, help="the small document (default: the largest corpus file)")
    parser.add_argument("--big-size", type=parse_size, default=parse_size("20M"))
    parser.add_argument("--rounds", type=int, default=40)
    args = parser.parse_args()
    logging.getLogger("pygls").setLevel(logging.CRITICAL)  # the client's own note on an answer to a cancelled request
    small = args.file or _largest()
    with tempfile.TemporaryDirectory() as folder:
        big = Path(folder) / "big.eds"
        big.write_bytes(synthetic_eds(args.big_size))
        print(f"{small.name} ({small.stat().st_size / 1000:.0f} kB) beside a synthetic EDS of "
              f"{big.stat().st_size / 1e6:.1f} MB, load average {os.getloadavg()[0]:.1f}:")  # fmt: skip
        asyncio.run(run(small, big, args.rounds))
        print(f"  load average after: {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
