"""One test per kind of change and impact class, on edits of a shipped example."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from diffkit import BASE, device, diff_of, drop_section, only, set_key, summary

from cantools_od import dumps, loads
from cantools_od.changes import Breaks, Impact, Kind, compare, describe


def test_the_same_file_has_no_changes() -> None:
    result = diff_of(BASE)
    assert result.empty and not list(result.changes())


def test_spelling_only_is_no_change() -> None:
    """Radix, the case of a key no peer looks up by case, of an access type, blanks around `=` and section order
    change nothing; the case of a key python-canopen looks up is what it reads differently."""
    text = set_key(BASE, "1017", "DefaultValue", "0x3E8")  # 1000 in hex
    text = text.replace("SubNumber=5", "SUBNUMBER=5")
    text = text.replace("AccessType=rw\nDefaultValue=0x3E8", "AccessType = RW\nDefaultValue=0x3E8")
    assert diff_of(text).empty
    respelled = text.replace("ParameterName=Producer heartbeat time", "parametername=Producer heartbeat time")
    assert [(c.kind, c.index, c.field) for c in diff_of(respelled).changes()] == [
        (Kind.PEER_READING, 0x1017, "spelling.ParameterName")
    ]
    reordered = drop_section(BASE, "1017") + "\n[1017]\nParameterName=Producer heartbeat time\nObjectType=0x7\n"
    reordered += "DataType=0x0006\nAccessType=rw\nDefaultValue=1000\nPDOMapping=0\n"
    assert diff_of(reordered).empty


def test_object_removed_is_breaking_and_added_compatible() -> None:
    removed = drop_section(BASE, "1017")
    assert summary(diff_of(removed)) == {("object-removed", "breaking", 0x1017, None)}
    assert summary(diff_of(BASE, removed)) == {("object-added", "compatible", 0x1017, None)}


def test_sub_object_removed_is_breaking_and_added_compatible() -> None:
    removed = set_key(drop_section(BASE, "1003sub4"), "1003", "SubNumber", "4")
    assert summary(diff_of(removed)) == {("sub-removed", "breaking", 0x1003, 4)}
    assert summary(diff_of(BASE, removed)) == {("sub-added", "compatible", 0x1003, 4)}


def test_rename_that_changes_the_identifier_is_breaking() -> None:
    change = only(diff_of(set_key(BASE, "1017", "ParameterName", "Heartbeat producer time")))
    assert (change.kind, change.impact, change.index) == (Kind.NAME, Impact.BREAKING, 0x1017)
    assert "producer_heartbeat_time → heartbeat_producer_time" in change.note


def test_rename_that_keeps_the_identifier_is_cosmetic() -> None:
    change = only(diff_of(set_key(BASE, "1017", "ParameterName", "Producer Heartbeat-Time")))
    assert (change.kind, change.impact) == (Kind.NAME, Impact.COSMETIC)


def test_rename_of_a_pinned_entry_is_cosmetic() -> None:
    renamed = set_key(BASE, "2000sub2", "ParameterName", "Debounce time")
    assert only(diff_of(renamed)).impact is Impact.BREAKING
    pins = {"2000sub2": "input_filter_time"}
    change = only(diff_of(renamed, old_pins=pins, new_pins=pins))
    assert (change.kind, change.impact, change.subindex) == (Kind.NAME, Impact.COSMETIC, 2)


def test_identifier_taken_by_a_new_object_is_breaking() -> None:
    """A new object at a lower index takes the name: the old entry's identifier gets a suffix."""
    text = BASE.replace("[1017]", "[1016A]", 0)
    extra = "\n[1010]\nParameterName=Producer heartbeat time\nObjectType=0x7\nDataType=0x0005\nAccessType=rw\n"
    result = diff_of(text + extra)
    assert ("identifier", "breaking", 0x1017, None) in summary(result)
    assert ("object-added", "compatible", 0x1010, None) in summary(result)


