"""A Windows-1252 file opened by an editor as UTF-8 (VS Code's default): the editor's text holds U+FFFD where the
file has other letters. The server reads the file's bytes to learn what they stand for: it reports what `lint`
reports (EDS100 included), before and after an edit, and never formats or fixes such text (that would save "�")."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
import pytest_lsp
from lspkit import SERVER, Lint, close_file, diagnostics_for, expected, open_file, seen, start
from lsprotocol import types
from pytest_lsp import LanguageClient

from support import EXAMPLES, corpus_file

pytestmark = pytest.mark.asyncio(loop_scope="module")


@pytest_lsp.fixture(config=SERVER, scope="module")
async def client(lsp_client: LanguageClient):
    await start(lsp_client)
    yield
    await lsp_client.shutdown_session()


def _as_vscode_shows(path: Path) -> str:
    """The text VS Code shows for the file with its default encoding, UTF-8."""
    return path.read_bytes().decode("utf-8", "replace")


async def test_a_windows_1252_file_shown_as_utf8_gets_lint_s_findings(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "faulhaber.eds"
    shutil.copyfile(corpus_file("faulhaber__605.3150.71-A-EK-3-60.eds"), path)
    text = _as_vscode_shows(path)
    assert "\ufffd" in text
    found = await open_file(client, path, text)
    wanted = Lint([path]).result()
    assert any(f["code"] == "EDS100" for f in wanted)
    assert sorted(seen(found)) == sorted(expected(wanted, text))

    # an edit of the text: the file as the editor would save it, had it the file's encoding
    lines = text.splitlines(keepends=True)
    number = next(n for n, line in enumerate(lines) if line.startswith("ParameterName="))
    edited = "ParameterName=Renamed by hand\n"
    uri = path.resolve().as_uri()
    client.text_document_did_change(
        types.DidChangeTextDocumentParams(
            types.VersionedTextDocumentIdentifier(2, uri),
            [types.TextDocumentContentChangePartial(
                types.Range(types.Position(number, 0), types.Position(number + 1, 0)), edited)],
        )
    )  # fmt: skip
    after = await diagnostics_for(client, uri, 2)
    data = path.read_bytes().split(b"\n")
    data[number] = edited.rstrip("\n").encode()
    check = tmp_path / "check" / path.name
    check.parent.mkdir()
    check.write_bytes(b"\n".join(data))
    new_text = "".join([*lines[:number], edited, *lines[number + 1 :]])
    assert sorted(seen(after)) == sorted(expected(Lint([check]).result(), new_text))
    close_file(client, path)


async def test_text_with_replacement_characters_is_neither_formatted_nor_fixed(
    client: LanguageClient, tmp_path: Path
) -> None:
    path = tmp_path / "drive.eds"
    lines = (
        (EXAMPLES / "cia402_drive.eds").read_text().replace("SupportedObjects=3", "SupportedObjects=7", 1).split("\n")
    )
    lines.insert(1, "; Schönaich")
    path.write_bytes("\n".join(lines).encode("cp1252"))
    text = _as_vscode_shows(path)
    diagnostics = await open_file(client, path, text)
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    formatted = await client.text_document_formatting_async(
        types.DocumentFormattingParams(document, types.FormattingOptions(4, True))
    )
    assert not formatted
    fixable = [d for d in diagnostics if d.data and d.data.get("safe")]
    assert fixable, "the example has a finding with a safe fix"
    offered = await client.text_document_code_action_async(
        types.CodeActionParams(document, fixable[0].range, types.CodeActionContext(diagnostics=fixable[:1]))
    )
    for action in offered or []:
        assert isinstance(action, types.CodeAction)
        edits = (action.edit.changes or {}).get(document.uri, []) if action.edit else []
        assert not any("\ufffd" in edit.new_text for edit in edits), action.title
        assert not edits, action.title
    close_file(client, path)

    # the same file opened as Windows-1252: formatting and fixes are offered
    shown_right = path.read_bytes().decode("cp1252")
    await open_file(client, path, shown_right)
    formatted = await client.text_document_formatting_async(
        types.DocumentFormattingParams(document, types.FormattingOptions(4, True))
    )
    assert formatted and not any("\ufffd" in edit.new_text for edit in formatted)
    close_file(client, path)
