"""Bytes → text: UTF-8 with or without BOM, else a DOS/Windows code page."""

from __future__ import annotations

_BOM = b"\xef\xbb\xbf"


def decode_as(data: bytes) -> tuple[str, str, str | None]:
    """The text, the codec that read it, and a note when that is not UTF-8."""
    if data.startswith(_BOM):
        data = data[len(_BOM) :]
    try:
        return data.decode("utf-8"), "utf-8", None
    except UnicodeDecodeError as error:
        where = f"byte 0x{data[error.start]:02X} at offset {error.start}"
    try:
        return data.decode("cp1252"), "cp1252", f"not UTF-8 ({where}); read as Windows-1252"
    except UnicodeDecodeError:
        return data.decode("latin-1"), "latin-1", f"not UTF-8 ({where}); read as Latin-1"


def decode(data: bytes) -> tuple[str, str | None]:
    """The text, and a note naming the fallback encoding when UTF-8 failed."""
    text, _, note = decode_as(data)
    return text, note
