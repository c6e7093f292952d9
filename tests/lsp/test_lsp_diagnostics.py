"""Diagnostics over the protocol: what `lint --format json` says of the same file, on open and after edits."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
import pytest_lsp
from lspkit import (
    SERVER,
    XDD_CORPUS,
    Lint,
    close_file,
    diagnostics_for,
    expected,
    open_file,
    seen,
    start,
    text_of,
)
from lsprotocol import types
from pytest_lsp import LanguageClient

from cantools_od.lsp.edits import apply

from support import EXAMPLES, corpus_devices

pytestmark = pytest.mark.asyncio(loop_scope="module")


@pytest_lsp.fixture(config=SERVER, scope="module")
async def client(lsp_client: LanguageClient):
    await start(lsp_client)
    yield
    await lsp_client.shutdown_session()


def _xdd_files() -> list[Path]:
    if not XDD_CORPUS.is_dir():
        return []
    return sorted(p for p in XDD_CORPUS.iterdir() if p.suffix.lower() in (".xdd", ".xdc", ".xpd"))


def _mapping_entries(path: Path) -> list[tuple[int, int, int, int]]:
    """(line, column) from 1 of each PDO mapping entry's value, with the index and sub-index it maps."""
    from cantools_od.api import load
    from cantools_od.lint.rules import Context, LintOptions
    from cantools_od.model.cia301.pdo import pdos

    device = load(path)
    at = Context(device, LintOptions())
    found = []
    for pdo in pdos(device):
        for entry in pdo.mapped():
            where = entry.slot.location(at)
            if not entry.is_dummy and entry.index in device.objects and not entry.slot.implicit:
                found.append((where.line, where.column, entry.index, entry.subindex))
    return found


def _names_object(line: str, index: int, subindex: int) -> bool:
    """The line is the header of the mapped object's section, or of its sub-object's: EDS or XDD."""
    text = line.strip().lower()
    eds = (f"[{index:04x}]", f"[{index:04x}sub{subindex:x}]")
    xdd = f'index="{index:04x}"' in text or f'subindex="{subindex:02x}"' in text
    return text in eds or (text.startswith("<canopen") and xdd)


async def _definitions(client: LanguageClient, path: Path, text: str) -> list[str]:
    """Where definition goes from each mapping entry that maps an object of the file: wrong landings."""
    lines = text.replace("\r\n", "\n").replace("\r", "\n").split("\n")
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    wrong = []
    for line, column, index, subindex in _mapping_entries(path):
        position = types.Position(line - 1, column - 1)
        found = await client.text_document_definition_async(types.DefinitionParams(document, position))
        target = found if isinstance(found, types.Location) else None
        if target is None or not _names_object(lines[target.range.start.line], index, subindex):
            wrong.append(
                f"{path.name}:{line}: {index:04X}sub{subindex:X} -> {target.range.start.line + 1 if target else None}"
            )
    return wrong


async def _formatted(client: LanguageClient, path: Path, text: str) -> str:
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    found = await client.text_document_formatting_async(
        types.DocumentFormattingParams(document, types.FormattingOptions(4, True))
    )
    return apply(text, list(found or []))


async def _sweep(client: LanguageClient, files: list[Path], copies: Path) -> None:
    """Open each file once: its diagnostics are lint's, formatting gives what fmt writes, and each mapping
    entry's definition lands on the header of the object it maps."""
    lint = Lint(files)  # lint and fmt run beside the server: one process each for the whole sweep
    for path in files:
        shutil.copyfile(path, copies / path.name)
    fmt = Lint([copies / path.name for path in files], command="fmt")
    got, formatted, misplaced = {}, {}, []
    for path in files:
        text = text_of(path)
        got[path.name] = (text, seen(await open_file(client, path)))
        misplaced += await _definitions(client, path, text)
        formatted[path.name] = await _formatted(client, path, text)
        close_file(client, path)
    by_file: dict[str, list[dict[str, object]]] = {}
    for finding in lint.result():
        by_file.setdefault(Path(str(finding["file"])).name, []).append(finding)
    wrong = [
        name
        for name, (text, diagnostics) in got.items()
        if sorted(diagnostics) != sorted(expected(by_file.get(name, []), text))
    ]
    assert not wrong, f"diagnostics differ from lint for {len(wrong)} of {len(files)} files: {wrong[:5]}"
    fmt.wait()
    unlike = [name for name, text in formatted.items() if text != text_of(copies / name)]
    assert not unlike, f"formatting differs from fmt for {len(unlike)} of {len(files)} files: {unlike[:5]}"
    assert not misplaced, f"{len(misplaced)} definitions miss their object: {misplaced[:5]}"


async def test_every_corpus_eds_as_lint_fmt_and_definitions_say(client: LanguageClient, tmp_path: Path) -> None:
    files = corpus_devices()
    if not files:
        pytest.skip("../shared/eds-corpus is absent")
    await _sweep(client, files, tmp_path)


