"""Small EDS/DCF builders for the PDO, COB-ID and network rule tests.

A test writes only the objects it is about; `eds()` adds the file sections around them. `where()`
finds the line (and value column) of a key, so that tests assert exact locations without
counting lines by hand.
"""

from __future__ import annotations

from cantools_od import loads
from cantools_od.lint import Finding, LintOptions, lint
from cantools_od.model import Device

VALUE_COLUMN = len("DefaultValue=") + 1


def section(name: str, **keys: object) -> str:
    lines = [f"[{name}]"] + [f"{key}={value}" for key, value in keys.items()]
    return "\n".join(lines) + "\n"


def var(
    index: int, name: str = "Object", dtype: int = 0x0006, access: str = "rw", mapping: int | None = 1, **extra: object
) -> str:
    """A VAR; `mapping=None` leaves PDOMapping out, `extra` adds keys (HighLimit=...)."""
    keys: dict[str, object] = {"ParameterName": name, "ObjectType": "0x7", "DataType": f"0x{dtype:04X}"}
    keys.update(AccessType=access, DefaultValue=0, **({} if mapping is None else {"PDOMapping": mapping}), **extra)
    return section(f"{index:04X}", **keys)


def sub(index: int, subindex: int, name: str, dtype: int, value: object, access: str = "rw", mapping: int = 0) -> str:
    return section(
        f"{index:04X}sub{subindex:X}",
        ParameterName=name,
        ObjectType="0x7",
        DataType=f"0x{dtype:04X}",
        AccessType=access,
        DefaultValue=value,
        PDOMapping=mapping,
    )


def record(
    index: int, name: str, subs: dict[int, tuple[str, int, object]], access: str = "rw", object_type: str = "0x9"
) -> str:
    """A RECORD with sub-objects {sub-index: (name, data type, default)}; sub0 is added when absent."""
    if 0 not in subs:
        subs = {0: ("Highest sub-index supported", 0x0005, max(subs, default=0)), **subs}
    text = section(f"{index:04X}", ParameterName=name, ObjectType=object_type, SubNumber=len(subs))
    for subindex, (sub_name, dtype, value) in sorted(subs.items()):
        text += "\n" + sub(index, subindex, sub_name, dtype, value, "ro" if subindex == 0 else access)
    return text


def comm(index: int, cob_id: str, tt: object = 255, *, object_type: object = "0x9", **extra: object) -> str:
    """A PDO communication record: COB-ID, transmission type and optional inhibit/timer/sync/sub0 values."""
    subs: dict[int, tuple[str, int, object]] = {1: ("COB-ID", 0x0007, cob_id), 2: ("Transmission type", 0x0005, tt)}
    for key, (subindex, dtype) in {"inhibit": (3, 0x0006), "timer": (5, 0x0006), "sync": (6, 0x0005)}.items():
        if key in extra:
            subs[subindex] = (key, dtype, extra[key])
    if "sub0" in extra:
        subs[0] = ("Highest sub-index supported", 0x0005, extra["sub0"])
    return record(index, f"PDO communication parameter {index:04X}", subs, object_type=str(object_type))


def mapping(
    index: int,
    *entries: str,
    count: object = None,
    object_type: str = "0x9",
    entry_type: int = 0x0007,
    count_access: str = "rw",
) -> str:
    """A PDO mapping record with the given entries; sub0 counts them unless `count` is given."""
    subs: dict[int, tuple[str, int, object]] = {
        0: ("Number of mapped objects", 0x0005, len(entries) if count is None else count)
    }
    for position, entry in enumerate(entries, 1):
        subs[position] = (f"Mapped object {position}", entry_type, entry)
    text = section(
        f"{index:04X}", ParameterName=f"PDO mapping parameter {index:04X}", ObjectType=object_type, SubNumber=len(subs)
    )
    for subindex, (sub_name, dtype, value) in sorted(subs.items()):
        text += "\n" + sub(index, subindex, sub_name, dtype, value, count_access if subindex == 0 else "rw")
    return text


def eds(*parts: str, granularity: int = 8, dummies: str = "0002,0003,0004,0005,0006,0007", head: str = "") -> str:
    """An EDS with [DeviceInfo], [DummyUsage] and the given object sections."""
    usage = "".join(f"Dummy{code}=1\n" for code in dummies.split(",") if code)
    text = (
        "[FileInfo]\nFileName=t.eds\nEDSVersion=4.0\n\n"
        f"[DeviceInfo]\nVendorName=Test\nGranularity={granularity}\nNrOfRXPDO=0\nNrOfTXPDO=0\n{head}\n"
        f"[DummyUsage]\n{usage}"
    )
    return text + "".join("\n" + part for part in parts)


def dcf(node_id: int | None, *parts: str, sync: bool = False) -> str:
    """A DCF of one node: NodeID (None: no NodeID key), SYNC producer or not, the given objects."""
    commissioning = "[DeviceComissioning]\n" + (f"NodeID={node_id}\n" if node_id is not None else "NodeName=x\n")
    sync_id = "0x40000080" if sync else "0x00000080"
    objects = (section("1005", ParameterName="COB-ID SYNC", DataType="0x0007", AccessType="rw", DefaultValue=sync_id),)
    return eds(*objects, *parts) + "\n" + commissioning


def load(text: str, source: str = "t.eds", node_id: int | None = None) -> Device:
    return loads(text.encode(), source=source, node_id=node_id)


def findings(text: str, code: str, options: LintOptions | None = None, source: str = "t.eds") -> list[Finding]:
    """The findings of one rule code (or code prefix) for an EDS text."""
    return [f for f in lint(load(text, source), options) if f.code.startswith(code)]


def where(text: str, name: str, key: str | None = None) -> int:
    """The line number of `[name]`, or of `key=` inside that section."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.strip().lower() == f"[{name.lower()}]")
    if key is None:
        return start + 1
    for number in range(start + 1, len(lines)):
        if lines[number].startswith("["):
            break
        if lines[number].split("=", 1)[0].strip().lower() == key.lower():
            return number + 1
    raise LookupError(f"[{name}] has no {key}")


def at(finding: Finding) -> tuple[int, int]:
    return finding.location.line, finding.location.column
