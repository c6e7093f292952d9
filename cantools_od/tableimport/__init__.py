"""Import vendor object-dictionary tables (manual text, CSV/TSV, XLSX, Markdown) into a Device."""

from __future__ import annotations

from .api import LAYOUTS, UnreadableInput, detect_layout, import_tables, read_source
from .report import ImportResult

__all__ = ["LAYOUTS", "ImportResult", "UnreadableInput", "detect_layout", "import_tables", "read_source"]
