"""Formatting replies never lose or duplicate a line: a property over random ranges of every corpus file.

The reference is the `fmt` command, run once over copies of every corpus file (LF and CRLF). A whole-document
reply must give `fmt`'s output (or nothing, where `fmt` leaves the file). A range reply must give the unchanged
text, `fmt`'s output, or the text with only the sections the range touches changed, and such that `fmt` of it
is `fmt`'s output: nothing lost, nothing doubled, nothing outside the sections asked about touched.
"""

from __future__ import annotations

import re
import shutil
import subprocess
from dataclasses import dataclass, field
from pathlib import Path

import pytest
import pytest_lsp
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from lspkit import SERVER, XDD_CORPUS, close_file, open_file, start
from lsprotocol import types
from pytest_lsp import LanguageClient

from cantools_od.api import dumps, format_for, loads
from cantools_od.eds.decode import decode_as
from cantools_od.lint import LintOptions
from cantools_od.lsp.document import Analysis, Encoding, analyse
from cantools_od.lsp.edits import apply
from cantools_od.lsp.formatting import NotFormatted, blocks, format_edits

from support import CORPUS, cli_command, corpus_file

EXAMPLES = 160
"""Random ranges drawn (over 2 x 107 documents); about a minute with the one `fmt` run."""
_HEADER = re.compile(r"[ \t]*\[")


@dataclass
class Case:
    """One corpus file as an editor holds it, with one line end throughout, and `fmt`'s output for it."""

    path: Path
    text: str = field(repr=False)
    formatted: str = field(repr=False)
    analysis: list[Analysis] = field(default_factory=list, repr=False)

    def analysed(self) -> Analysis:
        if not self.analysis:
            encoding = Encoding.of_file(self.path)
            self.analysis.append(analyse(self.path.as_uri(), self.text, 1, encoding, LintOptions()))
        return self.analysis[0]

    def reply(self, within: types.Range | None) -> list[types.TextEdit]:
        try:
            return format_edits(self.path.as_uri(), self.analysed(), Encoding.of_file(self.path), within)
        except NotFormatted:
            return []


def _with_ends(data: bytes, eol: bytes) -> bytes:
    return data.replace(b"\r\n", b"\n").replace(b"\r", b"\n").replace(b"\n", eol)


@pytest.fixture(scope="module")
def cases(tmp_path_factory: pytest.TempPathFactory) -> list[Case]:
    sources = sorted(CORPUS.glob("*.[eEdD][dDcC][sSfF]")) + sorted(XDD_CORPUS.glob("*.xdd"))
    if not sources:
        pytest.skip("../shared/eds-corpus is absent")
    root = tmp_path_factory.mktemp("range-formatting")
    documents, formatted = root / "documents", root / "fmt"
    pairs = []
    for eol, name in ((b"\n", "lf"), (b"\r\n", "crlf")):
        for source in sources:
            for folder in (documents, formatted):
                (folder / name).mkdir(parents=True, exist_ok=True)
                (folder / name / source.name).write_bytes(_with_ends(source.read_bytes(), eol))
            pairs.append((documents / name / source.name, formatted / name / source.name))
    done = subprocess.run([*cli_command(), "fmt", "--jobs", "2", *(str(f) for _, f in pairs)], capture_output=True)
    assert done.returncode in (0, 1, 2), done.stderr[-2000:]
    return [Case(doc, decode_as(doc.read_bytes())[0], decode_as(fmt.read_bytes())[0]) for doc, fmt in pairs]


def _fmt(case: Case, text: str) -> str:
    """`fmt` of a text as the command formats it (the same reading and writing, in this process)."""
    device = loads(Encoding.of_file(case.path).bytes(text), source=str(case.path))
    return decode_as(dumps(device, format_for(case.path), style="canonical"))[0]  # in the code page fmt keeps


def _sections_around(lines: list[str], first: int, last: int) -> tuple[int, int]:
    """The lines (first, past the last) of the sections `first`..`last` touch. A section is its header, what follows
    it up to the next section, and the comment lines right above its header, as the server reads sections: a
    selection that ends on the comment above a header touches that header's section."""
    touched = [b for b in blocks(lines) if b.start <= last and b.stop > first]
    return touched[0].start, touched[-1].stop


