"""Edits over the protocol: an edit inside one object gets the exact diagnostics at once (that object
read again) or, where that path does not hold, quick ones first (without a version); the diagnostics
published with the edit's version are always what `lint` says of the edited text, whatever the edit
(a value, a removed or added line, a header)."""

from __future__ import annotations

import random
import shutil
from pathlib import Path

import pytest
import pytest_lsp
from lspkit import SERVER, Client, Lint, close_file, diagnostics_for, expected, open_file, seen, start, text_of
from lsprotocol import types
from pytest_lsp import LanguageClient

from cantools_od.lsp.document import Encoding
from cantools_od.lsp.edits import apply
from cantools_od.lsp.positions import Lines

from support import EXAMPLES, corpus_devices

pytestmark = pytest.mark.asyncio(loop_scope="module")


@pytest_lsp.fixture(config=SERVER, scope="module")
async def client(lsp_client: LanguageClient):
    await start(lsp_client)
    yield
    await lsp_client.shutdown_session()


def _replace_line(client: LanguageClient, uri: str, version: int, number: int, old: str, new: str) -> None:
    """Replace line `number` (from 0; `old` is its text without the line end) by `new`, which may hold line ends."""
    units = len(old.encode("utf-16-le")) // 2
    change = types.TextDocumentContentChangePartial(
        range=types.Range(types.Position(number, 0), types.Position(number, units)), text=new
    )
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(types.VersionedTextDocumentIdentifier(version=version, uri=uri), [change])
    )


def _quick(client: LanguageClient, uri: str) -> list[types.Diagnostic] | None:
    assert isinstance(client, Client)
    return client.published.pop((uri, None), None)


async def _value_edit(client: LanguageClient, path: Path) -> tuple[list[object], list[types.Diagnostic] | None]:
    """Open `path`, set the DefaultValue of [1001] to 300 (out of UNSIGNED8's range); the diagnostics
    published with the edit's version, the quick ones before them (None when none came), and what
    lint says of the edited text."""
    text = text_of(path)
    lines = text.split("\n")
    await open_file(client, path)
    number = next(n for n in range(lines.index("[1001]"), len(lines)) if lines[n].startswith("DefaultValue="))
    uri = path.resolve().as_uri()
    _quick(client, uri)
    _replace_line(client, uri, 2, number, lines[number], "DefaultValue=300")
    exact = seen(await diagnostics_for(client, uri, 2))
    quick = _quick(client, uri)
    lines[number] = "DefaultValue=300"
    edited = path.parent / "edited" / path.name
    edited.parent.mkdir()
    edited.write_bytes(Encoding.of_file(path).bytes("\n".join(lines)))
    want = expected(Lint([edited]).result(), text_of(edited))
    assert want and sorted(exact) == sorted(want)
    close_file(client, path)
    return want, quick


async def test_a_value_edit_gets_the_exact_diagnostics_at_once(client: LanguageClient, tmp_path: Path) -> None:
    """An edit inside one object: that object is read again, the exact diagnostics come without quick ones."""
    path = tmp_path / "drive.eds"
    shutil.copyfile(EXAMPLES / "cia402_drive.eds", path)
    _, quick = await _value_edit(client, path)
    assert quick is None


async def test_an_edit_the_incremental_check_leaves_gets_quick_diagnostics_first(
    client: LanguageClient, tmp_path: Path
) -> None:
    """A file in Windows-1252 is read again whole after an edit: the quick diagnostics come first."""
    path = tmp_path / "drive.eds"
    path.write_bytes("; Drehzahl f\u00fcr Achse 1\n".encode("cp1252") + (EXAMPLES / "cia402_drive.eds").read_bytes())
    want, quick = await _value_edit(client, path)
    assert quick is not None, "no quick diagnostics before the exact ones"
    assert sorted(seen(quick)) == sorted(want)  # an out-of-range default: the object alone tells


def _edit(rng: random.Random, lines: list[str]) -> tuple[int, str]:
    """A random one-line edit: (line number from 0, its new text, which may be two lines or none)."""
    number = rng.randrange(len(lines))
    line = lines[number]
    key = line.partition("=")[0] if "=" in line else "DefaultValue"
    choice = rng.random()
    if choice < 0.6:
        return number, f"{key}={rng.choice(['0', '300', '0x80', '$NODEID+0x180', '', 'x', '-1', '0x7FFFFFFF'])}"
    if choice < 0.75:
        return number, f"{line}\n{key}={rng.choice(['1', '0x1A00'])}"
    if choice < 0.85:
        return number, rng.choice(["", "[2FFF]", "; a comment", "[1000sub1]"])
    return number, line.upper() if line.startswith("[") else line + "0"


async def test_random_edits_of_corpus_files_end_in_what_lint_says(client: LanguageClient, tmp_path: Path) -> None:
    files = corpus_devices()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    rng = random.Random(25)
    largest = max(files, key=lambda p: p.stat().st_size)
    chosen = [largest, *rng.sample([p for p in files if p != largest and p.suffix.lower() != ".xdd"], 4)]
    got: dict[Path, tuple[str, list[tuple[int, int, str, str, str]]]] = {}
    for path in chosen:
        copy = tmp_path / path.name
        shutil.copyfile(path, copy)
        uri, encoding = copy.resolve().as_uri(), Encoding.of_file(copy)
        await open_file(client, copy)
        text = text_of(copy)
        for version in range(2, 6):
            lines = Lines(text)
            number, new = _edit(rng, [lines.line(n) for n in range(len(lines))])
            old = lines.line(number)
            _quick(client, uri)
            _replace_line(client, uri, version, number, old, new)
            diagnostics = await diagnostics_for(client, uri, version)
            span = types.Range(types.Position(number, 0), types.Position(number, lines.units(number, len(old))))
            text = apply(text, [types.TextEdit(span, new)])
            edited = tmp_path / f"v{version}" / path.name
            edited.parent.mkdir(exist_ok=True)
            edited.write_bytes(encoding.bytes(text))
            got[edited] = (text, seen(diagnostics))
        close_file(client, copy)
    findings: dict[str, list[dict[str, object]]] = {}
    for version in range(2, 6):
        folder = tmp_path / f"v{version}"
        for finding in Lint(sorted(folder.iterdir())).result():
            findings.setdefault(str(folder / Path(str(finding["file"])).name), []).append(finding)
    wrong = [
        edited.relative_to(tmp_path)
        for edited, (text, diagnostics) in got.items()
        if sorted(diagnostics) != sorted(expected(findings.get(str(edited), []), text))
    ]
    assert not wrong, f"the diagnostics of {len(wrong)} of {len(got)} edits differ from lint: {wrong[:5]}"
