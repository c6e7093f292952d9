"""The generated C API beyond pack/unpack: constants, NAME_init, the object table, range checks,
error codes, and use from C++ (linked against the C object)."""

from __future__ import annotations

from pathlib import Path

from ckit import C_FLAGS, CXX_FLAGS, EXAMPLES, generate, run, tool, write, write_odd_eds

ODD_CHECKS = r"""
#include <string.h>
#include "odd_bits.h"

#define CHECK(condition) \
    do { if (!(condition)) { printf("FAILED line %d: %s\n", __LINE__, #condition); failed = 1; } } while (0)

int main(void)
{
    static const uint16_t unicode[] = {0x0041u, 0x00E9u, 0x20ACu};
    volatile float zero = 0.0f;
    struct odd_bits_od od;
    struct odd_bits_tpdo5 tpdo5;
    uint8_t frame[64];
    size_t i;
    int failed = 0;

    /* constants */
    CHECK(ODD_BITS_INT64_VALUE_DEFAULT == INT64_MIN);
    CHECK(ODD_BITS_UNS64_VALUE_DEFAULT == UINT64_MAX);
    CHECK(ODD_BITS_INT32_VALUE_DEFAULT == INT32_MIN && ODD_BITS_INT32_VALUE_LOW_LIMIT == INT32_MIN);
    CHECK(ODD_BITS_INT16_VALUE_DEFAULT == INT16_MIN && ODD_BITS_INT8_VALUE_DEFAULT == INT8_MIN);
    CHECK(ODD_BITS_INT48_VALUE_DEFAULT == -140737488355328ll);
    CHECK(ODD_BITS_UNS56_VALUE_DEFAULT == 0xFFFFFFFFFFFFFFull && ODD_BITS_UNS40_VALUE_DEFAULT == 0x123456789Aull);
    CHECK(ODD_BITS_REAL32_VALUE_DEFAULT == 1.5f && ODD_BITS_REAL32_VALUE_LOW_LIMIT == -2.5f);
    CHECK(ODD_BITS_REAL64_VALUE_DEFAULT == -0.1 && ODD_BITS_HUGE_REAL64_DEFAULT == 1e300);
    CHECK(ODD_BITS_FLAG_A_DEFAULT == true && ODD_BITS_FLAG_B_DEFAULT == false);
    CHECK(ODD_BITS_UNS32_VALUE_DEFAULT(7) == 0x47u);
    CHECK(ODD_BITS_TPDO1_COB_ID(3) == 0x183u && ODD_BITS_RPDO5_COB_ID == 0x80000485u);
    CHECK(ODD_BITS_OCTETS_LENGTH == 3u && memcmp(ODD_BITS_OCTETS_DEFAULT, "\x00\xff\x10", 3) == 0);
    CHECK(ODD_BITS_UNICODE_TEXT_LENGTH == 3u);
    CHECK(ODD_BITS_TPDO1_DLC == 8u && ODD_BITS_RPDO5_DLC == 30u && ODD_BITS_PDO_MAX_DLC == 64u);
    CHECK(ODD_BITS_FLAG_A_PDO_MAPPABLE == 1 && ODD_BITS_OCTETS_PDO_MAPPABLE == 0);
    CHECK(ODD_BITS_FLAG_A_ACCESS == ODD_BITS_ACCESS_RW && (ODD_BITS_DEVICE_TYPE_ACCESS & ODD_BITS_ACCESS_WRITE) == 0);
    CHECK(ODD_BITS_INT24_VALUE_DATA_TYPE == 0x0010u && ODD_BITS_TX_MAP_1_ENTRY_2_SUBINDEX == 2u);

    /* defaults */
    memset(&od, 0xA5, sizeof od);
    odd_bits_init(&od, 9);
    CHECK(od.int24_value == -5 && od.int48_value == ODD_BITS_INT48_VALUE_DEFAULT && od.uns24_value == 0xABCDEFu);
    CHECK(od.uns32_value == 0x49u && od.tx_comm_2.cob_id == 0x289u && od.real32_value == 1.5f);
    CHECK(od.not_a_number == 0.0f && od.time_of_day == 0u);
    CHECK(memcmp(od.octets, ODD_BITS_OCTETS_DEFAULT, 3) == 0 && memcmp(od.unicode_text, unicode, sizeof unicode) == 0);
    CHECK(sizeof od.name_with_quotes_and_trigraph_x == ODD_BITS_NAME_WITH_QUOTES_AND_TRIGRAPH_X_LENGTH);
    CHECK(memcmp(od.name_with_quotes_and_trigraph_x, "He said \"hi\" */ \\ \?\?=", 21) == 0);
    odd_bits_init(NULL, 1);

    /* the object table: sorted, every stored value where it says */
    for (i = 0u; i < ODD_BITS_OBJECT_COUNT; ++i) {
        const struct odd_bits_object_info *info = &odd_bits_objects[i];
        if (i > 0u) {
            const struct odd_bits_object_info *before = &odd_bits_objects[i - 1u];
            CHECK(before->index < info->index || (before->index == info->index && before->subindex < info->subindex));
        }
        CHECK(info->size == 0u || info->offset + info->size <= sizeof od);
        if (info->index == ODD_BITS_INT48_VALUE_INDEX) {
            CHECK(info->offset == offsetof(struct odd_bits_od, int48_value) && info->size == 8u && info->bits == 48u);
            CHECK(info->data_type == 0x0013u && info->pdo_mappable && info->access == ODD_BITS_ACCESS_RW);
        }
        if (info->index == ODD_BITS_A_DOMAIN_INDEX) {
            CHECK(info->size == 0u && info->bits == 0u);
        }
    }

    /* range checks: type range, LowLimit/HighLimit, limits that exclude everything */
    CHECK(odd_bits_tpdo5_limited_int16_is_in_range(-100) && odd_bits_tpdo5_limited_int16_is_in_range(100));
    CHECK(!odd_bits_tpdo5_limited_int16_is_in_range(-101) && !odd_bits_tpdo5_limited_int16_is_in_range(101));
    CHECK(!odd_bits_tpdo5_limited_uns8_is_in_range(0) && odd_bits_tpdo5_limited_uns8_is_in_range(200));
    CHECK(!odd_bits_tpdo5_limited_uns8_is_in_range(201) && odd_bits_tpdo5_int32_value_is_in_range(INT32_MIN));
    CHECK(!odd_bits_tpdo5_backwards_limits_is_in_range(7));
    CHECK(odd_bits_tpdo2_int24_value_is_in_range(-8388608) && !odd_bits_tpdo2_int24_value_is_in_range(-8388609));
    CHECK(odd_bits_tpdo2_int24_value_is_in_range(8388607) && !odd_bits_tpdo2_int24_value_is_in_range(8388608));
    CHECK(odd_bits_tpdo2_uns40_value_is_in_range(0xFFFFFFFFFFull));
    CHECK(!odd_bits_tpdo2_uns40_value_is_in_range(1ull << 40));
    CHECK(odd_bits_tpdo3_uns24_value_is_in_range(0xFFFFFFu) && !odd_bits_tpdo3_uns24_value_is_in_range(0x1000000u));
    CHECK(odd_bits_tpdo3_real32_value_is_in_range(-2.5f) && !odd_bits_tpdo3_real32_value_is_in_range(100.5f));
    CHECK(!odd_bits_tpdo3_real32_value_is_in_range(zero / zero)); /* NaN */
    CHECK(odd_bits_tpdo1_flag_a_is_in_range(true) && odd_bits_tpdo4_real64_value_is_in_range(-1e308));

    /* error codes; only DLC bytes are written */
    memset(&tpdo5, 0, sizeof tpdo5);
    memset(frame, 0x77, sizeof frame);
    CHECK(odd_bits_tpdo5_pack(frame, &tpdo5, 7u) == ODD_BITS_ESIZE && frame[0] == 0x77u);
    CHECK(odd_bits_tpdo5_pack(NULL, &tpdo5, 8u) == ODD_BITS_EINVAL);
    CHECK(odd_bits_tpdo5_pack(frame, NULL, 8u) == ODD_BITS_EINVAL);
    CHECK(odd_bits_tpdo5_pack(frame, &tpdo5, sizeof frame) == 8 && frame[7] == 0u && frame[8] == 0x77u);
    CHECK(odd_bits_tpdo5_unpack(&tpdo5, frame, 7u) == ODD_BITS_ESIZE);
    CHECK(odd_bits_tpdo5_unpack(&tpdo5, NULL, 8u) == ODD_BITS_EINVAL);
    CHECK(odd_bits_rpdo1_pack(frame, NULL, 8u) == ODD_BITS_EINVAL);
    return failed;
}
"""

