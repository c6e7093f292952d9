"""One open document: its text, the bytes it stands for, and what reading and linting them found."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import unquote, urlparse

from ..eds.decode import CP1252, decode_as, encode
from ..lint import Finding, LintOptions, Selection, load_selection
from ..lint.runner import Linted, linted
from ..model import Device

_BOM = b"\xef\xbb\xbf"


def path_of(uri: str) -> Path | None:
    """The file a `file:` URI names; None for any other scheme."""
    parsed = urlparse(uri)
    if parsed.scheme != "file":
        return None
    return Path(unquote(parsed.path))


@dataclass(frozen=True)
class Encoding:
    """How the document's text becomes bytes again: the codec its file was read with, and its BOM."""

    codec: str = "utf-8"
    bom: bool = False

    @staticmethod
    def of_file(path: Path | None) -> Encoding:
        try:
            data = path.read_bytes() if path is not None else b""
        except OSError:
            data = b""
        return Encoding(decode_as(data)[1], data.startswith(_BOM))

    def bytes(self, text: str) -> bytes:
        try:
            body = encode(text, self.codec)
        except UnicodeEncodeError:  # a character the file's code page cannot hold: the editor's text wins
            body = text.encode("utf-8", "surrogateescape" if self.codec != CP1252 else "replace")
        return (_BOM if self.bom else b"") + body


@dataclass
class Analysis:
    """The device read from one version of the text and the findings lint has for it."""

    version: int | None
    text: str
    device: Device | None
    findings: list[Finding] = field(default_factory=list)
    refusal: tuple[str, str] | None = None
    """(code, one-line reason) when the text is no device description at all."""
    config_error: str | None = None
    linted: Linted | None = None
    """What lint kept of its check for the next one (an edit of one object re-checks that object alone)."""


def source_name(uri: str) -> str:
    path = path_of(uri)
    return str(path) if path is not None else uri


def selection_for(uri: str) -> Selection:
    """`[tool.cantools-od]` of the nearest pyproject.toml above the document's folder; raises ValueError."""
    path = path_of(uri)
    return load_selection(path.parent if path is not None else Path.cwd())


def read(uri: str, data: bytes) -> Device:
    """The device the bytes describe, read as `lint FILE` reads the file; raises NotADeviceDescription."""
    from ..api import loads

    return loads(data, source=source_name(uri))


def analyse(uri: str, text: str, version: int | None, encoding: Encoding, options: LintOptions) -> Analysis:
    """Read and lint one version of a document; never raises for its content."""
    from ..sniff import NotADeviceDescription

    try:
        selection = selection_for(uri)
    except ValueError as error:
        return Analysis(version, text, None, config_error=f"configuration: {error}")
    try:
        device = read(uri, encoding.bytes(text))
    except NotADeviceDescription as error:
        return Analysis(version, text, None, refusal=(error.code, str(error)))
    except RecursionError:
        return Analysis(version, text, None, refusal=("EDS000", "not readable: nested too deeply"))
    checked = linted(device, options, selection)
    return Analysis(version, text, device, checked.findings, linted=checked)
