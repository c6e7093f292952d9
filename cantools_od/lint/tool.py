"""Codes the table importer, the generators and the linter itself report (families import, gen, lint).

They are not checks: `import-table`, `gen` and `lint` print them while they work. They are declared
here so that `cantools-od rules CODE` explains them and `--select`/`--ignore` know them.
"""

from __future__ import annotations

from ..model import Severity
from . import examples as ex
from .rules import Clause, Placement, declare

E, W, INFO = Severity.ERROR, Severity.WARNING, Severity.INFO
_IMPORT = "docs/import-table.md describes the importer, its layouts and its overrides file."


_HEADER = "Index,Sub-index,Name,Data type,Access,Default value"
_ROWS = "0x1000,,Device type,UNSIGNED32,ro,0\n0x1001,,Error register,UNSIGNED8,ro,0"
_IMPORT_TABLE = "; $ cantools-od import-table table.csv -o device.eds"
# Key/value blocks of a manual's text (TAB-separated), as a PDF-to-text tool extracts them.
_MANUAL = (
    "; whole file: manual.txt\nIndex\t1000h\nName\tDevice type\nObject code\tVAR\nData type\tUNSIGNED32\n"
    "Access\tro\n\nIndex\t{index}\nName\tSpeed\nObject code\tVAR\nData type\tUNSIGNED16\nAccess\trw\n"
    "; $ cantools-od import-table manual.txt -o device.eds"
)


def _table(rows: str, header: str = _HEADER, command: str = _IMPORT_TABLE) -> str:
    """A rule example: a CSV table, then the import-table command line that reads it."""
    return f"; whole file: table.csv\n{header}\n{rows}\n{command}"


def _importer(code: str, severity: Severity, summary: str, why: str, example: str = "", fixed: str = "",
              fix: str = "", *, placed: Placement) -> None:  # fmt: skip
    declare(code, severity, summary, f"{why.strip()}\n\n{_IMPORT}", example, family="import", fixed=fixed,
            fix_safety=f"No automatic fix: {fix}" if fix else "", placed=placed)  # fmt: skip


