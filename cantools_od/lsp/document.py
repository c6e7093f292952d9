"""One open document: its text, the bytes it stands for, and what reading and linting them found."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import unquote, urlparse

from ..eds.decode import CP1252, decode_as, encode
from ..lint import Finding, LintOptions, Selection, load_selection
from ..lint.runner import Linted, linted
from ..model import Device
from .mojibake import restored

_BOM = b"\xef\xbb\xbf"


def path_of(uri: str) -> Path | None:
    """The file a `file:` URI names; None for any other scheme."""
    parsed = urlparse(uri)
    if parsed.scheme != "file":
        return None
    return Path(unquote(parsed.path))


@dataclass(frozen=True)
class Encoding:
    """How the document's text becomes bytes again: the codec its file was read with, its BOM, and what the
    file held where an editor that decoded it as UTF-8 shows replacement characters (U+FFFD)."""

    codec: str = "utf-8"
    bom: bool = False
    original: bytes = b""
    """The file's bytes when it is not UTF-8 (Windows-1252, a DOS code page): what the U+FFFD stand for."""
    on_disk: bool = False
    """The document is a file that could be read."""
    replaced: bool = False
    """The file, decoded as `lint` decodes it, holds U+FFFD itself."""

    @staticmethod
    def of_file(path: Path | None) -> Encoding:
        try:
            data = path.read_bytes() if path is not None else None
        except OSError:
            data = None
        if data is None:
            return Encoding()
        text, codec, _ = decode_as(data)
        return Encoding(codec, data.startswith(_BOM), data if codec != "utf-8" else b"", True, "\ufffd" in text)

    def mangled(self, text: str) -> str | None:
        """Why the text cannot be written back: it holds replacement characters the file does not (the editor
        decoded the file with another encoding than the file's); None when it can."""
        if not self.on_disk or self.replaced or "\ufffd" not in text:
            return None
        count = text.count("\ufffd")
        page = "Windows-1252" if self.codec == CP1252 else "its encoding"
        return (
            f"not changed: the editor shows {count} replacement character{'s' if count != 1 else ''} (U+FFFD) the "
            f"file does not hold; reopen the file as {page} (cantools-od reads it so)"
        )

    def bytes(self, text: str) -> bytes:
        if self.original and not self.replaced and "\ufffd" in text:
            return (_BOM if self.bom else b"") + restored(text, self.original.removeprefix(_BOM))
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
