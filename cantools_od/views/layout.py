"""Text drawings of PDO bit layouts, one byte per row, in the manner of `cantools dump`."""

from __future__ import annotations

from .pdo import Pdo

_HEADER = "            Bit\n\n       7   6   5   4   3   2   1   0\n     +---+---+---+---+---+---+---+---+"
_RULE = "     +---+---+---+---+---+---+---+---+"


def draw(pdo: Pdo) -> str:
    """Each entry runs from `x` (its least significant bit) to `<` (its most significant)."""
    owner: dict[int, int] = {}
    marks: dict[int, str] = {}
    for number, entry in enumerate(pdo.entries):
        for k in range(entry.bit_length):
            bit = entry.bit_offset + k
            owner[bit] = number
            marks[bit] = "x" if k == 0 else "<" if k == entry.bit_length - 1 else "-"
    size = max(1, (pdo.bit_length + 7) // 8)
    lines = [_HEADER]
    for byte in range(size):
        cells: list[str] = []
        for column, bit in enumerate(range(byte * 8 + 7, byte * 8 - 1, -1)):
            mark = marks.get(bit)
            cell = "   " if mark is None else {"x": "--x", "<": "<--", "-": "---"}[mark]
            if column:
                joined = bit + 1 in owner and owner.get(bit + 1) == owner.get(bit) and mark is not None
                cells.append("-" if joined else "|")
            cells.append(cell)
        lines.append(f" {byte:3d} |{''.join(cells)}|")
        lines.append(_RULE)
        for entry in pdo.entries:
            msb = entry.bit_offset + entry.bit_length - 1
            if entry.bit_length and msb // 8 == byte:
                column = 7 - msb % 8
                label = entry.identifier or f"({entry.label})"
                lines.append(" " * (7 + 4 * column) + f"+-- {label}")
    return "\n".join(lines)
