"""The change records every output of `diff` is made from.

Names of kinds and impact classes are stable: scripts and CI match on them (docs/diff.md).
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Iterator
from enum import StrEnum
from typing import Any

from pydantic import BaseModel, ConfigDict, PrivateAttr, computed_field

from ..model import Value
from ..model.assemble import construct
from ..views.pdo import Pdo


class Impact(StrEnum):
    """What a change means for generated code and for a master that uses the device, worst first."""

    BREAKING = "breaking"
    """Code or a master built for the old description may fail with the new one."""
    COMPATIBLE = "compatible"
    """Something was added or widened: what worked before still works."""
    VALUE = "value"
    """A default, configured or descriptive value changed: behaviour may differ, interfaces do not."""
    COSMETIC = "cosmetic"
    """Names whose identifiers stay, comments, file metadata: nothing a program sees."""


IMPACT_ORDER = (Impact.BREAKING, Impact.COMPATIBLE, Impact.VALUE, Impact.COSMETIC)


class Breaks(StrEnum):
    """Who a breaking change hurts: `--fail-on wire` and `--fail-on code` select by it."""

    WIRE = "wire"
    """A master or another node configured for the old file: COB-IDs, PDO layouts, types, access, ranges, identity."""
    CODE = "code"
    """Firmware generated from the old file: identifiers, storage groups, types, removed entries."""


class Kind(StrEnum):
    """What changed. One value per kind of change; the `field` of a record says which key when several share one."""

    OBJECT_ADDED = "object-added"
    OBJECT_REMOVED = "object-removed"
    OBJECT_MOVED = "object-moved"
    SUB_ADDED = "sub-added"
    SUB_MOVED = "sub-moved"
    SUB_REMOVED = "sub-removed"
    NAME = "name"
    IDENTIFIER = "identifier"
    OBJECT_TYPE = "object-type"
    DATA_TYPE = "data-type"
    ACCESS = "access"
    PDO_MAPPING = "pdo-mapping"
    LOW_LIMIT = "low-limit"
    HIGH_LIMIT = "high-limit"
    DEFAULT = "default"
    PARAMETER_VALUE = "parameter-value"
    NODEID_FORM = "nodeid-form"
    OBJ_FLAGS = "obj-flags"
    DENOTATION = "denotation"
    DCF_ENTRY = "dcf-entry"
    CANOPENNODE = "canopennode"
    OBJECT_LINKS = "object-links"
    EXTRA_KEY = "extra-key"
    COMMENT = "comment"
    IDENTITY = "identity"
    DEVICE_INFO = "device-info"
    BAUD_RATE = "baud-rate"
    DUMMY_USAGE = "dummy-usage"
    FILE_INFO = "file-info"
    COMMISSIONING = "commissioning"
    SECTION = "section"
    PDO_ADDED = "pdo-added"
    PDO_REMOVED = "pdo-removed"
    PDO_COB_ID = "pdo-cob-id"
    PDO_TRANSMISSION_TYPE = "pdo-transmission-type"
    PDO_TIMING = "pdo-timing"
    NOT_COMPARABLE = "not-comparable"
    PEER_READING = "peer-reading"
    PDO_LAYOUT = "pdo-layout"


_BOTH = frozenset({Breaks.WIRE, Breaks.CODE})
# Who a breaking change of each kind hurts; kinds not listed hurt the bus only.
_WHO: dict[Kind, frozenset[Breaks]] = {
    Kind.OBJECT_REMOVED: _BOTH,  # generated code loses the entry; a master's SDO access to it is refused
    Kind.SUB_REMOVED: _BOTH,
    Kind.OBJECT_TYPE: _BOTH,  # the generated structure changes, and the sub-indices a master addresses
    Kind.OBJECT_MOVED: _BOTH,  # a master addresses the old index; CANopenNode's OD_ENTRY_H<index> names change
    Kind.SUB_MOVED: _BOTH,  # a master and compiled code address the old sub-index: another quantity, or none
    Kind.DATA_TYPE: _BOTH,  # the C type changes, and the number of bytes on the bus
    Kind.NAME: frozenset({Breaks.CODE}),  # a rename reaches generated identifiers only
    Kind.IDENTIFIER: frozenset({Breaks.CODE}),
}
_WHO_BY_FIELD = {
    "canopennode.storage_group": frozenset({Breaks.CODE}),  # OD_RAM.x moves to OD_PERSIST_COMM.x; stored layout
    "canopennode.count_label": frozenset({Breaks.CODE}),
    "canopennode.disabled": _BOTH,  # left out of the generated OD, so gone from the bus too
}


def who_breaks(kind: Kind, field: str) -> frozenset[Breaks]:
    """Who a breaking change of this kind (and field) hurts."""
    return _WHO_BY_FIELD.get(field) or _WHO.get(kind, frozenset({Breaks.WIRE}))


class Change(BaseModel):
    """One change.

    `name` is the entry's display name (new side, old when removed). `old`/`new` are typed values
    (None: absent); `old_text`/`new_text` show them to people.

    `index`/`subindex` address the entry (None for device-level changes, subindex None for a whole
    object); `field` names the key that changed (`default`, `device_info.vendor_number`, `extra.Unit`...).
    `note` says why the change has its impact (`no longer writable`, `identifier speed → velocity`).
    """

    model_config = ConfigDict(frozen=True, defer_build=True)

    kind: Kind
    impact: Impact
    index: int | None = None
    subindex: int | None = None
    name: str = ""
    field: str = ""
    old: Value | None = None
    new: Value | None = None
    old_text: str = ""
    new_text: str = ""
    note: str = ""

    @computed_field  # type: ignore[prop-decorator]
    @property
    def breaks(self) -> list[Breaks]:
        """Who a breaking change hurts, `wire` and/or `code` (empty for every other impact)."""
        who = who_breaks(self.kind, self.field) if self.impact is Impact.BREAKING else frozenset()
        return [hurt for hurt in Breaks if hurt in who]


def new_change(**fields: Any) -> Change:
    """A Change of values already of the right type, without validation: a diff of two large revisions makes
    tens of thousands, and pydantic's generic `model_construct` took a third of such a diff's time."""
    return construct(Change, fields)


def replaced(change: Change, **fields: Any) -> Change:
    """`change` with some fields replaced (`model_copy(update=...)`, without its generic work)."""
    return construct(Change, {**change.__dict__, **fields})


class ObjectDiff(BaseModel):
    """The changes of one object, named by its new name (its old one when removed)."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    index: int
    name: str
    changes: list[Change]


