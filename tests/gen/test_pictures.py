"""The PDO pictures (`pdo --format svg`, beside `gen -t markdown`) and the HTML reference (`gen -t html`), looked at
in a real browser: each field's rectangles cover exactly its bits, every mapped entry is labelled, no two texts
overlap, anchors resolve, the filter finds objects; and one screenshot of each kind matches the committed image.

Without the browser, the HTML sweep still runs: every object of every corpus file has its section and anchor, and
no page refers to anything outside itself.
"""

from __future__ import annotations

import os
import re
import subprocess
from html.parser import HTMLParser
from pathlib import Path

import pytest
from browserkit import Page, browser, difference

from cantools_od.api import load
from cantools_od.render import renderer
from cantools_od.render.svg import sheet
from cantools_od.views.bitfield import diagram
from cantools_od.views.codegen import build_view
from cantools_od.views.pdo import Pdo, pdo_map
from cantools_od.xdd import refused

from support import EXAMPLES, ROOT, SHARED, cli_command, corpus_devices

pytestmark = pytest.mark.xdist_group("browser")

GOLDEN = ROOT / "tests" / "gen" / "golden" / "pictures"
EDS_CORPUS = [path for path in corpus_devices() if path.suffix.lower() in (".eds", ".dcf")]
XML_CORPUS = sorted(
    p for p in (SHARED / "eds-corpus" / "xdd").glob("*") if p.suffix.lower() in (".xdd", ".xdc", ".xpd")
)

MEASURE = (Path(__file__).parent / "measure_pictures.js").read_text(encoding="utf-8")


