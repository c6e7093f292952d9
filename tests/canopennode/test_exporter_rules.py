"""Storage as CANopenEditor's exporter gives it (libEDSsharp CanOpenNodeExporter_V4.cs), rule by rule.

CANopenEditor gives an entry memory (`dataOrig`) only where it has a default, and lets the application serve
the others through `OD_extension_init`. Each case is generated with `gen -t canopennode`, compiled with the
stack's CO_ODinterface.c and walked through OD_find/OD_getSub (what the stack sees); the objects the stack's
own init reads are then run through CO_CANopenInit. Where we differ on purpose, docs/canopennode.md says why.

The exporter's other storage rules are tested beside their neighbours: strings (capacity, terminator), octet
strings and DOMAINs in test_editor_reading.py; sub-index 0 without a default (1003h) and CO_disabled objects
against CANopenEditor's own OD.c in test_equivalence.py and test_real_projects.py.
"""

from __future__ import annotations

import re
from pathlib import Path

import pytest
import test_full_stack
from cnokit import gen, stack, walk

from support import ROOT

BLANK = ROOT / "examples" / "canopennode" / "blank_device.eds"


def section(name: str, dtype: int, access: str, default: str | None, kind: int = 0x7, subs: int = 0) -> str:
    lines = [f"ParameterName={name}", f"ObjectType=0x{kind:X}"]
    if subs:
        lines.append(f"SubNumber=0x{subs:X}")
    else:
        lines += [f"DataType=0x{dtype:04X}", f"AccessType={access}", "PDOMapping=0"]
        lines += [f"DefaultValue={default}"] if default is not None else []
    return "\n".join(lines) + "\n"


def array(index: int, name: str, dtype: int, defaults: list[str | None]) -> str:
    """An EDS ARRAY: sub-index 0 (ro, the count), then one element per default (None: no DefaultValue line)."""
    text = f"\n[{index:04X}]\n" + section(name, 0, "", None, 0x8, len(defaults) + 1)
    text += f"\n[{index:04X}sub0]\n" + section("Highest sub-index supported", 0x0005, "ro", str(len(defaults)))
    for n, default in enumerate(defaults, 1):
        text += f"\n[{index:04X}sub{n:X}]\n" + section(f"Element {n}", dtype, "rw", default)
    return text


def blank_device_with(objects: dict[int, str], undefault: tuple[str, ...]) -> str:
    """CANopenNode's blank example device with `objects` added (listed where CiA 306 lists them) and the
    DefaultValue lines of the `undefault` sections removed."""
    text = BLANK.read_text(encoding="utf-8")
    for name in undefault:
        text = re.sub(rf"(\[{name}\][^\[]*?)DefaultValue=[^\n]*\n", r"\1", text)
    for index, body in objects.items():
        listing = "ManufacturerObjects" if index >= 0x2000 else "OptionalObjects"
        head = re.search(rf"\[{listing}\]\nSupportedObjects=(\d+)\n((?:\d+=0x[0-9A-Fa-f]+\n)*)", text)
        assert head is not None
        count = int(head.group(1)) + 1
        text = text.replace(
            head.group(0), f"[{listing}]\nSupportedObjects={count}\n{head.group(2)}{count}=0x{index:04X}\n"
        )
        text += body
    return text


