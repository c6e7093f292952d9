"""The severity policy of docs/rules.md: error when a peer tool reads the file otherwise than it says (or cannot
load it) or a device built from it misbehaves; warning for portability or style. Every code names its clause
(`placed=` where it is registered). Built from real files of ../shared read in place through the installed CLI,
beside what the peers (python-canopen, lely's dcfchk) do with the same file."""

from __future__ import annotations

import json
import locale
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from cantools_od.lint.codes import codes
from cantools_od.lint.rules import Clause
from cantools_od.model import Severity

from support import CORPUS, ROOT, SHARED, cli_command

HISTORY = SHARED / "eds-history"
DCFCHK = Path(sys.executable).parent / "dcfchk"  # lely's checker, installed with dcf-tools

# What a rule's text says when python-canopen (or lely) cannot load a file that has the finding.
_CANNOT_LOAD = re.compile(r"(cannot|fails? to) load|load nothing|stops it loading|fail on the file", re.IGNORECASE)


def _lint(path: Path, select: str) -> list[tuple[str, str, str]]:
    if not path.is_file():
        pytest.skip(f"{path} is absent")
    done = subprocess.run(
        [*cli_command(), "lint", "-j1", "--format", "json", "--select", select, str(path)],
        capture_output=True,
        text=True,
    )
    assert done.returncode in (0, 1), done.stderr
    return [(f["code"], f["severity"], f["message"]) for f in json.loads(done.stdout)]


def test_every_code_is_placed_by_a_clause_of_its_severity_with_a_reason() -> None:
    table = codes()
    assert len(table) >= 177
    wrong = {c.code: (c.rule.placed.clause.value, c.severity.value) for c in table.values()
             if c.rule.placed.clause.severity is not c.severity}  # fmt: skip
    assert wrong == {}
    assert [c.code for c in table.values() if len(c.rule.placed.reason.split()) < 3] == []
    # every clause places some code, so the policy table holds no clause that nothing uses
    assert {c.rule.placed.clause for c in table.values()} == set(Clause)


def test_every_code_whose_finding_stops_a_peer_loading_the_file_is_an_error() -> None:
    placed = {code.code: code.rule.severity for code in codes().values() if _CANNOT_LOAD.search(code.rule.description)}
    assert {"DIA019", "DIA020", "DIA021"} <= set(placed)
    assert {code: severity for code, severity in placed.items() if severity is not Severity.ERROR} == {}


def test_real_files_python_canopen_cannot_load_fail_lint() -> None:
    import canopen  # the peer: it refuses both files

    empty_number = HISTORY / "lv-atomi__canopen-site-firmware__1" / "old.eds"  # ProductNumber=
    comment_case = HISTORY / "CANopenNode__CANopenSocket__1" / "new.eds"  # line5=
    for path, code in ((empty_number, "DIA019"), (comment_case, "DIA021")):
        with pytest.raises(Exception):  # noqa: B017 - python-canopen raises ValueError or NoOptionError
            canopen.import_od(str(path))
        assert {severity for found, severity, _ in _lint(path, code) if found == code} == {"error"}


def test_a_key_every_peer_passes_over_on_a_record_header_is_a_warning() -> None:
    # bggardner/canopen-rpi: DataType on the 1018h and 1200h RECORD headers; python-canopen reads the sub-objects
    found = _lint(HISTORY / "bggardner__canopen-rpi__1" / "old.eds", "EDS024")
    headers = [(severity, message) for _, severity, message in found if "type RECORD" in message]
    assert ("warning", "[1018]: DataType is not allowed on an object of type RECORD") in headers
    assert {severity for severity, _ in headers} == {"warning"}


def test_rules_md_states_the_policy() -> None:
    text = (ROOT / "docs" / "rules.md").read_text(encoding="utf-8")
    assert "## Severity policy" in text
    for clause in Clause:
        assert f"| {clause.severity.value} | `{clause.value}` | {clause.meaning} |" in text
    eds002 = text[text.index("### EDS002") :]
    assert "Severity: error, by `peer-cannot-load`: python-canopen and lely dcfchk raise" in eds002


def _python_canopen(path: Path) -> str:
    """What python-canopen makes of the file: "loads" or the exception it raises."""
    import canopen

    try:
        canopen.import_od(str(path), node_id=5)
    except Exception as error:
        return type(error).__name__
    return "loads"


def _dcfchk(path: Path) -> str:
    done = subprocess.run([str(DCFCHK), "-n", "5", str(path)], capture_output=True, text=True)
    if done.returncode == 0:
        return "passes"
    last = done.stderr.strip().splitlines()[-1] if done.stderr.strip() else ""
    return last.split(":")[0] if "Error" in last.split(":")[0] else "warns"


