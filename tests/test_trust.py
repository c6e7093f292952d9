"""What a new user broke in the first hour (issue 27), each as the user met it: the installed CLI on
careless input in tmp_path, checking exit code, the one line said, and the input left as it was."""

from __future__ import annotations

import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

import cantools_od
from cantools_od.sniff import NotADeviceDescription

from support import EXAMPLES, SHARED, cli_command

DRIVE = (EXAMPLES / "cia402_drive.eds").read_bytes()


def run(*args: str | Path, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [*cli_command(), *map(str, args)], cwd=cwd, capture_output=True, text=True, encoding="utf-8", check=False
    )


def no_python(result: subprocess.CompletedProcess[str]) -> None:
    for marker in ("Traceback", "Error:", "invalid literal", "set_int_max_str_digits", "[LNT001]"):
        assert marker not in result.stdout + result.stderr, result.stdout + result.stderr


def replaced(data: bytes, old: bytes, new: bytes, after: bytes = b"") -> bytes:
    start = data.index(after) if after else 0
    at = data.index(old, start)
    return data[:at] + new + data[at + len(old) :]


def written(tmp_path: Path, name: str, data: bytes) -> Path:
    path = tmp_path / name
    path.write_bytes(data)
    path.chmod(0o640)
    return path


def unchanged(path: Path, data: bytes) -> None:
    assert path.read_bytes() == data
    assert path.stat().st_mode & 0o777 == 0o640


# 1. JSON that is no model -----------------------------------------------------------------------

NOT_MODELS = {
    "package.json": b'{"name":"x","version":"1.0"}\n',
    "array.json": b"[1,2,3]\n",
    "array.eds": b"[1,2,3]\n",
    "empty-object.json": b"{}",
}
EVERY_COMMAND = [
    ["dump"],
    ["fmt"],
    ["fmt", "--check"],
    ["lint"],
    ["lint", "--fix"],
    ["pdo"],
    ["ids"],
    ["convert", "-o", "out.eds"],
    ["gen", "-t", "c", "-o", "gen"],
]


@pytest.mark.parametrize("name", sorted(NOT_MODELS))
@pytest.mark.parametrize("args", EVERY_COMMAND, ids=" ".join)
def test_json_that_is_no_model_is_refused(tmp_path: Path, name: str, args: list[str]) -> None:
    path = written(tmp_path, name, NOT_MODELS[name])
    result = run(args[0], name, *args[1:], cwd=tmp_path)
    assert result.returncode == 2, result.stderr
    # lint reports it as a finding in its report (stdout); every other command says it on stderr
    said = result.stdout.splitlines()[0] + "\n" if args[0] == "lint" else result.stderr
    assert said.count("\n") == 1 and said.rstrip().endswith("[EDS000]"), (result.stdout, result.stderr)
    assert "not a cantools-od model" in said
    unchanged(path, NOT_MODELS[name])
    assert sorted(p.name for p in tmp_path.iterdir()) == [name]


@pytest.mark.parametrize("name", sorted(NOT_MODELS))
def test_load_refuses_json_that_is_no_model(tmp_path: Path, name: str) -> None:
    path = written(tmp_path, name, NOT_MODELS[name])
    with pytest.raises(NotADeviceDescription):
        cantools_od.load(path)


def test_diff_refuses_json_that_is_no_model(tmp_path: Path) -> None:
    written(tmp_path, "package.json", NOT_MODELS["package.json"])
    written(tmp_path, "drive.eds", DRIVE)
    result = run("diff", "drive.eds", "package.json", cwd=tmp_path)
    assert result.returncode == 2 and "[EDS000]" in result.stderr, result.stderr


def test_a_real_model_and_a_lone_section_are_still_read(tmp_path: Path) -> None:
    model = cantools_od.dumps(cantools_od.loads(DRIVE), "json")
    assert cantools_od.loads(model).objects.keys() == cantools_od.loads(DRIVE).objects.keys()
    assert list(cantools_od.loads(b"[1000]\n").objects) == [0x1000]  # an (empty) object section, JSON or not


# 2. gen on values it cannot emit ----------------------------------------------------------------

