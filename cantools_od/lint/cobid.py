"""Rule family: cobid."""

from __future__ import annotations
