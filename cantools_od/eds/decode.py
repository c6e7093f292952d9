"""Bytes → text: UTF-8 with or without BOM, else a DOS/Windows code page."""

from __future__ import annotations

_BOM = b"\xef\xbb\xbf"


def decode(data: bytes) -> tuple[str, str | None]:
    """The text, and a note naming the fallback encoding when UTF-8 failed."""
    if data.startswith(_BOM):
        data = data[len(_BOM) :]
    try:
        return data.decode("utf-8"), None
    except UnicodeDecodeError as error:
        where = f"byte 0x{data[error.start]:02X} at offset {error.start}"
    try:
        return data.decode("cp1252"), f"not UTF-8 ({where}); read as Windows-1252"
    except UnicodeDecodeError:
        return data.decode("latin-1"), f"not UTF-8 ({where}); read as Latin-1"
