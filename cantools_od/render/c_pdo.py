"""PDO structs and their pack/unpack statements for the C target.

The payload layout is CiA 301's: entries packed from bit 0 of byte 0 in
sub-index order, each value little-endian. Every field becomes a short list of
C statements over a `uint64_t raw`: pack loads the value's bits into `raw` and
ORs them byte by byte into the zeroed frame; unpack gathers the bytes back,
sign-extends signed types and copies REAL bits with memcpy. The statements use
shifts only, so they are independent of the host's byte order.
"""

from __future__ import annotations

from dataclasses import dataclass

from ..model import ValueKind
from ..views.codegen import DeviceView, PdoEntryView, PdoView
from .c_types import Constant, constant, int_range, limit_value, real_literal, scalar_type, storage_bits, typed_integer
from .prose import count


@dataclass(frozen=True)
class CField:
    member: str
    ctype: str
    comment: str  # text for c_comment
    pack: tuple[str, ...]
    unpack: tuple[str, ...]
    in_range: str  # function name
    checks: tuple[str, ...]  # conditions on `value`, all must hold; none: every value is in range
    never: bool  # the limits leave no value in range


@dataclass(frozen=True)
class CPdo:
    title: str  # text for c_comment
    struct: str
    pack: str
    unpack: str
    dlc_macro: str
    dlc: int
    cob_id_macro: str
    cob_id: Constant | None
    fields: tuple[CField, ...]


@dataclass(frozen=True)
class Helpers:
    """The static functions of the .c file that some field uses."""

    sign_extend: bool
    real32: bool
    real64: bool


def _mask(bits: int) -> str:
    return f"(uint64_t)0x{(1 << bits) - 1:X}ull"


def member_names(pdo: PdoView) -> list[str]:
    """One struct member per mapped entry: the flat identifier, `_2`, `_3`, ... when mapped again."""
    taken = {field.identifier or "" for field in pdo.fields}
    names: list[str] = []
    for field in pdo.fields:
        base = field.identifier or ""
        name, count = base, 1
        while name in names or (count > 1 and name in taken):
            count += 1
            name = f"{base.rstrip('_')}_{count}"
        names.append(name)
    return names


