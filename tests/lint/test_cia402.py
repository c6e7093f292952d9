"""CiA 402 object conformance, in the rule style of CiA 301's (STD001-STD007): types and access of the profile objects
for the first logical drive (1000h names profile 402) and for further ones (their device type at 67FFh + n x 800h),
and the controlword/statusword mappable as the profile's predefined PDOs map them (STD007). The wrong accesses are
the ones real drives' files have (6040h/6060h `wo`, 6063h/6064h `rw`, 60FDh `rwr`); what real drives legitimately
declare otherwise (an unmappable 6060h, a VAR 60E4h, write-only 60C4h entries) is pinned as no finding, and every
finding of the added definitions on the real files of ../shared is one checked by hand."""

from __future__ import annotations

import json
import re
import subprocess
from pathlib import Path

import pytest
from lintkit import BASE, replace
from xddkit import MANDATORY, SHARED, document

from cantools_od import load, loads
from cantools_od.lint import lint
from cantools_od.sniff import NotADeviceDescription

from support import cli_command, corpus_file, file_params

DRIVE = replace(
    BASE, "DefaultValue=0x00000000\nPDOMapping=0\n\n[1001]", "DefaultValue=0x00020192\nPDOMapping=0\n\n[1001]"
)


def _var(index: int, name: str, data_type: str, access: str) -> str:
    return (
        f"\n[{index:04X}]\nParameterName={name}\nObjectType=0x7\nDataType={data_type}\nAccessType={access}\n"
        "DefaultValue=0\nPDOMapping=1\n"
    )


def _std004(text: str) -> list[str]:
    return [f.message for f in lint(loads(text, source="t.eds")) if f.code == "STD004"]


@pytest.mark.parametrize(
    ("index", "name", "data_type", "wrong", "right", "allowed"),
    [
        (0x6040, "Controlword", "0x0006", "wo", "rw", "rw"),
        (0x6060, "Modes of operation", "0x0002", "wo", "rww", "rw"),
        (0x6041, "Statusword", "0x0006", "rwr", "ro", "const/ro"),
        (0x6064, "Position actual value", "0x0004", "rw", "ro", "const/ro"),
        (0x6077, "Torque actual value", "0x0003", "rwr", "ro", "const/ro"),
        (0x6065, "Following error window", "0x0007", "wo", "ro", "const/ro/rw"),  # a parameter: rw, or fixed
    ],
)
def test_profile_access(index: int, name: str, data_type: str, wrong: str, right: str, allowed: str) -> None:
    assert _std004(DRIVE + _var(index, name, data_type, wrong)) == [
        f"[{index:04X}] AccessType={wrong}: CiA 402-2 gives {index:04X}h {name} access {allowed}"
    ]
    assert _std004(DRIVE + _var(index, name, data_type, right)) == []
    assert _std004(BASE + _var(index, name, data_type, wrong)) == []  # not a drive: a vendor's own object


def test_further_logical_drive_by_its_own_device_type() -> None:
    second = _var(0x6FFF, "Device type", "0x0007", "ro").replace("DefaultValue=0", "DefaultValue=0x00020192")
    statusword = _var(0x6841, "Statusword", "0x0006", "rwr")
    assert _std004(BASE + second + statusword) == [
        "[6841] AccessType=rwr: CiA 402-2 gives 6841h Statusword access const/ro"
    ]
    io_module = second.replace("0x00020192", "0x000F0191")  # sevcon's second logical device: profile 401
    assert _std004(BASE + io_module + statusword) == []
    wrong_type = statusword.replace("DataType=0x0006", "DataType=0x0007")
    assert any(f.code == "STD003" for f in lint(loads(BASE + second + wrong_type, source="t.eds")))


# --- types of the further profile objects, the default mapping (STD007) and what drives may lay out otherwise ---


def _codes(text: str, *codes: str) -> list[str]:
    return [f"{f.code} {f.message}" for f in lint(loads(text, source="t.eds")) if f.code in codes]


