"""How long `cantools-od lsp` takes to republish diagnostics after a one-line edit of a large file.

    python bench/bench_lsp.py                     # the largest corpus file
    python bench/bench_lsp.py path/to/file.eds --edits 10

A real client (pygls's) starts the server process, opens the file, waits for its diagnostics, then
makes one-line edits (DefaultValue lines of objects spread over the file rewritten) and times each
from the didChange notification to the diagnostics: the exact ones (published with the edit's
version: the edited object read again, the rest of the device kept, all of it linted; see
cantools_od/lsp/incremental.py) and, for an edit that path does not cover, the quick ones first
(published without a version, from a check of the edited object alone). Each edit follows a pause
(--pause, 0.5 s: a person between two one-line edits), so the server checks it at once; edits closer
together than DEBOUNCE (cantools_od/lsp/server.py) wait for the burst to pause. The times include the
protocol. Prints the open time
and the median and worst edit times in ms, the load average, and the CPU time one re-check takes
in this process (incremental, full and quick), which depends less on what else the machine runs.
"""

from __future__ import annotations

import argparse
import asyncio
import os
import re
import statistics
import sys
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

sys.path.insert(0, str(Path(__file__).resolve().parent))
import installed  # noqa: F401  (first: the installed package is measured, see bench/installed.py)

from cantools_od.eds.decode import decode_as

_NUMBER = re.compile(r"(?:0x[0-9a-f]+|[0-9]+)\Z", re.IGNORECASE)
CORPUS = Path(__file__).resolve().parent.parent.parent / "shared" / "eds-corpus" / "eds"


class Client(LanguageClient):
    def __init__(self) -> None:
        super().__init__("bench", "1")
        self.versions: dict[int | None, float] = {}
        self.quick: dict[int, float] = {}
        self.sent = 0  # the version last sent: a publish without a version answers it quickly
        self.arrived = asyncio.Event()

        @self.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
        def published(client: Client, params: types.PublishDiagnosticsParams) -> None:
            if params.version is None:
                client.quick.setdefault(client.sent, time.perf_counter())
            else:
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


def _edit_lines(lines: list[str], edits: int) -> list[int]:
    """DefaultValue lines with a number (decimal or hex), spread evenly over the file."""
    found = [n for n, t in enumerate(lines) if t.startswith("DefaultValue=") and _NUMBER.match(t[13:].strip())]
    return [found[k * len(found) // edits] for k in range(edits)]


def _edited(lines: list[str], line: int) -> str:
    """The line with another value: every edit changes the text."""
    return "DefaultValue=1" if lines[line].strip() != "DefaultValue=1" else "DefaultValue=2"


async def run(path: Path, edits: int, pause: float) -> dict[str, list[float]]:
    client = Client()
    server = Path(sys.executable).parent / "cantools-od"
    await client.start_io(str(server), "lsp")
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities()))
    client.initialized(types.InitializedParams())
    text = decode_as(path.read_bytes())[0]
    uri = path.resolve().as_uri()
    lines = text.splitlines()
    start = time.perf_counter()
    client.text_document_did_open(types.DidOpenTextDocumentParams(types.TextDocumentItem(uri, "eds", 1, text)))
    opened = await client.published(1) - start
    exact, quick = [], []
    for version, line in enumerate(_edit_lines(lines, edits), 2):
        new = _edited(lines, line)
        change = types.TextDocumentContentChangePartial(
            range=types.Range(types.Position(line, 0), types.Position(line, len(lines[line]))), text=new
        )
        lines[line] = new
        await asyncio.sleep(pause)
        client.sent = version
        sent = time.perf_counter()
        client.text_document_did_change(
            types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version=version, uri=uri), [change])
        )
        exact.append(await client.published(version) - sent)
        if version in client.quick:
            quick.append(client.quick[version] - sent)
    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()
    return {"open": [opened * 1000], "exact": [t * 1000 for t in exact], "quick": [t * 1000 for t in quick]}


def cpu(path: Path, edits: int) -> dict[str, list[float]]:
    """CPU time (ms) of one re-check in this process, for the same edits: the incremental one the
    server makes (only the edited object read again), the full one (the whole text read) and the quick one."""
    from cantools_od.lint import LintOptions
    from cantools_od.lsp.document import Encoding, analyse
    from cantools_od.lsp.incremental import reanalyse
    from cantools_od.lsp.quick import quick_findings

    data = path.read_bytes()
    text, codec, _ = decode_as(data)
    encoding, uri, options = Encoding(codec, data.startswith(b"\xef\xbb\xbf")), path.resolve().as_uri(), LintOptions()
    before = analyse(uri, text, 1, encoding, options)
    spent: dict[str, list[float]] = {"incremental": [], "full": [], "quick": []}
    for version, line in enumerate(_edit_lines(text.splitlines(), edits), 2):
        lines = before.text.splitlines(keepends=True)
        ending = lines[line][len(lines[line].rstrip("\r\n")) :]
        lines[line] = _edited(lines, line) + ending
        edited = "".join(lines)
        started = time.process_time()
        quick_findings(before, edited, uri, encoding, options)
        spent["quick"].append((time.process_time() - started) * 1000)
        started = time.process_time()
        found = reanalyse(before, uri, edited, version, encoding, options)
        if found is not None:
            spent["incremental"].append((time.process_time() - started) * 1000)
        started = time.process_time()
        fresh = analyse(uri, edited, version, encoding, options)
        spent["full"].append((time.process_time() - started) * 1000)
        before = found or fresh
    return spent


def _times(values: list[float]) -> str:
    if not values:
        return "none"
    return f"median {statistics.median(values):.0f} ms, worst {max(values):.0f} ms"


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("file", nargs="?", type=Path)
    parser.add_argument("--edits", type=int, default=12)
    parser.add_argument("--pause", type=float, default=0.5, help="seconds of quiet before each edit")
    args = parser.parse_args()
    path = args.file or _largest()
    load = os.getloadavg()[0]
    result = asyncio.run(run(path, args.edits, args.pause))
    spent = cpu(path, args.edits)
    size = path.stat().st_size / 1000
    print(f"{path.name} ({size:.0f} kB), {args.edits} one-line edits, load average {load:.1f} before, "
          f"{os.getloadavg()[0]:.1f} after:")  # fmt: skip
    print(f"  open to diagnostics {result['open'][0]:.0f} ms")
    print(f"  edit to quick diagnostics: {_times(result['quick'])} ({len(result['quick'])} of {args.edits} edits)")
    print(f"  edit to exact diagnostics: {_times(result['exact'])}")
    print(f"  CPU per re-check in process: incremental {_times(spent['incremental'])} "
          f"({len(spent['incremental'])} of {args.edits} edits); full {_times(spent['full'])}; "
          f"quick {_times(spent['quick'])}")  # fmt: skip


if __name__ == "__main__":
    main()