def _check_range(case: Case, first: int, last: int) -> None:
    within = types.Range(types.Position(first, 0), types.Position(last, 3))
    after = apply(case.text, case.reply(within))
    if after in (case.text, case.formatted):
        return
    old, new = case.text.splitlines(keepends=True), after.splitlines(keepends=True)
    start, stop = _sections_around(old, first, last)
    assert new[:start] == old[:start], f"{case.path.name}: lines before the sections of {first}-{last} changed"
    tail = len(old) - stop
    assert tail == 0 or new[-tail:] == old[-tail:], f"{case.path.name}: lines after the sections of {first}-{last}"
    assert _fmt(case, after) == case.formatted, f"{case.path.name}: formatting lines {first}-{last} lost text"


@settings(max_examples=EXAMPLES, deadline=None, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])  # fmt: skip
@given(data=st.data())
def test_every_formatting_reply_is_fmt_or_unchanged_or_fmt_of_the_sections_asked(cases: list[Case], data) -> None:  # type: ignore[no-untyped-def]
    case = data.draw(st.sampled_from(cases), label="document")
    whole = apply(case.text, case.reply(None))
    assert whole == case.formatted, f"{case.path.name}: the whole document's formatting is not fmt's"
    count = len(case.text.splitlines())
    first = data.draw(st.integers(0, max(count - 1, 0)), label="first line")
    size = data.draw(st.one_of(st.integers(0, 12), st.integers(0, 400), st.just(count)), label="lines")
    _check_range(case, first, min(first + size, max(count - 1, 0)))


@pytest.mark.parametrize("eol", ["\n", "\r\n"], ids=["lf", "crlf"])
def test_formatting_lines_301_to_306_of_the_demo_device_keeps_every_section(tmp_path: Path, eol: str) -> None:
    """The issue's case: fmt moves sections of this file; formatting six lines once deleted lines 165-2205."""
    source = corpus_file("canopendemo__demoDevice.eds")
    path = tmp_path / source.name
    path.write_bytes(_with_ends(source.read_bytes(), eol.encode()))
    copy = tmp_path / "fmt" / source.name
    copy.parent.mkdir()
    shutil.copyfile(path, copy)
    subprocess.run([*cli_command(), "fmt", str(copy)], capture_output=True, check=True)
    case = Case(path, decode_as(path.read_bytes())[0], decode_as(copy.read_bytes())[0])
    for first, last in ((300, 305), (160, 170), (0, 11), (2790, 2829)):
        _check_range(case, first, last)


@pytest_lsp.fixture(config=SERVER)
async def client(lsp_client: LanguageClient):
    await start(lsp_client)
    yield
    await lsp_client.shutdown_session()


@pytest.mark.asyncio
async def test_range_formatting_over_the_protocol_keeps_every_section(client: LanguageClient, tmp_path: Path) -> None:
    source = corpus_file("canopendemo__demoDevice.eds")
    path = tmp_path / source.name
    path.write_bytes(_with_ends(source.read_bytes(), b"\n"))
    text = decode_as(path.read_bytes())[0]
    await open_file(client, path, text)
    document = types.TextDocumentIdentifier(path.resolve().as_uri())
    for first, last in ((300, 306), (1000, 1011)):
        reply = await client.text_document_range_formatting_async(
            types.DocumentRangeFormattingParams(
                document,
                types.Range(types.Position(first, 0), types.Position(last, 0)),
                types.FormattingOptions(4, True),
            )
        )
        after = apply(text, list(reply or []))
        assert len(after.splitlines()) >= len(text.splitlines()) - (last - first), (first, last)
        assert sorted(line for line in after.splitlines() if _HEADER.match(line)) == sorted(
            line for line in text.splitlines() if _HEADER.match(line)
        ), (first, last)
    close_file(client, path)


def test_a_selection_ending_on_the_comment_above_a_header_touches_that_section(cases: list[Case]) -> None:
    """Found by the property test: lines 15-27 of zltech-sim__zlac8015d.eds end on the comment right above
    [2008], so [2008] is formatted too; the check had taken the comment for the end of the section before it."""
    case = next((c for c in cases if c.path.name == "zltech-sim__zlac8015d.eds"), None)
    if case is None:
        pytest.skip("zltech-sim__zlac8015d.eds is not in ../shared/eds-corpus")
    assert case.text.splitlines()[27].startswith(";") and case.text.splitlines()[28] == "[2008]"
    _check_range(case, 15, 27)
