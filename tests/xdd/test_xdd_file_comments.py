"""The EDS `[Comments]` survive XDD and XDC: written as one marked XML comment after the XML declaration,
read back into `[Comments]`, so that python-canopen reads the same comments, node-ID, bit rate and
entries from EDS → XDC → DCF and EDS → XDD → EDS as from the EDS itself (the facts its own test suite
checks on its sample.eds)."""

from __future__ import annotations

import logging
import re
import subprocess
from pathlib import Path

import canopen
import pytest

from cantools_od import dumps, load, loads
from cantools_od.eds.decode import decode_as

from support import CORPUS, cli_command, file_params

# What python-canopen's test suite asks of its sample.eds, in a file of our own: commissioning, a
# DCF value, $NODEID, sub-objects, and comments that an XML comment cannot hold as
# they are: "--", "-" at the end, "-->", backslashes, non-ASCII, an empty line, a control character.
HOSTILE_LINES = [
    "|-------------|",
    "| Don't panic |",
    "|-------------|",
    "",
    "--> not the end, <!-- nor a start --",
    "ends with a dash -",
    "-",
    r"C:\vendor\-x \\ \u0041 \- backslashes as written",
    "Müller ✓ 日本語",
    "tab\tinside and \x1b escape",
    "a ; b",
]
LINES = HOSTILE_LINES + [f"line {n} -- of many ---" for n in range(len(HOSTILE_LINES) + 1, 301)]
OBJECTS = """
[MandatoryObjects]
SupportedObjects=3
1=0x1000
2=0x1001
3=0x1018

[1000]
ParameterName=Device type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x00020192
PDOMapping=0

[1001]
ParameterName=Error register
ObjectType=0x7
DataType=0x0005
AccessType=ro
PDOMapping=1

[1018]
ParameterName=Identity object
ObjectType=0x9
SubNumber=3

[1018sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=const
DefaultValue=2

[1018sub1]
ParameterName=Vendor-ID
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0x12345678

[1018sub2]
ParameterName=Product code
ObjectType=0x7
DataType=0x0007
AccessType=ro

[OptionalObjects]
SupportedObjects=4
1=0x1003
2=0x1017
3=0x1400
4=0x2000

[1003]
ParameterName=Pre-defined error field
ObjectType=0x8
SubNumber=2

[1003sub0]
ParameterName=Number of errors
ObjectType=0x7
DataType=0x0005
AccessType=rw
DefaultValue=0

[1003sub1]
ParameterName=Standard error field
ObjectType=0x7
DataType=0x0007
AccessType=ro

[1017]
ParameterName=Producer heartbeat time
ObjectType=0x7
DataType=0x0006
AccessType=rw
DefaultValue=0
ParameterValue=500

[1400]
ParameterName=Receive PDO 0 Communication Parameter
ObjectType=0x9
SubNumber=2

[1400sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=const
DefaultValue=1

[1400sub1]
ParameterName=COB-ID use by RPDO 1
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=$NODEID+0x200

[ManufacturerObjects]
SupportedObjects=1
1=0x2000

[2000]
ParameterName=Valve % open
ObjectType=0x7
DataType=0x0009
AccessType=rw
DefaultValue=closed
"""


def sample_eds(lines: list[str]) -> str:
    comments = "".join(f"Line{n}={text}\n" for n, text in enumerate(lines, 1))
    head = (
        "[FileInfo]\nFileName=sample.eds\nEDSVersion=4.0\n\n"
        "[DeviceInfo]\nVendorName=Vendor Name\nVendorNumber=1\nBaudRate_500=1\nNrOfRXPDO=1\nNrOfTXPDO=0\n\n"
        "[DeviceComissioning]\nNodeID=0x10\nNodeName=Some name\nBaudrate=500\nNetNumber=0\n\n"
        f"[Comments]\nLines={len(lines)}\n{comments}"
    )
    return head + OBJECTS


def _run(cwd: Path, *args: str) -> None:
    result = subprocess.run([*cli_command(), *args], capture_output=True, text=True, cwd=cwd)
    assert result.returncode == 0, result.stderr
    assert "[Comments]" not in result.stderr  # nothing said lost


def _entries(od: canopen.ObjectDictionary) -> dict[tuple[int, int], tuple[object, ...]]:
    found = {}
    for index, obj in od.items():
        if not isinstance(index, int):
            continue  # the same objects again, by name
        for var in obj.values() if not isinstance(obj, canopen.objectdictionary.ODVariable) else [obj]:
            value = getattr(var, "value", None)
            found[(index, var.subindex)] = (var.name, var.data_type, var.access_type, var.default, value)
    return found


def _read(path: Path) -> canopen.ObjectDictionary:
    logging.getLogger("canopen").setLevel(logging.ERROR)
    return canopen.import_od(str(path))


def test_python_canopen_reads_the_same_after_xdc_and_xdd(tmp_path: Path) -> None:
    (tmp_path / "sample.eds").write_text(sample_eds(LINES), encoding="utf-8")
    _run(tmp_path, "convert", "sample.eds", "-o", "s.xdc")
    _run(tmp_path, "convert", "s.xdc", "-o", "s.dcf")
    _run(tmp_path, "convert", "sample.eds", "-o", "s.xdd")
    _run(tmp_path, "convert", "s.xdd", "-o", "s.eds")
    original = _read(tmp_path / "sample.eds")
    assert original.comments == "\n".join([*LINES[:10], "a", *LINES[11:]])  # python-canopen cuts at ";"
    assert (original.node_id, original.bitrate) == (16, 500_000)
    for name in ("s.dcf", "s.eds"):
        od = _read(tmp_path / name)
        assert od.comments == original.comments, name
        assert (od.node_id, od.bitrate) == (16, 500_000), name
        assert _entries(od) == _entries(original), name
    xdd = (tmp_path / "s.xdd").read_bytes()
    assert b"--" not in xdd.split(b"<!--", 1)[1].split(b"-->", 1)[0]
    # fmt of the XDD keeps it byte for byte, comments included
    _run(tmp_path, "fmt", "s.xdd")
    assert (tmp_path / "s.xdd").read_bytes() == xdd