@pytest.mark.parametrize(
    ("index", "name", "wrong", "right", "defined"),
    [
        (0x606A, "Sensor selection code", "0x0006", "0x0003", "INTEGER16 (0x0003)"),  # dchcan.eds: UNSIGNED16
        (0x60E0, "Positive torque limit value", "0x0003", "0x0006", "UNSIGNED16 (0x0006)"),  # e35.eds: INTEGER16
        (0x6042, "vl target velocity", "0x0004", "0x0003", "INTEGER16 (0x0003)"),
        (0x60B9, "Touch probe status", "0x0007", "0x0006", "UNSIGNED16 (0x0006)"),
        (0x60F2, "Positioning option code", "0x0003", "0x0006", "UNSIGNED16 (0x0006)"),
    ],
    ids=["606A", "60E0", "6042", "60B9", "60F2"],
)
def test_profile_data_types(index: int, name: str, wrong: str, right: str, defined: str) -> None:
    written = {"0x0003": "INTEGER16 (0x0003)", "0x0004": "INTEGER32 (0x0004)", "0x0006": "UNSIGNED16 (0x0006)",
               "0x0007": "UNSIGNED32 (0x0007)"}[wrong]  # fmt: skip
    access = "ro" if index == 0x60B9 else "rw"
    assert _codes(DRIVE + _var(index, name, wrong, access), "STD003") == [
        f"STD003 [{index:04X}] DataType={written}: CiA 402-2 defines {index:04X}h {name} as {defined}"
    ]
    assert _codes(DRIVE + _var(index, name, right, access), "STD003") == []


def test_measured_values_of_further_modes_are_read_only() -> None:
    assert _codes(DRIVE + _var(0x6044, "vl velocity actual value", "0x0003", "rww"), "STD004") == [
        "STD004 [6044] AccessType=rww: CiA 402-2 gives 6044h vl velocity actual value access const/ro"
    ]
    assert _codes(DRIVE + _var(0x60BA, "Touch probe 1 positive edge", "0x0004", "rw"), "STD004") == [
        "STD004 [60BA] AccessType=rw: CiA 402-2 gives 60BAh Touch probe 1 positive edge access const/ro"
    ]


def test_second_logical_drive_types_and_default_mapping() -> None:
    second = _var(0x6FFF, "Device type", "0x0007", "ro").replace("DefaultValue=0", "DefaultValue=0x00020192")
    target = _var(0x6842, "vl target velocity", "0x0004", "rww")
    statusword = _var(0x6841, "Statusword", "0x0006", "ro").replace("PDOMapping=1", "PDOMapping=0")
    assert _codes(BASE + second + target + statusword, "STD003", "STD007") == [
        "STD003 [6842] DataType=INTEGER32 (0x0004): CiA 402-2 defines 6842h vl target velocity as INTEGER16 (0x0003)",
        "STD007 [6841] not mappable: CiA 402-2 maps 6841h Statusword into TPDOs by default",
    ]
    io_module = second.replace("0x00020192", "0x000F0191")  # a second logical device of profile 401: not a drive
    assert _codes(BASE + io_module + target + statusword, "STD003", "STD007") == []