ARRAY_CHECKS = r"""
#include "cia402_drive.h"

int main(void)
{
    struct cia402_drive_od od;
    size_t i;
    int found = 0;

    cia402_drive_init(&od, 1);
    if (od.software_position_limit.values[0] != CIA402_DRIVE_SOFTWARE_POSITION_LIMIT_MIN_POSITION_LIMIT_DEFAULT) {
        return 1;
    }
    for (i = 0u; i < CIA402_DRIVE_OBJECT_COUNT; ++i) {
        const struct cia402_drive_object_info *info = &cia402_drive_objects[i];
        if (info->index == 0x607Du && info->subindex == 2u) {
            found = info->offset == offsetof(struct cia402_drive_od, software_position_limit.values[1]);
            found = found && info->size == 4u;
        }
    }
    return found ? 0 : 2;
}
"""

CXX_USER = r"""
#include <cstdio>
#include "odd_bits.h"

int main()
{
    odd_bits_tpdo2 in = {-5, 0x123456789Aull};
    odd_bits_tpdo2 out = {0, 0};
    uint8_t frame[ODD_BITS_PDO_MAX_DLC];
    const int n = odd_bits_tpdo2_pack(frame, &in, sizeof frame);
    if (n != static_cast<int>(ODD_BITS_TPDO2_DLC) || odd_bits_tpdo2_unpack(&out, frame, sizeof frame) != n) {
        return 1;
    }
    std::printf("%d %d\n", out.int24_value, static_cast<int>(ODD_BITS_OBJECT_COUNT > 0u));
    return out.int24_value == in.int24_value && out.uns40_value == in.uns40_value ? 0 : 2;
}
"""