OUT_OF_RANGE = replaced(DRIVE, b"DefaultValue=0x0000", b"DefaultValue=70000", after=b"[6040]")


def test_gen_fails_on_a_value_its_type_cannot_hold(tmp_path: Path) -> None:
    written(tmp_path, "drive.eds", OUT_OF_RANGE)
    result = run("gen", "drive.eds", "-t", "c", "-t", "rust", "-t", "python", "-o", "out", cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    assert "6040h DefaultValue: 70000 is outside UNSIGNED16 (0..65535) [GEN001]" in result.stderr
    assert "nothing generated" in result.stderr and "--keep-going" in result.stderr
    assert not (tmp_path / "out").exists()


def test_gen_keep_going_says_what_it_left_out(tmp_path: Path) -> None:
    written(tmp_path, "drive.eds", OUT_OF_RANGE)
    result = run("gen", "drive.eds", "-t", "c", "-o", "out", "--keep-going", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "left out of the generated files: 6040h Controlword" in result.stderr
    header = (tmp_path / "out" / "drive.h").read_text()
    assert "6040h Controlword" in header.split("*/", 3)[1] and "DRIVE_CONTROLWORD_DEFAULT" not in header


@pytest.mark.parametrize(
    ("key", "value", "dtype"),
    [("HighLimit", b"70000", b"0x0006"), ("LowLimit", b"-1", b"0x0006"), ("DefaultValue", b"1e39", b"0x0008")],
)
def test_gen_fails_on_limits_and_reals_it_cannot_emit(tmp_path: Path, key: str, value: bytes, dtype: bytes) -> None:
    section = b"[2000]\nParameterName=Probe\nObjectType=0x7\nDataType=" + dtype + b"\nAccessType=rw\n"
    data = DRIVE.replace(b"[1000]", section + key.encode() + b"=" + value + b"\nPDOMapping=0\n\n[1000]", 1)
    written(tmp_path, "probe.eds", data)
    result = run("gen", "probe.eds", "-t", "c", "-o", "out", cwd=tmp_path)
    assert result.returncode == 1 and "2000h" in result.stderr and "error:" in result.stderr, result.stderr
    assert not (tmp_path / "out").exists()


# 3. non-ASCII digits in number and key positions ------------------------------------------------

UNICODE_DIGIT_FILES = {
    "list-position.eds": replaced(DRIVE, b"\n1=0x1005", "\n²=0x1005".encode()),
    "comment-line.eds": replaced(DRIVE, b"Line1=", "Line¹=".encode()),
    "cp1252-byte.eds": replaced(DRIVE, b"\n1=0x1005", b"\n\xb9=0x1005"),
    "arabic-digit.eds": replaced(DRIVE, b"\n2=0x1017", "\n٢=0x1017".encode()),
    "compact-key.eds": replaced(DRIVE, b"[1000]", "[2000]\nParameterName=A\nObjectType=0x8\nDataType=0x0005\n"
                                "AccessType=rw\nCompactSubObj=2\n\n[2000Name]\nNrOfEntries=1\n³=x\n\n[1000]".encode()),
}  # fmt: skip


@pytest.mark.parametrize("name", sorted(UNICODE_DIGIT_FILES))
@pytest.mark.parametrize("args", [["dump"], ["lint"], ["fmt", "--check"], ["convert", "-o", "out.xdd"]], ids=" ".join)
def test_unicode_digits_are_text_with_a_diagnostic(tmp_path: Path, name: str, args: list[str]) -> None:
    data = UNICODE_DIGIT_FILES[name]
    path = written(tmp_path, name, data)
    result = run(args[0], name, *args[1:], cwd=tmp_path)
    no_python(result)
    assert result.returncode in (0, 1), result.stderr
    if args == ["lint"]:
        assert result.returncode == 1 and "error:" in result.stdout, result.stdout
    unchanged(path, data)


@pytest.mark.parametrize("name", sorted(UNICODE_DIGIT_FILES))
def test_load_reads_unicode_digits_as_text(name: str) -> None:
    device = cantools_od.loads(UNICODE_DIGIT_FILES[name], source=name)
    assert 0x6040 in device.objects


# 4. fmt and a file that is UTF-8 but for one byte -----------------------------------------------

MIXED = replaced(DRIVE, b"Description=", "Description=Müller \xb9 ".encode().replace(b"\xc2\xb9", b"\xb9"))


def test_fmt_refuses_a_file_of_mixed_encodings(tmp_path: Path) -> None:
    path = written(tmp_path, "mixed.eds", MIXED)
    result = run("fmt", "mixed.eds", cwd=tmp_path)
    assert result.returncode == 1, result.stderr
    lines = [line for line in result.stderr.splitlines() if "error" in line]
    assert len(lines) == 1 and "not formatted: UTF-8 text" in lines[0] and "0xB9" in lines[0], result.stderr
    unchanged(path, MIXED)


def test_fmt_still_rewrites_a_file_all_in_windows_1252(tmp_path: Path) -> None:
    data = replaced(DRIVE, b"Description=", "Description=Müller ".encode("cp1252"))
    written(tmp_path, "legacy.eds", data)
    result = run("fmt", "legacy.eds", cwd=tmp_path)
    assert result.returncode == 0, result.stderr
    assert "Description=Müller" in (tmp_path / "legacy.eds").read_text(encoding="cp1252")  # in its code page


# 4b. a file in a DOS code page (#39: Faulhaber's `Sch\x94naich` became `Sch”naich`) -------------------

FAULHABER = SHARED / "eds-corpus" / "eds" / "faulhaber__605.3150.71-A-EK-3-60.eds"


def _lines_with_high_bytes(data: bytes) -> list[bytes]:
    return [line.rstrip(b"\r") for line in data.split(b"\n") if re.search(rb"[\x80-\xff]", line)]


def test_a_dos_code_page_file_keeps_every_character(tmp_path: Path) -> None:
    """The real file: read as code page 850 (Schönaich, the maker's seat, postcode 71101), said so by EDS100;
    `fmt` and `convert` to EDS or DCF leave the bytes of its text as written; XDD and JSON say Schönaich."""
    if not FAULHABER.is_file():
        pytest.skip("../shared/eds-corpus is absent")
    original = FAULHABER.read_bytes()
    assert b"Sch\x94naich" in original
    path = written(tmp_path, "drive.eds", original)
    lint = run("lint", "drive.eds", cwd=tmp_path)
    assert "read as DOS code page 850 ('Schönaich', not 'Sch”naich') [EDS100]" in lint.stdout, lint.stdout
    for target in ("copy.eds", "copy.dcf"):
        converted = run("convert", "drive.eds", "-o", target, "--node-id", "5", cwd=tmp_path)
        assert converted.returncode == 0, converted.stderr
        assert _lines_with_high_bytes((tmp_path / target).read_bytes()) == _lines_with_high_bytes(original)
    for target in ("copy.xdd", "copy.json"):
        assert run("convert", "drive.eds", "-o", target, cwd=tmp_path).returncode == 0
        text = (tmp_path / target).read_text(encoding="utf-8")
        assert "71101 Schönaich" in text and "Sch”naich" not in text.replace("not 'Sch”naich'", "")
    diff = run("fmt", "--check", "--diff", "drive.eds", cwd=tmp_path)
    assert "naich" not in diff.stdout and "Traceback" not in diff.stderr
    result = run("fmt", "drive.eds", cwd=tmp_path)
    assert result.returncode == 0 and "reformatted drive.eds" in result.stderr, result.stderr
    formatted = path.read_bytes()
    assert formatted != original and _lines_with_high_bytes(formatted) == _lines_with_high_bytes(original)


@pytest.mark.parametrize("byte", range(0x80, 0x100), ids=lambda byte: f"{byte:02X}")
def test_fmt_writes_every_byte_of_text_back_as_it_was(byte: int) -> None:
    """Whatever code page a byte is taken for, inside a word or beside one, `fmt` (the canonical writer) writes it
    back: a guess never turns one character into another."""
    for word in (b"Sch%cnaich", b"%cSpeed%c", b"Sensor%cValue", b"f%cr Gr%c%ce"):
        text = word.replace(b"%c", bytes([byte]))
        data = replaced(DRIVE, b"Description=", b"Description=" + text + b" ")
        formatted = cantools_od.dumps(cantools_od.loads(data, source="t.eds"), "eds", "canonical")
        assert b"Description=" + text in formatted, (text, formatted[:400])


# 5. numbers of any length -----------------------------------------------------------------------


@pytest.mark.parametrize("digits", [70, 5000, 100_000])
@pytest.mark.parametrize("radix", ["decimal", "hex"])
@pytest.mark.parametrize(
    "args",
    [["dump"], ["lint"], ["fmt"], ["pdo"], ["ids"], ["gen", "-t", "c", "-o", "out"], ["diff", "drive.eds"]],
    ids=" ".join,
)
def test_huge_numbers_are_diagnostics(tmp_path: Path, digits: int, radix: str, args: list[str]) -> None:
    number = b"7" * digits if radix == "decimal" else b"0x" + b"F" * digits
    data = replaced(DRIVE, b"DefaultValue=0x0000", b"DefaultValue=" + number, after=b"[6040]")
    path = written(tmp_path, "huge.eds", data)
    written(tmp_path, "drive.eds", DRIVE)
    before, after = (args[1:], []) if args[0] == "diff" else ([], args[1:])
    result = run(args[0], *before, "huge.eds", *after, cwd=tmp_path)
    no_python(result)
    assert result.returncode in (0, 1), result.stderr
    if args[0] != "diff":
        assert "error: DefaultValue: a value of" in result.stderr + result.stdout or digits == 70
        assert "[EDS030]" in result.stderr + result.stdout
    unchanged(path, data)


def test_huge_numbers_in_keys_and_xml(tmp_path: Path) -> None:
    key = replaced(DRIVE, b"Line1=", b"Line" + b"1" * 5000 + b"=")
    device = cantools_od.loads(key)
    assert device.comments is not None
    xdd = (EXAMPLES.parent / "tests" / "xdd").glob("**/*.xdd")
    sample = next(iter(sorted(xdd)), None)
    if sample is not None and b"fileVersion=" in sample.read_bytes():
        data = sample.read_bytes()
        at = data.index(b"fileVersion=") + len(b'fileVersion="')
        cantools_od.loads(data[:at] + b"9" * 5000 + data[data.index(b'"', at) :])


# 6. messages that say what is wrong -------------------------------------------------------------


@pytest.mark.parametrize(
    "args",
    [
        ["convert", "drive.eds", "-o", "regfile/out.xdd"],
        ["ids", "drive.eds", "-o", "regfile/drive.ids.toml"],
        ["gen", "drive.eds", "-t", "c", "-o", "out", "--depfile", "regfile/deps.d"],
        ["gen", "drive.eds", "-t", "c", "-o", "regfile/deeper"],
    ],
    ids=lambda a: " ".join(a[:2]) + (" --depfile" if "--depfile" in a else ""),
)
def test_the_path_that_is_not_a_folder_is_named(tmp_path: Path, args: list[str]) -> None:
    written(tmp_path, "drive.eds", DRIVE)
    (tmp_path / "regfile").write_text("a file\n")
    result = run(*args, cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.rstrip().endswith(": regfile is not a folder"), result.stderr
    assert (tmp_path / "regfile").read_text() == "a file\n"


def test_import_table_names_the_folder_too_and_refuses_unknown_extensions(tmp_path: Path) -> None:
    table = tmp_path / "table.csv"
    table.write_text("Index,Sub,Name,Type,Access,Default\n0x2000,0,Speed,UNSIGNED16,rw,0\n")
    (tmp_path / "regfile").write_text("a file\n")
    result = run("import-table", "table.csv", "-o", "regfile/out.eds", cwd=tmp_path)
    assert result.returncode == 2 and result.stderr.rstrip().endswith("regfile is not a folder"), result.stderr
    result = run("import-table", "table.csv", "-o", "out.eds", "--report", "regfile/report.md", cwd=tmp_path)
    assert result.returncode == 2 and result.stderr.rstrip().endswith("regfile is not a folder"), result.stderr
    result = run("import-table", "table.csv", "-o", "x.txt", cwd=tmp_path)
    assert result.returncode == 2 and "unknown file extension '.txt'" in result.stderr, result.stderr
    assert not (tmp_path / "x.txt").exists() and not (tmp_path / "out.eds").exists()


@pytest.mark.skipif(shutil.which("git") is None, reason="git is not installed")
def test_diff_git_names_what_is_missing(tmp_path: Path) -> None:
    env = {**os.environ, "GIT_AUTHOR_NAME": "t", "GIT_AUTHOR_EMAIL": "t@t", "GIT_COMMITTER_NAME": "t",
           "GIT_COMMITTER_EMAIL": "t@t"}  # fmt: skip
    written(tmp_path, "drive.eds", DRIVE)
    for args in (["init", "-q"], ["add", "drive.eds"], ["commit", "-qm", "one"]):
        subprocess.run(["git", *args], cwd=tmp_path, env=env, check=True)
    result = run("diff", "--git", "HEAD", "missing/x.eds", cwd=tmp_path)
    assert result.returncode == 2
    assert result.stderr.strip() == "error: missing/x.eds does not exist at HEAD", result.stderr
    result = run("diff", "--git", "NOSUCHREV", "drive.eds", cwd=tmp_path)
    assert result.returncode == 2 and "cannot run git" not in result.stderr and "NOSUCHREV" in result.stderr


@pytest.mark.parametrize(
    ("source", "target", "said"),
    [("drive.eds", "out.dcf", "a DCF describes one node: give its node-ID (--node-id N) to make one from an EDS"),
     ("drive.eds", "out.xdc", "an XDC describes one node: give its node-ID (--node-id N) to make one from an EDS"),
     ("drive.xdd", "out.xdc", "an XDC describes one node: give its node-ID (--node-id N) to make one from an XDD")],
)  # fmt: skip
def test_convert_to_one_node_names_node_id(tmp_path: Path, source: str, target: str, said: str) -> None:
    written(tmp_path, "drive.eds", DRIVE)
    if source.endswith(".xdd"):
        assert run("convert", "drive.eds", "-o", source, cwd=tmp_path).returncode == 0
    result = run("convert", source, "-o", target, cwd=tmp_path)
    assert result.returncode == 2 and result.stderr.strip().endswith(said), result.stderr
    assert not (tmp_path / target).exists()


def test_convert_refuses_a_node_id_the_file_is_not_commissioned_for(tmp_path: Path) -> None:
    # Before, `--node-id 7` was ignored without a word and the DCF said NodeID=16.
    commissioned = replaced(DRIVE, b"[DeviceInfo]", b"[DeviceComissioning]\nNodeID=16\nBaudrate=500\n\n[DeviceInfo]")
    source = written(tmp_path, "drive.eds", commissioned)
    for target in ("out.dcf", "out.xdc"):
        result = run("convert", "drive.eds", "-o", target, "--node-id", "7", cwd=tmp_path)
        assert result.returncode == 2, result.stderr
        assert result.stderr.strip().splitlines() == [
            "drive.eds: error: the file is commissioned for node-ID 16, not 7:"
            " leave out --node-id or change the node-ID in the file"
        ]
        assert not (tmp_path / target).exists()
    agreed = run("convert", "drive.eds", "-o", "out.dcf", "--node-id", "16", cwd=tmp_path)
    assert agreed.returncode == 0, agreed.stderr
    assert b"NodeID=16" in (tmp_path / "out.dcf").read_bytes()
    assert source.read_bytes() == commissioned


# 7. help and docs: what the command pages cannot check (tests/test_help_readme.py checks the rest) -----


def test_gen_explain_without_canopennode_is_refused_with_a_reason(tmp_path: Path) -> None:
    written(tmp_path, "drive.eds", DRIVE)
    result = run("gen", "drive.eds", "-t", "c", "-o", "out", "--explain", cwd=tmp_path)
    assert result.returncode == 2 and "--explain" in result.stderr and "-t canopennode" in result.stderr
    assert not (tmp_path / "out").exists()


def test_gen_name_error_states_the_rule(tmp_path: Path) -> None:
    written(tmp_path, "drive.eds", DRIVE)
    result = run("gen", "drive.eds", "-t", "c", "-o", "out", "--name", "Drive", cwd=tmp_path)
    assert result.returncode == 2 and "snake_case" in result.stderr, result.stderr


def test_select_takes_the_names_rules_prints(tmp_path: Path) -> None:
    data = replaced(DRIVE, b"DefaultValue=0x0000", b"DefaultValue=70000", after=b"[6040]")
    written(tmp_path, "drive.eds", data)
    by_name = run("lint", "drive.eds", "--select", "value-outside-type-range", "--format", "json", cwd=tmp_path)
    by_code = run("lint", "drive.eds", "--select", "EDS034", "--format", "json", cwd=tmp_path)
    assert by_name.returncode == 1 and by_name.stdout == by_code.stdout and "EDS034" in by_name.stdout
    ignored = run("lint", "drive.eds", "--ignore", "value-outside-type-range", "--format", "json", cwd=tmp_path)
    assert "EDS034" not in ignored.stdout


# 8. long work, lint --fix, fmt --diff -----------------------------------------------------------


def on_a_terminal(*args: str, cwd: Path) -> str:
    """What the command prints on stderr when stderr is a terminal (a pseudo-terminal here)."""
    import pty

    leader, follower = pty.openpty()
    env = {key: value for key, value in os.environ.items() if key != "CI"} | {"TERM": "xterm"}
    with subprocess.Popen([*cli_command(), *args], cwd=cwd, stdout=subprocess.DEVNULL, stderr=follower, env=env):
        os.close(follower)
        chunks = []
        while True:
            try:
                chunk = os.read(leader, 4096)
            except OSError:
                break
            if not chunk:
                break
            chunks.append(chunk)
    os.close(leader)
    return b"".join(chunks).decode("utf-8", "replace")


@pytest.mark.parametrize(
    ("args", "shown"),
    [
        # Files checked in processes are counted as they end, each named: either file can end last.
        (["lint", "a.eds", "b.eds", "--format", "json"], "lint: 2/2 [ab].eds"),
        (["fmt", "--check", "a.eds", "b.eds"], "fmt: 2/2 [ab].eds"),
        (["gen", "a.eds", "-t", "c", "-o", "out"], "gen: 2 a.c"),
        (["diff", "a.eds", "b.eds"], "diff: 2 comparing"),
    ],
    ids=lambda a: a[0] if isinstance(a, list) else "",
)
def test_progress_on_a_terminal_only(tmp_path: Path, args: list[str], shown: str) -> None:
    written(tmp_path, "a.eds", DRIVE)
    written(tmp_path, "b.eds", DRIVE.replace(b"ParameterName=Controlword", b"ParameterName=Control word"))
    assert re.search(shown, on_a_terminal(*args, cwd=tmp_path))
    piped = run(*args, cwd=tmp_path)
    assert shown.split(":")[0] + ":" not in piped.stderr and "\x1b[K" not in piped.stderr + piped.stdout


def test_lint_fix_says_what_it_fixed(tmp_path: Path) -> None:
    data = DRIVE.replace(b"ParameterName=Controlword", b"parametername=Controlword", 1)
    written(tmp_path, "drive.eds", data)
    before = run("lint", "drive.eds", "--format", "json", cwd=tmp_path)
    assert '"code": "DIA018"' in before.stdout, before.stdout
    result = run("lint", "--fix", "--unsafe-fixes", "drive.eds", cwd=tmp_path)  # python-canopen looks the key up
    assert "drive.eds: fixed DIA018" in result.stderr, result.stderr
    assert b"ParameterName=Controlword" in (tmp_path / "drive.eds").read_bytes()


def test_fmt_diff_of_line_ends_alone_is_one_note(tmp_path: Path) -> None:
    canonical = run("fmt", written(tmp_path, "drive.eds", DRIVE).name, cwd=tmp_path)
    assert canonical.returncode == 0
    lf = (tmp_path / "drive.eds").read_bytes()
    path = written(tmp_path, "drive.eds", lf.replace(b"\n", b"\r\n"))
    result = run("fmt", "--diff", "drive.eds", cwd=tmp_path)
    assert result.returncode == 1
    assert result.stdout == "", result.stdout[:300]
    assert "drive.eds: note: line ends CRLF become LF" in result.stderr
    assert path.read_bytes() == lf.replace(b"\n", b"\r\n")
