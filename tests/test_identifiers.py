"""Identifier rules shared by every generator: cantools_od.identifiers."""

from __future__ import annotations

import keyword
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from hypothesis import given, settings
from hypothesis import strategies as st

from cantools_od.identifiers import RESERVED, Identifiers, assign, is_identifier, load_pins, snake_case
from cantools_od.model import Device, Object, ObjectKind, SubObject

from support import corpus_devices

CORPUS = Path(__file__).resolve().parents[2] / "shared" / "eds-corpus" / "eds"
EXAMPLE = Path(__file__).resolve().parents[1] / "eds" / "cia402_drive.eds"
SHAPE = re.compile(r"^[a-z][a-z0-9_]*$")


def valid(name: str) -> bool:
    """Usable as is in C, C++, Rust and Python."""
    return (
        SHAPE.match(name) is not None
        and "__" not in name
        and name.isidentifier()
        and not keyword.iskeyword(name)
        and not keyword.issoftkeyword(name)
        and name not in RESERVED
    )


def var(index: int, name: str) -> Object:
    return Object(index=index, name=name)


def record(index: int, name: str, subs: dict[int, str], kind: ObjectKind = ObjectKind.RECORD) -> Object:
    return Object(index=index, name=name, object_type=kind, subs={s: SubObject(name=n) for s, n in subs.items()})


def device(*objects: Object) -> Device:
    return Device(objects={obj.index: obj for obj in objects})


def all_names(device: Device, ids: Identifiers) -> tuple[list[str], list[str], dict[int, list[str]]]:
    """Object identifiers, flat identifiers of entries that are not VARs, members per object."""
    objects = [ids.object(index) for index in device.objects]
    flats = [ids.flat(i, s) for i, obj in device.objects.items() if obj.has_subs for s in obj.subs]
    members = {i: [ids.member(i, s) for s in obj.subs] for i, obj in device.objects.items() if obj.has_subs}
    return objects, flats, members


def assert_unique(device: Device, ids: Identifiers) -> None:
    objects, flats, members = all_names(device, ids)
    everything = objects + flats  # VARs are in `objects` only: their flat is their object identifier
    assert len(set(everything)) == len(everything)
    for names in members.values():
        assert len(set(names)) == len(names)
    for name in everything + [m for names in members.values() for m in names]:
        assert valid(name), name
    for index, obj in device.objects.items():
        if not obj.has_subs:
            assert ids.flat(index, 0) == ids.object(index)


# --- snake_case --------------------------------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("Identity object", "identity_object"),
        ("Vendor-ID", "vendor_id"),
        ("Highest sub-index supported", "highest_sub_index_supported"),
        ("COB-ID used by RPDO", "cob_id_used_by_rpdo"),
        ("TPDO1 mapping", "tpdo1_mapping"),
        ("Motor #1; left", "motor_1_left"),
        ("SDO server parameter", "sdo_server_parameter"),
        ("ControlWord", "control_word"),
        ("controlWord", "control_word"),
        ("HTTPServer", "http_server"),
        ("ABC123def", "abc123_def"),
        ("ABC123Def", "abc123_def"),
        ("Func.InOutIO.G1OffsetX0", "func_in_out_io_g1_offset_x0"),
        ("Number of PDOs", "number_of_pdos"),
        ("CANopen NodeID", "canopen_node_id"),
        ("CanOpen baud rate", "canopen_baud_rate"),
        ("1st mapped object", "n_1st_mapped_object"),
        ("Digital In (16b)", "digital_in_16b"),
        ("  __Spaced__  out__ ", "spaced_out"),
        ("SDO COB-ID Client->Server", "sdo_cob_id_client_server"),
        ("Snake_case_already", "snake_case_already"),
    ],
)
def test_snake_case_examples(name: str, expected: str) -> None:
    assert snake_case(name) == expected


