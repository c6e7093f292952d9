"""The EDS reader's per-line scanner is compiled into the wheel (cantools_od/eds/_scan.c, built by hatch_build.py);
its Python form (`ini._scan_python`) is the reference. The two must read every text alike: every real file, and
generated text full of what breaks lines, blanks, comments and wide characters."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from hypothesis import example, given
from hypothesis import strategies as st

from cantools_od.eds import ini
from cantools_od.eds.decode import decode

from support import EXAMPLES, ROOT, shared_files


def _real_files() -> list[Path]:
    suffixes = (".eds", ".dcf")
    return sorted(p for p in EXAMPLES.iterdir() if p.suffix.lower() in suffixes) + shared_files(suffixes)


def _read(text: str, scan: Callable[..., Any], monkeypatch: pytest.MonkeyPatch) -> tuple[object, ...]:
    monkeypatch.setattr(ini, "scan", scan)
    stream = ini.Stream(_pieces(text))
    sections = list(stream)
    kinds = [type(entry) for section in sections for entry in section.entries]
    return sections, kinds, stream.preamble_stray, stream.long_lines, stream.trailing


def _pieces(text: str) -> Iterator[str]:
    """The text as the reader of a large file gives it: cut before a header line, here the middle one."""
    starts = [0, *ini._header_starts(text)]
    middle = starts[len(starts) // 2]
    yield from (piece for piece in (text[:middle], text[middle:]) if piece)


def compiled() -> Callable[..., Any]:
    from cantools_od.eds import _scan

    return _scan.scan


def test_the_installed_reader_uses_the_compiled_scanner() -> None:
    # make test installs the wheel; a machine without a C compiler would get the Python form, and this says so
    assert ini.scan is compiled(), f"the compiled EDS scanner is not installed beside {ini.__file__}"


@pytest.mark.parametrize("path", _real_files(), ids=lambda p: p.relative_to(ROOT.parent).as_posix())
def test_compiled_and_python_read_every_real_file_alike(path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    text = decode(path.read_bytes())[0]
    assert _read(text, compiled(), monkeypatch) == _read(text, ini._scan_python, monkeypatch)


_PARTS = ["[", "]", "[1000]", "[1000sub1]", "=", " = ", ";c", "#c", " ", "\t", "\r", "\n", "\r\n", "Key", "0x7F",
          "\v", "\x85", "\u2028", "\x00", "é", "€", "\U0001d11e", "x" * 250]  # fmt: skip


@given(st.lists(st.sampled_from(_PARTS), max_size=60))
@example(["x" * 250, "x" * 250, "\r\n", "[A]", "\r", "\r\n", " ", "=", "\n", "\t", ";c"])
@example(["[A]", "\n", " \t", "Key", " ", "=", " ", "\n", "#c", "\n", "Key", "=", "\r"])
@example(["\U0001d11e", "[", "€", "\n", "é", "=", "\u2028", "\v", "\n", "\r"])
def test_compiled_and_python_read_any_text_alike(parts: list[str]) -> None:
    text = "".join(parts)
    with pytest.MonkeyPatch.context() as patch:
        assert _read(text, compiled(), patch) == _read(text, ini._scan_python, patch)


def test_compiled_scanner_refuses_wrong_arguments_with_an_exception() -> None:
    scan = compiled()
    with pytest.raises(TypeError):
        scan(b"[A]\n", 1, 1, [], [], [], [], True)
    with pytest.raises(TypeError):
        scan("[A]\n", 1, 1, (), [], [], [], True)
    with pytest.raises(TypeError):
        scan("[A]\n", 1)


@pytest.mark.parametrize("scan", [compiled, lambda: ini._scan_python], ids=["compiled", "python"])
def test_a_section_must_start_with_its_header(scan: Callable[[], Callable[..., Any]]) -> None:
    with pytest.raises(ValueError, match="starts with its header line"):
        scan()("Key=1\n[A]\n", 1, 1, [], [], [], [], True)
