"""The network a bus description states: its master, its slaves and what the master configures in each.

The keys and defaults are those of lely's `dcfgen` bus.yml (as ros2_canopen documents them); every
part keeps the line it was written on, so that a check or a refusal can point at it.
"""

from __future__ import annotations

from typing import Literal

from pydantic import BaseModel, ConfigDict, Field

from ..model.cia301.cobid import TIME_ID


class _Part(BaseModel):
    model_config = ConfigDict(frozen=False, defer_build=True)

    line: int = 0
    lines: dict[str, int] = Field(default_factory=dict)
    """The line of each key as written."""

    def line_of(self, key: str) -> int:
        return self.lines.get(key, self.line)


class Options(_Part):
    dcf_path: str = ""
    heartbeat_multiplier: float = 3.0
    retry_factor: int = 3


class Mapped(_Part):
    """One object a PDO carries: index, sub-index (0 unless given)."""

    index: int
    sub_index: int = 0


class PdoConfig(_Part):
    """What the YAML says about one RPDO or TPDO (None: keep what the device has)."""

    number: int
    enabled: bool = True
    cob_id: int | Literal["auto"] | None = None
    transmission: int | None = None
    inhibit_time: int | None = None
    event_timer: int | None = None
    event_deadline: int | None = None
    sync_start: int | None = None
    mapping: list[Mapped] | None = None


class SdoEntry(_Part):
    """One write of the YAML's `sdo` list."""

    index: int
    sub_index: int = 0
    value: int | float | str = 0


class Master(_Part):
    node_id: int = 255
    baudrate: int = 1000
    vendor_id: int = 0
    product_code: int = 0
    revision_number: int = 0
    serial_number: int = 0
    sync_period: int = 0
    sync_window: int = 0
    sync_overflow: int = 0
    time_cob_id: int = TIME_ID
    emcy_inhibit_time: int = 0
    heartbeat_multiplier: float | None = None
    heartbeat_consumer: bool = True
    heartbeat_producer: int = 0
    error_behavior: dict[int, int] = Field(default_factory=lambda: {1: 0})
    nmt_inhibit_time: int = 0
    start: bool = True
    start_nodes: bool = True
    start_all_nodes: bool = False
    reset_all_nodes: bool = False
    stop_all_nodes: bool = False
    boot_time: int = 0
    extra: dict[str, object] = Field(default_factory=dict)
    """Keys ros2_canopen reads for its driver (driver, package, ...): kept, not used here."""


class Slave(_Part):
    name: str
    dcf: str
    dcf_file: str = ""
    """Where `dcf` was found."""
    dcf_path: str | None = None
    node_id: int | None = None
    revision_number: int | None = None
    serial_number: int | None = None
    heartbeat_multiplier: float | None = None
    heartbeat_consumer: bool = False
    heartbeat_producer: int | None = None
    time_cob_id: int | None = None
    guard_time: int | None = None
    life_time_factor: int | None = None
    retry_factor: int | None = None
    error_behavior: dict[int, int] = Field(default_factory=dict)
    rpdo: list[PdoConfig] = Field(default_factory=list)
    tpdo: list[PdoConfig] = Field(default_factory=list)
    boot: bool = True
    mandatory: bool = False
    reset_communication: bool = True
    software_file: str = ""
    software_version: int = 0
    configuration_file: str | None = None
    restore_configuration: int = 0
    sdo: list[SdoEntry] = Field(default_factory=list)
    extra: dict[str, object] = Field(default_factory=dict)


class Network(BaseModel):
    model_config = ConfigDict(defer_build=True)

    file: str
    options: Options = Field(default_factory=Options)
    master: Master
    slaves: list[Slave] = Field(default_factory=list)
    warnings: list[str] = Field(default_factory=list)
    """`file:line: warning: ...` lines of keys that have no effect where they stand, or are replaced."""
