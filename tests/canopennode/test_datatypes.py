"""Every CiA 301 data type, laid out as the stack expects: a crafted EDS with one object per type (and
the edge values of each) goes through `gen -t canopennode`, compiles as C and C++, and the stack's
OD_getSub sees the lengths, attributes and bytes the model says (the checks of test_walk.py)."""

from __future__ import annotations

from pathlib import Path

from cnokit import WARNINGS, gen, includes, run, stack, walk
from test_walk import KIND, check_object

from cantools_od.api import load

REQUIRED = """[1000]
ParameterName=Device type
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=0
PDOMapping=0

[1001]
ParameterName=Error register
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=0
PDOMapping=1

[1003]
ParameterName=Pre-defined error field
ObjectType=0x8
SubNumber=2

[1003sub0]
ParameterName=Number of errors
ObjectType=0x7
DataType=0x0005
AccessType=rw
DefaultValue=
PDOMapping=0

[1003sub1]
ParameterName=Standard error field
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=
PDOMapping=0

[1014]
ParameterName=COB-ID EMCY
ObjectType=0x7
DataType=0x0007
AccessType=ro
DefaultValue=$NODEID+0x80
PDOMapping=0

[1016]
ParameterName=Consumer heartbeat time
ObjectType=0x8
SubNumber=2

[1016sub0]
ParameterName=Highest sub-index supported
ObjectType=0x7
DataType=0x0005
AccessType=ro
DefaultValue=1
PDOMapping=0

[1016sub1]
ParameterName=Consumer heartbeat time
ObjectType=0x7
DataType=0x0007
AccessType=rw
DefaultValue=0
PDOMapping=0

[1017]
ParameterName=Producer heartbeat time
ObjectType=0x7
DataType=0x0006
AccessType=rw
PDOMapping=0
"""

# (data type, access, PDO mapping, default): one VAR at 2000h + n each
TYPES = [
    (0x0001, "rw", 1, "1"),
    (0x0002, "rw", 1, "-128"),
    (0x0003, "ro", 1, "-32768"),
    (0x0004, "wo", 1, "-2147483648"),
    (0x0015, "rw", 1, "-9223372036854775808"),
    (0x0005, "const", 0, "0xFF"),
    (0x0006, "rwr", 1, "0xBEEF"),
    (0x0007, "rww", 1, "0xFFFFFFFF"),
    (0x001B, "rw", 1, "0xFFFFFFFFFFFFFFFF"),
    (0x0010, "rw", 1, "-8388608"),
    (0x0012, "rw", 0, "-1"),
    (0x0013, "rw", 0, "0x7FFFFFFFFFFF"),
    (0x0014, "rw", 0, "-36028797018963968"),
    (0x0016, "rw", 1, "0xABCDEF"),
    (0x0018, "rw", 0, "0x123456789A"),
    (0x0019, "rw", 0, "0xFFFFFFFFFFFF"),
    (0x001A, "rw", 0, "0x00FFFFFFFFFFFFFF"),
    (0x0008, "rw", 1, "-1.5e-3"),
    (0x0011, "rw", 1, "6.02214076e23"),
    (0x0009, "rw", 0, "Tab\tquote' back\\ euro \u20ac"),
    (0x000A, "rw", 0, "00FF7F80"),
    (0x000B, "rw", 0, "Unicode \u00e9"),
    (0x000C, "rw", 0, "0x000100000005"),
    (0x000D, "rw", 0, "0x00020FFFFFFF"),
    (0x000F, "rw", 0, ""),
    (0x0007, "rw", 0, ""),  # no default: no memory
]


def crafted() -> str:
    sections = [REQUIRED]
    for n, (dtype, access, pdo, default) in enumerate(TYPES):
        sections.append(
            f"[{0x2000 + n:04X}]\nParameterName=Value {n}\nObjectType=0x7\nDataType=0x{dtype:04X}\n"
            f"AccessType={access}\nDefaultValue={default}\nPDOMapping={pdo}\n"
        )
    return "\n".join(sections)


def test_every_data_type_reaches_the_stack_as_the_model_says(tmp_path: Path) -> None:
    stack()
    source = tmp_path / "types.eds"
    source.write_text(crafted(), encoding="utf-8")
    result = gen(source, tmp_path / "od")
    assert result.returncode == 0, result.stderr
    run(["g++", "-x", "c++", *WARNINGS, *includes(tmp_path / "od"), "-c", "OD.c", "-o", "od.o"], cwd=tmp_path / "od")
    seen = walk(tmp_path / "od", tmp_path / "walk")
    device = load(str(source))
    for obj in device.objects.values():
        if obj.kind in KIND:
            check_object(device, obj, seen[obj.index])
    assert seen[0x2000 + len(TYPES) - 2].subs[0].data is None  # DOMAIN
    assert seen[0x2000 + len(TYPES) - 1].subs[0].data is None  # no default
    assert seen[0x2013].subs[0].data == "Tab\tquote' back\\ euro \u20ac".encode()