def test_only_the_marked_comment_before_the_root_is_read(tmp_path: Path) -> None:
    (tmp_path / "sample.eds").write_text(sample_eds(["kept", "--"]), encoding="utf-8")
    _run(tmp_path, "convert", "sample.eds", "-o", "s.xdd")
    text = (tmp_path / "s.xdd").read_text(encoding="utf-8")
    ours = re.search(r"<!--.*?-->\n", text, re.S)
    assert ours is not None and text.index(ours.group()) == text.index("\n") + 1  # right after the declaration
    foreign = "<!--\n[Comments]\nLines=1\nLine1=a tool's banner\n-->\n"
    assert load(tmp_path / "s.xdd").comments.lines == {1: "kept", 2: "--"}  # type: ignore[union-attr]
    # a foreign comment first, ours after it: ours is read, the other stays a comment
    (tmp_path / "both.xdd").write_text(text.replace(ours.group(), foreign + ours.group()), encoding="utf-8")
    assert load(tmp_path / "both.xdd").comments.lines == {1: "kept", 2: "--"}  # type: ignore[union-attr]
    # only a foreign one, or ours inside the document: no [Comments]
    moved = text.replace(ours.group(), foreign).replace(
        "</ISO15745ProfileContainer>", ours.group() + "</ISO15745ProfileContainer>"
    )
    (tmp_path / "moved.xdd").write_text(moved, encoding="utf-8")
    assert load(tmp_path / "moved.xdd").comments is None


def test_an_xdd_without_comments_gets_none(tmp_path: Path) -> None:
    eds = sample_eds([]).replace("[Comments]\nLines=0\n", "")
    (tmp_path / "plain.eds").write_text(eds, encoding="utf-8")
    _run(tmp_path, "convert", "plain.eds", "-o", "plain.xdd")
    assert b"<!--" not in (tmp_path / "plain.xdd").read_bytes()
    assert load(tmp_path / "plain.xdd").comments is None
    (tmp_path / "empty.eds").write_text(sample_eds([]), encoding="utf-8")
    _run(tmp_path, "convert", "empty.eds", "-o", "empty.xdd")
    assert load(tmp_path / "empty.xdd").comments.line_count == 0  # type: ignore[union-attr]


def _commented() -> list[Path]:
    """The corpus EDS/DCF with a [Comments] section."""
    if not CORPUS.is_dir():
        return []
    found = re.compile(rb"^[ \t]*\[comments\]", re.I | re.M)
    return sorted(p for p in CORPUS.iterdir() if p.suffix.lower() in (".eds", ".dcf") and found.search(p.read_bytes()))


def _comments(path: Path, tmp_path: Path) -> str | None:
    """The comments as python-canopen reads them from the file; where it refuses the file for another
    reason (a missing DummyUsage key, a value it cannot read, not UTF-8), from the [Comments] section alone;
    None when it cannot read that either."""
    try:
        return str(_read(path).comments)
    except Exception:
        pass
    data = path.read_bytes()
    try:
        text = data.decode("utf-8")
    except UnicodeDecodeError:  # what python-canopen reads under the locale of the file's code page (Faulhaber's
        text = decode_as(data)[0]  # is DOS 850: Schönaich, not Windows-1252's Sch”naich; see test_trust.py)
    lines = text.splitlines(keepends=True)
    start = next(n for n, line in enumerate(lines) if line.strip().lower() == "[comments]")
    end = next((n for n in range(start + 1, len(lines)) if lines[n].lstrip().startswith("[")), len(lines))
    alone = tmp_path / f"{path.stem}.comments.eds"
    alone.write_text("".join(lines[start:end]), encoding="utf-8")
    try:
        return str(_read(alone).comments)
    except Exception:
        return None


@pytest.mark.parametrize("path", file_params(_commented(), "../shared/eds-corpus is absent"))
def test_corpus_comments_survive_xdd_and_xdc(tmp_path: Path, path: Path) -> None:
    device = load(path, node_id=5)
    back_xdd, back_xdc = tmp_path / "back.eds", tmp_path / "back.dcf"
    back_xdd.write_bytes(dumps(loads(dumps(device, "xdd", "canonical"), fmt="xdd"), "eds", "canonical"))
    back_xdc.write_bytes(dumps(loads(dumps(device, "xdc", "canonical"), fmt="xdc", node_id=5), "dcf", "canonical"))
    want = device.content()["comments"]
    assert want is not None
    assert load(back_xdd).content()["comments"] == want
    assert load(back_xdc).content()["comments"] == want
    # as python-canopen reads them: as from the file, or (where it cannot read them there, as a
    # missing Line<n>) as from our EDS of it
    expected = _comments(path, tmp_path)
    if expected is None:
        plain = tmp_path / "plain.eds"
        plain.write_bytes(dumps(device, "eds", "canonical"))
        expected = _comments(plain, tmp_path)
    assert expected is not None
    assert _comments(back_xdd, tmp_path) == expected
    assert _comments(back_xdc, tmp_path) == expected
