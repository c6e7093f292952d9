"""Helpers of the Python and Markdown generator tests: generating in-process, importing generated
modules, a crafted EDS with odd bit lengths, python-canopen's own PDO bytes, Markdown checks."""

from __future__ import annotations

import importlib.util
import itertools
import random
import re
import shutil
import struct
import sys
import unicodedata
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType
from typing import Any

import canopen
from click.testing import CliRunner, Result

from cantools_od import load
from cantools_od.cli.gen import command as gen_command
from cantools_od.render import renderer
from cantools_od.views.codegen import DeviceView, build_view

from support import EXAMPLES, assert_golden

GOLDEN = Path(__file__).resolve().parent / "gen" / "golden"
_COUNTER = itertools.count()


def view_of(path: Path, name: str, node_id: int | None = None) -> DeviceView:
    device = load(path, node_id=node_id)
    return build_view(device, name, node_id)


def generate(path: Path, target: str, name: str, node_id: int | None = None) -> str:
    """The one file `target` makes for `path` (the page, for Markdown: its PDO pictures beside it are SVG files),
    rendered in-process."""
    files = renderer(target)(view_of(path, name, node_id))
    if target == "markdown":
        files = {file: text for file, text in files.items() if not file.endswith(".svg")}
    assert len(files) == 1, files
    return next(iter(files.values()))


def assert_example_golden(name: str, target: str, suffix: str, tmp_path: Path) -> None:
    """What `target` makes for the shipped example `name` is its golden file, and the same for a copy of
    the example elsewhere (the output does not depend on where the file is)."""
    stem = Path(name).stem
    text = generate(EXAMPLES / name, target, stem)
    copy = tmp_path / name
    shutil.copy(EXAMPLES / name, copy)
    assert generate(copy, target, stem) == text
    assert_golden(GOLDEN / target / f"{stem}{suffix}", text)


def run_gen(*args: str | Path) -> Result:
    """`cantools-od gen ARGS`, in-process."""
    return CliRunner().invoke(gen_command, [str(a) for a in args], catch_exceptions=True)


