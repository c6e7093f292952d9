"""Rule family: objlists."""

from __future__ import annotations
