"""The device: everything an EDS or DCF says about one CANopen device."""

from __future__ import annotations

from collections.abc import Collection, Iterator
from enum import StrEnum
from typing import Literal

from pydantic import BaseModel, ConfigDict, Field, PrivateAttr

from .cia301.objects import DATA_TYPE_AREA, MANUFACTURER_AREA
from .cia301.objects import MANDATORY as MANDATORY_INDICES
from .datatypes import DOMAIN, DataType, standard_type
from .objects import Object, ObjectKind, Section, Variable
from .source import Diagnostic, Severity
from .values import NodeIdExpr, Value


class Dialect(StrEnum):
    """The value conventions a file follows (the dialects peer tools write)."""

    CIA306 = "cia306"
    LELY = "lely"
    PYTHON_CANOPEN = "python-canopen"
    CANOPENNODE = "canopennode"


class FileInfo(Section):
    file_name: str | None = None
    file_version: int | None = None
    file_revision: int | None = None
    eds_version: str | None = None
    description: str | None = None
    creation_time: str | None = None
    creation_date: str | None = None
    created_by: str | None = None
    modification_time: str | None = None
    modification_date: str | None = None
    modified_by: str | None = None
    last_eds: str | None = None


class DeviceInfo(Section):
    vendor_name: str | None = None
    vendor_number: int | None = None
    product_name: str | None = None
    product_number: int | None = None
    revision_number: int | None = None
    order_code: str | None = None
    baud_rates: dict[int, bool] = Field(default_factory=dict)
    """kbit/s → supported, from the BaudRate_<kbit/s> keys."""
    simple_boot_up_master: bool | None = None
    simple_boot_up_slave: bool | None = None
    granularity: int | None = None
    dynamic_channels_supported: int | None = None
    group_messaging: bool | None = None
    nr_of_rx_pdo: int | None = None
    nr_of_tx_pdo: int | None = None
    lss_supported: bool | None = None
    compact_pdo: int | None = None
    canopen_safety_supported: bool | None = None


class DummyUsage(Section):
    enabled: dict[int, bool] = Field(default_factory=dict)
    """Data-type index → may be used as a dummy mapping entry."""


class Comments(Section):
    line_count: int | None = None
    lines: dict[int, str] = Field(default_factory=dict)


class ObjectList(Section):
    """[MandatoryObjects], [OptionalObjects] or [ManufacturerObjects] as written."""

    supported_objects: int | None = None
    entries: dict[int, int] = Field(default_factory=dict)
    """Position (1..n) → object index."""
    # Where the file writes a position more than once: position → (line, key column, object index) of
    # each of its entries in file order (`entries` holds the last one, as for any repeated key).
    # Source layout, not data: kept out of the schema and the content.
    _repeats: dict[int, list[tuple[int, int, int]]] = PrivateAttr(default_factory=dict)

    @property
    def repeats(self) -> dict[int, list[tuple[int, int, int]]]:
        return self._repeats


class Commissioning(Section):
    """[DeviceComissioning] of a DCF."""

    node_id: int | None = None
    node_name: str | None = None
    node_refd: str | None = None
    baudrate: int | None = None
    net_number: int | None = None
    network_name: str | None = None
    net_refd: str | None = None
    canopen_manager: bool | None = None
    lss_serial_number: int | None = None


# CiA 306's object lists: section name → the Device field that holds it.
OBJECT_LISTS = {
    "MandatoryObjects": "mandatory_objects",
    "OptionalObjects": "optional_objects",
    "ManufacturerObjects": "manufacturer_objects",
}


def object_list_home(index: int) -> str | None:
    """The object list (its section name) an object belongs in by its index; None for data types, not listed."""
    if index < DATA_TYPE_AREA.stop:
        return None
    if index in MANDATORY_INDICES:
        return "MandatoryObjects"
    return "ManufacturerObjects" if index in MANUFACTURER_AREA else "OptionalObjects"


def object_lists_of(indices: Collection[int]) -> dict[str, ObjectList]:
    """The three object lists that list these objects, each in index order (every list, even an empty one)."""
    homes: dict[str, list[int]] = {name: [] for name in OBJECT_LISTS}
    for index in sorted(indices):
        home = object_list_home(index)
        if home is not None:
            homes[home].append(index)
    return {
        name: ObjectList.model_construct(supported_objects=len(listed), entries=dict(enumerate(listed, start=1)))
        for name, listed in homes.items()
    }


class RawSection(Section):
    """A section this model keeps as text: module concept, tools, vendor sections."""

    name: str
    entries: dict[str, str] = Field(default_factory=dict)


