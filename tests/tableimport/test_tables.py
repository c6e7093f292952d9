"""CSV, TSV, XLSX and Markdown sources: the same table, read the same way."""

from __future__ import annotations

import importlib
from pathlib import Path
from typing import Any

import pytest

from cantools_od import load
from cantools_od.api import save
from cantools_od.model import AccessType, NodeIdExpr, ObjectKind
from cantools_od.tableimport import UnreadableInput, detect_layout, import_tables

HEADER = ["Index", "Sub-index", "Name", "Object code", "Data type", "Access", "PDO mapping", "Default value"]
ROWS = [
    ["0x1000", "", "Device type", "VAR", "UNSIGNED32", "RO", "No", "0x00020192"],
    ["0x1001", "", "Error register", "VAR", "UNSIGNED8", "RO", "Yes", "0"],
    ["0x1018", "", "Identity object", "RECORD", "", "", "", ""],
    ["", "0", "Number of entries", "VAR", "UNSIGNED8", "RO", "", "2"],
    ["", "1", "Vendor-ID", "VAR", "UNSIGNED32", "RO", "", "0x000002D9"],
    ["", "2", "Product code", "VAR", "UNSIGNED32", "RO", "", "0"],
    ["0x1400", "", "RPDO1 communication", "RECORD", "", "", "", ""],
    ["", "1", "COB-ID", "VAR", "UNSIGNED32", "RW", "", "0x200 + Node-ID"],
    ["", "2", "Transmission type", "VAR", "UNSIGNED8", "RW", "", "255"],
    ["0x2100", "", "Parameters", "ARRAY", "", "", "", ""],
    ["", "1", "Parameter 1", "VAR", "INTEGER16", "RW", "Yes", "0"],
    ["", "2", "Parameter 2", "VAR", "INTEGER16", "RW", "Yes", "0"],
    ["", ":", ":", ":", ":", ":", ":", ":"],
    ["", "5", "Parameter 5", "VAR", "INTEGER16", "RW", "Yes", "FFFFh"],
    ["0x6040", "", "Controlword", "VAR", "U16", "R/W", "RPDO", ""],
]


