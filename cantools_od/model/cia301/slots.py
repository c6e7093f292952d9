"""A value-carrying entry of the object dictionary as the communication profile reads it."""

from __future__ import annotations

from typing import NamedTuple, Protocol

from ..device import Device
from ..objects import Object, Section, SubObject, Variable
from ..source import Location


class Locator(Protocol):
    """Turns model parts into file locations (the linter's context is one)."""

    def at(self, section: Section | None, key: str | None = None) -> Location: ...

    def value_at(self, section: Section | None, key: str) -> Location: ...

    def written_at(self, owner: Object, var: Variable, key: str) -> Location: ...


def as_int(value: object) -> int | None:
    """An integer value; None for bool, text, `$NODEID` formulas and unreadable values."""
    return value if isinstance(value, int) and not isinstance(value, bool) else None


class Slot(NamedTuple):
    """One value-carrying entry: an object's sub-index (or a VAR) and where its value is written."""

    owner: Object
    subindex: int
    var: Variable

    @property
    def key(self) -> str:
        return self.var.held_key

    @property
    def name(self) -> str:
        return f"{self.owner.index:04X}" if self.var is self.owner else f"{self.owner.index:04X}sub{self.subindex:X}"

    @property
    def implicit(self) -> bool:
        """No section of its own (CompactSubObj, CompactPDO): findings go to the owner."""
        return isinstance(self.var, SubObject) and self.var.implicit

    def location(self, at: Locator) -> Location:
        """Where the configured value is written: the [xxxxValue] entry of a CompactSubObj value,
        the owner when the entry is not written at all (CompactPDO, CompactSubObj default)."""
        return at.written_at(self.owner, self.var, self.key)

    def key_location(self, at: Locator, key: str) -> Location:
        if self.implicit:
            return at.at(self.owner)
        return at.at(self.var, key)

    def value(self, node_id: int | None = None) -> object:
        return self.var.value(node_id)


def slot(device: Device, index: int, subindex: int) -> Slot | None:
    obj = device.objects.get(index)
    var = obj.entry(subindex) if obj is not None else None
    return Slot(obj, subindex, var) if obj is not None and var is not None else None