@pytest.mark.parametrize(
    ("old", "new", "impact"),
    [
        ("0x0006", "0x0007", Impact.BREAKING),  # UNSIGNED16 → UNSIGNED32: width
        ("0x0006", "0x0003", Impact.BREAKING),  # UNSIGNED16 → INTEGER16: signedness
    ],
)
def test_data_type_change(old: str, new: str, impact: Impact) -> None:
    text = set_key(BASE, "1017", "DataType", new)
    change = only(diff_of(text, set_key(BASE, "1017", "DataType", old)))
    assert (change.kind, change.impact) == (Kind.DATA_TYPE, impact)
    assert change.note in ("width 16 bits → 32 bits", "signedness changed")


def test_data_type_through_an_alias_of_the_same_type_is_cosmetic() -> None:
    alias = "\n[0040]\nParameterName=MyU16\nObjectType=0x5\nDataType=0x0006\nAccessType=ro\n"
    old = BASE + alias
    new = set_key(old, "1017", "DataType", "0x0040")
    kinds = {(c.kind, c.impact) for c in diff_of(new, old).changes()}
    assert kinds == {(Kind.DATA_TYPE, Impact.COSMETIC)}


@pytest.mark.parametrize(
    ("old", "new", "impact"),
    [
        ("rw", "ro", Impact.BREAKING),
        ("rw", "wo", Impact.BREAKING),
        ("ro", "rw", Impact.COMPATIBLE),
        ("ro", "const", Impact.COSMETIC),
        ("rw", "rww", Impact.COSMETIC),
    ],
)
def test_access_narrowed_or_widened(old: str, new: str, impact: Impact) -> None:
    change = only(diff_of(set_key(BASE, "1017", "AccessType", new), set_key(BASE, "1017", "AccessType", old)))
    assert (change.kind, change.impact) == (Kind.ACCESS, impact)


def test_pdo_mapping_flag() -> None:
    change = only(diff_of(set_key(BASE, "1001", "PDOMapping", "0")))
    assert (change.kind, change.impact) == (Kind.PDO_MAPPING, Impact.BREAKING)
    change = only(diff_of(set_key(BASE, "1017", "PDOMapping", "1")))
    assert (change.kind, change.impact) == (Kind.PDO_MAPPING, Impact.COMPATIBLE)


@pytest.mark.parametrize(
    ("access", "key", "value", "impact"),
    [
        # a narrower range breaks a master only where it writes the entry
        ("rw", "LowLimit", "5", Impact.BREAKING),  # 1 → 5: narrowed
        ("wo", "HighLimit", "100", Impact.BREAKING),
        ("ro", "LowLimit", "5", Impact.COMPATIBLE),  # a master only reads it: fewer values still read fine
        ("const", "HighLimit", "100", Impact.COMPATIBLE),
        # a wider range breaks a master only where it reads the entry
        ("rw", "LowLimit", "0", Impact.BREAKING),
        ("ro", "HighLimit", None, Impact.BREAKING),  # no bound: the type's own range
        ("wo", "HighLimit", "65535", Impact.COMPATIBLE),  # a master only writes it: what it wrote still fits
        ("wo", "LowLimit", "0", Impact.COMPATIBLE),
    ],
)
def test_limits(access: str, key: str, value: str | None, impact: Impact) -> None:
    edited = set_key(BASE, "2000sub2", "AccessType", access)
    change = only(diff_of(set_key(edited, "2000sub2", key, value), edited))
    assert change.kind is (Kind.LOW_LIMIT if key == "LowLimit" else Kind.HIGH_LIMIT)
    assert change.impact is impact
    assert change.breaks == ([Breaks.WIRE] if impact is Impact.BREAKING else [])


def test_default_is_a_value_change() -> None:
    change = only(diff_of(set_key(BASE, "1017", "DefaultValue", "500")))
    assert (change.kind, change.impact, change.old, change.new) == (Kind.DEFAULT, Impact.VALUE, 1000, 500)
    assert (change.old_text, change.new_text) == ("1000 ms", "500 ms")  # the producer heartbeat time, decoded