@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("Current µA", "current_u_a"),
        ("Current μs", "current_us"),
        ("Temperature °C", "temperature_deg_c"),
        ("Load %", "load_percent"),
        ("Load 10%", "load_10_percent"),
        ("Error rate ‰", "error_rate_permille"),
        ("Area m²", "area_m2"),
        ("Straße", "strasse"),
        ("Drehmomentübersetzung", "drehmomentubersetzung"),
        ("Résistance Ω", "resistance_ohm"),
        ("Vitesse réelle", "vitesse_reelle"),
        ("½ step", "n_1_2_step"),
        ("Kraft 电机 Wert", "kraft_wert"),
    ],
)
def test_snake_case_folds_to_ascii(name: str, expected: str) -> None:
    assert snake_case(name) == expected


@pytest.mark.parametrize("word", ["type", "match", "case", "self", "crate", "async", "try", "abstract", "final"])
def test_keywords_get_a_trailing_underscore(word: str) -> None:
    assert snake_case(word) == word + "_"
    assert snake_case(word.upper()) == word + "_"


LANGUAGES = {
    "c": "auto break char const double enum extern goto int long register restrict signed sizeof static struct "
    "switch typedef union unsigned void volatile while inline alignas alignof bool constexpr false nullptr "
    "static_assert thread_local true typeof typeof_unqual",
    "c library": "errno assert stdin stdout stderr offsetof complex noreturn main uint8_t int32_t size_t",
    "c++": "and and_eq asm bitand bitor catch char8_t char16_t char32_t class compl concept consteval constinit "
    "const_cast co_await co_return co_yield decltype delete dynamic_cast explicit export friend mutable namespace "
    "new noexcept not not_eq operator or or_eq private protected public reinterpret_cast requires static_cast "
    "template this throw try typeid typename using virtual wchar_t xor xor_eq final override import module",
    "rust": "as crate fn impl in let loop match mod move mut pub ref self super trait type unsafe use where async "
    "await dyn abstract become box do macro priv unsized yield gen union u8 i64 usize f32 str",
    "python": " ".join(keyword.kwlist + keyword.softkwlist) + " str int bool float bytes object list dict",
}


@pytest.mark.parametrize("language", sorted(LANGUAGES))
def test_reserved_words_of_every_language(language: str) -> None:
    for word in LANGUAGES[language].split():
        assert word in RESERVED, word
        result = snake_case(word)
        assert valid(result), (word, result)
        if word.islower() and word.isalnum():
            assert result == word + "_"


def test_reserved_uppercase_words_are_listed() -> None:
    for word in ("Self", "None", "True", "False", "NULL", "EOF", "_Bool", "_Static_assert"):
        assert word in RESERVED
    assert snake_case("_Bool") == "bool_"
    assert snake_case("None") == "none"  # only `None` itself is reserved; identifiers are lower-case


def test_leading_digit_gets_a_prefix() -> None:
    assert snake_case("1st value") == "n_1st_value"
    assert snake_case("2") == "n_2"
    assert snake_case("16-bit counter") == "n_16_bit_counter"


@pytest.mark.parametrize("name", ["", "????", "---", "   ", "__", "电机"])
def test_symbol_only_names_fall_back(name: str) -> None:
    assert snake_case(name) == "unnamed"
    assert snake_case(name, "object_1a00") == "object_1a00"
    ids = assign(device(var(0x1A00, name), record(0x2000, name, {0: name, 0x1F: name})))
    assert ids.object(0x1A00) == "object_1a00"
    assert ids.object(0x2000) == "object_2000"
    assert ids.member(0x2000, 0) == "sub_0"
    assert ids.member(0x2000, 0x1F) == "sub_1f"
    assert ids.flat(0x2000, 0x1F) == "object_2000_sub_1f"


@settings(max_examples=300, deadline=None)
@given(st.text())
def test_snake_case_is_always_an_identifier(name: str) -> None:
    result = snake_case(name)
    assert valid(result)
    assert result == snake_case(result)  # idempotent on its own output


# --- assign -------------------------------------------------------------------------------------------------------