async def test_every_corpus_xdd_as_lint_fmt_and_definitions_say(client: LanguageClient, tmp_path: Path) -> None:
    files = _xdd_files()
    if not files:
        pytest.skip("../shared/eds-corpus/xdd is absent")
    await _sweep(client, files, tmp_path)


def _change(client: LanguageClient, path: Path, version: int, start: tuple[int, int], end: tuple[int, int], text: str):
    change = types.TextDocumentContentChangePartial(
        range=types.Range(types.Position(*start), types.Position(*end)), text=text
    )
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(version=version, uri=path.resolve().as_uri()), [change]
        )
    )


async def test_an_edit_republishes_what_lint_says_of_the_edited_text(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "drive.eds"
    original = (EXAMPLES / "cia402_drive.eds").read_bytes()
    path.write_bytes(original)
    assert await open_file(client, path) == []
    lines = original.decode().splitlines()
    number = next(n for n, line in enumerate(lines) if line.startswith("DataType=")) if lines else 0
    _change(client, path, 2, (number, 0), (number, len(lines[number])), "DataType=0x0099")
    got = seen(await diagnostics_for(client, path.resolve().as_uri(), 2))
    edited = tmp_path / "edited" / "drive.eds"
    edited.parent.mkdir()
    edited.write_text("\n".join([*lines[:number], "DataType=0x0099", *lines[number + 1 :]]) + "\n")
    lint = Lint([edited])
    want = expected(lint.result(), edited.read_text())
    assert want and sorted(got) == sorted(want)
    assert path.read_bytes() == original  # the server never writes the file
    close_file(client, path)


async def test_the_configuration_beside_the_file_selects_as_for_lint(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "bad.eds"
    path.write_bytes((EXAMPLES / "cia402_drive.eds").read_bytes().replace(b"DataType=0x0006", b"DataType=0x0099", 1))
    everything = await open_file(client, path)
    close_file(client, path)
    assert everything
    codes = sorted({str(d.code) for d in everything})
    (tmp_path / "pyproject.toml").write_text(f'[tool.cantools-od]\nignore = ["{codes[0]}"]\n')
    fewer = await open_file(client, path)
    close_file(client, path)
    assert {str(d.code) for d in fewer} == set(codes[1:])
    assert sorted(seen(fewer)) == sorted(expected(Lint([path]).result(), path.read_text()))
    (tmp_path / "pyproject.toml").write_text('[tool.cantools-od]\nselect = ["NOPE999"]\n')
    broken = await open_file(client, path)
    close_file(client, path)
    assert len(broken) == 1 and broken[0].message.startswith("configuration:") and "\n" not in broken[0].message


HOSTILE = {
    "empty.eds": b"",
    "binary.eds": b"\x00\x01\x02[1000]\xff\xfe",
    "blank.eds": b"  \n\t\n",
    "huge.eds": b"[1000]\nParameterName=x\nObjectType=0x7\nDataType=0x0007\nAccessType=ro\nDefaultValue="
    + b"9" * 5000
    + b"\nLowLimit=0x"
    + b"F" * 4000
    + b"\n[2000sub"
    + b"7" * 300
    + b"]\nSubNumber=99999999999999999999999\n",
    "deep.xdd": b"<a>" * 20000 + b"</a>" * 20000,
    "bad.xdd": b"<?xml version='1.0'?><ISO15745ProfileContainer><unclosed>",
    "latin1.eds": b"[FileInfo]\nDescription=caf\xe9\n[1000]\nParameterName=Ger\xe4tetyp\nDataType=0x0007\n",
    "nul_after.eds": b"[FileInfo]\nFileName=x\n\x00",
}


@pytest.mark.parametrize("name", sorted(HOSTILE))
async def test_hostile_documents_get_one_line_diagnostics_and_the_server_lives_on(
    client: LanguageClient, tmp_path: Path, name: str
) -> None:
    path = tmp_path / name
    path.write_bytes(HOSTILE[name])
    got = await open_file(client, path, text_of(path))
    assert all("\n" not in d.message and "Traceback" not in d.message for d in got)
    want = Lint([path]).result() if b"\0" not in HOSTILE[name] and HOSTILE[name].strip() else None
    if want is not None:
        assert sorted(seen(got)) == sorted(expected(want, text_of(path)))
    else:
        assert len(got) == 1 and str(got[0].code) == "EDS000"
    # the server still answers every other request on it
    uri = path.resolve().as_uri()
    document = types.TextDocumentIdentifier(uri)
    await client.text_document_hover_async(types.HoverParams(document, types.Position(0, 0)))
    await client.text_document_document_symbol_async(types.DocumentSymbolParams(document))
    await client.text_document_completion_async(types.CompletionParams(document, types.Position(0, 0)))
    await client.text_document_formatting_async(
        types.DocumentFormattingParams(document, types.FormattingOptions(4, True))
    )
    close_file(client, path)
    assert path.read_bytes() == HOSTILE[name]