def test_nodeid_form() -> None:
    fixed = set_key(BASE, "1014", "DefaultValue", "0x85")
    change = only(diff_of(fixed, node_id=5))
    assert (change.kind, change.impact) == (Kind.NODEID_FORM, Impact.VALUE)
    assert only(diff_of(fixed)).kind is Kind.DEFAULT  # no node-ID: a formula is not a number
    assert only(diff_of(fixed, node_id=6)).kind is Kind.DEFAULT


def test_obj_flags_and_denotation() -> None:
    assert summary(diff_of(set_key(BASE, "1017", "ObjFlags", "1"))) == {("obj-flags", "value", 0x1017, None)}
    assert summary(diff_of(set_key(BASE, "1017", "Denotation", "heartbeat"))) == {
        ("denotation", "cosmetic", 0x1017, None)
    }


def test_parameter_value_in_a_dcf() -> None:
    dcf = set_key(BASE, "1017", "ParameterValue", "250")
    assert summary(diff_of(dcf)) == {("parameter-value", "value", 0x1017, None)}


def test_object_type_change_is_breaking() -> None:
    change = only(diff_of(set_key(BASE, "1017", "ObjectType", "0x2")))
    assert (change.kind, change.impact) == (Kind.OBJECT_TYPE, Impact.BREAKING)


def test_identity_device_info_and_file_info() -> None:
    result = diff_of(
        set_key(set_key(BASE, "DeviceInfo", "ProductNumber", "0x402"), "DeviceInfo", "RevisionNumber", "0x20000")
    )
    assert summary(result) == {("identity", "breaking", None, None), ("identity", "value", None, None)}
    assert summary(diff_of(set_key(BASE, "DeviceInfo", "ProductName", "Other"))) == {
        ("device-info", "cosmetic", None, None)
    }
    assert summary(diff_of(set_key(BASE, "FileInfo", "FileVersion", "2"))) == {("file-info", "cosmetic", None, None)}
    assert summary(diff_of(set_key(BASE, "DeviceInfo", "NrOfTXPDO", "1"))) == {("device-info", "breaking", None, None)}
    assert summary(diff_of(set_key(BASE, "DeviceInfo", "LSS_Supported", "0"))) == {
        ("device-info", "breaking", None, None)
    }


def test_baud_rates_and_dummy_usage() -> None:
    dropped = set_key(BASE, "DeviceInfo", "BaudRate_20", "0")
    change = only(diff_of(dropped))
    assert (change.kind, change.impact, change.field) == (Kind.BAUD_RATE, Impact.BREAKING, "device_info.baud_rates.20")
    assert only(diff_of(BASE, dropped)).impact is Impact.COMPATIBLE
    change = only(diff_of(set_key(BASE, "DummyUsage", "Dummy0005", "0")))
    assert (change.kind, change.impact) == (Kind.DUMMY_USAGE, Impact.BREAKING)


def test_comments_are_cosmetic() -> None:
    change = only(diff_of(set_key(BASE, "Comments", "Line1", "Another first line")))
    assert (change.kind, change.impact) == (Kind.COMMENT, Impact.COSMETIC)
    commented = BASE.replace("[1017]\n", "[1017]\n; the heartbeat\n", 1)
    assert summary(diff_of(commented)) == {("comment", "cosmetic", 0x1017, None)}


def test_pdo_layout_change_is_shown_as_a_pdo() -> None:
    moved = set_key(set_key(BASE, "1A00sub2", "DefaultValue", "0x64010210"), "1A00sub3", "DefaultValue", "0x64010110")
    result = diff_of(moved)
    assert not result.objects, "mapping values are shown with the PDO, not again as object values"
    (pdo,) = result.pdos
    assert pdo.name == "TPDO1"
    (change,) = pdo.changes
    assert (change.kind, change.impact, change.index) == (Kind.PDO_LAYOUT, Impact.BREAKING, 0x1A00)
    assert pdo.before is not None and pdo.after is not None
    assert [(e.index, e.subindex) for e in pdo.before.entries] == [(0x6000, 1), (0x6401, 1), (0x6401, 2)]
    assert [(e.index, e.subindex) for e in pdo.after.entries] == [(0x6000, 1), (0x6401, 2), (0x6401, 1)]


