"""Rule family: pdo."""

from __future__ import annotations
