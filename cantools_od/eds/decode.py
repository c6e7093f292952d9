"""Bytes → text: UTF-8 with or without BOM, else DOS code page 850 when the file's words say so, else
Windows-1252.

A byte above 7Fh inside a word tells the code pages apart: Faulhaber's `71101 Sch\x94naich` is Schönaich in
code page 850 (and 437) and `Sch”naich` in Windows-1252, whose 80h-9Fh are mostly punctuation that no word
holds. A file is read as code page 850 when some such byte between lower-case letters is a lower-case letter
there and no letter in Windows-1252, and no byte inside a word is a letter in Windows-1252 only (`f\xfcr` is
für there, `f³r` in 850). Whichever it is read with, a file is written back in it (`encode`), so no byte of
text that was not changed changes.

The five bytes Windows-1252 leaves undefined (81h, 8Dh, 8Fh, 90h, 9Dh) stand for the control
characters of the same number, as in Latin-1, so every byte decodes the same way whatever the rest of
the file holds, and encodes back to itself.
"""

from __future__ import annotations

import codecs
import re
from collections.abc import Iterator

_BOM = b"\xef\xbb\xbf"
CP1252 = "cp1252"
ERRORS = "cantools-od-cp1252"
_UNDEFINED = frozenset(b"\x81\x8d\x8f\x90\x9d")


def _handle(error: UnicodeError) -> tuple[str | bytes, int]:
    if isinstance(error, UnicodeDecodeError):
        chunk = error.object[error.start : error.end]
        if all(byte in _UNDEFINED for byte in chunk):
            return "".join(chr(byte) for byte in chunk), error.end
    elif isinstance(error, UnicodeEncodeError):
        chunk_text = error.object[error.start : error.end]
        if all(ord(char) in _UNDEFINED for char in chunk_text):
            return bytes(ord(char) for char in chunk_text), error.end
    raise error


codecs.register_error(ERRORS, _handle)


def decode_as(data: bytes) -> tuple[str, str, str | None]:
    """The text, the codec that read it, and a note when that is not UTF-8."""
    if data.startswith(_BOM):
        data = data[len(_BOM) :]
    try:
        return data.decode("utf-8"), "utf-8", None
    except UnicodeDecodeError as error:
        where = f"byte 0x{data[error.start]:02X} at offset {error.start}"
    dos = _dos_word(data)
    if dos is not None:
        text = data.decode(DOS)
        shown = f"{text[dos.start() : dos.end()]!r}, not {data[dos.start() : dos.end()].decode(CP1252, ERRORS)!r}"
        return text, DOS, f"not UTF-8 ({where}); read as DOS code page 850 ({shown})"
    return data.decode(CP1252, ERRORS), CP1252, f"not UTF-8 ({where}); read as Windows-1252"


DOS = "cp850"
_INSIDE_WORD = re.compile(rb"(?<=[A-Za-z\x80-\xff])[\x80-\xff](?=[A-Za-z\x80-\xff])")
_WORD = re.compile(rb"[A-Za-z\x80-\xff]+")
_BETWEEN_WORDS = frozenset(b"\x96\x97\xa0")  # Windows-1252's dashes and no-break space may join two words


def _letter(byte: int, codec: str) -> str:
    """The byte's character in `codec` when it is a letter, "upper"/"lower" for its case, else ""."""
    char = bytes([byte]).decode(codec, ERRORS if codec == CP1252 else "strict")
    return "" if not char.isalpha() else "lower" if char.islower() else "upper"


def _dos_word(data: bytes) -> re.Match[bytes] | None:
    """The first word that shows `data` (not UTF-8) is DOS code page 850 text, or None when it is not shown (see
    the module's doc)."""
    shown: re.Match[bytes] | None = None
    for inside in _INSIDE_WORD.finditer(data):
        byte, before, after = data[inside.start()], data[inside.start() - 1], data[inside.end()]
        in_1252, in_850 = _letter(byte, CP1252), _letter(byte, DOS)
        if in_1252 and not in_850:
            return None  # a letter in Windows-1252 only: `f\xfcr`
        lower_around = chr(before).islower() and chr(after).islower()
        if shown is None and in_850 == "lower" and not in_1252 and lower_around and byte not in _BETWEEN_WORDS:
            shown = _WORD.search(data, max(inside.start() - 40, 0), inside.end() + 40)
            while shown is not None and shown.end() <= inside.start():
                shown = _WORD.search(data, shown.end(), inside.end() + 40)
    return shown


_UTF8_SEQUENCE = re.compile(rb"[\xc2-\xdf][\x80-\xbf]|[\xe0-\xef][\x80-\xbf]{2}|[\xf0-\xf4][\x80-\xbf]{3}")


def mixed_encoding(data: bytes) -> str | None:
    """Why `data` is UTF-8 in part and not in other parts, or None: such text read as Windows-1252
    turns its UTF-8 letters into mojibake (`Müller` into `MÃ¼ller`), which a rewrite would save."""
    body = data.removeprefix(_BOM)
    try:
        body.decode("utf-8")
    except UnicodeDecodeError as error:
        utf8 = _UTF8_SEQUENCE.search(body)
        if utf8 is None:
            return None  # Windows-1252 throughout
        return (
            f"UTF-8 text (from offset {utf8.start()}) with a byte that is not "
            f"(0x{body[error.start]:02X} at offset {error.start + len(data) - len(body)})"
        )
    return None


def decode(data: bytes) -> tuple[str, str | None]:
    """The text, and a note naming the fallback encoding when UTF-8 failed."""
    text, _, note = decode_as(data)
    return text, note


def encode(text: str, encoding: str) -> bytes:
    """Text in the codec it was read with; raises UnicodeEncodeError for characters it cannot hold."""
    return text.encode(encoding, ERRORS if encoding == CP1252 else "strict")


_SECTION_START = re.compile(rb"[\r\n][ \t]*\[")
CHUNK = 1 << 20


def utf8_pieces(data: bytes) -> Iterator[str]:
    """`data` as UTF-8 text (without a BOM) in pieces of about CHUNK bytes, each but the first
    starting at a section header, so that a large file is never all text at once. Raises
    UnicodeDecodeError, with offsets into `data`, when it is not UTF-8."""
    start = len(_BOM) if data.startswith(_BOM) else 0
    while start < len(data):
        match = _SECTION_START.search(data, start + CHUNK)
        end = match.start() + 1 if match is not None else len(data)
        try:
            yield data[start:end].decode("utf-8")
        except UnicodeDecodeError as error:
            raise UnicodeDecodeError("utf-8", data, start + error.start, start + error.end, error.reason) from None
        start = end