@pytest.mark.parametrize(
    "text",
    [
        # Sevcon's controllers: modes of operation (display) not mappable; Faulhaber's static mapping: the
        # actual values not mappable. The profile lets both be: only 6040h/6041h must be mappable.
        _var(0x6060, "Modes of operation", "0x0002", "rw").replace("PDOMapping=1", "PDOMapping=0"),
        _var(0x6061, "Modes of operation display", "0x0002", "ro").replace("PDOMapping=1", "PDOMapping=0"),
        _var(0x6064, "Position actual value", "0x0004", "ro").replace("PDOMapping=1", "PDOMapping=0"),
        # Elmo's 60E4h/60E5h are VARs; the profile's ARRAY is not claimed.
        _var(0x60E4, "Additional Position Actual Value", "0x0004", "ro"),
        # Nanotec's 6090h of INTEGER32, an obsolete DSP 402 object; an XDD's 6089h VISIBLE_STRING.
        _var(0x6090, "Velocity encoder resolution", "0x0004", "rw"),
        _var(0x6089, "Position notation index", "0x0009", "rw"),
        # 60C4h sub-indices 5 and 6 write-only and mappable, as drives have them.
        "\n[60C4]\nParameterName=Interpolation data configuration\nObjectType=0x9\nSubNumber=3\n"
        "[60C4sub0]\nParameterName=Highest sub-index supported\nObjectType=0x7\nDataType=0x0005\nAccessType=ro\n"
        "DefaultValue=6\nPDOMapping=0\n"
        "[60C4sub5]\nParameterName=Size of data record\nObjectType=0x7\nDataType=0x0005\nAccessType=wo\n"
        "DefaultValue=1\nPDOMapping=1\n"
        "[60C4sub6]\nParameterName=Buffer clear\nObjectType=0x7\nDataType=0x0005\nAccessType=wo\n"
        "DefaultValue=0\nPDOMapping=1\n",
    ],
    ids=["6060-unmapped", "6061-unmapped", "6064-unmapped", "60E4-var", "6090-int32", "6089-string", "60C4-wo"],
)
def test_what_drives_may_declare_is_no_finding(text: str) -> None:
    assert _codes(DRIVE + text, "STD001", "STD002", "STD003", "STD004", "STD005", "STD007") == []


def _lint_json(path: Path) -> list[tuple[int, str]]:
    """(line, message) of the STD007 findings the installed CLI reports for the file."""
    done = subprocess.run([*cli_command(), "lint", "--format", "json", "--select", "STD007", str(path)],
                          capture_output=True, text=True, check=False)  # fmt: skip
    assert done.returncode in (0, 1), done.stderr
    return [(f["line"], f["message"]) for f in json.loads(done.stdout)]


def _edit(text: str, section: str, old: str, new: str) -> str:
    """The text with `old` replaced by `new` once, in `section` only."""
    start = text.index(f"[{section}]")
    end = text.index("\n[", start)
    assert old in text[start:end]
    return text[:start] + text[start:end].replace(old, new, 1) + text[end:]


def _line_of(path: Path, section: str, key: str) -> int:
    lines = path.read_text(encoding="latin-1").splitlines()
    return lines.index(key, lines.index(f"[{section}]")) + 1


def test_default_mapping_on_a_real_drive_file(tmp_path: Path) -> None:
    """Infranor's Easy-ak drive: its 6040h (rww) and 6041h (ro) are mappable, as the profile's first PDOs need;
    the same file with the statusword unmappable or the controlword TPDO-only (rwr) is reported at that key."""
    text = corpus_file("infranor__Easy-ak_v1.30.eds").read_text(encoding="latin-1")
    source = tmp_path / "drive.eds"
    source.write_text(text, encoding="latin-1")
    assert _lint_json(source) == []
    unmapped = tmp_path / "unmapped.eds"
    unmapped.write_text(_edit(text, "6041", "PDOMapping=0x01", "PDOMapping=0x00"), encoding="latin-1")
    before = unmapped.read_bytes()
    line = _line_of(unmapped, "6041", "PDOMapping=0x00")
    message = "[6041] not mappable: CiA 402-2 maps 6041h Statusword into TPDOs by default"
    assert _lint_json(unmapped) == [(line, message)]
    assert unmapped.read_bytes() == before
    tpdo_only = tmp_path / "tpdo_only.eds"
    tpdo_only.write_text(_edit(text, "6040", "AccessType=rww", "AccessType=rwr"), encoding="latin-1")
    line = _line_of(tpdo_only, "6040", "AccessType=rwr")
    assert _lint_json(tpdo_only) == [(line, "[6040] TPDO only: CiA 402-2 maps 6040h Controlword into RPDOs by default")]


