"""In-file suppression: a comment line `; cantools-od: ignore CODE[,CODE]` directly above a
section header silences those codes in the whole section; above a key, on that key's line."""

from __future__ import annotations

import re

from ..model import Device

_DIRECTIVE = re.compile(r"[;#]\s*cantools-od\s*:\s*ignore\s+([A-Za-z0-9_, ]+)", re.IGNORECASE)


def _codes(comments: list[str]) -> set[str]:
    found: set[str] = set()
    for comment in comments:
        if "cantools-od" not in comment.lower():
            continue
        match = _DIRECTIVE.match(comment)
        if match:
            found.update(code.strip().upper() for code in match.group(1).split(",") if code.strip())
    return found


class Suppressions:
    """Line number → codes silenced there."""

    def __init__(self, device: Device) -> None:
        self.by_line: dict[int, set[str]] = {}
        for section in device.sections():
            origin = section.origin
            if origin is None or not section.comments:
                continue
            by_key = {key: codes for key, comments in section.comments.items() if (codes := _codes(comments))}
            if not by_key:
                continue  # the common case: comments, but no directive among them
            whole = by_key.pop("", set())
            positions = list(origin.positions())
            last = max([origin.line, *(where[0] for _, where in positions)])
            if whole:
                for line in range(origin.line, last + 1):
                    self.by_line.setdefault(line, set()).update(whole)
            for key, where in positions:
                if key in by_key:
                    self.by_line.setdefault(where[0], set()).update(by_key[key])

    def silenced(self, code: str, line: int) -> bool:
        return code in self.by_line.get(line, ())
