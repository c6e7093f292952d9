"""Paths to the example files and the shared real-world corpus."""

from __future__ import annotations

from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
EXAMPLES = ROOT / "eds"
CORPUS = ROOT.parent / "shared" / "eds-corpus" / "eds"


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


def corpus_params() -> list[object]:
    files = corpus_devices()
    if not files:
        return [pytest.param(None, marks=pytest.mark.skip(reason="../shared/eds-corpus is absent"))]
    return [pytest.param(path, id=path.name) for path in files]


def corpus_file(name: str) -> Path:
    path = CORPUS / name
    if not path.is_file():
        pytest.skip(f"{name} is not in ../shared/eds-corpus")
    return path


def cli_command() -> list[str]:
    """The installed console script beside this interpreter, else `python -m cantools_od`."""
    import sys

    script = Path(sys.executable).parent / "cantools-od"
    return [str(script)] if script.exists() else [sys.executable, "-m", "cantools_od"]