_importer(
    "IMP001",
    E,
    "A source cannot be read",
    """
The file is missing, unreadable or a damaged workbook (or openpyxl is not installed);
import-table exits with 2.""",
    "; $ cantools-od import-table manual.txt -o device.eds",
    _table(_ROWS),
    "name a file that exists and can be read.",
    placed=Placement(Clause.NOT_DONE, "import-table exits 2"),
)
_importer(
    "IMP002",
    E,
    "No object table or block found in a source",
    """
Nothing in the source looks like an object-dictionary table or block in any known layout; with
no object from any source, import-table exits with 2.""",
    "; whole file: manual.txt\nJust some text.\nNo tables here.\n; $ cantools-od import-table manual.txt -o device.eds",
    _table(_ROWS),
    "give the source holding the object table, or force its layout with --layout.",
    placed=Placement(Clause.NOT_DONE, "import-table exits 2"),
)
_importer(
    "IMP003",
    E,
    "Overrides file not valid",
    """
The overrides file is not valid TOML, or names an unknown field, index or value; import-table
exits with 2.""",
    _table(_ROWS, command="; whole file: fixes.toml\n[objects\n" + _IMPORT_TABLE + " --overrides fixes.toml"),
    _table(
        _ROWS,
        command='; whole file: fixes.toml\n[objects."0x1000"]\naccess = "ro"\n'
        + _IMPORT_TABLE
        + " --overrides fixes.toml",
    ),
    "correct the overrides file.",
    placed=Placement(Clause.NOT_DONE, "import-table exits 2"),
)
_importer(
    "IMP004",
    W,
    "CSV/TSV file malformed",
    """
A delimited file could not be read as CSV or TSV from the reported line on.""",
    "; $ python3 -c \"print('Index,Name\\n0x1000,Device type\\n0x2000,' + 'x' * 140000)\" > table.csv\n"
    + _IMPORT_TABLE,
    _table(_ROWS),
    "export the table again; a cell holds at most 128 KiB.",
    placed=Placement(Clause.LEFT_OUT, "rows from the reported line on are missing"),
)
_importer(
    "IMP010",
    W,
    "Cell not understood",
    """
An access, data type, PDO-mapping flag or object code is spelled in a way the importer does not
know; the value is left unknown.""",
    _table(_ROWS + "\n0x2000,,Speed,UNSIGNED16,rw,0,maybe", _HEADER + ",PDO mapping"),
    _table(_ROWS + "\n0x2000,,Speed,UNSIGNED16,rw,0,yes", _HEADER + ",PDO mapping"),
    "spell the cell as CiA 301 does, or set the field in the overrides file.",
    placed=Placement(Clause.LEFT_OUT, "the value is left unknown"),
)
_importer(
    "IMP011",
    W,
    "Index not understood",
    """
The index of an object block in a manual's text is not an object index, so the block's entries
cannot be placed and are skipped. (In a column table such a row is taken for a note.)""",
    _MANUAL.format(index="20xxh"),
    _MANUAL.format(index="2000h"),
    "write the index as a hex number (`2000h`, `0x2000`).",
    placed=Placement(Clause.LEFT_OUT, "the block is skipped"),
)
_importer(
    "IMP012",
    W,
    "Sub-index not understood",
    """
The row's sub-index cell is not a sub-index or a range of them; the row is skipped.""",
    _table(_ROWS + "\n0x2000,x,Speed,UNSIGNED16,rw,0"),
    _table(_ROWS + "\n0x2000,,Speed,UNSIGNED16,rw,0"),
    "write the sub-index as a number.",
    placed=Placement(Clause.LEFT_OUT, "the row is skipped"),
)
_importer(
    "IMP013",
    W,
    "Index range names no object",
    """
An index range (`1600h-17FFh`) whose concrete objects no source names: its rows are reported and
dropped.""",
    _table(_ROWS + "\n0x1600-0x17FF,1,Mapped object 1,UNSIGNED32,rw,0"),
    _table(_ROWS + "\n0x1600,0,Number of mapped objects,UNSIGNED8,rw,0\n0x1600,1,Mapped object 1,UNSIGNED32,rw,0"),
    "name the concrete objects the range stands for.",
    placed=Placement(Clause.LEFT_OUT, "the range's rows are dropped"),
)
_importer(
    "IMP020",
    W,
    "Conflict resolved by the policy",
    """
Sources disagree about a value and no override decides: the policy took one; the import report
shows both with their lines.""",
    "; whole file: a.csv\nIndex,Name,Data type,Access\n0x1000,Device type,UNSIGNED32,ro\n; whole file: b.csv\n"
    "Index,Name,Data type,Access\n0x1000,Device type,UNSIGNED32,rw\n"
    "; $ cantools-od import-table a.csv b.csv -o device.eds --strict",
    "; whole file: a.csv\nIndex,Name,Data type,Access\n0x1000,Device type,UNSIGNED32,ro\n; whole file: b.csv\n"
    "Index,Name,Data type,Access\n0x1000,Device type,UNSIGNED32,ro\n"
    "; $ cantools-od import-table a.csv b.csv -o device.eds --strict",
    "decide in the overrides file which value holds.",
    placed=Placement(Clause.LEFT_OUT, "the policy chose one value"),
)
_importer(
    "IMP031",
    W,
    "No data type or access in any source",
    """
No source states the entry's data type or access type; the EDS key is left out and the EDS needs
an override.""",
    _table(_ROWS + "\n0x2000,,Speed,,rw,0"),
    _table(_ROWS + "\n0x2000,,Speed,UNSIGNED16,rw,0"),
    "give the data type and access in a source or the overrides file.",
    placed=Placement(Clause.LEFT_OUT, "the EDS key is left out"),
)
_importer(
    "IMP032",
    W,
    "Sub-index FFh not written",
    """
Sub-index FFh holds an object's structure (CiA 301) and cannot be written to an EDS.""",
    _table(
        _ROWS + "\n0x2000,0,Highest sub-index supported,UNSIGNED8,ro,1\n0x2000,1,Gain,INTEGER16,rw,0\n"
        "0x2000,255,Structure,UNSIGNED32,ro,0x0307"
    ),
    _table(_ROWS + "\n0x2000,0,Highest sub-index supported,UNSIGNED8,ro,1\n0x2000,1,Gain,INTEGER16,rw,0"),
    "the EDS describes the structure through ObjectType and the sub-objects.",
    placed=Placement(Clause.LEFT_OUT, "sub-index FFh cannot be written to an EDS"),
)
_importer(
    "IMP040",
    W,
    "Override matches no imported entry",
    """
An override names an index, sub-index or field that no source imported; it is probably
misspelled.""",
    _table(
        _ROWS,
        command='; whole file: fixes.toml\n[objects."0x2000"]\naccess = "ro"\n'
        + _IMPORT_TABLE
        + " --overrides fixes.toml",
    ),
    _table(
        _ROWS,
        command='; whole file: fixes.toml\n[objects."0x1000"]\naccess = "ro"\n'
        + _IMPORT_TABLE
        + " --overrides fixes.toml",
    ),
    "correct the override's index, sub-index or field.",
    placed=Placement(Clause.LEFT_OUT, "the override changes nothing"),
)
_importer(
    "IMP050",
    W,
    "Value does not fit its type",
    """
A default or limit is outside its data type's range; it is left out of the EDS.""",
    _table(_ROWS + "\n0x2000,,Speed,UNSIGNED8,rw,300"),
    _table(_ROWS + "\n0x2000,,Speed,UNSIGNED16,rw,300"),
    "correct the value or the data type, in a source or the overrides file.",
    placed=Placement(Clause.LEFT_OUT, "the value is left out of the EDS"),
)
_importer(
    "IMP051",
    INFO,
    "Default COB-ID written as $NODEID+base",
    """
An absolute default COB-ID of the pre-defined connection set (CiA 301), printed for node 1 or
127, is written node-relative.""",
    _table(_ROWS + "\n0x1014,,COB-ID EMCY,UNSIGNED32,rw,0x81"),
    _table(_ROWS + "\n0x1014,,COB-ID EMCY,UNSIGNED32,rw,$NODEID+0x80"),
    "the importer writes it so itself; write it node-relative in the source to silence it.",
    placed=Placement(Clause.DECISION, "written node-relative, as CiA 301 means it"),
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
    lambda: "; file: drive.eds\n" + ex.pdo("tx", "0x60410010") + "; $ cantools-od gen drive.eds -t c -o out",
    family="gen",
    fixed=lambda: (
        "; file: drive.eds\n" + ex.pdo("tx", "0x60410010") + ex.STATUSWORD + "; $ cantools-od gen drive.eds -t c -o out"
    ),
    fix_safety="No automatic fix: `--keep-going` leaves the PDO out of the generated code instead.",
    placed=Placement(Clause.NOT_DONE, "gen writes nothing"),
)
declare(
    "LNT001",
    E,
    "A rule failed",
    """
A rule raised an exception on this file. The other rules still ran; the failing rule's findings
are missing. Please report it with the file.""",
    family="lint",
    fix_safety="No automatic fix: report the failure with the file; meanwhile `--ignore` the rule's code.",
    placed=Placement(Clause.NOT_DONE, "the rule's findings are missing"),
)