def identity() -> Object:
    return record(0x1018, "Identity object", {0: "Highest sub-index supported", 1: "Vendor-ID", 2: "Product code"})


def test_members_and_flats() -> None:
    dev = device(var(0x1000, "Device type"), identity())
    ids = assign(dev)
    assert ids.object(0x1000) == "device_type"
    assert ids.flat(0x1000, 0) == "device_type"
    assert ids.object(0x1018) == "identity_object"
    assert ids.member(0x1018, 0) == "highest_sub_index_supported"
    assert ids.member(0x1018, 1) == "vendor_id"
    assert ids.flat(0x1018, 1) == "identity_object_vendor_id"
    assert_unique(dev, ids)
    with pytest.raises(KeyError):
        ids.member(0x1000, 0)
    with pytest.raises(KeyError):
        ids.object(0x1234)


def test_array_collisions_are_suffixed_with_the_subindex() -> None:
    subs = {0: "Number of errors"} | {s: "Standard error field" for s in range(1, 9)}
    dev = device(record(0x1003, "Pre-defined error field", subs, ObjectKind.ARRAY))
    ids = assign(dev)
    assert ids.member(0x1003, 0) == "number_of_errors"
    assert ids.member(0x1003, 1) == "standard_error_field"
    assert [ids.member(0x1003, s) for s in range(2, 9)] == [f"standard_error_field_{s}" for s in range(2, 9)]
    assert ids.flat(0x1003, 8) == "pre_defined_error_field_standard_error_field_8"
    assert_unique(dev, ids)


def test_subindex_suffix_is_decimal_and_loops_when_taken() -> None:
    dev = device(record(0x2000, "Table", {1: "Entry", 2: "Entry 11", 11: "Entry", 12: "Entry 11"}))
    ids = assign(dev)
    assert [ids.member(0x2000, s) for s in (1, 2, 11, 12)] == ["entry", "entry_11", "entry_11_2", "entry_11_12"]
    assert_unique(dev, ids)


def test_object_collisions_are_suffixed_with_the_hex_index() -> None:
    dev = device(var(0x6401, "Analog input"), var(0x6402, "Analog input"), var(0x6A00, "Analog input 6402"))
    ids = assign(dev)
    assert [ids.object(i) for i in (0x6401, 0x6402, 0x6A00)] == [
        "analog_input",
        "analog_input_6402",
        "analog_input_6402_6a00",
    ]
    assert_unique(dev, ids)


def test_flat_names_do_not_collide_with_vars() -> None:
    # "Motor" + "Speed" and the VAR "Motor speed" would both be motor_speed.
    dev = device(record(0x2000, "Motor", {1: "Speed"}), var(0x2001, "Motor speed"), record(0x2002, "Motor", {1: "x"}))
    ids = assign(dev)
    assert ids.flat(0x2000, 1) == "motor_speed"
    assert ids.object(0x2001) == "motor_speed_2001"
    assert ids.object(0x2002) == "motor_2002"
    dev = device(var(0x2000, "Motor speed"), record(0x2001, "Motor", {1: "Speed"}))
    ids = assign(dev)
    assert ids.object(0x2000) == "motor_speed"
    assert ids.flat(0x2001, 1) == "motor_speed_2001"
    assert_unique(dev, ids)


def test_composed_names_are_checked_for_keywords() -> None:
    dev = device(record(0x2000, "co", {1: "await"}), record(0x2001, "Type", {1: "Value", 2: "type"}))
    ids = assign(dev)
    assert ids.flat(0x2000, 1) == "co_await_"
    assert ids.object(0x2001) == "type_"
    assert ids.flat(0x2001, 1) == "type_value"
    assert ids.flat(0x2001, 2) == "type_type_"
    assert_unique(dev, ids)


