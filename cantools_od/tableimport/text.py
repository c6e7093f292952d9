"""Text sources as numbered lines of cells, and what the readers share about headings."""

from __future__ import annotations

import re
from dataclasses import dataclass

from .notation import clean


@dataclass(frozen=True)
class Line:
    number: int  # 1-based line number in the source file
    raw: str
    cells: tuple[str, ...]  # cleaned cells (TAB-separated in manual text)

    @property
    def blank(self) -> bool:
        return not any(self.cells)

    @property
    def filled(self) -> list[str]:
        return [cell for cell in self.cells if cell]

    @property
    def text(self) -> str:
        return " ".join(self.filled)


def split_lines(text: str, separator: str = "\t") -> list[Line]:
    """Every line of `text`, cells split on `separator` and cleaned; trailing empty cells dropped."""
    lines = []
    for number, raw in enumerate(text.splitlines(), start=1):
        cells = [clean(cell) for cell in raw.split(separator)] if separator else [clean(raw)]
        while cells and not cells[-1]:
            cells.pop()
        lines.append(Line(number, raw, tuple(cells)))
    return lines


_SECTION_NUMBER = re.compile(r"^(?:#+\s*)?(?:\d+(?:\.\d+)*\.?\s+)?")


def heading_title(raw: str) -> str | None:
    """The title of a Markdown heading (`### 11.3.4 COB-ID SYNC` → `COB-ID SYNC`) or of an
    italic line standing alone (`*vl\\_velocity\\_min\\_amount*`), else None."""
    text = raw.strip()
    if text.startswith("#"):
        title = _SECTION_NUMBER.sub("", text).strip()
        title = clean(title)
        return title or None
    if re.fullmatch(r"\*[^*]+\*", text) or re.fullmatch(r"_[^_]+_", text):
        return clean(text.strip("*_")) or None
    return None


def read_text(data: bytes) -> str:
    """Bytes as text: UTF-8 (with or without BOM), else Latin-1, which never fails."""
    if data.startswith(b"\xef\xbb\xbf"):
        data = data[3:]
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        return data.decode("latin-1")
