"""Import vendor object-dictionary tables (manual text, CSV/TSV, XLSX, Markdown) into a Device."""

from __future__ import annotations

from .api import LAYOUTS, ImportResult, UnreadableInput, detect_layout, import_tables, read_source

__all__ = ["LAYOUTS", "ImportResult", "UnreadableInput", "detect_layout", "import_tables", "read_source"]