def pack_lines(prefix: str, member: str, field: PdoEntryView, ctype: str) -> list[str]:
    kind = field.data_type.kind if field.data_type else None
    offset, length = field.bit_offset, field.bit_length
    value = f"src->{member}"
    if kind is ValueKind.BOOL:
        lines = [f"raw = {value} ? 1u : 0u;"]
    elif kind is ValueKind.REAL:
        lines = [f"raw = {prefix}real{length}_bits({value});"]
    elif length < 64 and (kind is ValueKind.SIGNED or storage_bits(ctype) > length):
        lines = [f"raw = (uint64_t){value} & {_mask(length)};"]
    else:
        lines = [f"raw = (uint64_t){value};"]
    for byte in range(offset // 8, (offset + length - 1) // 8 + 1):
        shift = 8 * byte - offset
        if shift == 0:
            lines.append(f"dst[{byte}] |= (uint8_t)raw;")
        elif shift > 0:
            lines.append(f"dst[{byte}] |= (uint8_t)(raw >> {shift});")
        else:
            lines.append(f"dst[{byte}] |= (uint8_t)(raw << {-shift});")
    return lines


def unpack_lines(prefix: str, member: str, field: PdoEntryView, ctype: str) -> list[str]:
    kind = field.data_type.kind if field.data_type else None
    offset, length = field.bit_offset, field.bit_length
    lines: list[str] = []
    for byte in range(offset // 8, (offset + length - 1) // 8 + 1):
        shift = 8 * byte - offset
        term = f"(uint64_t)src[{byte}]"
        if shift > 0:
            term = f"({term} << {shift})"
        elif shift < 0:
            term = f"({term} >> {-shift})"
        lines.append(f"raw {'|=' if lines else '='} {term};")
    target = f"dst->{member}"
    if kind is ValueKind.BOOL:
        lines.append(f"{target} = (raw & 0x1u) != 0u;")
    elif kind is ValueKind.REAL:
        lines.append(f"{target} = {prefix}real{length}_value(raw);")
    elif kind is ValueKind.SIGNED:
        lines.append(f"{target} = ({ctype}){prefix}sign_extend(raw, {length}u);")
    else:
        if storage_bits(ctype) > length:
            lines.append(f"raw &= {_mask(length)};")
        lines.append(f"{target} = ({ctype})raw;")
    return lines


def range_checks(field: PdoEntryView, ctype: str) -> tuple[tuple[str, ...], bool]:
    """Conditions on `value` from the type's range and LowLimit/HighLimit, and whether none can hold.

    A bound that the C type implies anyway is left out: compilers warn about comparisons that are
    always true.
    """
    dtype, entry = field.data_type, field.entry
    if dtype is None or entry is None or dtype.kind is ValueKind.BOOL:
        return (), False
    low = limit_value(entry.low_limit, dtype, upper=False)
    high = limit_value(entry.high_limit, dtype, upper=True)
    if dtype.kind is ValueKind.REAL:
        checks = []
        for bound, operator in ((low, ">="), (high, "<=")):
            text = real_literal(float(bound), dtype.bits or 64) if bound is not None else None
            if text is not None:
                checks.append(f"value {operator} {text}")
        if low is not None and high is not None and low > high:
            return (), True
        return tuple(checks), False
    type_low, type_high = dtype.int_range() or (0, 0)
    low = type_low if low is None else max(type_low, int(low))
    high = type_high if high is None else min(type_high, int(high))
    if low > high:
        return (), True
    c_low, c_high = int_range(ctype)
    checks = []
    if low > c_low:
        checks.append(f"value >= {typed_integer(low, ctype)}")
    if high < c_high:
        checks.append(f"value <= {typed_integer(high, ctype)}")
    return tuple(checks), False


def c_pdos(view: DeviceView, prefix: str, macro_prefix: str) -> tuple[list[CPdo], Helpers]:
    """The PDOs of `view` with at least one mapped object, and the helpers their code uses."""
    pdos: list[CPdo] = []
    used: set[str] = set()
    for pdo in view.pdos:
        struct = f"{prefix}{pdo.struct_name}"
        fields = []
        for member, field in zip(member_names(pdo), pdo.fields, strict=True):
            ctype = scalar_type(field.data_type) or "uint64_t"
            kind = field.data_type.kind if field.data_type else None
            if kind is ValueKind.SIGNED:
                used.add("sign_extend")
            elif kind is ValueKind.REAL:
                used.add(f"real{field.bit_length}")
            checks, never = range_checks(field, ctype)
            entry = field.entry
            where = f"{entry.index:04X}sub{entry.subindex:X} {entry.name}" if entry else ""
            last = field.bit_offset + field.bit_length - 1
            span = f"bit {last}" if field.bit_length == 1 else f"bits {field.bit_offset}-{last}"
            fields.append(
                CField(
                    member=member,
                    ctype=ctype,
                    comment=f"{where}: {span}, {field.data_type.name if field.data_type else ''}",
                    pack=tuple(pack_lines(prefix, member, field, ctype)),
                    unpack=tuple(unpack_lines(prefix, member, field, ctype)),
                    in_range=f"{struct}_{member.rstrip('_')}_is_in_range",
                    checks=checks,
                    never=never,
                )
            )
        comm = view.entry(pdo.pdo.comm_index, 1)
        cob_id = constant(comm.data_type, comm.default) if comm is not None and comm.default is not None else None
        base = f"{macro_prefix}{pdo.struct_name.upper()}"
        pdos.append(
            CPdo(
                title=_title(pdo),
                struct=struct,
                pack=f"{struct}_pack",
                unpack=f"{struct}_unpack",
                dlc_macro=f"{base}_DLC",
                dlc=pdo.byte_length,
                cob_id_macro=f"{base}_COB_ID",
                cob_id=cob_id if cob_id is not None and cob_id.text else None,
                fields=tuple(fields),
            )
        )
    return pdos, Helpers("sign_extend" in used, "real32" in used, "real64" in used)


def _title(pdo: PdoView) -> str:
    p = pdo.pdo
    cob = "?" if p.cob_id is None else f"0x{p.cob_id:X}" if isinstance(p.cob_id, int) else p.cob_id.canonical()
    tt = "?" if p.transmission_type is None else str(p.transmission_type)
    return (
        f"{p.name} ({p.comm_index:04X}/{p.map_index:04X}): COB-ID {cob}, transmission type {tt}, "
        f"{count(p.bit_length, 'bit')} in {count(pdo.byte_length, 'byte')}"
    )
