"""Files read as CANopenEditor reads them: PDO attribute bits, edge defaults, names, storage groups.

Each case is generated with `gen -t canopennode` as a user runs it, compiled with the stack's
CO_ODinterface.c and walked through OD_find/OD_getSub (cnokit.walk): what the stack sees.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from cnokit import gen, stack, walk
from xddkit import document

from support import cli_command

ACCESSES = ("ro", "const", "wo", "rw", "rwr", "rww")
WORDS = ("no", "optional", "default", "TPDO", "RPDO")
T, R = 0x04, 0x08
# CANopenEditor's ODA_*PDO bits (libEDSsharp ODentry.AccessPDO): an explicit direction wins, then optional/default.
EDITOR = {
    "no": {"rwr": T, "rww": R},
    "optional": {"ro": T | R, "const": T | R, "wo": T | R, "rw": T | R, "rwr": T, "rww": R},
    "default": {"ro": T | R, "const": T | R, "wo": T | R, "rw": T | R, "rwr": T, "rww": R},
    "TPDO": {**dict.fromkeys(ACCESSES, T), "rww": R},  # RPDO or rww is asked first
    "RPDO": dict.fromkeys(ACCESSES, R),
}
HEARTBEAT_XDD = """
          <CANopenObject index="1017" name="Producer heartbeat time" objectType="7"
            dataType="0006" accessType="rw" defaultValue="0" PDOmapping="no" />"""


def var(index: int, name: str, dtype: int, access: str, default: str, mapping: int = 0) -> str:
    return (f"\n[{index:04X}]\nParameterName={name}\nObjectType=0x7\nDataType=0x{dtype:04X}\nAccessType={access}\n"
            f"DefaultValue={default}\nPDOMapping={mapping}\n")  # fmt: skip


# What every build of the stack needs: device type, error register (ro, mappable: CNO010), producer heartbeat.
REQUIRED_EDS = (var(0x1000, "Device type", 0x0007, "ro", "0") + var(0x1001, "Error register", 0x0005, "ro", "0", 1)
                + var(0x1017, "Producer heartbeat time", 0x0006, "rw", "0"))  # fmt: skip


def pdo_bits(attribute: int) -> int:
    return attribute & (T | R)


def test_xdd_pdomapping_words_give_canopeneditors_bits_for_every_access(tmp_path: Path) -> None:
    stack()
    cases = [(word, access) for word in WORDS for access in ACCESSES]
    objects = "".join(
        f'\n          <CANopenObject index="{0x2100 + n:04X}" name="Case {n}" objectType="7" dataType="0006" '
        f'accessType="{access}" defaultValue="0" PDOmapping="{word}" />'
        for n, (word, access) in enumerate(cases)
    )
    from xddkit import MANDATORY

    (tmp_path / "cases.xdd").write_text(document(MANDATORY + HEARTBEAT_XDD + objects), encoding="utf-8")
    result = gen(tmp_path / "cases.xdd", tmp_path / "od")
    assert result.returncode == 0, result.stderr
    seen = walk(tmp_path / "od", tmp_path / "walk")
    got = {case: pdo_bits(seen[0x2100 + n].subs[0].attribute) for n, case in enumerate(cases)}
    assert got == {(word, access): EDITOR[word].get(access, 0) for word, access in cases}


def test_eds_pdomapping_keeps_the_direction_the_access_allows_and_says_so(tmp_path: Path) -> None:
    stack()
    body = REQUIRED_EDS + "".join(
        var(0x2100 + n, f"Case {n}", 0x0006, access, "0", mapping)
        for n, (mapping, access) in enumerate((m, a) for m in (0, 1) for a in ACCESSES)
    )
    (tmp_path / "cases.eds").write_text(body, encoding="utf-8")
    assert gen(tmp_path / "cases.eds", tmp_path / "ours").returncode == 0
    ours = walk(tmp_path / "ours", tmp_path / "w1")
    # PDOMapping=0 as CiA 311's no, PDOMapping=1 as TPDO on ro/const, RPDO on wo, optional on rw (rwr/rww explicit)
    expected = {"ro": T, "const": T, "wo": R, "rw": T | R, "rwr": T, "rww": R}
    assert [pdo_bits(ours[0x2100 + n].subs[0].attribute) for n in range(6)] == [
        EDITOR["no"].get(a, 0) for a in ACCESSES
    ]
    assert [pdo_bits(ours[0x2106 + n].subs[0].attribute) for n in range(6)] == [expected[a] for a in ACCESSES]
    lint = subprocess.run([*cli_command(), "lint", "--profile", "canopennode", "--select", "CNO010",
                           str(tmp_path / "cases.eds")], capture_output=True, text=True)  # fmt: skip
    named = sorted(line.split(": ")[2].split(":")[0] for line in lint.stdout.splitlines() if "[CNO010]" in line)
    assert named == ["1001h", "2106h", "2107h", "2108h"], lint.stdout  # the ro, const and wo ones with PDOMapping=1
    assert "CANopenEditor writes ODA_TRPDO" in lint.stdout and lint.returncode == 0
    # The setting keeps CANopenEditor's bits, and --explain says where.
    (tmp_path / "cases.canopennode.toml").write_text('[stack]\npdo_attributes = "canopeneditor"\n')
    kept = gen(tmp_path / "cases.eds", tmp_path / "theirs", "--explain")
    assert kept.returncode == 0 and "2106: ODA_TRPDO as CANopenEditor writes it, not ODA_TPDO" in kept.stderr
    theirs = walk(tmp_path / "theirs", tmp_path / "w2")
    assert [pdo_bits(theirs[0x2106 + n].subs[0].attribute) for n in range(6)] == [
        EDITOR["optional"][a] for a in ACCESSES
    ]


def test_edge_defaults_as_canopeneditor_reads_them(tmp_path: Path) -> None:
    stack()
    body = REQUIRED_EDS + (
        var(0x2000, "Zero octets", 0x000A, "rw", "0")
        + var(0x2001, "Short octets", 0x000A, "rw", "1 2 A")
        + var(0x2002, "Hex octets", 0x000A, "rw", "01020A")
        + var(0x2003, "Spaced octets", 0x000A, "rw", "01 02 0A")
        + var(0x2004, "Empty octets", 0x000A, "rw", "")
        + var(0x2005, "Stream", 0x000F, "rw", "0")
        + var(0x2006, "Gain", 0x0008, "rw", "1.5f")
        + var(0x2007, "Name", 0x0009, "rw", "ab")
    )
    (tmp_path / "values.eds").write_text(body, encoding="utf-8")
    (tmp_path / "values.canopennode.toml").write_text(
        "[2000]\nstring_length_min = 32\n[2004]\nstring_length_min = 3\n[2007]\nstring_length_min = 4\n"
    )
    lint = subprocess.run([*cli_command(), "lint", "--profile", "canopennode", "--select", "CNO007",
                           str(tmp_path / "values.eds")], capture_output=True, text=True)  # fmt: skip
    assert "CNO007" not in lint.stdout, lint.stdout
    result = gen(tmp_path / "values.eds", tmp_path / "od", "--explain")
    assert result.returncode == 0, result.stderr
    assert "2005: DOMAIN default ignored" in result.stderr
    assert "2000: default '0' read as the bytes 00, as CANopenEditor does" in result.stderr
    seen = walk(tmp_path / "od", tmp_path / "walk")
    data = {index: (seen[index].subs[0].length, seen[index].subs[0].data) for index in range(0x2000, 0x2008)}
    assert data[0x2000] == (32, bytes(32))  # capacity 32, zero-filled
    assert data[0x2001] == (3, b"\x01\x02\x0a")
    assert data[0x2002] == data[0x2003] == (3, b"\x01\x02\x0a")
    assert data[0x2004] == (3, bytes(3))
    assert data[0x2005] == (0, None)  # a DOMAIN: no memory, the application streams it
    assert data[0x2006] == (4, bytes.fromhex("0000c03f"))
    assert data[0x2007] == (4, b"ab\0\0")


def test_names_and_storage_groups_of_a_canopeneditor_project(tmp_path: Path) -> None:
    stack()
    objects = (
        HEARTBEAT_XDD
        + '\n          <CANopenObject index="2000" name="Trigger input x8" objectType="7" dataType="0005" '
        'accessType="rw" defaultValue="0" PDOmapping="no" />'
        '\n          <CANopenObject index="2001" name="3 phase current" objectType="7" dataType="0005" '
        'accessType="rw" defaultValue="0" PDOmapping="no" />'
        '\n          <CANopenObject index="1014" name="COB-ID EMCY" objectType="7" dataType="0007" '
        'accessType="rw" defaultValue="$NODEID+0x80" PDOmapping="no" />'
    )
    from xddkit import MANDATORY

    plain = document(MANDATORY + objects)
    (tmp_path / "plain.xdd").write_text(plain, encoding="utf-8")
    # CANopenEditor writes CO_* properties into its projects, and none where the storage group is RAM.
    marked = objects.replace(
        'index="2001" name="3 phase current" objectType="7"', 'index="2001" uniqueIDRef="UID_OBJ_2001" objectType="7"'
    )
    parameter = (
        '          <parameter uniqueID="UID_OBJ_2001"><label lang="en">3 phase current</label>'
        '<property name="CO_storageGroup" value="PERSIST_APP" /></parameter>'
    )
    (tmp_path / "project.xdd").write_text(document(MANDATORY + marked, parameter), encoding="utf-8")
    assert gen(tmp_path / "plain.xdd", tmp_path / "plain").returncode == 0
    project = gen(tmp_path / "project.xdd", tmp_path / "project", "--explain")
    assert project.returncode == 0, project.stderr
    header = (tmp_path / "plain" / "OD.h").read_text()
    assert "x2000_triggerInputX8" in header and "x2001__3PhaseCurrent" in header
    assert walk(tmp_path / "plain", tmp_path / "w1")[0x1014].subs[0].group == "PERSIST_COMM"  # inferred by index
    ours = walk(tmp_path / "project", tmp_path / "w2")
    assert ours[0x1014].subs[0].group == "RAM" and ours[0x2001].subs[0].group == "PERSIST_APP"
    assert "1014h: storage group RAM: a CANopenEditor project leaves it unsaid where it is RAM" in project.stderr


def test_array_elements_typed_only_by_their_array(tmp_path: Path) -> None:
    """Older CANopenEditor projects write dataType="0000" on ARRAY elements; it takes the ARRAY's type."""
    stack()
    from xddkit import MANDATORY

    elements = "".join(
        f'\n            <CANopenSubObject subIndex="{n:02X}" name="Field" objectType="7" dataType="0000" '
        f'accessType="rw" defaultValue="{text}" PDOmapping="no" />'
        for n, text in ((1, "0"), (2, "0x10"), (3, "010"))
    )
    array = (
        '\n          <CANopenObject index="2200" name="Fields" objectType="8" dataType="0007" subNumber="4">'
        '\n            <CANopenSubObject subIndex="00" name="Count" objectType="7" dataType="0005" accessType="ro" '
        'defaultValue="3" PDOmapping="no" />' + elements + "\n          </CANopenObject>"
    )
    (tmp_path / "old.xdd").write_text(document(MANDATORY + HEARTBEAT_XDD + array), encoding="utf-8")
    result = gen(tmp_path / "old.xdd", tmp_path / "od")
    assert result.returncode == 0, result.stderr
    seen = walk(tmp_path / "od", tmp_path / "walk")[0x2200]
    assert [(seen.subs[n].length, seen.subs[n].data) for n in (1, 2, 3)] == [
        (4, bytes(4)), (4, b"\x10\0\0\0"), (4, b"\x08\0\0\0")
    ]  # fmt: skip