def test_pdo_cob_id_and_transmission_type() -> None:
    text = set_key(BASE, "1800sub1", "DefaultValue", "$NODEID+0x190")
    text = set_key(text, "1800sub2", "DefaultValue", "1")
    (pdo,) = diff_of(text).pdos
    kinds = {(c.kind, c.impact) for c in pdo.changes}
    # 255 → 1: sent on every SYNC instead of on change, which a master without SYNC never receives
    assert kinds == {(Kind.PDO_COB_ID, Impact.BREAKING), (Kind.PDO_TRANSMISSION_TYPE, Impact.BREAKING)}


def test_pdo_removed_is_breaking() -> None:
    text = set_key(drop_section(drop_section(BASE, "1A01"), "1801"), "DeviceInfo", "NrOfTXPDO", "1")
    for sub in range(4):
        text = drop_section(text, f"1A01sub{sub}")
    for section in re.findall(r"^\[(1801sub\d)\]", BASE, re.MULTILINE):
        text = drop_section(text, section)
    result = diff_of(text)
    assert [(p.name, [c.kind for c in p.changes]) for p in result.pdos] == [("TPDO2", [Kind.PDO_REMOVED])]
    assert {("object-removed", "breaking", 0x1801, None), ("object-removed", "breaking", 0x1A01, None)} <= summary(
        result
    )


def test_diff_against_canonical_and_json_forms_is_empty() -> None:
    original = device()
    for fmt in ("eds", "json"):
        again = loads(dumps(original, fmt, style="canonical"))
        assert compare(original, again).empty, fmt


def test_counts_and_flags() -> None:
    result = diff_of(set_key(drop_section(BASE, "1017"), "2000sub2", "DefaultValue", "20"))
    assert result.counts() == {Impact.BREAKING: 1, Impact.COMPATIBLE: 0, Impact.VALUE: 1, Impact.COSMETIC: 0}
    assert result.breaking and not result.empty


def test_an_eds_against_the_dcf_made_from_it() -> None:
    """`convert` to a DCF states the node-ID and the values `$NODEID` defaults take: the same configuration."""
    eds = device()
    eds_for_node = loads(BASE, node_id=5)
    dcf = loads(dumps(eds_for_node, "dcf"))
    assert any(obj.subs.get(1) and obj.subs[1].parameter_value == 0x185 for obj in dcf.objects.values())
    result = compare(eds, dcf)
    assert summary(result) == {("commissioning", "value", None, None)}
    change = only(result)
    assert (change.field, change.old, change.new) == ("commissioning.node_id", None, 5)
    configured = set_key(BASE, "1017", "ParameterValue", "250")  # a configured value that differs does count
    assert summary(compare(device(configured), dcf)) >= {("parameter-value", "value", 0x1017, None)}


def test_python_api_takes_paths_and_pin_files(tmp_path: Path) -> None:
    import cantools_od

    old, new, pins = tmp_path / "old.eds", tmp_path / "new.json", tmp_path / "pins.toml"
    old.write_text(BASE)
    new.write_bytes(dumps(device(set_key(BASE, "1017", "ParameterName", "Heartbeat")), "json"))
    result = cantools_od.diff(old, new)
    assert only(result).impact is Impact.BREAKING
    pins.write_text('[identifiers]\n"1017" = "producer_heartbeat_time"\n')
    assert only(cantools_od.diff(old, new, old_pins=pins, new_pins=pins)).impact is Impact.COSMETIC
    assert cantools_od.diff(device(), old).empty  # a Device and a path mix