# The CiA 402 objects whose definitions came with STD007 (types, access) and the findings they give on real files,
# each checked by hand against the file: the standard's type differs from the file's (same size, other sign).
ADDED = frozenset({0x6042, 0x6043, 0x6044, 0x6046, 0x6048, 0x6049, 0x604A, 0x604C, 0x6069, 0x606A,
                   0x60A8, 0x60A9, 0x60AA, 0x60AB, 0x60B8, 0x60B9, 0x60BA, 0x60BB, 0x60BC, 0x60BD, 0x60C0, 0x60C4,
                   0x60C5, 0x60C6, 0x60D5, 0x60D6, 0x60D7, 0x60D8, 0x60E0, 0x60E1, 0x60F2, 0x60F8, 0x60FA, 0x6403,
                   0x6404, 0x6503, 0x6504})  # fmt: skip
REVIEWED = {
    "dchcan__dchcan.eds": {"STD003 [606A] DataType=UNSIGNED16 (0x0006): CiA 402-2 defines 606Ah Sensor selection code "
                           "as INTEGER16 (0x0003)"},
    "python-canopen__e35.eds": {
        "STD003 [60E0] DataType=INTEGER16 (0x0003): CiA 402-2 defines 60E0h Positive torque limit value as UNSIGNED16 "
        "(0x0006)",
        "STD003 [60E1] DataType=INTEGER16 (0x0003): CiA 402-2 defines 60E1h Negative torque limit value as UNSIGNED16 "
        "(0x0006)",
    },
}  # fmt: skip


_LABEL = re.compile(r"\[([0-9A-F]{4})(?:sub[0-9A-F]+)?\] ")


def _real_files() -> list[Path]:
    """Every EDS, DCF, XDD and XDC of ../shared's corpus and of both sides of its history pairs."""
    if not SHARED.is_dir():
        return []
    corpus = SHARED / "eds-corpus"
    folders = [corpus / "eds", corpus / "xdd", *sorted((SHARED / "eds-history").iterdir())]
    suffixes = (".eds", ".dcf", ".xdd", ".xdc")
    return [p for f in folders if f.is_dir() for p in sorted(f.iterdir()) if p.suffix.lower() in suffixes]


def _real_params() -> list[object]:
    files = _real_files()
    if not files:
        return file_params([], "../shared is absent")
    return [pytest.param(path, id=str(path.relative_to(SHARED))) for path in files]


@pytest.mark.parametrize("path", _real_params())
def test_profile_findings_on_real_files_are_the_reviewed_ones(path: Path) -> None:
    """On every real file, the findings of the added definitions and of STD007 are the ones checked by hand."""
    try:
        device = load(path)
    except NotADeviceDescription:
        pytest.skip("not a device description")
    found = set()
    for finding in lint(device):
        label = _LABEL.match(finding.message)
        index = int(label.group(1), 16) if label is not None else 0
        base = index - (index - 0x6000) // 0x800 * 0x800 if index >= 0x6000 else index
        if finding.code == "STD007" or (finding.code.startswith("STD") and base in ADDED):
            found.add(f"{finding.code} {finding.message}")
    expected = REVIEWED.get(path.name, set()) if path.parent.parent.name == "eds-corpus" else set()
    assert found == expected


def test_default_mapping_in_an_xdd_says_the_direction() -> None:
    """An XDD states the direction: a statusword RPDO-only is reported, TPDO or optional is not."""

    def xdd(word: str) -> str:
        drive = MANDATORY.replace('defaultValue="0x00000000"', 'defaultValue="0x00020192"', 1)
        statusword = (
            '<CANopenObject index="6041" name="Statusword" objectType="7" dataType="0006" accessType="rw" '
            f'PDOmapping="{word}" />'
        )
        return document(drive + statusword)

    def std007(word: str) -> list[str]:
        return [f.message for f in lint(loads(xdd(word), source="t.xdd")) if f.code == "STD007"]

    assert std007("RPDO") == ["[6041] RPDO only: CiA 402-2 maps 6041h Statusword into TPDOs by default"]
    assert std007("no") == ["[6041] not mappable: CiA 402-2 maps 6041h Statusword into TPDOs by default"]
    assert std007("TPDO") == std007("optional") == []