def expected(pdos: list[Pdo]) -> dict[str, dict[str, list[int]]]:
    """Per PDO: each field's number → its bits, from the model (0: the unused bits that end the last byte)."""
    found: dict[str, dict[str, list[int]]] = {}
    for pdo in pdos:
        fields = {str(n): list(range(e.bit_offset, e.bit_offset + e.bit_length)) for n, e in enumerate(pdo.entries, 1)}
        end = -(-pdo.bit_length // 8) * 8
        if pdo.entries and end > pdo.bit_length:
            fields["0"] = list(range(pdo.bit_length, end))
        found[pdo.name.lower()] = fields
    return found


def check_pictures(page: Page, path: Path, pdos: list[Pdo]) -> None:
    measured = page.evaluate(MEASURE)
    want = expected(pdos)
    assert set(measured) == set(want), path.name
    for name, fields in want.items():
        got = measured[name]
        assert {n: sorted(bits) for n, bits in got["fields"].items()} == fields, f"{path.name} {name}: bits"
        assert not got["partial"], f"{path.name} {name}: a field covers part of a cell"
        assert not got["overlaps"], f"{path.name} {name}: overlapping texts {got['overlaps'][:3]}"
        assert not got["stray"], f"{path.name} {name}: labels outside their field {got['stray'][:3]}"
        numbered = {n for n in fields if n != "0"}
        assert numbered <= set(got["labelled"]), f"{path.name} {name}: a field without its label"
        assert set(fields) == set(got["legend"]), f"{path.name} {name}: the legend"


def with_pdos() -> list[tuple[Path, list[Pdo]]]:
    """Each example and corpus file that maps anything, with its PDOs, each file read once."""
    found = []
    for path in [*EXAMPLES.glob("*.eds"), *EDS_CORPUS]:
        try:
            pdos = pdo_map(load(path))
        except Exception:  # a file the reader refuses has no pictures to check
            continue
        if any(p.entries for p in pdos):
            found.append((path, pdos))
    return found


def test_pdo_pictures_cover_exactly_their_bits_in_a_browser(tmp_path: Path) -> None:
    files = with_pdos()
    assert len(files) >= 20, "the corpus has fewer files with PDOs than it had"
    with browser() as chrome:
        page = chrome.page()
        for number, (path, pdos) in enumerate(files):
            svg = tmp_path / f"{number}.svg"
            svg.write_text(sheet([diagram(p) for p in pdos]), encoding="utf-8")
            page.open(svg)
            check_pictures(page, path, pdos)


def test_pdo_svg_from_the_command_line(tmp_path: Path) -> None:
    """`pdo --format svg` prints one sheet; with -o, one file a PDO, each a document of its own."""
    example = EXAMPLES / "cia402_drive.eds"
    sheet_run = subprocess.run([*cli_command(), "pdo", str(example), "--format", "svg", "--node-id", "5"],
                               capture_output=True, text=True, cwd=tmp_path, check=False)  # fmt: skip
    assert sheet_run.returncode == 0, sheet_run.stderr
    assert sheet_run.stdout.count("<svg ") == 1 and 'data-pdo="tpdo2"' in sheet_run.stdout
    run = subprocess.run([*cli_command(), "pdo", str(example), "--format", "svg", "-o", "pictures"],
                         capture_output=True, text=True, cwd=tmp_path, check=False)  # fmt: skip
    assert run.returncode == 0, run.stderr
    assert sorted(p.name for p in (tmp_path / "pictures").iterdir()) == [
        "rpdo1.svg",
        "rpdo2.svg",
        "tpdo1.svg",
        "tpdo2.svg",
    ]
    wrong = subprocess.run([*cli_command(), "pdo", str(example), "-o", "pictures"],
                           capture_output=True, text=True, cwd=tmp_path, check=False)  # fmt: skip
    assert wrong.returncode == 2 and "--format svg" in wrong.stderr and "Traceback" not in wrong.stderr


class _References(HTMLParser):
    """Ids, and every attribute or style that could fetch something."""

    def __init__(self) -> None:
        super().__init__()
        self.ids: set[str] = set()
        self.references: list[str] = []
        self.in_style = False

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.in_style = tag == "style"
        for name, value in attrs:
            if name == "id" and value is not None:
                self.ids.add(value)
            if name in ("href", "src", "xlink:href", "srcset", "action", "poster", "data") and value is not None:
                self.references.append(value)
            if name == "style" and value and "url(" in value:
                self.references += re.findall(r"url\(([^)]*)\)", value)

    def handle_data(self, data: str) -> None:
        if self.in_style:
            self.references += re.findall(r"url\(([^)]*)\)|@import\s+(\S+)", data)


@pytest.mark.parametrize("path", EDS_CORPUS + XML_CORPUS, ids=lambda p: p.name)
def test_every_object_has_its_section_and_nothing_is_fetched(path: Path) -> None:
    device = load(path)
    if refused(device):
        pytest.skip(f"{path.name} is refused by every command (not a device description)")
    page = renderer("html")(build_view(device, "page"))["page.html"]
    found = _References()
    found.feed(page)
    external = [ref for ref in found.references if not str(ref).startswith("#")]
    assert not external, external[:5]
    view = build_view(device, "page")
    for obj in view.objects:
        assert f"{obj.index:04X}" in found.ids, f"{obj.index:04X}h has no section"
        for entry in obj.entries:
            assert f"{obj.index:04X}-{entry.subindex:X}" in found.ids


ANCHORS_AND_FILTER = (Path(__file__).parent / "anchors_and_filter.js").read_text(encoding="utf-8")


def test_html_page_in_a_browser(tmp_path: Path) -> None:
    """The installed command's page: anchors resolve, the filter finds an object by index and by name, the PDO
    pictures inside it hold as they do alone."""
    example = EXAMPLES / "cia402_drive.eds"
    run = subprocess.run([*cli_command(), "gen", str(example), "-t", "html", "-o", "out", "--node-id", "5"],
                         capture_output=True, text=True, cwd=tmp_path, check=False)  # fmt: skip
    assert run.returncode == 0, run.stderr
    with browser() as chrome:
        page = chrome.page()
        page.open(tmp_path / "out" / "cia402_drive.html")
        found = page.evaluate(ANCHORS_AND_FILTER)
        assert found["broken"] == []
        assert found["byIndex"] == ["1A00"]
        assert "6041" in found["byName"] and "1000" not in found["byName"]
        assert found["none"] == []
        assert len(found["all"]) == len(load(example).objects)
        check_pictures(page, example, pdo_map(load(example)))
        assert page.evaluate("location.hash = '#1A00-1'; document.getElementById('1A00-1').matches(':target')")


SHOTS = {
    "pdo_sheet": ("pdo", ["--format", "svg", "--node-id", "5"], 1200, 760),
    "html_page": ("gen", ["-t", "html", "-o", "out", "--node-id", "5"], 1000, 700),
    "bus": ("network", ["--svg", "bus.svg"], 1000, 400),
}


@pytest.mark.parametrize("kind", sorted(SHOTS))
def test_screenshot_matches_the_committed_image(kind: str, tmp_path: Path) -> None:
    """What a person sees, within a tolerance for font rendering: UPDATE_GOLDEN=1 rewrites the image."""
    command, options, width, height = SHOTS[kind]
    example = ROOT / "examples" / "network" / "bus.yml" if command == "network" else EXAMPLES / "cia402_drive.eds"
    run = subprocess.run([*cli_command(), command, str(example), *options],
                         capture_output=True, cwd=tmp_path, check=False)  # fmt: skip
    assert run.returncode == 0, run.stderr
    shown = {"gen": tmp_path / "out" / "cia402_drive.html", "pdo": tmp_path / "sheet.svg"}.get(
        command, tmp_path / "bus.svg"
    )
    if command == "pdo":
        shown.write_bytes(run.stdout)
    with browser() as chrome:
        page = chrome.page()
        page.open(shown, width, height)
        image = page.screenshot()
    golden = GOLDEN / f"{kind}.png"
    if os.environ.get("UPDATE_GOLDEN") or not golden.exists():
        golden.parent.mkdir(parents=True, exist_ok=True)
        golden.write_bytes(image)
        if not os.environ.get("UPDATE_GOLDEN"):
            pytest.fail(f"{golden} was missing and is written now: review and commit it")
    share = difference(image, golden.read_bytes())
    assert share <= 0.01, f"{share:.2%} of the pixels differ from {golden.name} (UPDATE_GOLDEN=1 after review)"


def test_the_readme_picture_is_current(tmp_path: Path) -> None:
    """The picture the README (and pdo's page) shows is what `pdo --format svg -o` makes of the example today."""
    run = subprocess.run([*cli_command(), "pdo", str(EXAMPLES / "cia402_drive.eds"), "--format", "svg", "-o", "out"],
                         capture_output=True, text=True, cwd=tmp_path, check=False)  # fmt: skip
    assert run.returncode == 0, run.stderr
    shown = ROOT / "docs" / "pictures" / "cia402_drive.tpdo2.svg"
    assert "](docs/pictures/cia402_drive.tpdo2.svg)" in (ROOT / "README.md").read_text(encoding="utf-8")
    assert "](../pictures/cia402_drive.tpdo2.svg)" in (ROOT / "docs" / "commands" / "pdo.md").read_text(
        encoding="utf-8"
    )
    assert (tmp_path / "out" / "tpdo2.svg").read_bytes() == shown.read_bytes(), f"regenerate {shown}"