def test_stability_when_objects_are_added_at_higher_indices() -> None:
    base = [
        var(0x2000, "Speed"),
        record(0x2100, "Channel", {0: "Count", 1: "Speed", 2: "Speed"}),
        var(0x2200, "Channel speed"),
    ]
    before = assign(device(*base))
    added = [var(0x3000, "Speed"), var(0x3001, "Channel"), var(0x3002, "Channel speed"), identity()]
    after = assign(device(*base, *added))
    for obj in base:
        assert after.object(obj.index) == before.object(obj.index)
        for sub in obj.subs:
            assert after.member(obj.index, sub) == before.member(obj.index, sub)
            assert after.flat(obj.index, sub) == before.flat(obj.index, sub)
    assert after.object(0x3000) == "speed_3000"


@settings(max_examples=150, deadline=None)
@given(
    st.dictionaries(
        st.integers(0x1000, 0x1040),
        st.tuples(
            st.sampled_from(["", "Speed", "Motor", "Motor speed", "type", "1st", "co", "await", "x 1", "x"])
            | st.text(max_size=12),
            st.none() | st.dictionaries(st.integers(0, 20), st.sampled_from(["Speed", "", "x", "await", "x_1", "1"])),
        ),
        max_size=30,
    )
)
def test_assign_gives_unique_valid_identifiers(spec: dict[int, tuple[str, dict[int, str] | None]]) -> None:
    objects = [var(i, name) if subs is None else record(i, name, subs) for i, (name, subs) in spec.items()]
    dev = device(*objects)
    assert_unique(dev, assign(dev))


# --- pins ---------------------------------------------------------------------------------------------------------


def test_pins_replace_generated_names() -> None:
    dev = device(var(0x1000, "Device type"), identity())
    ids = assign(dev, {"1000": "kind", "1018SUB1": "vendor", "1018": "ident"})
    assert ids.object(0x1000) == "kind"
    assert ids.object(0x1018) == "ident"
    assert ids.member(0x1018, 1) == "vendor"
    assert ids.flat(0x1018, 1) == "ident_vendor"
    assert ids.flat(0x1018, 2) == "ident_product_code"


def test_pins_take_precedence_in_collisions() -> None:
    dev = device(var(0x2000, "Speed"), var(0x2001, "Velocity"), record(0x2100, "Set", {1: "A", 2: "B"}))
    ids = assign(dev, {"2001": "speed", "2100sub2": "a"})
    assert ids.object(0x2001) == "speed"
    assert ids.object(0x2000) == "speed_2000"
    assert ids.member(0x2100, 2) == "a"
    assert ids.member(0x2100, 1) == "a_1"


def test_pins_for_missing_entries_are_ignored() -> None:
    ids = assign(device(var(0x2000, "Speed")), {"3000": "gone", "2000sub1": "nothing"})
    assert ids.object(0x2000) == "speed"


@pytest.mark.parametrize(
    ("pins", "message"),
    [
        ({"2000": "type"}, "'2000'"),
        ({"2000": "Speed"}, "'2000'"),
        ({"2000": "1st"}, "'2000'"),
        ({"2000": "_speed"}, "'2000'"),
        ({"2000": "my__speed"}, "'2000'"),
        ({"2000": ""}, "'2000'"),
        ({"2000sub1": "a-b"}, "'2000sub1'"),
        ({"20000": "speed"}, "'20000'"),
        ({"2000sub": "speed"}, "'2000sub'"),
        ({"x": "speed"}, "'x'"),
        ({"2000": "speed", "2001": "speed"}, "'2001'"),
        ({"2000sub1": "b", "2000SUB01": "c"}, "'2000SUB01'"),
    ],
)
def test_invalid_pins_raise(pins: dict[str, str], message: str) -> None:
    with pytest.raises(ValueError, match=message):
        assign(device(var(0x2000, "Speed"), var(0x2001, "Other")), pins)