# TPDO1's entries as layout notes name them
DI = "0x6000:01 read_input_8_bit_digital_inputs_1_to_8"
AI1, AI2, AI3 = (f"0x6401:0{n} read_analog_input_16_bit_analog_input_{n}" for n in (1, 2, 3))


def _layout_note(edited: str) -> str:
    result = diff_of(edited)
    notes = [c.note for c in result.changes() if c.kind is Kind.PDO_LAYOUT]
    assert len(notes) == 1, [(c.kind.value, c.index, c.subindex) for c in result.changes()]
    return notes[0]


@pytest.mark.parametrize(
    ("edits", "note"),
    [
        # TPDO1 maps 0x6000:01 (8 bits), 0x6401:01 (16), 0x6401:02 (16): 5 bytes
        (
            {"1A00sub0": "2"},
            "trailing entry dropped: " + AI2 + "; length 5 bytes → 3 bytes",
        ),
        (
            {"1A00sub3": "0x64010310"},
            "source at bits 24-39: " + AI2 + " → " + AI3,
        ),
        (
            {"1A00sub2": "0x64010210", "1A00sub3": "0x64010110"},
            "reordered: 2 of 3 entries at other bits",
        ),
        (
            {"1A00sub1": "0x60000110", "1A00sub0": "1"},
            "resized " + DI + ": 8 → 16 bits; removed " + AI1 + ", " + AI2 + "; length 5 bytes → 2 bytes",
        ),
    ],
)
def test_pdo_layout_notes(edits: dict[str, str], note: str) -> None:
    edited = BASE
    for section, value in edits.items():
        edited = set_key(edited, section, "DefaultValue", value)
    assert _layout_note(edited) == note


def test_pdo_layout_appended() -> None:
    edited = set_key(BASE, "1A00sub0", "DefaultValue", "4")
    edited = edited.replace(
        "[1A01]\n",
        "[1A00sub4]\nParameterName=Mapped object 4\nObjectType=0x7\nDataType=0x0007\n"
        "AccessType=rw\nDefaultValue=0x64010310\nPDOMapping=0\n\n[1A01]\n",
        1,
    )
    edited = set_key(edited, "1A00", "SubNumber", "5")
    assert _layout_note(edited) == "appended " + AI3 + "; length 5 bytes → 7 bytes"


def test_pdo_timing_is_with_the_pdo() -> None:
    result = diff_of(set_key(set_key(BASE, "1800sub5", "DefaultValue", "500"), "1800sub3", "DefaultValue", "50"))
    assert not result.objects  # shown with the PDO, not again under 0x1800
    (pdo,) = result.pdos
    shown = {(c.kind, c.index, c.subindex, c.old_text, c.new_text, c.impact, c.note) for c in pdo.changes}
    assert shown == {  # TPDO1 is event-driven: both change its traffic
        (
            Kind.PDO_TIMING,
            0x1800,
            3,
            "100 (10 ms)",
            "50 (5 ms)",
            Impact.BREAKING,
            "now at most every 5 ms instead of every 10 ms",
        ),
        (Kind.PDO_TIMING, 0x1800, 5, "1000 ms", "500 ms", Impact.BREAKING, "now every 500 ms instead of every 1000 ms"),
    }
    assert pdo.after is not None and pdo.after.timing == {3: 50, 5: 500}


