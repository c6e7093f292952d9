"""Truth against peers: every error the standard-object and spelling rules report on a corpus file is
something python-canopen or lely's dcf-tools read differently from what the standard fixes, or a
key or section they do not find. The exceptions are listed, each with its reason."""

from __future__ import annotations

import re
import warnings
from pathlib import Path
from typing import Any

import pytest

from cantools_od import load
from cantools_od.lint import Finding, lint
from cantools_od.model.cia301 import cia402, definitions
from cantools_od.model.cia301.definitions import Definition

from support import corpus_params

canopen = pytest.importorskip("canopen")
lely_parse = pytest.importorskip("dcf.parse")

CODES = ("STD001", "STD003", "EDS091")
_LABEL = re.compile(r"\[([0-9A-F]{4})(?:sub([0-9A-F]+))?\] ")

# (file, code, line) → why the finding stays an error although no peer reads it differently.
# None today: every STD001/STD003/EDS091 error on the corpus is confirmed by python-canopen or lely.
EXCEPTIONS: dict[tuple[str, str, int], str] = {}


def lely(path: Path) -> Any:
    """lely's reading of the file (configparser, case-insensitive names), or None when it refuses the file."""
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return lely_parse.parse_file(str(path))
    except Exception:
        return None


def python_canopen(path: Path) -> Any:
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return canopen.import_od(str(path))
    except Exception:
        return None


def _standard(index: int, drive: bool) -> Definition | None:
    return definitions.definition(index) or (cia402.definition(index) if drive else None)


def _lely_type(cfg: Any, index: int, sub: int | None) -> int | None:
    for section in ([f"{index:04X}sub{sub:X}"] if sub is not None else []) + [f"{index:04X}"]:
        if cfg is not None and section in cfg and "DataType" in cfg[section]:
            return int(cfg[section]["DataType"], 0)
    return None


def _canopen_entry(od: Any, index: int, sub: int | None) -> Any:
    if od is None or index not in od:
        return None
    obj = od[index]
    if sub is None:
        return obj
    try:
        return obj[sub]
    except (KeyError, TypeError):
        return None


def peers_disagree(path: Path, finding: Finding, cfg: Any, od: Any, drive: bool) -> bool:
    """Whether a peer reads what the finding says the file says, against the standard."""
    if finding.code == "EDS091":
        written = finding.message.split(":", 1)[0]
        canonical = finding.message.split(" spells this ", 1)[1].split()[1].rstrip(";")
        if "section" in finding.message:
            return cfg is None or canonical not in cfg or (od is not None and od.node_id is None)
        return cfg is None or all(canonical not in cfg[s] for s in cfg if written in cfg[s])
    match = _LABEL.match(finding.message)
    assert match is not None, finding.message
    index, sub = int(match.group(1), 16), int(match.group(2), 16) if match.group(2) else None
    standard = _standard(index, drive)
    assert standard is not None
    if finding.code == "STD001":
        layout = standard.kind.name in ("ARRAY", "RECORD")
        entry = _canopen_entry(od, index, None)
        if entry is not None and isinstance(entry, canopen.objectdictionary.ODVariable) == layout:
            return True
        section = f"{index:04X}"
        if cfg is None or section not in cfg:
            return False
        return (int(cfg[section].get("ObjectType", "0x7"), 0) in (0x8, 0x9)) != layout
    wanted = standard.entry(sub or 0)
    assert wanted is not None and wanted.data_type is not None
    entry = _canopen_entry(od, index, sub)
    canopen_type = getattr(entry, "data_type", None)
    lely_type = _lely_type(cfg, index, sub)
    return (canopen_type not in (None, wanted.data_type)) or (lely_type not in (None, wanted.data_type))


@pytest.mark.parametrize("path", corpus_params())
def test_errors_on_standard_objects_are_what_peers_read(path: Path) -> None:
    device = load(path)
    errors = [f for f in lint(device) if f.code in CODES and f.severity.value == "error"]
    if not errors:
        return
    from cantools_od.lint.standard import is_drive

    cfg, od = lely(path), python_canopen(path)
    unconfirmed = [
        f"{f.code} line {f.location.line}: {f.message}"
        for f in errors
        if not peers_disagree(path, f, cfg, od, is_drive(device))
        and (path.name, f.code, f.location.line) not in EXCEPTIONS
    ]
    assert unconfirmed == []
