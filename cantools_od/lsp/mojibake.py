"""The bytes behind an editor's text when the editor decoded a Windows-1252 (or DOS code page) file as UTF-8.

Such an editor shows one replacement character (U+FFFD) for each run of bytes UTF-8 cannot decode (the
Unicode "maximal subpart" rule, which Python's decoder follows too). Putting those bytes back where the
characters stand gives the file `lint` reads, so that the server reports what `lint` reports (EDS100 and
the names as the file spells them), at the same lines and columns.
"""

from __future__ import annotations

import codecs
import threading

from ..eds.decode import CP1252, encode

_RECORD = "cantools-od-lsp-record"
_recorded = threading.local()


def _record(error: UnicodeError) -> tuple[str, int]:
    if not isinstance(error, UnicodeDecodeError):
        raise error
    _recorded.chunks.append(error.object[error.start : error.end])
    return "\ufffd", error.end


codecs.register_error(_RECORD, _record)


def _undecodable(data: bytes) -> tuple[str, list[bytes]]:
    """`data` decoded as UTF-8 with U+FFFD for what cannot be, and the bytes of each U+FFFD in order."""
    _recorded.chunks = []
    try:
        return data.decode("utf-8", _RECORD), _recorded.chunks
    finally:
        _recorded.chunks = []


def _common_ends(a: str, b: str) -> tuple[int, int]:
    """The lengths of the common head and (not overlapping it) the common tail of two texts."""
    head = 0
    limit = min(len(a), len(b))
    step = 4096
    while head < limit:  # in blocks first: the texts are mostly equal
        size = min(step, limit - head)
        if a[head : head + size] == b[head : head + size]:
            head += size
        elif size == 1:
            break
        else:
            step = max(size // 2, 1)
    tail = 0
    while tail < limit - head and a[len(a) - 1 - tail] == b[len(b) - 1 - tail]:
        tail += 1
    return head, tail


def _piece(text: str) -> bytes:
    try:
        return encode(text, CP1252)
    except UnicodeEncodeError:  # typed in the editor, beyond the code page: as the editor would save it
        return text.encode("utf-8")


def restored(text: str, original: bytes) -> bytes:
    """`text` as bytes, each U+FFFD that stands where `original` had undecodable bytes being those bytes; the
    rest in Windows-1252. A U+FFFD of an edited stretch stays one (in UTF-8)."""
    shown, chunks = _undecodable(original)
    if shown.count("\ufffd") != len(chunks):  # the file holds U+FFFD itself: nothing to restore
        return text.encode("utf-8")
    head, tail = _common_ends(text, shown)
    before = text[:head].count("\ufffd")
    after = text[len(text) - tail :].count("\ufffd") if tail else 0
    sources = chunks[:before] + [None] * text[head : len(text) - tail].count("\ufffd")
    sources += chunks[len(chunks) - after :] if after else []
    parts = text.split("\ufffd")
    out = [_piece(parts[0])]
    for source, part in zip(sources, parts[1:], strict=True):
        out.append(source if source is not None else "\ufffd".encode())
        out.append(_piece(part))
    return b"".join(out)