# Severities this policy changed, each on a real file with the finding: (file, code, severity lint reports, what
# python-canopen does, what lely's dcfchk does (None: not shown)).
CHANGED = [
    # a key given twice (infranor) and sections given twice (kacanopen): neither peer loads the file
    (CORPUS / "infranor__Easy-ak_v1.30.eds", "EDS002", "error", "DuplicateOptionError",
     "configparser.DuplicateOptionError"),
    (HISTORY / "KITmedical__kacanopen__1" / "new.eds", "EDS002", "error", "DuplicateSectionError",
     "configparser.DuplicateSectionError"),
    (CORPUS / "faulhaber__605.3150.71-A-EK-3-60.eds", "EDS100", "error", "UnicodeDecodeError", "UnicodeDecodeError"),
    # lely's own DCF, without Dummy0001-0004: dcfchk passes it, python-canopen cannot load it
    (CORPUS / "lely-core__coctl.dcf", "DIA001", "error", "NoOptionError", "passes"),
    # lely's DCFs have no [FileInfo] and no [DummyUsage]: both peers load them
    (CORPUS / "lely-core__co-emcy.dcf", "EDS009", "warning", "loads", "passes"),
    # 0x1019 listed three times: both peers read the one object
    (HISTORY / "samsamfire__gocanopen__3" / "old.eds", "EDS016", "warning", "loads", None),
    # a 351-character Description line: python-canopen reads the file; but without [ManufacturerObjects]
    # lely's dcfchk cannot load it
    (CORPUS / "canopen-bench__CiA301Base.eds", "EDS001", "warning", "loads", None),
    (CORPUS / "canopen-bench__CiA301Base.eds", "EDS019", "error", "loads", "KeyError"),
]  # fmt: skip


@pytest.mark.parametrize("path, code, severity, canopen_does, dcfchk_does", CHANGED, ids=lambda v: str(v)[-40:])
def test_a_changed_severity_follows_what_the_peers_do_with_a_real_file(
    path: Path, code: str, severity: str, canopen_does: str, dcfchk_does: str | None
) -> None:
    if code == "EDS100" and locale.getpreferredencoding(False).lower().replace("-", "") != "utf8":
        pytest.skip("python-canopen opens the file in the locale's encoding, which is not UTF-8 here")
    found = {found_severity for found, found_severity, _ in _lint(path, code) if found == code}
    assert found == {severity}
    assert _python_canopen(path) == canopen_does
    if dcfchk_does is not None:
        assert _dcfchk(path) == dcfchk_does


def test_a_missing_device_info_stays_an_error_as_dcfchk_refuses_the_file() -> None:
    path = CORPUS / "node-canopen__sample.eds"
    found = {(severity, message) for code, severity, message in _lint(path, "EDS009") if code == "EDS009"}
    assert ("error", "[DeviceInfo] is missing") in found
    assert _dcfchk(path) != "passes"


def test_an_empty_pdo_mapping_is_an_error_as_python_canopen_cannot_load_it(tmp_path: Path) -> None:
    # No file of ../shared has `PDOMapping=`: the rule's own example, framed into a whole file, stands for one.
    from cantools_od.lint.exampleset import parse

    content, _ = parse(codes()["DIA015"].rule.example).files[0].content()
    path = tmp_path / "device.eds"
    path.write_bytes(content)
    assert {severity for code, severity, _ in _lint(path, "DIA015") if code == "DIA015"} == {"error"}
    assert _python_canopen(path) == "ValueError"


def test_nodeid_placed_last_is_an_error_as_lelys_tools_refuse_the_file(tmp_path: Path) -> None:
    # oresat-firmware's EDS writes `0x80+$NODEID`: python-canopen reads it, lely's dcf-tools (dcfchk, and dcfgen,
    # which loads a slave's file with Device.from_dcf) refuse the file; fmt writes `$NODEID+0x80`
    import canopen
    from dcf.device import Device

    source = HISTORY / "oresat__oresat-firmware__13" / "old.eds"
    found = [(severity, message) for code, severity, message in _lint(source, "EDS033") if code == "EDS033"]
    assert (
        "error",
        "DefaultValue: '0x80+$NODEID': $NODEID should come first ($NODEID+n); lely rejects this form",
    ) in found
    assert canopen.import_od(str(source), node_id=5)[0x1014].default == 0x85
    with pytest.raises(ValueError, match="invalid DCF"):
        Device.from_dcf(str(source), env={"NODEID": 5})
    path = tmp_path / "device.eds"
    path.write_bytes(source.read_bytes())
    done = subprocess.run([*cli_command(), "fmt", str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert "DefaultValue=$NODEID+0x80\n" in path.read_text(encoding="utf-8")
    assert [code for code, _, _ in _lint(path, "EDS033")] == []


def test_fmt_repairs_a_key_given_twice_that_no_peer_can_load(tmp_path: Path) -> None:
    # EDS002 is an error for lint, yet fmt writes the file once, as cantools-od read it: then python-canopen loads it
    source = CORPUS / "infranor__Easy-ak_v1.30.eds"
    if not source.is_file():
        pytest.skip(f"{source} is absent")
    path = tmp_path / source.name
    shutil.copyfile(source, path)
    done = subprocess.run([*cli_command(), "fmt", str(path)], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert _python_canopen(source) == "DuplicateOptionError"
    assert _python_canopen(path) == "loads"
    assert [code for code, _, _ in _lint(path, "EDS002")] == []
