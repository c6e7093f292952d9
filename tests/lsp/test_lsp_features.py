"""Hover, references, code actions, range formatting, outline and completion over the protocol."""

from __future__ import annotations

import shutil
from pathlib import Path

import pytest
import pytest_lsp
from lspkit import SERVER, Lint, close_file, open_file, start, text_of
from lsprotocol import types
from pytest_lsp import LanguageClient

from cantools_od.lsp.edits import apply

from support import EXAMPLES, cli_command

pytestmark = pytest.mark.asyncio(loop_scope="module")
DRIVE = EXAMPLES / "cia402_drive.eds"


@pytest_lsp.fixture(config=SERVER, scope="module")
async def client(lsp_client: LanguageClient):
    await start(lsp_client, {"nodeId": 5, "rulesUrl": "https://example.invalid/docs/rules.md"})
    yield
    await lsp_client.shutdown_session()


def _line(text: str, wanted: str, after: str = "") -> int:
    """The line (from 0) of the first line equal to `wanted` after the line equal to `after`."""
    lines = text.splitlines()
    start = lines.index(after) if after else 0
    return lines.index(wanted, start)


async def _hover(client: LanguageClient, path: Path, line: int, column: int = 0) -> str:
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    found = await client.text_document_hover_async(types.HoverParams(document, types.Position(line, column)))
    assert found is not None and isinstance(found.contents, types.MarkupContent)
    return found.contents.value


@pytest.fixture
def drive(tmp_path: Path) -> Path:
    path = tmp_path / "drive.eds"
    shutil.copyfile(DRIVE, path)
    return path


async def test_hover_decodes_a_mapping_entry_a_cob_id_and_an_object(client: LanguageClient, drive: Path) -> None:
    await open_file(client, drive)
    text = text_of(drive)
    entry = await _hover(client, drive, _line(text, "DefaultValue=0x60410010"), 3)
    assert "Mapping entry 0x60410010: index 6041h, sub-index 0h, 16 bits; bits 0-15 of TPDO1" in entry
    assert "Maps **6041h sub0 Statusword**: UNSIGNED16 (0006h)" in entry
    cob = await _hover(client, drive, _line(text, "DefaultValue=$NODEID+0x180", "[1800sub1]"))
    assert "COB-ID of TPDO1: CAN-ID 185h for node-ID 5" in cob
    assert "bit 31 (valid): 0, valid" in cob and "follows the node-ID: `$NODEID+0x180`" in cob
    header = await _hover(client, drive, _line(text, "[6041]"))
    assert "Standard: Statusword (CiA 402-2)" in header
    assert "| data type | UNSIGNED16 (0006h) |" in header and "| access | ro |" in header
    assert "| PDO mapping | yes |" in header
    close_file(client, drive)


async def test_references_of_an_object_are_its_mapping_and_list_entries(client: LanguageClient, drive: Path) -> None:
    await open_file(client, drive)
    text = text_of(drive)
    document = types.TextDocumentIdentifier(drive.resolve().as_uri())
    found = await client.text_document_references_async(
        types.ReferenceParams(
            text_document=document,
            position=types.Position(_line(text, "[6041]"), 1),
            context=types.ReferenceContext(include_declaration=False),
        )
    )
    lines = text.splitlines()
    landed = sorted(lines[where.range.start.line] for where in found or [])
    assert landed == ["13=0x6041", "DefaultValue=0x60410010", "DefaultValue=0x60410010"]  # TPDO1, TPDO3, the list
    listed = await client.text_document_references_async(
        types.ReferenceParams(
            text_document=document,
            position=types.Position(_line(text, "[1018]"), 1),
            context=types.ReferenceContext(include_declaration=False),
        )
    )
    assert [lines[where.range.start.line] for where in listed or []] == ["3=0x1018"]
    back = await client.text_document_definition_async(
        types.DefinitionParams(document, types.Position(_line(text, "3=0x1018"), 3))
    )
    assert isinstance(back, types.Location) and lines[back.range.start.line] == "[1018]"
    close_file(client, drive)


async def test_a_quick_fix_is_the_edit_lint_fix_makes(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "bad.eds"
    original = DRIVE.read_text().replace("SupportedObjects=3", "SupportedObjects=7", 1)
    path.write_text(original)
    diagnostics = await open_file(client, path)
    counted = [d for d in diagnostics if d.data and d.data.get("safe")]
    assert counted, "the example has a finding with a safe fix"
    link = counted[0].code_description
    assert link is not None and link.href.startswith(
        f"https://example.invalid/docs/rules.md#{str(counted[0].code).lower()}-"
    )
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(document, counted[0].range, types.CodeActionContext(diagnostics=counted[:1]))
    )
    assert actions
    quick = [a for a in actions if isinstance(a, types.CodeAction) and a.kind == types.CodeActionKind.QuickFix]
    assert quick and quick[0].is_preferred and "unsafe" not in quick[0].title
    fix_all = [a for a in actions if isinstance(a, types.CodeAction) and a.kind == types.CodeActionKind.SourceFixAll]
    assert fix_all and fix_all[0].edit is not None and fix_all[0].edit.changes is not None
    fixed_by_server = apply(original, list(fix_all[0].edit.changes[document.uri]))
    close_file(client, path)
    assert path.read_text() == original  # the server never writes the file
    copy = tmp_path / "copy" / "bad.eds"
    copy.parent.mkdir()
    copy.write_text(original)
    Lint([copy], "--fix").wait()
    assert fixed_by_server == copy.read_text() != original


