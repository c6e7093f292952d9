"""The server's incremental re-check (cantools_od/lsp/incremental.py) against a fresh read, after many
random one-line edits of real files: the findings must be `lint --format json` of the edited text
byte for byte, and the device the same model (positions included), whichever edit it was."""

from __future__ import annotations

import random
import subprocess
from pathlib import Path

import pytest

from cantools_od.eds.decode import decode_as
from cantools_od.lint import LintOptions, lint
from cantools_od.lint.output import as_json
from cantools_od.lsp.document import Analysis, Encoding, analyse
from cantools_od.lsp.incremental import reanalyse

from support import ROOT, cli_command, corpus_file

# The largest corpus file; one with CompactPDO; a DCF; a file of another vendor and layout.
FILES = [
    ("sevcon__Nano_pc0x04013019_rev0x0001000b.eds", 30),
    ("curtis__inverter.eds", 30),
    ("oresat__c3.dcf", 40),
    ("nanotec-pd4__example.eds", 40),
]
_VALUES = ["0", "1", "0x10", "300", "-5", "$NODEID+0x180", "0x180+$NODEID", "abc", "", "99999999999"]
_LINES = ["LowLimit=5", "HighLimit=2", "; a comment", "", "ParameterName=Renamed", "not an entry", "PDOMapping=1",
          "AccessType=ro", "DataType=0x0007", "ObjectType=0x7", "DefaultValue=7", "ParameterValue=3"]  # fmt: skip


def _headers(lines: list[str]) -> list[int]:
    return [n for n, line in enumerate(lines) if line.lstrip(" \t").startswith("[")]


def _edit(rng: random.Random, lines: list[str]) -> str:
    """One random one-line edit of `lines` (each with its line end), in place; says which."""
    kind = rng.choice(["value", "value", "insert", "delete", "change", "header", "section"])
    number = rng.randrange(1, len(lines))
    end = lines[number][len(lines[number].rstrip("\r\n")) :] or "\n"
    if kind == "value":
        number = rng.choice([n for n, line in enumerate(lines) if "=" in line and not line.startswith(";")])
        end = lines[number][len(lines[number].rstrip("\r\n")) :] or "\n"
        lines[number] = f"{lines[number].split('=')[0]}={rng.choice(_VALUES)}{end}"
    elif kind == "insert":
        lines.insert(number, rng.choice(_LINES) + end)
    elif kind == "delete":
        del lines[number]
    elif kind == "change":
        lines[number] = rng.choice(_LINES) + end
    elif kind == "header":
        headers = _headers(lines)
        number, names = rng.choice(headers), {lines[n].strip().lower() for n in headers}
        name = next(n for n in iter(lambda: f"[{rng.randrange(0x2000, 0x5FFF):x}{rng.choice(['', 'sub1'])}]", "")
                    if n not in names)  # fmt: skip
        lines[number] = name.upper().replace("SUB", "sub") + end
    else:
        headers = _headers(lines)
        at = rng.randrange(len(headers))
        del lines[headers[at] : headers[at + 1] if at + 1 < len(headers) else len(lines)]
    return kind


def _dump(analysis: Analysis) -> object:
    device = analysis.device
    assert device is not None
    return device.model_dump(exclude={"diagnostics"}), sorted(map(str, device.diagnostics))


@pytest.mark.parametrize(("name", "edits"), FILES)
def test_incremental_recheck_equals_a_fresh_lint_after_random_edits(name: str, edits: int, tmp_path: Path) -> None:
    source = corpus_file(name)
    data = source.read_bytes()
    text, codec, _ = decode_as(data)
    path = tmp_path / name
    uri, encoding, options = path.as_uri(), Encoding(codec, data.startswith(b"\xef\xbb\xbf")), LintOptions()
    rng = random.Random(25)
    lines = text.splitlines(keepends=True)
    before = analyse(uri, text, 1, encoding, options)
    taken = 0
    for version in range(2, edits + 2):
        kind = _edit(rng, lines)
        edited = "".join(lines)
        fresh = analyse(uri, edited, version, encoding, options)
        found = reanalyse(before, uri, edited, version, encoding, options)
        if found is not None:
            taken += 1
            where = f"edit {version - 1} ({kind})"
            assert as_json(found.findings) == as_json(fresh.findings), where
            assert _dump(found) == _dump(fresh), where
        if version % 10 == 0 or version == edits + 1:  # the CLI itself, now and then
            path.write_bytes(encoding.bytes(edited))
            run = subprocess.run(
                [*cli_command(), "lint", "--format", "json", str(path)], capture_output=True, text=True
            )
            assert run.stdout == as_json((found or fresh).findings)
        before = found or fresh
    assert taken >= edits // 3, f"the incremental path took only {taken} of {edits} edits"


def test_a_value_edit_of_the_largest_file_is_read_again_incrementally(tmp_path: Path) -> None:
    """The edit the bench times (a DefaultValue of an object in the middle of the file) takes the path."""
    data = corpus_file(FILES[0][0]).read_bytes()
    text = decode_as(data)[0]
    uri, encoding, options = (tmp_path / "nano.eds").as_uri(), Encoding(), LintOptions()
    before = analyse(uri, text, 1, encoding, options)
    lines = text.splitlines(keepends=True)
    values = [n for n, line in enumerate(lines) if line.startswith("DefaultValue=")]
    number = values[len(values) // 2]
    lines[number] = "DefaultValue=70000\r\n"
    lines.insert(number, "LowLimit=70001\r\n")
    found = reanalyse(before, uri, "".join(lines), 2, encoding, options)
    assert found is not None and found.device is not None
    fresh = lint(analyse(uri, "".join(lines), 2, encoding, options).device or found.device, options)
    assert as_json(found.findings) == as_json(fresh)
    assert any(f.location.line == number + 2 for f in found.findings)  # the new value is judged


def test_per_object_findings_are_judged_again_on_the_edited_object_and_moved_elsewhere(tmp_path: Path) -> None:
    """The per-object rules' findings the incremental check keeps (lint/runner.py) are never stale: the edited
    object's appear and go with its values, another object's move with the lines the edit adds and removes."""
    text = (ROOT / "eds" / "io_device.eds").read_text()
    text = text.replace("DefaultValue=0x00\nPDOMapping=1", "DefaultValue=300\nPDOMapping=1", 1)  # [6000sub1]: EDS034
    uri, encoding, options = (tmp_path / "io.eds").as_uri(), Encoding(), LintOptions()
    before = analyse(uri, text, 1, encoding, options)
    later = [f.location.line for f in before.findings if f.code == "EDS034"]
    assert later and before.linted is not None
    steps = [
        ("DefaultValue=10\n", "DefaultValue=5000\nParameterValue=1\n", {"EDS035", "EDS052"}, 1),  # [2000sub2]
        ("DefaultValue=5000\nParameterValue=1\n", "DefaultValue=10\n", set(), 0),
    ]
    for version, (old, new, codes, moved) in enumerate(steps, 2):
        edited = before.text.replace(old, new, 1)
        found = reanalyse(before, uri, edited, version, encoding, options)
        fresh = analyse(uri, edited, version, encoding, options)
        assert found is not None and found.linted is not None
        assert as_json(found.findings) == as_json(fresh.findings)
        assert {f.code for f in found.findings} - {"EDS034"} == codes
        assert [f.location.line for f in found.findings if f.code == "EDS034"] == [line + moved for line in later]
        before = found
