"""What an entry read from a device says about its description: the PRB findings (lint/probe.py), located at
the entry's lines in the file."""

from __future__ import annotations

from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

from ..lint.codes import load
from ..lint.rules import Context, Finding
from ..model import AccessType, Object, Variable
from ..model.cia301 import aborts, bootcheck
from ..model.cia301.objects import (
    COMMUNICATION_AREA,
    ERROR_HISTORY,
    ERROR_REGISTER,
    IDENTITY,
    IDENTITY_SERIAL,
    MANUFACTURER_STATUS,
)

if TYPE_CHECKING:
    import canopen


@dataclass
class Reading:
    """One entry as the device answered: its bytes, or the abort code (TIMEOUT when it did not answer)."""

    index: int
    subindex: int
    data: bytes | None = None
    abort: int | None = None


# Values the device changes by itself: its error state, not a configuration.
STATUS = {ERROR_REGISTER, MANUFACTURER_STATUS, ERROR_HISTORY}


class Judge:
    def __init__(self, ctx: Context, od: canopen.ObjectDictionary) -> None:
        load()  # the PRB codes' declarations, which a finding takes its severity from
        self.ctx, self.od = ctx, od

    def reading(self, owner: Object, sub: int, var: Variable, reading: Reading) -> list[Finding]:
        if reading.abort is not None:
            return self._aborted(owner, sub, var, reading.abort)
        data = reading.data or b""
        od = self._od(owner.index, sub)
        if od.fixed_size and len(data) != len(od) // 8:
            return [self._report("PRB002", owner, sub, var, f"the device answers {_bytes(len(data))}, "
                                 f"the data type has {_bytes(len(od) // 8)}")]  # fmt: skip
        if (owner.index, sub) in bootcheck.CHECKED_BY:
            return self._identity(owner, sub, var, od, data)
        return self._value(owner, sub, var, od, data)

    def written(self, owner: Object, sub: int, var: Variable, abort: int | None) -> list[Finding]:
        if abort is None:
            return []
        access = var.access.value if var.access is not None else "rw"
        return [self._report("PRB007", owner, sub, var, f"writable ({access}) in the file, the device refuses "
                             f"the value it just gave ({_abort(abort)})")]  # fmt: skip

    def _aborted(self, owner: Object, sub: int, var: Variable, abort: int) -> list[Finding]:
        if abort == aborts.NO_DATA:  # an empty value, or an error history entry not filled (CiA 301 1003h)
            return []
        if abort == aborts.NO_OBJECT:
            where = self.ctx.at(owner)
            message = f"[{owner.index:04X}] {owner.name}: the device has no such object ({_abort(abort)})"
            return [self.ctx.report("PRB001", message, where)]
        if abort == aborts.NO_SUB_INDEX:
            return [self._report("PRB001", owner, sub, var, f"the device has no such sub-index ({_abort(abort)})")]
        if abort in aborts.LENGTH:
            return [self._report("PRB002", owner, sub, var, f"the device refuses the read ({_abort(abort)})")]
        if abort == aborts.TIMEOUT:
            return [self._report("PRB008", owner, sub, var, "the device does not answer the read")]
        access = var.access.value if var.access is not None else "rw"
        return [self._report("PRB003", owner, sub, var, f"readable ({access}) in the file, the device refuses "
                             f"to read it ({_abort(abort)})")]  # fmt: skip

    def _identity(self, owner: Object, sub: int, var: Variable, od: Any, data: bytes) -> list[Finding]:
        """Device type and identity against what the master's boot-up check compares (0: not checked); the
        serial number only when a DCF gives it (an EDS describes every device of its kind)."""
        device = self.ctx.device
        if sub == IDENTITY_SERIAL and owner.index == IDENTITY and var.parameter_value is None:
            return []
        wanted = bootcheck.expected(device, owner.index, sub, self.ctx.options.node_id)
        if not wanted or not _fits(od, wanted):  # a value outside the type: lint reports the file (EDS034)
            return []
        actual = od.decode_raw(data)
        if actual == wanted:
            return []
        key = "ParameterValue" if var.parameter_value is not None else "DefaultValue"
        source = "[DeviceInfo]" if bootcheck.device_info_number(device, owner.index, sub) else f"the file's {key}"
        checked_by = bootcheck.CHECKED_BY[owner.index, sub]
        message = (f"the device says {_hex(actual)}, {source} {_hex(wanted)}; the master's boot-up check "
                   f"({checked_by:04X}h) compares it")  # fmt: skip
        return [self._report("PRB004", owner, sub, var, message, key=key)]

    def _value(self, owner: Object, sub: int, var: Variable, od: Any, data: bytes) -> list[Finding]:
        expected = _expected(od)
        if expected is None or self._changes_by_itself(owner, var):
            return []
        if not _fits(od, expected):
            return []
        wanted = od.encode_raw(expected)
        if _same(od, wanted, data):
            return []
        key = "ParameterValue" if var.parameter_value is not None else "DefaultValue"
        code = "PRB006" if owner.index in COMMUNICATION_AREA else "PRB005"
        message = f"the device holds {_shown(od, data)}, the file's {key} is {_shown(od, wanted)}"
        return [self._report(code, owner, sub, var, message, key=key)]

    def _changes_by_itself(self, owner: Object, var: Variable) -> bool:
        """Error state, and inputs the device produces (read-only and mappable): their value is the present one."""
        produced = var.access in (AccessType.RO, AccessType.RWR) and bool(var.pdo_mapping)
        return owner.index in STATUS or produced

    def _od(self, index: int, sub: int) -> Any:
        return self.od.get_variable(index, sub)

    def _report(self, code: str, owner: Object, sub: int, var: Variable, what: str, key: str | None = None) -> Finding:
        where = f"[{owner.index:04X}]" if var is owner else f"[{owner.index:04X}sub{sub:X}]"
        section = self.ctx.section_of(owner, var)
        location = self.ctx.written_at(owner, var, key) if key else self.ctx.at(section)
        return self.ctx.report(code, f"{where} {var.name}: {what}", location)


def _expected(od: Any) -> Any:
    return od.value if od.value is not None else od.default


def _fits(od: Any, value: Any) -> bool:
    try:
        od.encode_raw(value)
    except (ValueError, TypeError, UnicodeError, OverflowError):
        return False
    return True


def _same(od: Any, wanted: bytes, data: bytes) -> bool:
    if od.fixed_size:
        return wanted == data
    # Strings: a C device pads with NULs; python-canopen's reading strips them too.
    return wanted.rstrip(b"\0") == data.rstrip(b"\0")


def _shown(od: Any, data: bytes) -> str:
    value = od.decode_raw(data)
    if isinstance(value, bool):
        return str(int(value))
    if isinstance(value, int):
        return str(value) if -0x10000 < value < 0x10000 else f"0x{value:X}"
    if isinstance(value, (bytes, bytearray)):
        return bytes(value).hex(" ").upper() or "nothing"
    return repr(value)


def _hex(value: Any) -> str:
    return f"0x{value:08X}" if isinstance(value, int) else repr(value)


def _bytes(count: int) -> str:
    return f"{count} byte{'s' if count != 1 else ''}"


def _abort(code: int) -> str:
    return f"abort {aborts.describe(code)}"
