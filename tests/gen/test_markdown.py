"""`cantools-od gen -t markdown`: golden files, tables and escaping checked with a real Markdown parser
(markdown-it-py: CommonMark with GFM tables), stable anchors, COB-IDs, provenance."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from pykit import (
    LINK,
    assert_example_golden,
    check_markdown,
    eds_text,
    generate,
    github_slug,
    headings,
    html_anchors,
    markdown_tokens,
    odd_bits_eds,
    pdo,
    plain,
    record,
    rendered_ids,
    run_gen,
    tables,
    var,
    view_of,
    walk,
)

from cantools_od.render import renderer
from cantools_od.render.escape import markdown_cell, markdown_text

from support import EXAMPLES

pytest.importorskip("markdown_it", reason="markdown-it-py is in the test extras")

EXAMPLE_FILES = ["io_device.eds", "cia402_drive.eds"]
HOSTILE = [
    "<script>alert(1)</script>",
    "a|b",
    "*x* _y_ __z__",
    "`tick` ``two``",
    "[link](http://example.com) ![img](x.png)",
    "&amp; &#60; &lt;",
    "back\\slash\\|pipe\\",
    "# heading",
    "1. item",
    "- bullet",
    "> quote",
    "http://example.com www.example.com foo@bar.com",
    "$x^2$ ~~strike~~ :smile:",
    "<!-- comment --> <div>block</div>",
    "===",
    "| --- |",
]


@pytest.mark.parametrize("name", EXAMPLE_FILES)
def test_markdown_golden(name: str, tmp_path: Path) -> None:
    assert_example_golden(name, "markdown", ".md", tmp_path)


@pytest.mark.parametrize("name", EXAMPLE_FILES)
def test_examples_are_valid_documents(name: str) -> None:
    text = generate(EXAMPLES / name, "markdown", Path(name).stem)
    tokens = check_markdown(text)
    found = tables(tokens)
    objects = next(t for t in found if t[0][:2] == ["Index", "Name"])
    assert len(objects) - 1 == text.count('\n### <a id="')
    assert all(re.fullmatch(r"[0-9A-F]{4}h", row[0]) for row in objects[1:])


def test_device_summary_pdos_and_provenance() -> None:
    text = generate(EXAMPLES / "io_device.eds", "markdown", "io_device")
    cells = tables(markdown_tokens(text))
    summary = dict(tuple(row) for row in cells[0][1:])
    assert summary["Vendor"] == "cantools-od examples (0x00000CA7)"
    assert summary["Product"] == "cantools-od example I/O module (0x00000401)"
    assert summary["Revision number"] == "0x00010000"
    assert summary["File"] == summary["FileName"] == "io_device.eds"
    pdos = {row[0]: row for row in cells[1][1:]}
    assert pdos["TPDO1"][1:3] == ["$NODEID+0x180", "255"] and pdos["TPDO1"][5] == "40"
    tpdo1 = next(t for t in cells if t[0][-1] == "Identifier" and t[1][-1] == "read_input_8_bit_digital_inputs_1_to_8")
    assert tpdo1[2] == ["2", "8..23", "16", "6401h sub 1h", "Analog input 1", "INTEGER16", tpdo1[2][-1]]
    grids = [t for t in cells if t[0][0] == "Byte"]
    assert grids[1][1:] == [[str(b)] + [n] * 8 for b, n in enumerate("12233")]  # TPDO1: 8 + 16 + 16 bits
    assert grids[0][2] == ["1"] + ["2"] * 8  # RPDO1's dummy entry
    objects = {row[0]: row for row in next(t for t in cells if t[0][0] == "Index")[1:]}
    assert objects["1018h"][-1] == "io_device.eds:223"
    assert objects["2000h"][5] == "TPDO2" and objects["1001h"][5] == "mappable" and objects["1000h"][5] == "no"
    assert objects["1014h"][6] == "$NODEID+0x80"
    details = next(t for t in cells if t[0][0] == "Sub" and t[1][-2] == "device_settings_highest_sub_index_supported")
    assert details[2][1:8] == [
        "Input filter enable",
        "BOOLEAN",
        "rw",
        "no",
        "true",
        "\u2014",
        "device_settings_input_filter_enable",
    ]
    assert details[3][6] == "1..1000" and details[3][-1] == "io_device.eds:548"


def test_node_id_makes_cob_ids_numeric(tmp_path: Path) -> None:
    result = run_gen(EXAMPLES / "io_device.eds", "-t", "markdown", "-o", tmp_path, "--node-id", "5")
    assert result.exit_code == 0, result.output
    text = (tmp_path / "io_device.md").read_text(encoding="utf-8")
    pdos = {row[0]: row for row in tables(markdown_tokens(text))[1][1:]}
    assert pdos["TPDO1"][1] == "0x185" and pdos["RPDO1"][1] == "0x205"
    assert "| Node-ID | 5 |" in text
    assert "0x85 (\\$NODEID\\+0x80)" in text


def _hostile_eds() -> str:
    objects = [var(0x2000 + n, name, 0x0009, "rw", name) for n, name in enumerate(HOSTILE)]
    objects.append(record(0x2100, "a|b <b>", [(name, 0x0005, "rw", "0") for name in HOSTILE]))
    objects.append(pdo("tx", 1, [(0x2100, 1, 8), (0x2100, 2, 8)]))
    text = eds_text(objects)
    text = text.replace("VendorName=cantools-od tests", "VendorName=<img src=x onerror=alert(1)>|*v*")
    return text.replace("ProductName=Crafted", "ProductName=Object 2000h | `x` <h1>")


def test_hostile_text_renders_literally(tmp_path: Path) -> None:
    path = tmp_path / "hostile.eds"
    path.write_text(_hostile_eds(), encoding="utf-8")
    text = generate(path, "markdown", "hostile")
    tokens = check_markdown(text)
    assert headings(tokens)[0] == "Object dictionary: Object 2000h | `x` <h1>"
    found = tables(tokens)
    summary = dict(tuple(row) for row in found[0][1:])
    assert summary["Vendor"] == "<img src=x onerror=alert(1)>|*v*"
    objects = {row[0]: row for row in next(t for t in found if t[0][0] == "Index")[1:]}
    for number, name in enumerate(HOSTILE):
        row = objects[f"{0x2000 + number:04X}h"]
        assert row[1] == name.strip() and row[6] == f'"{name}"', row
    assert objects["2100h"][1] == "a|b <b>"
    subs = next(t for t in found if t[0][0] == "Sub" and t[1][-2].startswith("a_b_b_"))
    assert [row[1] for row in subs[2:]] == [name.strip() for name in HOSTILE]
    tpdo1 = next(t for t in found if t[0][0] == "#")
    assert [row[4] for row in tpdo1[1:]] == HOSTILE[:2]


def test_object_headings_carry_names_and_anchors_by_index_only(tmp_path: Path) -> None:
    """Why: the anchors were GitHub's slugs of the headings (`#object-1400h-rpdo-communication-parameter-1`), so a
    rename broke every link into the page, though the page said they never depend on names."""
    path = tmp_path / "odd_bits.eds"
    path.write_text(odd_bits_eds(), encoding="ascii")
    before_text = generate(path, "markdown", "odd_bits")
    before = headings(markdown_tokens(before_text))
    assert "Object 2100h: Odd values" in before
    path.write_text(odd_bits_eds().replace("Odd values", "Renamed: odd *values*"), encoding="ascii")
    after_text = generate(path, "markdown", "odd_bits")
    tokens = check_markdown(after_text)
    after = headings(tokens)
    assert "Object 2100h: Renamed: odd *values*" in after  # the name as written, not as Markdown
    changed = [(b, a) for b, a in zip(before, after, strict=True) if b != a]
    assert changed == [("Object 2100h: Odd values", "Object 2100h: Renamed: odd *values*")]
    assert html_anchors(markdown_tokens(before_text)) == html_anchors(tokens)
    assert set(LINK.findall(before_text)) == set(LINK.findall(after_text))
    assert "](#2100)" in after_text and '### <a id="2100"></a>Object 2100h: Renamed' in after_text
    assert not [link for link in LINK.findall(after_text) if re.match(r"object-[0-9a-f]{4}h", link)]
    view = view_of(path, "odd_bits")
    objects = [f"{obj.index:04X}" for obj in view.objects]
    subs = [f"{obj.index:04X}-{entry.subindex:X}" for obj in view.objects for entry in obj.entries]
    assert set(objects + subs) <= set(html_anchors(tokens))
    assert {"tpdo4", "rpdo2"} <= {github_slug(h) for h in after}


@pytest.mark.parametrize("name", EXAMPLE_FILES)
def test_rendered_page_has_every_anchor_its_links_name(name: str) -> None:
    """The page as HTML (CommonMark keeps inline HTML, as GitHub does for `<a id>`): every in-page link reaches an
    element of that id or a heading; each object's and sub-object's anchor is its index, `1400` and `1400-1`."""
    text = generate(EXAMPLES / name, "markdown", Path(name).stem)
    page = rendered_ids(text)
    assert page.links and page.links <= page.ids | {github_slug(h) for h in headings(markdown_tokens(text))}
    assert {"1400", "1400-1", "1800-1", "1A00-1"} <= page.ids if name == "cia402_drive.eds" else {"1400-1"} <= page.ids
    mapped = re.findall(r"\[([0-9A-F]{4})h sub ([0-9A-F]+)h\]\(#([0-9A-F]{4}-[0-9A-F]+)\)", text)
    assert all(f"{index}-{sub}" == target for index, sub, target in mapped)
    assert mapped or name == "cia402_drive.eds"  # its PDOs map VAR objects only


def test_counts_in_prose_are_singular_for_one(tmp_path: Path) -> None:
    path = tmp_path / "single.eds"
    objects = [var(0x2000, "Flag", 0x0001, "rw", "0"), record(0x2001, "Empty", [])]
    objects.append(pdo("tx", 1, [(0x2000, 0, 1)]))
    path.write_text(eds_text(objects), encoding="utf-8")
    text = generate(path, "markdown", "single")
    assert "1 bit (1 byte)" in text and "RECORD with 1 sub-object," in text and "RECORD, 1 sub-object |" in text
    for target in ("markdown", "c", "rust", "python"):
        generated = "".join(renderer(target)(view_of(path, "single")).values())
        assert not re.search(r"\b1 (bits|bytes|sub-objects)\b", generated), target
        assert re.search(r"\b1 (bit|byte)\b", generated), target


def test_odd_bits_layout_table(tmp_path: Path) -> None:
    path = tmp_path / "odd_bits.eds"
    path.write_text(odd_bits_eds(), encoding="ascii")
    found = tables(check_markdown(generate(path, "markdown", "odd_bits")))
    grids = [t for t in found if t[0][0] == "Byte"]
    tpdo1 = grids[2]  # RPDO1, RPDO2, TPDO1, ...
    assert tpdo1[1] == ["0", *["2"] * 7, "1"]  # bit 0: flag A, bits 1..: INTEGER48
    assert tpdo1[7] == ["6", "9", "8", "7", "6", "5", "4", "3", "2"]  # bit 48: INTEGER48's last, then flags
    assert tpdo1[8] == ["7", *["10"] * 8]
    rpdo2 = grids[1]
    assert rpdo2[3] == ["2", *["2"] * 8]  # the dummy UNSIGNED8 is entry 2


@given(st.text(st.characters(codec="utf-8"), max_size=40) | st.text("\\|`*_<>&[]()!#-+.:=~$^@ ab1\n", max_size=20))
@settings(max_examples=400, deadline=None)
def test_escaped_text_renders_literally(text: str) -> None:
    cell, inline = markdown_cell(text), markdown_text(text)
    document = f"| a | b |\n| --- | --- |\n| {cell} | x |\n\nSay {inline} now.\n"
    tokens = markdown_tokens(document)
    kinds = {t.type for t in walk(tokens)}
    assert not kinds & {"html_inline", "html_block", "em_open", "strong_open", "s_open", "link_open", "image"}
    shown = " ".join("".join(" " if ord(c) < 0x20 or ord(c) == 0x7F else c for c in text).split())
    assert tables(tokens) == [[["a", "b"], [shown or "\u2014", "x"]]]
    paragraph = next(t for t in tokens if t.type == "inline" and t.content.startswith("Say"))
    assert plain(paragraph.children or []) == f"Say {shown} now." if shown else "Say  now."


def _type_definitions_eds() -> str:
    deftype = "[0041]\nParameterName=Motor parameters\nObjectType=0x5\nDataType=0x0007\nAccessType=const\n"
    deftype += "DefaultValue=2048\nPDOMapping=0"
    member = "\nObjectType=0x7\nDataType={}\nAccessType=const\nDefaultValue={}"
    defstruct = [
        "[0042]\nParameterName=Pair type\nObjectType=0x6\nSubNumber=3",
        "[0042sub0]\nParameterName=Number of entries" + member.format("0x0005", "2"),
        "[0042sub1]\nParameterName=First" + member.format("0x0006", "0x0007"),
        "[0042sub2]\nParameterName=Second" + member.format("0x0006", "0x0006"),
    ]
    objects = ["[MandatoryObjects]\nSupportedObjects=1\n1=0x1000", var(0x1000, "Device type", 0x0007, "ro")]
    return eds_text([*objects, "[OptionalObjects]\nSupportedObjects=2\n1=0x0041\n2=0x0042", deftype, *defstruct])


def test_type_definitions_are_in_the_reference(tmp_path: Path) -> None:
    """Objects 0040h-005Fh that define types (DEFTYPE, DEFSTRUCT) are named in the document like any other."""
    path = tmp_path / "types.eds"
    path.write_text(_type_definitions_eds(), encoding="ascii")
    text = generate(path, "markdown", "types")
    check_markdown(text)
    found = {row[0]: row for table in tables(markdown_tokens(text)) for row in table[1:]}
    assert found["0041h"][1:5] == ["Motor parameters", "DEFTYPE", "UNSIGNED32", "2048 bits"]
    assert '### <a id="0042"></a>Object 0042h: Pair type' in text
    assert "[Type definitions](#type-definitions)" in text and "Type definitions" in headings(markdown_tokens(text))