def test_objects_the_stack_does_not_read_get_no_memory_without_a_default(tmp_path: Path) -> None:
    """The issue's case, in the shape of a CANopenNode bootloader (EvgenyDD/sh_node ldr/profile.xdd): the program
    download ARRAYs 1F51h/1F56h and the error behaviour 1029h without defaults are the application's, through an
    OD extension; CANopenEditor gives them `.dataOrig = NULL` (Prepare_arr: no default on the first element, no
    array), and so do we. 1018h without defaults: no member memory (Prepare_rec). 1016h, which CO_CANopenInit
    reads (CO_HBconsumer_init), keeps zeroed memory: the init fails on an entry without memory."""
    stack()
    objects = {
        0x1029: array(0x1029, "Error behavior", 0x0005, [None]),
        0x1F51: array(0x1F51, "Program control", 0x0005, [None, None]),
        0x1F56: array(0x1F56, "Program software identification", 0x0007, [None, None]),
    }
    undefault = ("1000", *(f"1018sub{n}" for n in range(1, 5)), *(f"1016sub{n}" for n in range(1, 5)))
    (tmp_path / "loader.eds").write_text(blank_device_with(objects, undefault), encoding="utf-8")
    result = gen(tmp_path / "loader.eds", tmp_path / "od", "--explain")
    assert result.returncode == 0, result.stderr
    seen = walk(tmp_path / "od", tmp_path / "walk")
    for index, count in ((0x1029, 1), (0x1F51, 2), (0x1F56, 2), (0x1018, 4)):
        assert [seen[index].subs[n].data for n in range(1, count + 1)] == [None] * count, f"{index:04X}"
    assert (seen[0x1000].subs[0].length, seen[0x1000].subs[0].data) == (4, None)  # a VAR: Prepare_var
    assert seen[0x1018].subs[0].data == b"\x04"  # a RECORD member with a default keeps its memory
    assert [seen[0x1F56].subs[n].length for n in (1, 2)] == [4, 4]  # the stack still knows the size
    assert seen[0x1F56].subs[0].data == b"\x02"  # sub-index 0 has a default: memory of its own
    assert [seen[0x1016].subs[n].data for n in range(1, 5)] == [bytes(4)] * 4
    assert "1F56sub1: no default value: no memory in the OD, the application provides it" in result.stderr
    assert "1016sub1: no default value: 0, as CO_CANopenInit reads it from the OD" in result.stderr
    run = test_full_stack.build_and_run(tmp_path / "od", tmp_path / "run")
    assert "operational after 2000 iterations" in run, run


def test_the_first_element_decides_an_arrays_memory(tmp_path: Path) -> None:
    """Prepare_arr reads the first element's default for the whole C array: without it the ARRAY has no memory
    even where later elements have defaults; with it, every element has memory (0 where it has no default)."""
    stack()
    objects = {
        0x2000: array(0x2000, "First without", 0x0006, [None, "5", "6"]),
        0x2001: array(0x2001, "First with", 0x0006, ["7", None, "9"]),
    }
    (tmp_path / "device.eds").write_text(blank_device_with(objects, ()), encoding="utf-8")
    result = gen(tmp_path / "device.eds", tmp_path / "od", "--explain")
    assert result.returncode == 0, result.stderr
    seen = walk(tmp_path / "od", tmp_path / "walk")
    assert [seen[0x2000].subs[n].data for n in (1, 2, 3)] == [None, None, None]
    assert [seen[0x2001].subs[n].data for n in (1, 2, 3)] == [b"\x07\0", b"\0\0", b"\x09\0"]
    assert "2000sub2: default ignored: the ARRAY's first element has none" in result.stderr
    assert "2001sub2: no default value: 0, as the ARRAY's first element has one" in result.stderr


def test_an_object_the_init_reads_needs_memory_where_canopeneditor_gives_none(tmp_path: Path) -> None:
    """Why we differ on purpose: 1016h without defaults gets `.dataOrig = NULL` from CANopenEditor (Prepare_arr), and
    then CO_HBconsumer_init's OD_get_u32 answers ODR_SUB_NOT_EXIST and CO_CANopenInit fails on 1016h. Ours, with
    zeroed memory, runs (the first test); the same OD with CANopenEditor's NULL does not."""
    stack()
    undefault = tuple(f"1016sub{n}" for n in range(1, 5))
    (tmp_path / "device.eds").write_text(blank_device_with({}, undefault), encoding="utf-8")
    assert gen(tmp_path / "device.eds", tmp_path / "od").returncode == 0
    source = tmp_path / "od" / "OD.c"
    ours = source.read_text(encoding="utf-8")
    theirs = re.sub(r"(\.dataOrig = )&OD_\w+\.x1016_consumerHeartbeatTime\[0\]", r"\1NULL", ours)
    assert theirs != ours
    source.write_text(theirs, encoding="utf-8")
    with pytest.raises(AssertionError, match=r"CO_CANopenInit: -\d+, OD entry 0x1016"):
        test_full_stack.build_and_run(tmp_path / "od", tmp_path / "run")
