"""How long `cantools-od lsp` takes to republish diagnostics after a one-line edit of a large file.

    PYTHONPATH=. python bench/bench_lsp.py                     # the largest corpus file
    PYTHONPATH=. python bench/bench_lsp.py path/to/file.eds --edits 10

A real client (pygls's) starts the server process, opens the file, waits for its diagnostics, then
makes one-line edits (a DefaultValue rewritten, alternately to two values) and times each from the
didChange notification to the publishDiagnostics of that version: the debounce, reading and linting
the whole text, and the protocol. Prints the open time and the median and worst edit time, in ms.
"""

from __future__ import annotations

import argparse
import asyncio
import statistics
import sys
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

from cantools_od.eds.decode import decode_as

CORPUS = Path(__file__).resolve().parent.parent.parent / "shared" / "eds-corpus" / "eds"


class Client(LanguageClient):
    def __init__(self) -> None:
        super().__init__("bench", "1")
        self.versions: dict[int | None, float] = {}
        self.arrived = asyncio.Event()

        @self.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def published(client: Client, params: types.PublishDiagnosticsParams) -> None:
            client.versions[params.version] = time.perf_counter()
            client.arrived.set()

    async def published(self, version: int) -> float:
        while version not in self.versions:
            self.arrived.clear()
            await asyncio.wait_for(self.arrived.wait(), 300)
        return self.versions[version]


def _largest() -> Path:
    files = [p for p in CORPUS.glob("*") if p.suffix.lower() in (".eds", ".dcf")]
    if not files:
        sys.exit("bench_lsp: error: ../shared/eds-corpus/eds is absent; name a file")
    return max(files, key=lambda p: p.stat().st_size)


async def run(path: Path, edits: int) -> dict[str, float]:
    client = Client()
    server = Path(sys.executable).parent / "cantools-od"
    await client.start_io(str(server), "lsp")
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities()))
    client.initialized(types.InitializedParams())
    text = decode_as(path.read_bytes())[0]
    uri = path.resolve().as_uri()
    lines = text.splitlines()
    line = next(n for n, t in enumerate(lines) if t.startswith("DefaultValue=") and t[13:].strip().isdigit())
    start = time.perf_counter()
    client.text_document_did_open(types.DidOpenTextDocumentParams(types.TextDocumentItem(uri, "eds", 1, text)))
    opened = await client.published(1) - start
    times = []
    for version in range(2, edits + 2):
        new = f"DefaultValue={version % 2}"
        change = types.TextDocumentContentChangePartial(
            range=types.Range(types.Position(line, 0), types.Position(line, len(lines[line]))), text=new
        )
        lines[line] = new
        sent = time.perf_counter()
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version=version, uri=uri), [change])
        )
        times.append(await client.published(version) - sent)
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return {"open": opened * 1000, "median": statistics.median(times) * 1000, "worst": max(times) * 1000}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", nargs="?", type=Path)
    parser.add_argument("--edits", type=int, default=10)
    args = parser.parse_args()
    path = args.file or _largest()
    result = asyncio.run(run(path, args.edits))
    size = path.stat().st_size / 1000
    print(f"{path.name} ({size:.0f} kB): open {result['open']:.0f} ms; one-line edit to diagnostics: "
          f"median {result['median']:.0f} ms, worst {result['worst']:.0f} ms over {args.edits} edits")  # fmt: skip


if __name__ == "__main__":
    main()