async def test_an_unsafe_fix_is_labelled_and_not_preferred(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "unsafe.eds"
    # 1F00h listed in [OptionalObjects] but not described: removing the entry is an unsafe fix
    original = DRIVE.read_text().replace(
        "[OptionalObjects]\nSupportedObjects=", "[OptionalObjects]\nSupportedObjects=", 1
    )
    lines = original.splitlines()
    optional = lines.index("[OptionalObjects]")
    count = int(lines[optional + 1].split("=")[1])
    lines[optional + 1] = f"SupportedObjects={count + 1}"
    lines.insert(optional + 2 + count, f"{count + 1}=0x1F00")
    path.write_text("\n".join(lines) + "\n")
    diagnostics = await open_file(client, path)
    unsafe = [d for d in diagnostics if d.data and d.data.get("safe") is False]
    assert unsafe
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    actions = await client.text_document_code_action_async(
        types.CodeActionParams(document, unsafe[0].range, types.CodeActionContext(diagnostics=unsafe[:1]))
    )
    titled = [a for a in actions or [] if isinstance(a, types.CodeAction) and "unsafe" in a.title]
    assert titled and not titled[0].is_preferred
    close_file(client, path)


async def test_range_formatting_changes_only_the_lines_asked_about(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "drive.eds"
    original = DRIVE.read_text().replace("DataType=0x0006\n", "DataType=6\n")
    path.write_text(original)
    await open_file(client, path)
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    whole = await client.text_document_formatting_async(
        types.DocumentFormattingParams(document, types.FormattingOptions(4, True))
    )
    copy = tmp_path / "fmt" / "drive.eds"
    copy.parent.mkdir()
    copy.write_text(original)
    Lint([copy], command="fmt").wait()
    assert apply(original, list(whole or [])) == copy.read_text() != original
    first = next(n for n, line in enumerate(original.splitlines()) if line == "DataType=6")
    ranged = await client.text_document_range_formatting_async(
        types.DocumentRangeFormattingParams(
            document, types.Range(types.Position(first, 0), types.Position(first, 10)), types.FormattingOptions(4, True)
        )
    )
    assert ranged and all(e.range.start.line <= first <= e.range.end.line for e in ranged)
    after = apply(original, list(ranged)).splitlines()
    assert after[first] == "DataType=0x0006" and original.count("DataType=6") > 1 and "DataType=6" in after
    close_file(client, path)


async def test_the_outline_holds_objects_with_their_sub_objects(client: LanguageClient, drive: Path) -> None:
    await open_file(client, drive)
    document = types.TextDocumentIdentifier(drive.resolve().as_uri())
    found = await client.text_document_document_symbol_async(types.DocumentSymbolParams(document))
    symbols = [s for s in found or [] if isinstance(s, types.DocumentSymbol)]
    names = [s.name for s in symbols]
    assert "FileInfo" in names and "1A00 TPDO mapping parameter 1" in names
    tpdo = symbols[names.index("1A00 TPDO mapping parameter 1")]
    assert [c.name for c in tpdo.children or []] == [
        "sub0 Number of mapped objects",
        "sub1 Mapped object 1",
        "sub2 Mapped object 2",
    ]
    close_file(client, drive)


async def _complete(client: LanguageClient, path: Path, line: int, column: int) -> list[str]:
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    found = await client.text_document_completion_async(types.CompletionParams(document, types.Position(line, column)))
    items = found.items if isinstance(found, types.CompletionList) else found or []
    return [item.label for item in items]


async def test_completion_offers_keys_types_access_and_standard_names(client: LanguageClient, tmp_path: Path) -> None:
    path = tmp_path / "new.eds"
    text = DRIVE.read_text() + "\n[1016]\nParameterName=\nDataType=\nAccessType=\n\n"
    path.write_text(text)
    await open_file(client, path)
    lines = text.splitlines()
    start = lines.index("[1016]")
    assert "Consumer heartbeat time" in await _complete(client, path, start + 1, len("ParameterName="))
    assert "0x0007" in await _complete(client, path, start + 2, len("DataType="))
    assert {"ro", "rw", "const"} <= set(await _complete(client, path, start + 3, len("AccessType=")))
    keys = await _complete(client, path, start + 4, 0)
    assert "DefaultValue" in keys and "ParameterName" not in keys
    close_file(client, path)


def test_the_command_answers_help_in_one_process() -> None:
    import subprocess

    result = subprocess.run([*cli_command(), "lsp", "--help"], capture_output=True, text=True, timeout=60)
    assert result.returncode == 0 and "Language Server Protocol" in result.stdout


async def test_an_xdd_unique_id_ref_goes_to_its_parameter_and_back(client: LanguageClient) -> None:
    from lspkit import XDD_CORPUS

    path = XDD_CORPUS / "canopendemo__demoDevice.xdd"
    if not path.is_file():
        pytest.skip("../shared/eds-corpus/xdd is absent")
    await open_file(client, path)
    lines = text_of(path).splitlines()
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    users = [(n, line) for n, line in enumerate(lines) if "<CANopenObject " in line and 'uniqueIDRef="' in line]
    assert users
    for number, line in users[:25]:
        ref = line.split('uniqueIDRef="', 1)[1].split('"', 1)[0]
        column = line.index('uniqueIDRef="') + 3
        found = await client.text_document_definition_async(
            types.DefinitionParams(document, types.Position(number, column))
        )
        assert isinstance(found, types.Location), ref
        assert f'uniqueID="{ref}"' in lines[found.range.start.line], ref
        back = await client.text_document_references_async(
            types.ReferenceParams(
                text_document=document,
                position=types.Position(found.range.start.line, lines[found.range.start.line].index("uniqueID=") + 2),
                context=types.ReferenceContext(include_declaration=False),
            )
        )
        assert number in {where.range.start.line for where in back or []}, ref
    close_file(client, path)