def test_constants_defaults_table_and_range_checks(tmp_path: Path) -> None:
    tool("gcc")
    write(tmp_path, generate(write_odd_eds(tmp_path / "eds"), "odd_bits", can_fd=True))
    (tmp_path / "checks.c").write_text("#include <stdio.h>\n" + ODD_CHECKS, encoding="utf-8")
    built = run(["gcc", *C_FLAGS, "-Wno-overlength-strings", "-o", "checks", "checks.c", "odd_bits.c"], tmp_path)
    assert built.returncode == 0, built.stderr
    result = run([str(tmp_path / "checks")], tmp_path)
    assert result.returncode == 0, result.stdout


def test_arrays_are_arrays(tmp_path: Path) -> None:
    tool("gcc")
    write(tmp_path, generate(EXAMPLES / "cia402_drive.eds", "cia402_drive"))
    (tmp_path / "checks.c").write_text(ARRAY_CHECKS, encoding="utf-8")
    built = run(["gcc", *C_FLAGS, "-o", "checks", "checks.c", "cia402_drive.c"], tmp_path)
    assert built.returncode == 0, built.stderr
    assert run([str(tmp_path / "checks")], tmp_path).returncode == 0


def test_cxx_program_links_against_the_c_code(tmp_path: Path) -> None:
    tool("gcc")
    tool("g++")
    write(tmp_path, generate(write_odd_eds(tmp_path / "eds"), "odd_bits", can_fd=True))
    (tmp_path / "user.cpp").write_text(CXX_USER, encoding="utf-8")
    for command in (
        ["gcc", *C_FLAGS, "-c", "odd_bits.c", "-o", "odd_bits.o"],
        ["g++", *CXX_FLAGS, "-o", "user", "user.cpp", "odd_bits.o"],
    ):
        built = run(command, tmp_path)
        assert built.returncode == 0, built.stderr
    result = run([str(tmp_path / "user")], tmp_path)
    assert (result.returncode, result.stdout) == (0, "-5 1\n")