def test_pin_table_round_trip(tmp_path: Path) -> None:
    subs = {0: "Number of errors"} | {s: "Standard error field" for s in range(1, 4)}
    dev = device(var(0x1000, "Device type"), identity(), record(0x1003, "Errors", subs, ObjectKind.ARRAY))
    ids = assign(dev)
    text = ids.to_toml()
    lines = text.splitlines()
    assert "[identifiers]" in lines
    assert '"1018" = "identity_object"' in lines
    assert '"1018sub1" = "vendor_id"' in lines
    assert '"1003sub3" = "standard_error_field_3"' in lines
    keys = [line.split('"')[1] for line in lines if line.startswith('"')]
    assert keys == ["1000", "1003", "1003sub0", "1003sub1", "1003sub2", "1003sub3", "1018"] + [
        f"1018sub{s}" for s in range(3)
    ]
    path = tmp_path / "ids.toml"
    path.write_text(text)
    pins = load_pins(path)
    assert len(pins) == len(keys)
    # Renamed display names keep their identifiers once pinned.
    renamed = device(var(0x1000, "Kind of device"), identity(), record(0x1003, "Errors", subs, ObjectKind.ARRAY))
    assert assign(renamed, pins).to_toml() == text


@pytest.mark.parametrize(
    ("content", "message"),
    [
        ("[identifiers\n", "not a TOML file"),
        ('[other]\n"2000" = "x"\n', "no \\[identifiers\\] table"),
        ('identifiers = "x"\n', "no \\[identifiers\\] table"),
        ('[identifiers]\n"2000" = 3\n', "must be a string"),
        ('[identifiers]\n"zz" = "x"\n', "'zz'"),
        ('[identifiers]\n"2000" = "Type"\n', "'2000'"),
    ],
)
def test_load_pins_rejects_malformed_files(tmp_path: Path, content: str, message: str) -> None:
    path = tmp_path / "pins.toml"
    path.write_text(content)
    with pytest.raises(ValueError, match=message):
        load_pins(path)


def test_is_identifier() -> None:
    assert is_identifier("type_")
    assert is_identifier("a1_b2")
    for name in ("type", "_a", "a__b", "A", "1a", "", "a-b", "aé"):
        assert not is_identifier(name)


# --- whole files --------------------------------------------------------------------------------------------------


@pytest.mark.parametrize("path", corpus_devices() or [None], ids=lambda p: p.name if p else "no-corpus")
def test_corpus_identifiers_are_unique(path: Path | None) -> None:
    if path is None:
        pytest.skip(f"no corpus at {CORPUS}")
    from cantools_od import load

    dev = load(str(path))
    ids = assign(dev)
    assert_unique(dev, ids)
    assert assign(dev, dict(ids.items())).to_toml() == ids.to_toml()  # a full pin table changes nothing


def test_cli_prints_the_pin_table(tmp_path: Path) -> None:
    from cantools_od.cli.ids import command

    runner = CliRunner()
    result = runner.invoke(command, [str(EXAMPLE)])
    assert result.exit_code == 0, result.output
    assert '"1018sub1" = "vendor_id"' in result.output
    pins = tmp_path / "pins.toml"
    pins.write_text('[identifiers]\n"1018" = "ident"\n')
    result = runner.invoke(command, [str(EXAMPLE), "--pins", str(pins)])
    assert result.exit_code == 0
    assert '"1018" = "ident"' in result.output
    pins.write_text('[identifiers]\n"1018" = "match"\n')
    result = runner.invoke(command, [str(EXAMPLE), "--pins", str(pins)])
    assert result.exit_code == 2
    assert "'1018'" in result.output


def test_large_device_gets_unique_identifiers() -> None:
    """5,000 objects with colliding names: every identifier unique (its speed is measured in bench/)."""
    objects = {}
    for k in range(5000):
        index = 0x2000 + k
        if k % 5 == 0:
            objects[index] = var(index, f"Parameter value {k}")
        else:
            names = {
                s: "Highest sub-index supported" if s == 0 else f"Setting {s % 4} of channel {k}" for s in range(8)
            }
            objects[index] = record(index, f"Motor channel {k % 50} settings", names)
    dev = Device(objects=objects)
    ids = assign(dev)
    assert len(set(ids.flat(i, s) for i, o in objects.items() for s in (o.subs or {0: None}))) == 1000 + 4000 * 8
