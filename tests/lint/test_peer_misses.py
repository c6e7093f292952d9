"""Misses that made a named peer fail on real files: an empty number in [DeviceInfo] (DIA019), an octal-looking one
(DIA020), a [Comments] key in another case (DIA021). Each finding names what python-canopen does, and python-canopen
(the judge) does fail on the finding's shape and reads the fixed one."""

from __future__ import annotations

from pathlib import Path

import pytest
from peermatrix import canopen_reading

from cantools_od import loads
from cantools_od.lint import lint

from support import corpus_file

HEAD = "[FileInfo]\nFileName=t.eds\nEDSVersion=4.0\n\n[DeviceInfo]\nVendorName=Acme\n"
TAIL = "\n[Comments]\nLines=2\nLine1=First\nLine2=Second\n"


def _found(text: str, code: str) -> list[tuple[int, str]]:
    return [(f.location.line, f.message) for f in lint(loads(text, source="t.eds")) if f.code == code]


def _python_canopen(tmp_path: Path, text: str) -> str | None:
    path = tmp_path / "t.eds"
    path.write_text(text)
    reading = canopen_reading(path, None)
    return reading if isinstance(reading, str) else None


@pytest.mark.parametrize(
    ("code", "bad", "good", "message"),
    [
        ("DIA019", "VendorNumber=\n", "VendorNumber=0x123\n",
         "[DeviceInfo] VendorNumber is empty; python-canopen fails to load the file"),
        ("DIA019", "ProductNumber=\nNrOfRXPDO=\n", "",
         "[DeviceInfo] ProductNumber is empty; python-canopen fails to load the file"),
        ("DIA020", "ProductNumber=014101\n", "ProductNumber=14101\n",
         "[DeviceInfo] ProductNumber=014101: octal by CiA 306 (6209); python-canopen and lely fail on it"),
    ],
)  # fmt: skip
def test_device_info_numbers_python_canopen_cannot_read(
    tmp_path: Path, code: str, bad: str, good: str, message: str
) -> None:
    text = HEAD + bad + TAIL
    assert _found(text, code)[0] == (7, message)
    assert _python_canopen(tmp_path, text) is not None  # the judge: it fails on the file
    fixed = HEAD + good + TAIL
    assert _found(fixed, code) == []
    assert _python_canopen(tmp_path, fixed) is None


def test_zeros_are_zero_for_every_reader() -> None:
    assert _found(HEAD + "VendorNumber=000\n" + TAIL, "DIA020") == []


def test_comments_key_case(tmp_path: Path) -> None:
    text = HEAD + TAIL.replace("Line2=", "line2=")
    assert _found(text, "DIA021") == [(11, "[Comments] line2: python-canopen looks it up as Line2 and fails")]
    assert _python_canopen(tmp_path, text) is not None
    assert _found(HEAD + TAIL, "DIA021") == [] and _python_canopen(tmp_path, HEAD + TAIL) is None
    assert _found(HEAD + TAIL.replace("Lines=", "LINES="), "DIA021")[0][1].startswith("[Comments] LINES: ")


@pytest.mark.parametrize(
    ("name", "code", "lines"),
    [
        ("canopennode-v1__IO.eds", "DIA021", [49]),
        ("damiao__dm4310_slave.eds", "DIA019", [17, 19]),
        ("faulhaber__605.0141.01-O.eds", "DIA020", [18]),
    ],
)
def test_real_files(name: str, code: str, lines: list[int]) -> None:
    path = corpus_file(name)
    assert [line for line, _ in _found(path.read_text("latin-1"), code)] == lines
    assert isinstance(canopen_reading(path, None), str)  # python-canopen cannot load it