def import_file(path: Path) -> ModuleType:
    """Import a generated module from its file under a unique name (as `import` would: in sys.modules)."""
    name = f"{path.stem}_{next(_COUNTER)}"
    spec = importlib.util.spec_from_file_location(name, path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[name] = module
    try:
        spec.loader.exec_module(module)
    except BaseException:
        del sys.modules[name]
        raise
    return module


def generated_module(path: Path, folder: Path, name: str, node_id: int | None = None) -> ModuleType:
    target = folder / f"{name}.py"
    target.write_text(generate(path, "python", name, node_id), encoding="utf-8")
    return import_file(target)


# --- a crafted EDS ---------------------------------------------------------------------------------------


def eds_text(objects: list[str], dummies: bool = True) -> str:
    head = [
        "[FileInfo]",
        "FileName=crafted.eds",
        "EDSVersion=4.0",
        "[DeviceInfo]",
        "VendorName=cantools-od tests",
        "ProductName=Crafted",
        "BaudRate_250=1",
    ]
    if dummies:
        head += ["[DummyUsage]", *(f"Dummy000{n}=1" for n in range(1, 8))]
    return "\n".join([*head, *objects]) + "\n"


def var(index: int, name: str, data_type: int, access: str = "rw", default: str = "0", **keys: str) -> str:
    lines = [f"[{index:04X}]", f"ParameterName={name}", "ObjectType=0x7", f"DataType=0x{data_type:04X}"]
    lines += [f"AccessType={access}", f"DefaultValue={default}", "PDOMapping=1"]
    lines += [f"{key}={value}" for key, value in keys.items()]
    return "\n".join(lines)


def record(index: int, name: str, subs: list[tuple[str, int, str, str]], mappable: bool = True) -> str:
    """subs: (name, data type, access, default) for sub-index 1..n; sub-index 0 is the count."""
    lines = [f"[{index:04X}]", f"ParameterName={name}", "ObjectType=0x9", f"SubNumber={len(subs) + 1}"]
    lines += [f"[{index:04X}sub0]", "ParameterName=Highest sub-index supported", "ObjectType=0x7"]
    lines += ["DataType=0x0005", "AccessType=ro", f"DefaultValue={len(subs)}", "PDOMapping=0"]
    for number, (sub_name, data_type, access, default) in enumerate(subs, 1):
        lines += [f"[{index:04X}sub{number:X}]", f"ParameterName={sub_name}", "ObjectType=0x7"]
        lines += [f"DataType=0x{data_type:04X}", f"AccessType={access}", f"DefaultValue={default}"]
        lines += [f"PDOMapping={int(mappable)}"]
    return "\n".join(lines)


def pdo(direction: str, number: int, entries: list[tuple[int, int, int]]) -> str:
    """Communication and mapping records of one PDO mapping (index, sub-index, bits) entries."""
    comm = (0x1400 if direction == "rx" else 0x1800) + number - 1
    base = {"rx": 0x200, "tx": 0x180}[direction] + 0x100 * (number - 1)
    parameters = [("COB-ID", 0x7, "rw", f"$NODEID+0x{base:X}"), ("Transmission type", 0x5, "rw", "255")]
    values = [("Mapped object", 0x7, "rw", f"0x{i:04X}{s:02X}{b:02X}") for i, s, b in entries]
    return "\n".join(
        [
            record(comm, f"PDO communication {number}", parameters, mappable=False),
            record(comm + 0x200, f"PDO mapping {number}", values, mappable=False),
        ]
    )


# the record that the odd-bit PDOs map, sub-index → (name, type)
ODD = 0x2100
ODD_SUBS = {1: ("Flag A", 0x1), 2: ("Flag B", 0x1), 3: ("Int24", 0x10), 4: ("Uint40", 0x18)}
ODD_SUBS |= {5: ("Int48", 0x13), 6: ("Real", 0x8), 7: ("Byte", 0x5), 8: ("Int16", 0x3)}
A, B, I24, U40, I48, REAL, BYTE, I16 = (
    (ODD, sub, bits) for sub, bits in zip(range(1, 9), (1, 1, 24, 40, 48, 32, 8, 16), strict=True)
)
# python-canopen writes a field that does not start on a byte with the struct of its own type at the field's
# first byte: the frame must be long enough for that struct, and bits the struct spills over must be written
# after it. Each of these layouts keeps to that, so python-canopen's bytes are right and can be compared.
ODD_PDOS = {
    ("tx", 1): [A, I48, B, A, B, A, B, A, B, BYTE],  # INTEGER48 at bit 1, the same object mapped again and again
    ("tx", 2): [I24, U40],
    ("tx", 3): [REAL, I24, BYTE],
    ("tx", 4): [B, I24, A, B, A, B, A, B, A, REAL],  # INTEGER24 at bit 1
    ("rx", 1): [U40, I24],
    ("rx", 2): [I16, (0x0005, 0, 8), BYTE, (0x0007, 0, 32)],  # dummy entries
}


def odd_bits_eds() -> str:
    subs = [(name, data_type, "rw", "0") for name, data_type in ODD_SUBS.values()]
    objects = [
        var(0x1000, "Device type", 0x7, "ro"),
        var(0x1017, "Producer heartbeat time", 0x6, "rw", "0"),
        record(ODD, "Odd values", subs),
        *(pdo(direction, number, entries) for (direction, number), entries in ODD_PDOS.items()),
    ]
    return eds_text(objects)


# --- python-canopen's PDO bytes -------------------------------------------------------------------------


def canopen_pdos(path: Path, node_id: int) -> dict[str, Any]:
    """{"Rpdo1": PdoMap, "Tpdo1": PdoMap, ...} of python-canopen, read from the file's default values."""
    node = canopen.RemoteNode(node_id, canopen.import_od(str(path), node_id))
    canopen.Network().add_node(node)
    node.tpdo.read(from_od=True)
    node.rpdo.read(from_od=True)
    maps: dict[str, Any] = {}
    for prefix, pdos in (("Rpdo", node.rpdo), ("Tpdo", node.tpdo)):
        for number, pdo_map in pdos.map.items():
            maps[f"{prefix}{number}"] = pdo_map
    return maps


def random_value(rng: random.Random, kind: str, bits: int) -> int | float | bool:
    if kind == "bool":
        return rng.random() < 0.5
    if kind == "real":
        if bits == 32:
            special = [0.0, -0.0, 1.5, -2.25, 3.4028234663852886e38, 1e-45]
            value = rng.choice(special) if rng.random() < 0.2 else rng.uniform(-1e6, 1e6)
            return float(struct.unpack("<f", struct.pack("<f", value))[0])
        return rng.uniform(-1e300, 1e300)
    low, high = (-(1 << (bits - 1)), (1 << (bits - 1)) - 1) if kind == "signed" else (0, (1 << bits) - 1)
    return rng.choice([low, high, 0, -1 if low else 1, rng.randint(low, high)])


def canopen_bytes(pdo_map: Any, values: list[int | float | bool]) -> bytes:
    """python-canopen's bytes for a PDO whose non-dummy variables take `values`, set in map order."""
    pdo_map.data = bytearray(len(pdo_map.data))
    variables = [v for v in pdo_map.map if v.index >= 0x1000]
    assert len(variables) == len(values)
    for variable, value in zip(variables, values, strict=True):
        variable.raw = value
    return bytes(pdo_map.data)


# --- Markdown ---------------------------------------------------------------------------------------------


def markdown_tokens(text: str) -> list[Any]:
    from markdown_it import MarkdownIt

    return MarkdownIt("commonmark").enable("table").enable("strikethrough").parse(text)


def walk(tokens: list[Any]) -> Iterator[Any]:
    for token in tokens:
        yield token
        if token.children:
            yield from walk(token.children)


def tables(tokens: list[Any]) -> list[list[list[str]]]:
    """Each table as rows of cell texts (the rendered inline text), the header row first."""
    found: list[list[list[str]]] = []
    row: list[str] | None = None
    for index, token in enumerate(tokens):
        if token.type == "table_open":
            found.append([])
        elif token.type == "tr_open":
            row = []
        elif token.type == "tr_close":
            assert row is not None
            found[-1].append(row)
        elif token.type in ("th_open", "td_open"):
            inline = tokens[index + 1]
            assert row is not None
            row.append(plain(inline.children or []) if inline.type == "inline" else "")
    return found


def plain(children: list[Any]) -> str:
    """The text an inline token renders, without markup."""
    return "".join(c.content for c in walk(children) if c.type in ("text", "code_inline", "text_special"))


def github_slug(text: str) -> str:
    """GitHub's heading anchor: lower case, punctuation other than `-` and `_` dropped, spaces to `-`."""
    out = []
    for char in text.lower():
        category = unicodedata.category(char)
        if char in " -":
            out.append("-")
        elif char == "_" or category[0] in "LNM":
            out.append(char)
    return "".join(out)


def headings(tokens: list[Any]) -> list[str]:
    return [plain(tokens[i + 1].children or []) for i, t in enumerate(tokens) if t.type == "heading_open"]


LINK = re.compile(r"\]\(#([^)]*)\)")
PICTURE = re.compile(r"[a-z0-9_]+\.[rt]pdo[0-9]+\.svg")
CELL = re.compile(r"(?<!\\)\|")  # a pipe that splits a GFM table row (one not escaped)


ANCHOR_TAG = re.compile(r'<a id="([0-9A-F]{4}(?:-[0-9A-F]{1,2})?)"></a>')
"""The one piece of raw HTML a reference may hold: an empty element carrying an object's anchor by index."""


def html_anchors(tokens: list[Any]) -> list[str]:
    """The anchors of `<a id>` elements, in order; asserts that they are the only HTML and each is closed."""
    found: list[str] = []
    inline = [t for t in walk(tokens) if t.type in ("html_inline", "html_block")]
    for opening, closing in zip(inline[::2], inline[1::2], strict=True):
        match = ANCHOR_TAG.fullmatch(opening.content + closing.content)
        assert opening.type == closing.type == "html_inline" and match, (opening.content, closing.content)
        found.append(match.group(1))
    return found


@dataclass(frozen=True)
class RenderedPage:
    ids: set[str]
    links: set[str]


def rendered_ids(text: str) -> RenderedPage:
    """The ids of the elements of the page rendered as HTML, and the in-page links' targets."""
    from html.parser import HTMLParser

    from markdown_it import MarkdownIt

    page = RenderedPage(set(), set())

    class Collect(HTMLParser):
        def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
            found = dict(attrs)
            if found.get("id"):
                page.ids.add(str(found["id"]))
            href = found.get("href") or ""
            if tag == "a" and href.startswith("#"):
                page.links.add(href[1:])

    Collect().feed(MarkdownIt("commonmark").enable("table").render(text))
    return page


def check_markdown(text: str) -> list[Any]:
    """Tokens of a valid document: no HTML but anchors by index, links only to anchors of the document (a heading's
    or an explicit one), tables well-formed."""
    check_markdown_lines(text)
    tokens = markdown_tokens(text)
    kinds = {t.type for t in walk(tokens)}
    assert not kinds & {"em_open", "strong_open", "s_open"}, kinds
    for token in walk(tokens):  # the only images are the PDO pictures gen writes beside the page
        if token.type == "image":
            assert PICTURE.fullmatch(str(token.attrGet("src"))), token.attrGet("src")
    anchors: dict[str, int] = {}
    for name in [github_slug(heading) for heading in headings(tokens)] + html_anchors(tokens):
        count = anchors.get(name, 0)
        anchors[name] = count + 1
        assert count == 0, f"two places have the anchor #{name}"
    for token in walk(tokens):
        if token.type == "link_open":
            href = token.attrGet("href")
            assert isinstance(href, str) and href.startswith("#") and href[1:] in anchors, href
    lines = text.splitlines()
    for token in tokens:
        if token.type == "table_open":
            start, end = token.map
            header = CELL.split(lines[start].strip()[1:-1])
            for line in lines[start:end]:
                assert len(CELL.split(line.strip()[1:-1])) == len(header), line
    for table in tables(tokens):
        assert all(len(row) == len(table[0]) for row in table)
    return tokens


def check_markdown_lines(text: str) -> None:
    """Cheaper checks, without a parser: every table row has its header's cells, nothing unescaped opens HTML but
    the anchors by index, every link points to a heading or an anchor of the document."""
    header: list[str] | None = None
    for line in text.splitlines():
        if not line.startswith("|"):
            header = None
            continue
        assert line.startswith("| ") and line.endswith(" |"), line
        cells = CELL.split(line[1:-1])
        if header is None:
            header = cells
        assert len(cells) == len(header), line
    assert re.search(r"(?<!\\)<", ANCHOR_TAG.sub("", text)) is None, "unescaped <"
    headed = [ANCHOR_TAG.sub("", line).lstrip("#").strip() for line in text.splitlines() if line.startswith("#")]
    assert set(LINK.findall(text)) <= {github_slug(h) for h in headed} | set(ANCHOR_TAG.findall(text))


@contextmanager
def virtual_network(channel: str) -> Iterator[canopen.Network]:
    network = canopen.Network()
    network.connect(interface="virtual", channel=channel, receive_own_messages=False)
    try:
        yield network
    finally:
        network.disconnect()
