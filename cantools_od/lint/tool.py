"""Codes the table importer, the generators and the linter itself report (families import, gen, lint).

They are not checks: `import-table`, `gen` and `lint` print them while they work. They are declared
here so that `cantools-od rules CODE` explains them and `--select`/`--ignore` know them.
"""

from __future__ import annotations

from ..model import Severity
from .rules import declare

E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO
_IMPORT = "docs/import-table.md describes the importer, its layouts and its overrides file."


def _importer(code: str, severity: Severity, summary: str, why: str) -> None:
    declare(code, severity, summary, f"{why.strip()}\n\n{_IMPORT}", family="import")


_importer(
    "IMP001",
    E,
    "A source cannot be read",
    """
The file is missing, unreadable or a damaged workbook (or openpyxl is not installed);
import-table exits with 2.""",
)
_importer(
    "IMP002",
    E,
    "No object table or block found in a source",
    """
Nothing in the source looks like an object-dictionary table or block in any known layout; with
no object from any source, import-table exits with 2.""",
)
_importer(
    "IMP003",
    E,
    "Overrides file not valid",
    """
The overrides file is not valid TOML, or names an unknown field, index or value; import-table
exits with 2.""",
)
_importer(
    "IMP004",
    W,
    "CSV/TSV file malformed",
    """
A delimited file could not be read as CSV or TSV from the reported line on.""",
)
_importer(
    "IMP010",
    W,
    "Cell not understood",
    """
An access, data type, PDO-mapping flag or object code is spelled in a way the importer does not
know; the value is left unknown.""",
)
_importer(
    "IMP011",
    W,
    "Index not understood",
    """
The row's index cell is not an object index; the row is skipped.""",
)
_importer(
    "IMP012",
    W,
    "Sub-index not understood",
    """
The row's sub-index cell is not a sub-index or a range of them; the row is skipped.""",
)
_importer(
    "IMP013",
    W,
    "Index range names no object",
    """
An index range (`1600h-17FFh`) whose concrete objects no source names: its rows are reported and
dropped.""",
)
_importer(
    "IMP020",
    W,
    "Conflict resolved by the policy",
    """
Sources disagree about a value and no override decides: the policy took one; the import report
shows both with their lines.""",
)
_importer(
    "IMP031",
    W,
    "No data type or access in any source",
    """
No source states the entry's data type or access type; the EDS key is left out and the EDS needs
an override.""",
)
_importer(
    "IMP032",
    W,
    "Sub-index FFh not written",
    """
Sub-index FFh holds an object's structure (CiA 301) and cannot be written to an EDS.""",
)
_importer(
    "IMP040",
    W,
    "Override matches no imported entry",
    """
An override names an index, sub-index or field that no source imported; it is probably
misspelled.""",
)
_importer(
    "IMP050",
    W,
    "Value does not fit its type",
    """
A default or limit is outside its data type's range; it is left out of the EDS.""",
)
_importer(
    "IMP051",
    INFO,
    "Default COB-ID written as $NODEID+base",
    """
An absolute default COB-ID of the pre-defined connection set (CiA 301), printed for node 1 or
127, is written node-relative.""",
)

declare(
    "GEN001",
    E,
    "Cannot generate code from this file",
    """
Generated PDO code packs and unpacks each mapped entry at its bit offset, so gen refuses a PDO it
cannot lay out: a mapped object that does not exist or has no fixed-size type, an entry length
that differs from the type's size, a mapping count above 64, or more bits than the frame holds
(64, or 512 with --can-fd). Nothing is written; lint explains each case (PDO040-PDO046).""",
    family="gen",
)
declare(
    "LNT001",
    E,
    "A rule failed",
    """
A rule raised an exception on this file. The other rules still ran; the failing rule's findings
are missing. Please report it with the file.""",
    family="lint",
)