class Device(BaseModel):
    """One device's object dictionary with its file-level descriptions."""

    model_config = ConfigDict(defer_build=True)

    # Made without validation, which would build both schemas (and load pydantic's plugins) at import.
    file_info: FileInfo = FileInfo.model_construct()
    device_info: DeviceInfo = DeviceInfo.model_construct()
    dummy_usage: DummyUsage | None = None
    comments: Comments | None = None
    mandatory_objects: ObjectList | None = None
    optional_objects: ObjectList | None = None
    manufacturer_objects: ObjectList | None = None
    objects: dict[int, Object] = Field(default_factory=dict)
    commissioning: Commissioning | None = None
    module_sections: list[RawSection] = []
    other_sections: list[RawSection] = []
    """Sections of no known meaning, kept in file order."""
    trailing_comments: list[str] = []
    """Comment lines after the last entry of the file."""
    dialect: Dialect = Dialect.CIA306
    file_format: Literal["eds", "xdd"] = "eds"
    """The syntax the device was read from: CiA 306 INI text (EDS/DCF) or CiA 311 XML (XDD/XDC)."""
    is_dcf: bool = False
    node_id: int | None = None
    """The node-ID `$NODEID` stands for: given when loading, else the DCF's NodeID."""
    source: str = ""
    """The file this device was read from, for messages."""
    diagnostics: list[Diagnostic] = []

    # The bytes the device was read from: the preserving writer edits them.
    _original: bytes | None = PrivateAttr(default=None)
    # Set by a lint fix: the preserving writer then also rewrites these counts the model derives
    # (NrOfEntries of [xxxxName]/[xxxxValue]/[xxxxDenotation], ObjectLinks) where the file has them wrong.
    _recount: set[str] = PrivateAttr(default_factory=set)
    # Set by a lint fix: names and list numbers to write otherwise, as text edits of the original
    # (line → column, as written, new spelling); the file read back then says what the fixed model says.
    _respell: dict[int, tuple[int, str, str]] = PrivateAttr(default_factory=dict)

    def resolve(self, value: Value | None, node_id: int | None = None) -> Value | None:
        """A value with `$NODEID` replaced by the given or commissioned node-ID."""
        nid = node_id if node_id is not None else self.node_id
        if isinstance(value, NodeIdExpr) and nid is not None:
            return value.resolve(nid)
        return value

    def as_built(self) -> Device:
        """The device as built from the file: without the objects the project leaves out (`Object.left_out`).
        Itself when there are none; otherwise a copy sharing every object."""
        if not any(obj.left_out for obj in self.objects.values()):
            return self
        kept = {index: obj for index, obj in self.objects.items() if not obj.left_out}
        return self.model_copy(update={"objects": kept})

    def sections(self) -> Iterator[Section]:
        """Every part of the model that a file section describes, in a fixed order."""
        yield self.file_info
        yield self.device_info
        for optional in (
            self.dummy_usage,
            self.comments,
            self.commissioning,
            self.mandatory_objects,
            self.optional_objects,
            self.manufacturer_objects,
        ):
            if optional is not None:
                yield optional
        for obj in self.objects.values():
            yield obj
            yield from obj.subs.values()
        yield from self.module_sections
        yield from self.other_sections

    def entry_type(self, var: Variable, owner: Object) -> DataType | None:
        """The type `var`'s values are written in: a CiA 301 type, or one a DEFTYPE object aliases.

        `owner` is the object `var` belongs to (or `var` itself for a VAR or DOMAIN).
        """
        if var.data_type is None:
            return DOMAIN if var is owner and owner.kind is ObjectKind.DOMAIN else None
        dtype = standard_type(var.data_type)
        if dtype is None and var.data_type < DATA_TYPE_AREA.stop:
            alias = self.objects.get(var.data_type)
            if alias is not None and alias.kind is ObjectKind.DEFTYPE:
                dtype = standard_type(alias.data_type)
        return dtype

    def content(self, fields: Collection[str] | None = None) -> dict[str, object]:
        """The model as JSON data without source positions, diagnostics, dialect and file format.

        Two devices describe the same thing when their contents are equal,
        whichever files and layouts they were read from. `fields`: only these top-level fields (a
        fraction of the cost when the objects are not among them).
        """
        if fields is None:
            data = self.model_dump(mode="json", exclude={"diagnostics", "source", "dialect", "file_format"})
        else:
            data = self.model_dump(mode="json", include=set(fields))
        stripped = _strip_origins(data)
        assert isinstance(stripped, dict)
        return stripped


def _strip_origins(data: object) -> object:
    if isinstance(data, dict):
        return {
            key: _strip_origins(value)
            for key, value in data.items()
            if key != "origin" and not (key == "text" and "nodeid" in data)
        }
    if isinstance(data, list):
        return [_strip_origins(item) for item in data]
    return data


READ_WHOLE = frozenset({"EDS002", "EDS033", "EDS100"})
"""Reader errors about the peers, not about what the reader could read: python-canopen and lely's dcfchk cannot load
such a file (they raise), so lint reports an error, but the reader read all of it, one way, and a command carrying
it on loses nothing. A section or key given twice (EDS002) is written once, as the reader merged it: `fmt` and
`convert` are how it is repaired; so is a `$NODEID` formula in another order (EDS033), written `$NODEID+n` (a
subtraction keeps its spelling). A file that is not UTF-8 (EDS100) is read whole in the code page it was guessed
to be in, which `fmt` keeps."""


def blocking_errors(device: Device) -> list[Diagnostic]:
    """The reader's errors that stop a command carrying the content on: all but `READ_WHOLE`'s."""
    return [d for d in device.diagnostics if d.severity is Severity.ERROR and d.code not in READ_WHOLE]


def errors_to_fix(device: Device) -> str | None:
    """`N errors to fix first` when reading found errors: a command that would carry the content
    on (fmt, convert, ids, the editor's formatting) then does nothing rather than lose or spread what it
    could not read. The errors of lint's rules do not count: what such a file says is carried on as it is
    (the input's error is lint's to report, and fmt changes nothing peers read); nor do the reader's errors
    about peers on a file it read whole (`READ_WHOLE`)."""
    count = len(blocking_errors(device))
    return f"{count} error{'s' if count != 1 else ''} to fix first" if count else None
