"""Rule family: structure."""

from __future__ import annotations
