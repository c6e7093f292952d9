"""Paths to the example files and the shared real-world corpus."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "eds"
SHARED = ROOT.parent / "shared"
CORPUS = SHARED / "eds-corpus" / "eds"


def shared_files(suffixes: tuple[str, ...]) -> list[Path]:
    """Every file anywhere in ../shared (corpus, both sides of the history pairs, third_party) whose suffix, in
    lower case, is one of `suffixes`; [] when ../shared is absent."""
    if not SHARED.is_dir():
        return []
    return sorted(p for p in SHARED.rglob("*") if p.suffix.lower() in suffixes and p.is_file())


def corpus_files() -> list[Path]:
    """Every real EDS/DCF of ../shared, or [] when that folder is absent."""
    if not CORPUS.is_dir():
        return []
    return sorted(p for p in CORPUS.iterdir() if p.suffix.lower() in (".eds", ".dcf"))


def corpus_devices() -> list[Path]:
    """The corpus files that are device descriptions: the rest (an empty file) every command refuses,
    which the corpus sweeps of gen check (tests/gen/test_c_corpus.py)."""
    from cantools_od.sniff import NotADeviceDescription, sniff

    devices = []
    for path in corpus_files():
        try:
            sniff(path.read_bytes(), path.name)
        except NotADeviceDescription:
            continue
        devices.append(path)
    return devices


def file_params(files: list[Path], absent: str) -> list[object]:
    """One pytest parameter a file (named by the file), or one skipped parameter saying what is absent."""
    if not files:
        return [pytest.param(None, marks=pytest.mark.skip(reason=absent))]
    return [pytest.param(path, id=path.name) for path in files]


def corpus_params() -> list[object]:
    return file_params(corpus_devices(), "../shared/eds-corpus is absent")


def corpus_file(name: str) -> Path:
    path = CORPUS / name
    if not path.is_file():
        pytest.skip(f"{name} is not in ../shared/eds-corpus")
    return path


UPDATE_GOLDEN = os.environ.get("UPDATE_GOLDEN") == "1"  # the one switch: UPDATE_GOLDEN=1 rewrites every golden file


def assert_golden(golden: Path, text: str) -> None:
    """The generated `text` is the golden file (C, Rust, Python, Markdown alike); UPDATE_GOLDEN=1 rewrites it first."""
    if UPDATE_GOLDEN:
        golden.parent.mkdir(parents=True, exist_ok=True)
        golden.write_text(text, encoding="utf-8")
    assert golden.is_file(), f"{golden} is missing; run with UPDATE_GOLDEN=1 to write it and review the diff"
    assert golden.read_text(encoding="utf-8") == text, (
        f"{golden} differs from the output; if intended, run with UPDATE_GOLDEN=1 and review the diff"
    )


def cli_command() -> list[str]:
    """The installed console script beside this interpreter, else `python -m cantools_od`."""
    import sys

    script = Path(sys.executable).parent / "cantools-od"
    return [str(script)] if script.exists() else [sys.executable, "-m", "cantools_od"]