class PdoEntryView(BaseModel):
    model_config = ConfigDict(frozen=True, defer_build=True)

    index: int
    subindex: int
    bit_offset: int
    bit_length: int
    name: str
    data_type: str
    identifier: str | None
    exists: bool = True
    """The mapped object (or dummy type) is in the dictionary."""


class PdoView(BaseModel):
    """A PDO as configured on one side: COB-ID, transmission type and its mapped entries."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    cob_id: Value | None
    transmission_type: int | None
    entries: list[PdoEntryView]
    timing: dict[int, int] = {}
    """Inhibit time (sub-index 3, 100 µs), event timer (5, ms), SYNC start value (6), as configured."""
    _pdo: Pdo | None = PrivateAttr(default=None)

    @classmethod
    def of(cls, pdo: Pdo, timing: dict[int, int] | None = None) -> PdoView:
        view = cls.model_construct(
            cob_id=pdo.cob_id,
            transmission_type=pdo.transmission_type,
            timing=timing or {},
            entries=[
                PdoEntryView.model_construct(
                    index=e.index,
                    subindex=e.subindex,
                    bit_offset=e.bit_offset,
                    bit_length=e.bit_length,
                    name=e.name,
                    data_type=e.data_type_name,
                    identifier=e.identifier,
                    exists=e.exists,
                )
                for e in pdo.entries
            ],
        )
        view._pdo = pdo
        return view

    @property
    def pdo(self) -> Pdo | None:
        """The PDO of the PDO view (views/pdo.py), for drawing; None for a record read back from JSON."""
        return self._pdo


class PdoDiff(BaseModel):
    """One PDO that changed: its changes, and the PDO before and after (None: absent on that side)."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    name: str
    direction: str
    number: int
    comm_index: int
    map_index: int
    before: PdoView | None
    after: PdoView | None
    changes: list[Change]


class DeviceDiff(BaseModel):
    """Everything that changed from `old` to `new`: device-level changes, objects in index order, PDOs."""

    model_config = ConfigDict(frozen=True, defer_build=True)

    old: str
    new: str
    device: list[Change]
    objects: list[ObjectDiff]
    pdos: list[PdoDiff]

    def changes(self) -> Iterator[Change]:
        """Every change record: device, objects, then PDOs."""
        yield from self.device
        for obj in self.objects:
            yield from obj.changes
        for pdo in self.pdos:
            yield from pdo.changes

    def counts(self) -> dict[Impact, int]:
        """Number of changes per impact class, every class present."""
        counted = Counter(change.impact for change in self.changes())
        return {impact: counted[impact] for impact in IMPACT_ORDER}

    @property
    def empty(self) -> bool:
        return not (self.device or self.objects or self.pdos)

    @property
    def breaking(self) -> bool:
        return any(change.impact is Impact.BREAKING for change in self.changes())

    def hurts(self, who: Breaks) -> bool:
        """A change breaks the bus (`Breaks.WIRE`) or generated code (`Breaks.CODE`)."""
        return any(who in change.breaks for change in self.changes())