@pytest.mark.parametrize(
    ("section", "value", "old_text", "new_text", "impact"),
    [
        (
            "1005",
            "0x40000080",
            "0x80 (consumes SYNC, CAN-ID 080h)",
            "0x40000080 (produces SYNC, CAN-ID 080h)",
            Impact.BREAKING,
        ),
        ("1016sub1", "0x000505DC", "0 (off)", "0x505DC (329180) (node 5, 1500 ms)", Impact.VALUE),
        (
            "1014",
            "0x80000081",
            "$NODEID+0x80 (CAN-ID node-ID + 080h)",
            "0x80000081 (not valid, CAN-ID 081h)",
            Impact.BREAKING,
        ),
        ("1800sub1", "0xC0000181", "", "", Impact.BREAKING),  # a PDO's COB-ID: with the PDO
    ],
)
def test_values_are_decoded_where_cia301_defines_the_bits(
    section: str, value: str, old_text: str, new_text: str, impact: Impact
) -> None:
    change = only(diff_of(set_key(BASE, section, "DefaultValue", value)))
    assert change.impact is impact
    if old_text:
        assert (change.old_text, change.new_text) == (old_text, new_text)
    else:
        assert change.kind is Kind.PDO_COB_ID
        assert change.new_text == "0xC0000181 (not valid, no RTR, CAN-ID 181h)"
        assert change.old_text == "$NODEID+0x180 (CAN-ID node-ID + 180h)"
    assert change.breaks == ([Breaks.WIRE] if impact is Impact.BREAKING else [])


def test_device_type_and_identity_break_the_bus() -> None:
    for section in ("1000", "1018sub1", "1018sub2"):
        change = only(diff_of(set_key(BASE, section, "DefaultValue", "0x12345")))
        assert (change.impact, change.breaks) == (Impact.BREAKING, [Breaks.WIRE]), section
    assert only(diff_of(set_key(BASE, "1018sub3", "DefaultValue", "0x12345"))).impact is Impact.VALUE


def test_storage_group_is_one_change_for_code() -> None:
    """`;StorageLocation=` is the storage group: one change, breaking generated code, not again as a comment."""

    def stored(group: str) -> str:
        return BASE.replace(
            "[2000]\nParameterName=Device settings\n",
            f"[2000]\nParameterName=Device settings\n;StorageLocation={group}\n",
            1,
        )

    change = only(diff_of(stored("PERSIST_COMM"), stored("RAM")))
    assert (change.kind, change.field, change.impact, change.breaks) == (
        Kind.CANOPENNODE,
        "canopennode.storage_group",
        Impact.BREAKING,
        [Breaks.CODE],
    )


def test_an_object_moved_to_another_index_is_one_change() -> None:
    moved = BASE.replace("[2000", "[2001").replace("=0x2000\n", "=0x2001\n").replace("0x20000320", "0x20010320")
    result = diff_of(moved)
    (obj,) = result.objects
    change = only(result.model_copy(update={"pdos": []}))
    assert (obj.index, change.kind, change.old, change.new) == (0x2001, Kind.OBJECT_MOVED, 0x2000, 0x2001)
    assert change.breaks == [Breaks.WIRE, Breaks.CODE]
    assert "moved from 0x2000 to 0x2001" in describe.sentence(change)
    back = diff_of(BASE, moved)
    assert [c.kind for c in back.objects[0].changes] == [Kind.OBJECT_MOVED]


def test_an_object_added_disabled_says_so() -> None:
    from cantools_od.model import CanopenNodeInfo

    new = device()
    new.objects[0x2000].canopennode = CanopenNodeInfo(disabled=True)
    old = device()
    del old.objects[0x2000]
    change = only(compare(old, new).model_copy(update={"pdos": []}))
    assert change.kind is Kind.OBJECT_ADDED and "disabled (CO_disabled" in change.new_text


@pytest.mark.parametrize(
    ("source", "title"),
    [
        ("HEAD~1:od/device.eds", "HEAD~1:device.eds"),  # --git REV1 REV2 PATH
        ("v1.2.0:firmware/od/drive.xdd", "v1.2.0:drive.xdd"),
        ("/dev/null", "/dev/null"),  # a new or deleted file in git
        ("a/od/device.eds", "device.eds"),  # git's external diff driver
        ("../old/device.eds", "device.eds"),
    ],
)
def test_markdown_title_names_revisions(source: str, title: str) -> None:
    from cantools_od.changes.markdown import side_name

    assert side_name(source) == title
