"""The writer: preserve edits only what changed, canonical is a stable normal form."""

from __future__ import annotations

import difflib
import json
from pathlib import Path

import pytest

from cantools_od import dumps, load, loads, save
from cantools_od.model import Device, NodeIdExpr, Object, ObjectKind, SubObject

from support import EXAMPLES

ORIGINAL = (
    b"; vendor header\r\n"
    b"[FileInfo]\r\n"
    b"FileName=x.eds\r\n"
    b"\r\n"
    b"[2000]\r\n"
    b"ParameterName = Speed\r\n"
    b"DataType=0x0006\r\n"
    b"AccessType=RW\r\n"
    b"DefaultValue=500 ; half a second\r\n"
    b"\r\n"
    b"[2001]\r\n"
    b"ParameterName=Mode\r\n"
    b"DataType=0x0005\r\n"
    b"AccessType=rw\r\n"
)


def changed_lines(before: bytes, after: bytes) -> list[str]:
    diff = difflib.ndiff(before.decode().splitlines(True), after.decode().splitlines(True))
    return [line for line in diff if line[:1] in "+-"]


def test_preserve_is_byte_identical_when_nothing_changed() -> None:
    assert dumps(loads(ORIGINAL)) == ORIGINAL


def test_preserve_edit_touches_one_line() -> None:
    device = loads(ORIGINAL)
    device.objects[0x2000].default = 750
    after = dumps(device)
    assert changed_lines(ORIGINAL, after) == ["- DefaultValue=500 ; half a second\r\n", "+ DefaultValue=0x02EE\r\n"]


def test_preserve_add_and_remove_keys_and_objects() -> None:
    device = loads(ORIGINAL)
    device.objects[0x2001].default = 3
    device.objects[0x2001].access = None
    device.objects[0x2002] = Object(index=0x2002, name="New", data_type=5, access=None)
    after = dumps(device)
    assert changed_lines(ORIGINAL, after) == [
        "- AccessType=rw\r\n",
        "+ DefaultValue=0x03\r\n",
        "+ \r\n",
        "+ [2002]\r\n",
        "+ ParameterName=New\r\n",
        "+ DataType=0x0005\r\n",
    ]
    assert loads(after).objects[0x2002].name == "New"
    del device.objects[0x2000]
    assert b"[2000]" not in dumps(device) and b"; vendor header" in dumps(device)


def test_canonical_form() -> None:
    text = dumps(loads(ORIGINAL), style="canonical").decode("ascii")
    assert "\r" not in text
    assert "[2000]\nParameterName=Speed\nDataType=0x0006\nAccessType=rw\n; half a second\nDefaultValue=0x01F4\n" in text
    assert text.startswith("; vendor header\n[FileInfo]\n")


def test_canonical_is_idempotent_and_reloads_equal() -> None:
    device = loads(ORIGINAL)
    once = dumps(device, style="canonical")
    again = loads(once)
    assert dumps(again, style="canonical") == once
    assert again.content() == device.content()


def test_dcf_from_eds_resolves_node_id(tmp_path: Path) -> None:
    device = loads(b"[1014]\nParameterName=COB-ID EMCY\nDataType=0x0007\nAccessType=ro\nDefaultValue=$NODEID+0x80\n")
    with pytest.raises(ValueError, match="node-ID"):
        dumps(device, "dcf")
    device.node_id = 3
    dcf = dumps(device, "dcf").decode()
    assert "[DeviceComissioning]\nNodeID=3\n" in dcf
    assert "DefaultValue=$NODEID+0x80\nParameterValue=0x00000083\n" in dcf
    reread = loads(dcf.encode(), fmt="dcf")
    assert reread.node_id == 3 and reread.objects[0x1014].value(3) == 0x83


def test_json_round_trip_is_exact() -> None:
    device = load(EXAMPLES / "io_device.eds")
    data = dumps(device, "json")
    again = loads(data)
    assert again.model_dump() == device.model_dump()  # every field, origins and diagnostics included
    assert dumps(again, "json") == data
    assert json.loads(data)["objects"]["4116"]["default"] == {"nodeid": 0x80, "text": "$NODEID+0x80"}


def test_json_round_trip_of_every_value_kind() -> None:
    sub = SubObject(name="s", default=b"\x00\xff", low_limit=1.25, high_limit=float("inf"))
    device = Device(
        objects={
            0x2000: Object(
                index=0x2000, name="r", object_type=ObjectKind.RECORD, subs={1: sub}, default=NodeIdExpr(offset=1)
            )
        }
    )
    assert loads(dumps(device, "json")) == device


def test_save_writes_only_on_change_and_atomically(tmp_path: Path) -> None:
    target = tmp_path / "out.eds"
    device = loads(ORIGINAL)
    assert save(device, target) is True
    mtime = target.stat().st_mtime_ns
    assert save(device, target) is False
    assert target.stat().st_mtime_ns == mtime
    assert [p.name for p in tmp_path.iterdir()] == ["out.eds"]  # no temporary left behind


def test_non_ascii_names_survive_canonical() -> None:
    device = loads("[2000]\nParameterName=Druck ‰\nDataType=0x0005\nAccessType=ro\n".encode())
    assert loads(dumps(device, style="canonical")).objects[0x2000].name == "Druck ‰"


def test_preserve_keeps_the_radix_of_an_edited_number() -> None:
    original = b"[1017]\nParameterName=Producer heartbeat time\nDataType=0x0006\nAccessType=rw\nDefaultValue=500\n"
    device = loads(original)
    device.objects[0x1017].default = 250
    assert dumps(device) == original.replace(b"=500", b"=250")


def test_edited_compact_sub_object_gets_its_own_section() -> None:
    text = b"[1600]\nParameterName=M\nObjectType=0x9\nDataType=0x0007\nAccessType=rw\nCompactSubObj=2\nDefaultValue=0\n"
    device = loads(text)
    device.objects[0x1600].subs[1].default = 0x60400010
    for style in ("preserve", "canonical"):
        again = loads(dumps(device, style=style))  # type: ignore[arg-type]
        assert again.objects[0x1600].subs[1].default == 0x60400010, style
        assert again.objects[0x1600].subs[2].default == 0 and again.objects[0x1600].subs[2].implicit


def test_edited_compact_pdo_is_written_with_its_mapping() -> None:
    text = (
        b"[DeviceInfo]\nCompactPDO=0x3\nNrOfRXPDO=2\nNrOfTXPDO=0\n"
        b"[1401]\nParameterName=RPDO2\nObjectType=0x9\nSubNumber=0\n"
    )
    device = loads(text)
    assert dumps(device) == text and dumps(device, style="canonical").count(b"[14") == 1  # implied, not written
    device.objects[0x1400].subs[1].default = 0x80000000
    for style in ("preserve", "canonical"):
        again = loads(dumps(device, style=style))  # type: ignore[arg-type]
        assert again.objects[0x1400].subs[1].default == 0x80000000, style
        assert 0x1600 in again.objects and not again.objects[0x1600].implicit, style
