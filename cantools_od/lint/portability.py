"""Rule family: portability."""

from __future__ import annotations