def write_csv(path: Path, rows: list[list[str]], delimiter: str = ",") -> Path:
    import csv

    with path.open("w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle, delimiter=delimiter)
        writer.writerow(HEADER)
        writer.writerows(rows)
    return path


def write_markdown(path: Path, rows: list[list[str]]) -> Path:
    lines = ["# Object dictionary", "", "| " + " | ".join(HEADER) + " |", "|" + "---|" * len(HEADER)]
    lines += ["| " + " | ".join(row) + " |" for row in rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def write_xlsx(path: Path, rows: list[list[str]]) -> Path:
    openpyxl: Any = importlib.import_module("openpyxl")
    book = openpyxl.Workbook()
    sheet = book.active
    sheet.title = "OD"
    sheet.append(HEADER)
    for row in rows:
        sheet.append([int(c) if c.isdigit() else c for c in row])  # numbers as numbers, as spreadsheets hold them
    book.save(path)
    return path


def make(fmt: str, tmp_path: Path, rows: list[list[str]] = ROWS) -> Path:
    if fmt == "csv":
        return write_csv(tmp_path / "od.csv", rows)
    if fmt == "tsv":
        return write_csv(tmp_path / "od.tsv", rows, "\t")
    if fmt == "markdown":
        return write_markdown(tmp_path / "od.md", rows)
    pytest.importorskip("openpyxl")
    return write_xlsx(tmp_path / "od.xlsx", rows)


FORMATS = ["csv", "tsv", "markdown", "xlsx"]


@pytest.mark.parametrize("fmt", FORMATS)
def test_each_format_gives_the_same_device(fmt: str, tmp_path: Path) -> None:
    source = make(fmt, tmp_path)
    assert detect_layout(str(source), source.read_bytes()) == fmt
    result = import_tables([source])
    device = result.device
    assert sorted(device.objects) == [0x1000, 0x1001, 0x1018, 0x1400, 0x2100, 0x6040]
    assert device.objects[0x1000].default == 0x00020192
    assert device.objects[0x1000].access is AccessType.RO and device.objects[0x1000].data_type == 0x07
    assert device.objects[0x1001].pdo_mapping is True
    identity = device.objects[0x1018]
    assert identity.kind is ObjectKind.RECORD and sorted(identity.subs) == [0, 1, 2]
    assert identity.subs[1].default == 0x2D9
    assert device.device_info.vendor_number == 0x2D9
    assert device.objects[0x1400].subs[1].default == NodeIdExpr(offset=0x200)
    # the elision row stands for sub-indices 3 and 4, named by counting on
    params = device.objects[0x2100]
    assert sorted(params.subs) == [0, 1, 2, 3, 4, 5]
    assert params.subs[3].name == "Parameter 3" and params.subs[4].data_type == 0x03
    assert params.subs[5].default == -1  # FFFFh, two's complement for INTEGER16
    assert params.subs[0].default == 5  # sub-index 0: the highest sub-index, inferred
    assert device.objects[0x6040].data_type == 0x06 and device.objects[0x6040].access is AccessType.RW
    # provenance: the row of the file each value came from
    origin = device.objects[0x1000].origin
    assert origin is not None and origin.file == str(source)
    line = 2 if fmt != "markdown" else 5
    assert origin.keys["DefaultValue"][0] == line if fmt != "xlsx" else origin.keys["DefaultValue"][0] == 2


@pytest.mark.parametrize("fmt", FORMATS)
def test_written_eds_reads_back(fmt: str, tmp_path: Path) -> None:
    result = import_tables([make(fmt, tmp_path)])
    out = tmp_path / "out.eds"
    save(result.device, out, style="canonical")
    again = load(out)
    assert [d for d in again.diagnostics if d.severity.value == "error"] == []
    assert sorted(again.objects) == sorted(result.device.objects)
    assert "; from od." in out.read_text()  # per-key provenance comments


def test_table_split_by_a_page_break_keeps_its_object(tmp_path: Path) -> None:
    text = "\t".join(HEADER) + "\n" + "\n".join("\t".join(r) for r in ROWS[:5])
    text += "\n\n" + "\t".join(HEADER) + "\n" + "\t".join(ROWS[5]) + "\n"  # header repeats, no index
    source = tmp_path / "manual.txt"
    source.write_text(text, encoding="utf-8")
    device = import_tables([source]).device
    assert sorted(device.objects[0x1018].subs) == [0, 1, 2]


def test_two_sources_disagree(tmp_path: Path) -> None:
    csv_rows = [row[:] for row in ROWS]
    csv_rows[1][5] = "RW"  # 1001h: RW in the CSV, RO in the Markdown
    first = write_csv(tmp_path / "a.csv", csv_rows)
    second = write_markdown(tmp_path / "b.md", ROWS)
    result = import_tables([first, second], policy="first")
    conflict = next(c for c in result.merged.conflicts if c.index == 0x1001 and c.field == "access")
    places = {(s.file, s.line) for c in conflict.candidates for s in c.sources}
    assert places == {(str(first), 3), (str(second), 6)}
    assert result.device.objects[0x1001].access is AccessType.RW  # policy "first"
    assert import_tables([first, second], policy="last").device.objects[0x1001].access is AccessType.RO
    assert "1001h" in result.report() and "a.csv:3" in result.report()


def test_overrides_resolve_and_exclude(tmp_path: Path) -> None:
    source = make("csv", tmp_path)
    overrides = tmp_path / "over.toml"
    overrides.write_text(
        '[exclude]\n"0x6040" = "not here"\n\n'
        '[objects."0x1001"]\naccess = "rw"\nreason = "test"\n\n'
        '[objects."0x2100".sub."1-2"]\ndefault = "7"\n\n'
        '[objects."0x2100".sub.5]\nexclude = true\n\n'
        '[device]\nvendor_name = "ACME"\nbaud_rates = [125, 500]\n',
        encoding="utf-8",
    )
    result = import_tables([source], overrides=overrides)
    device = result.device
    assert 0x6040 not in device.objects
    assert device.objects[0x1001].access is AccessType.RW
    assert device.objects[0x2100].subs[1].default == 7 and device.objects[0x2100].subs[2].default == 7
    assert 5 not in device.objects[0x2100].subs
    assert device.device_info.vendor_name == "ACME"
    assert device.device_info.baud_rates[500] is True and device.device_info.baud_rates[250] is False


def test_bad_overrides_file(tmp_path: Path) -> None:
    source = make("csv", tmp_path)
    bad = tmp_path / "bad.toml"
    bad.write_text('[objects."0x1001"]\naccess = "sometimes"\n', encoding="utf-8")
    with pytest.raises(UnreadableInput) as caught:
        import_tables([source], overrides=bad)
    assert caught.value.diagnostics[0].code == "IMP003"
    assert caught.value.diagnostics[0].location.line == 2


def test_unreadable_source(tmp_path: Path) -> None:
    with pytest.raises(UnreadableInput) as caught:
        import_tables([tmp_path / "missing.csv"])
    assert caught.value.diagnostics[0].code == "IMP001"


def test_not_a_table(tmp_path: Path) -> None:
    source = tmp_path / "notes.csv"
    source.write_text("a,b,c\n1,2,3\n", encoding="utf-8")
    result = import_tables([source])
    assert result.device.objects == {}
    assert [d.code for d in result.diagnostics] == ["IMP002"]


def test_damaged_xlsx(tmp_path: Path) -> None:
    pytest.importorskip("openpyxl")
    source = tmp_path / "broken.xlsx"
    source.write_bytes(b"PK\x03\x04 not really a workbook")
    with pytest.raises(UnreadableInput) as caught:
        import_tables([source])
    assert caught.value.diagnostics[0].code == "IMP001"
