"""Rule family: values."""

from __future__ import annotations
