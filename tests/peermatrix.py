"""Peer readers as judges: what python-canopen and lely's dcfchk read from a file, and how two readings compare.

Shared by the peer-matrix tests and bench/bench_peers.py. Facts used here, from the peers' own source:
python-canopen's `import_od` reads one RawConfigParser (keys case-sensitive, `;` comments after a blank), values
with `int(text, 0)` / `float(text)` / `bytes.fromhex(text)`, signed limits of 8/16/32/64 bits as two's complement,
and `$NODEID` by cutting `+?$NODEID+?` out of the text before `int()` (so a bare `$NODEID` reads as no value).
dcfchk (dcf-tools) lints a configparser reading, then builds its device; its REAL values must be integers (an IEEE
bit pattern, read with `int(text, 0)`), its `$NODEID` formulas `$NODEID+n`.
"""

from __future__ import annotations

import contextlib
import importlib.metadata
import io
import logging
import math
import os
import warnings
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import canopen
from sharedcache import cached_for_file

_DCF_TOOLS = importlib.metadata.version("dcf-tools")
NODE_ID = 5  # the node-ID peers read the files with, besides none
FIELDS = ("name", "data_type", "access_type", "default", "min", "max", "pdo_mappable", "value")

Reading = dict[tuple[int, int], dict[str, Any]]
"""(index, sub-index) → field → value; sub-index -1 is an ARRAY/RECORD's own entry (its kind and name)."""


@contextlib.contextmanager
def quiet() -> Iterator[None]:
    """Both peers log and warn about every odd entry; none of it is a finding here."""
    previous = logging.root.manager.disable
    logging.disable(logging.CRITICAL)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
                yield
    finally:
        logging.disable(previous)


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, float) and isinstance(b, float) and math.isnan(a) and math.isnan(b):
        return True
    return type(a) is type(b) and a == b


def canopen_od(path: Path, node_id: int | None = None) -> Any:
    """python-canopen's object dictionary of `path`, or the reason (a str) it could not read it."""
    try:
        with quiet():
            return canopen.import_od(str(path), node_id)
    except Exception as error:  # any failure of the peer is its verdict on the file
        return f"{type(error).__name__}: {error}"


def canopen_objects(od: Any) -> Iterator[tuple[int, Any, dict[int, Any] | None]]:
    """(index, object, its sub-indices) of every object python-canopen read; sub-indices None for a VAR."""
    for index, obj in od.indices.items():
        variable = isinstance(obj, canopen.objectdictionary.ODVariable)
        yield index, obj, None if variable else obj.subindices


def canopen_reading(path: Path, node_id: int | None) -> Reading | str:
    """python-canopen's reading of `path`, or the reason it could not read it; made once a run for the same bytes
    (several modules judge the same corpus files and the same outputs)."""
    parts = (canopen.__version__, repr(node_id))
    return cached_for_file("python-canopen", path, parts, lambda: _canopen_reading(path, node_id))


def _canopen_reading(path: Path, node_id: int | None) -> Reading | str:
    od = canopen_od(path, node_id)
    if isinstance(od, str):
        return od
    out: Reading = {}
    for index, obj, subs in canopen_objects(od):
        if subs is None:
            out[(index, 0)] = _variable(obj)
            continue
        out[(index, -1)] = {"kind": type(obj).__name__, "name": obj.name}
        for subindex, var in subs.items():
            out[(index, subindex)] = _variable(var)
    return out


# What python-canopen reads of a file besides its entries: the [DeviceInfo] it keeps (`od.device_information`).
DEVICE_INFO = ("vendor_name", "vendor_number", "product_name", "product_number", "revision_number", "order_code",
    "allowed_baudrates", "simple_boot_up_master", "simple_boot_up_slave", "granularity", "dynamic_channels_supported",
    "group_messaging", "nr_of_RXPDO", "nr_of_TXPDO", "LSS_supported")  # fmt: skip


def file_reading(path: Path, node_id: int | None) -> dict[str, Any] | str:
    """python-canopen's reading of `path` besides its entries: the node-ID and bit rate (its [DeviceComissioning]),
    [DeviceInfo] and [Comments]; or the reason it could not read the file. Made once a run for the same bytes."""
    parts = (canopen.__version__, repr(node_id))
    return cached_for_file("python-canopen-file", path, parts, lambda: _file_reading(path, node_id))


def _file_reading(path: Path, node_id: int | None) -> dict[str, Any] | str:
    od = canopen_od(path, node_id)
    if isinstance(od, str):
        return od
    info = od.device_information
    return {
        "node_id": od.node_id,
        "bitrate": od.bitrate,
        "comments": od.comments,
        **{f"[DeviceInfo] {name}": getattr(info, name, None) for name in DEVICE_INFO},
    }


def peer_changes(before: Path, after: Path, node_ids: tuple[int | None, ...] = (None, NODE_ID)) -> list[str]:
    """The oracle of what peers read: every difference between python-canopen's reading of `before` and of `after`
    (every entry's name, type, access, default, limits, PDO flag and value; node-ID, bit rate, [DeviceInfo]), read
    without a node-ID and with one. A file it could not read before constrains nothing; one it no longer reads is a
    difference."""
    found: list[str] = []
    for node_id in node_ids:
        old, new = canopen_reading(before, node_id), canopen_reading(after, node_id)
        old_file, new_file = file_reading(before, node_id), file_reading(after, node_id)
        if isinstance(old, str) or isinstance(old_file, str):
            continue
        at = f"node-ID {node_id}" if node_id is not None else "no node-ID"
        if isinstance(new, str) or isinstance(new_file, str):
            found.append(f"{at}: python-canopen no longer reads the file: {new if isinstance(new, str) else new_file}")
            continue
        found += [f"{at}: {d}" for d in differences(old, new)]
        found += [
            f"{at}: {k}: {v!r} -> {new_file.get(k)!r}" for k, v in old_file.items() if not _same(v, new_file.get(k))
        ]
    return found


def _variable(var: Any) -> dict[str, Any]:
    return {name: getattr(var, name) for name in FIELDS}


@dataclass
class Difference:
    key: tuple[int, int]
    field: str
    before: Any
    after: Any

    def __str__(self) -> str:
        index, sub = self.key
        where = f"{index:04X}" if sub < 0 else f"{index:04X}sub{sub:X}"
        return f"{where} {self.field}: {self.before!r} -> {self.after!r}"


def differences(before: Reading, after: Reading, fields: tuple[str, ...] = ("kind", *FIELDS)) -> list[Difference]:
    out: list[Difference] = []
    for key in sorted(before.keys() | after.keys()):
        if key not in after or key not in before:
            out.append(Difference(key, "present", key in before, key in after))
            continue
        for name in fields:
            if name in before[key] and not _same(before[key][name], after[key].get(name)):
                out.append(Difference(key, name, before[key][name], after[key].get(name)))
    return out


class Dcfchk:
    """lely's dcfchk on one file, as its command line runs it (`dcfchk [-n ID] FILE`): the lint, then the device
    built for the node-ID. The lint, by far its slowest stage, runs once for any number of node-IDs, and each
    verdict once a run for the same bytes (several modules judge the same corpus files and the same outputs)."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._parsed = False
        self.cfg: Any = None
        self.rejected: str | None = None

    def _parse(self) -> None:
        from dcf.lint import lint
        from dcf.parse import parse_file

        self._parsed = True
        try:
            with _caught() as caught:
                self.cfg = parse_file(os.fspath(self.path))
                if not lint(self.cfg):
                    self.rejected = caught[0] if caught else "rejected"
        except Exception as error:  # a crash is a rejection, as its exit status says
            self.rejected = f"{type(error).__name__}: {error}"

    def verdict(self, node_id: int | None = None) -> str | None:
        """None when dcfchk accepts the file, else why not."""
        return cached_for_file("dcfchk", self.path, (_DCF_TOOLS, repr(node_id)), lambda: self._verdict(node_id))

    def _verdict(self, node_id: int | None) -> str | None:
        from dcf.device import Device

        if not self._parsed:
            self._parse()
        if self.rejected is not None:
            return self.rejected
        try:
            with _caught():
                Device(self.cfg, {} if node_id is None else {"NODEID": node_id})
        except Exception as error:
            return f"{type(error).__name__}: {error}"
        return None


@contextlib.contextmanager
def _caught() -> Iterator[list[str]]:
    messages: list[str] = []
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
            try:
                yield messages
            finally:
                messages.extend(str(w.message) for w in caught)


def dcfchk_verdict(path: Path, node_id: int | None = None) -> str | None:
    return Dcfchk(path).verdict(node_id)


# --- the outputs judged: what `fmt`, `convert` (EDS -> DCF) and `lint --fix` write -------------------------------

OUTPUT_NAMES = ("fmt", "convert-dcf", "lint-fix")


# python-canopen's field → the model's attribute of the same entry
_MODEL_FIELDS = {
    "name": "name",
    "data_type": "data_type",
    "access_type": "access",
    "default": "default",
    "min": "low_limit",
    "max": "high_limit",
    "pdo_mappable": "pdo_mapping",
    "value": "parameter_value",
}


def _model_fields(device: Any) -> dict[tuple[tuple[int, int], str], Any]:
    out: dict[tuple[tuple[int, int], str], Any] = {}
    for index, obj in device.objects.items():
        entries = obj.subs.items() if obj.subs else [(0, obj)]
        if obj.subs:
            out[((index, -1), "name")] = obj.name
        for subindex, var in entries:
            for peer_field, attr in _MODEL_FIELDS.items():
                out[((index, subindex), peer_field)] = getattr(var, attr)
    return out


def outputs(source: Path) -> tuple[dict[str, bytes], set[tuple[tuple[int, int], str]]]:
    """What `fmt`, `convert SOURCE -o X.dcf --node-id 5` (EDS only) and `lint --fix` write for `source` (the
    API calls those commands make, on one reading of the file), and the entries the fixes changed. An EDS
    commissioned for another node-ID is written for node 5 all the same: `convert` refuses `--node-id 5` for it,
    and writes this DCF once the file's own NodeID is changed to 5."""
    from cantools_od.api import dumps, format_for, load
    from cantools_od.lint import LintOptions, lint

    device = load(source)
    fmt = format_for(source)
    out = {"fmt": dumps(device, fmt, style="canonical")}
    if fmt == "eds":
        device.node_id = NODE_ID
        out["convert-dcf"] = dumps(device, "dcf", style="canonical")
        device.node_id = None
    before = _model_fields(device)
    for finding in lint(device, LintOptions()):
        if finding.fix is not None and finding.fix.safe:
            finding.fix.apply(device)
    out["lint-fix"] = dumps(device, fmt)
    after = _model_fields(device)
    fixed = {key for key in before.keys() | after.keys() if before.get(key) != after.get(key)}
    return out, fixed


@dataclass
class Judgement:
    """One peer's verdict on one file before and after one output: None = read it, else why it could not."""

    before: str | None
    after: str | None
    differences: list[Difference] = field(default_factory=list)
    intended: list[Difference] = field(default_factory=list)  # what a lint fix meant to change


@dataclass
class FileResult:
    name: str
    judgements: dict[tuple[str, str], Judgement] = field(default_factory=dict)  # (output, peer) -> verdict


def _stated_value(d: Difference, before: Reading) -> bool:
    """A DCF states ParameterValue where the EDS had only a default: that value is the default resolved."""
    return d.field == "value" and d.before is None and _same(before[d.key].get("default"), d.after)


class _Source:
    """A source file's peer readings, each made once."""

    def __init__(self, path: Path) -> None:
        self.path = path
        self._canopen: dict[int | None, Reading | str] = {}
        self._dcfchk: Dcfchk | None = None

    def canopen(self, node_id: int | None) -> Reading | str:
        if node_id not in self._canopen:
            self._canopen[node_id] = canopen_reading(self.path, node_id)
        return self._canopen[node_id]

    def dcfchk(self, node_id: int | None) -> str | None:
        if self._dcfchk is None:
            self._dcfchk = Dcfchk(self.path)
        return self._dcfchk.verdict(node_id)


def _canopen_judgement(source: _Source, after: Path, node_id: int | None, dcf: bool) -> Judgement:
    a, b = source.canopen(node_id), canopen_reading(after, node_id)
    if isinstance(a, str) or isinstance(b, str):
        return Judgement(a if isinstance(a, str) else None, b if isinstance(b, str) else None)
    found = differences(a, b)
    if dcf:
        found = [d for d in found if not _stated_value(d, a)]
    return Judgement(None, None, found)


NOT_CHECKED = "not checked: dcfchk rejected the original"


def judge(path: Path, folder: Path, full: bool = True) -> FileResult:
    """Every peer's reading of `path` against its reading of each output written for it. Unless `full`,
    dcfchk checks an output only when it accepted the original (all the peer-matrix test asks)."""
    result = FileResult(path.name)
    source = _Source(path)
    original = path.read_bytes()
    folder.mkdir(parents=True, exist_ok=True)
    written, fixed = outputs(path)
    for output, data in written.items():
        makes_dcf = output == "convert-dcf"
        target = folder / (f"{output}.dcf" if makes_dcf else f"{output}{path.suffix}")
        target.write_bytes(data)
        for node_id in (NODE_ID,) if makes_dcf else (None, NODE_ID):
            peer = f"python-canopen ({'no node-ID' if node_id is None else f'node-ID {node_id}'})"
            if data == original:  # nothing written: every peer reads it as before
                verdict = source.canopen(node_id)
                result.judgements[(output, peer)] = Judgement(*(2 * (verdict if isinstance(verdict, str) else None,)))
                continue
            judgement = _canopen_judgement(source, target, node_id, makes_dcf)
            if output == "lint-fix":
                judgement.intended = [d for d in judgement.differences if (d.key, d.field) in fixed]
                judgement.differences = [d for d in judgement.differences if (d.key, d.field) not in fixed]
            result.judgements[(output, peer)] = judgement
        before = source.dcfchk(NODE_ID if makes_dcf else None)
        if data == original:
            after = before
        elif before is not None and not full:
            after = NOT_CHECKED
        else:
            after = dcfchk_verdict(target)
        result.judgements[(output, "dcfchk")] = Judgement(before, after)
    return result


@dataclass
class PeerCounts:
    """One row of the matrix: files a peer read before and after, and how many readings differ."""

    output: str
    peer: str
    files: int = 0
    original_accepted: int = 0
    output_accepted: int = 0
    lost: int = 0  # read the original, not the output
    files_differing: int = 0
    fields_differing: int = 0
    fields_fixed: int = 0


def tally(results: list[FileResult]) -> list[PeerCounts]:
    rows: dict[tuple[str, str], PeerCounts] = {}
    for result in results:
        for (output, peer), j in result.judgements.items():
            row = rows.setdefault((output, peer), PeerCounts(output, peer))
            row.files += 1
            row.original_accepted += j.before is None
            row.output_accepted += j.after is None
            row.lost += j.before is None and j.after is not None
            row.files_differing += bool(j.differences)
            row.fields_differing += len(j.differences)
            row.fields_fixed += len(j.intended)
    return list(rows.values())


def table(rows: list[PeerCounts]) -> str:
    head = (
        "output",
        "peer",
        "files",
        "original read",
        "output read",
        "read before, not after",
        "files differing",
        "fields differing",
        "fixed",
    )
    body = [
        (
            r.output,
            r.peer,
            r.files,
            r.original_accepted,
            r.output_accepted,
            r.lost,
            r.files_differing,
            r.fields_differing,
            r.fields_fixed if r.output == "lint-fix" and r.peer != "dcfchk" else "",
        )
        for r in rows
    ]
    widths = [max(len(str(row[i])) for row in [head, *body]) for i in range(len(head))]
    lines = [" | ".join(str(cell).ljust(w) for cell, w in zip(row, widths, strict=True)) for row in [head, *body]]
    lines.insert(1, "-|-".join("-" * w for w in widths))
    return "\n".join(lines)


# --- REAL values: each spelling an author uses, as a probe file the matrix judges like a real one ----------------

# (probe name, data type, entries). python-canopen reads REAL defaults with float() and REAL limits with int();
# lely reads every REAL as an integer, the IEEE bit pattern. A bit pattern and a decimal must each keep the
# reading both peers gave the original.
REAL_PROBES = (
    ("real32-pattern-limits", "0x0008", "LowLimit=0x0\nHighLimit=0xFFFF\nDefaultValue=0x0\nPDOMapping=0"),
    ("real32-pattern-default", "0x0008", "LowLimit=0x00000000\nHighLimit=0x7F7FFFFF\nDefaultValue=0x3F800000"),
    ("real32-pattern-nan", "0x0008", "DefaultValue=0x7FC00000\nPDOMapping=0"),
    ("real64-pattern", "0x0011", "LowLimit=0x0\nHighLimit=0x7FEFFFFFFFFFFFFF\nDefaultValue=0x400921FB54442D18"),
    ("real64-pattern-limit", "0x0011", "HighLimit=0xFFFFFFFF\nDefaultValue=0\nPDOMapping=0"),
    ("real32-decimal", "0x0008", "LowLimit=-10.25\nHighLimit=100\nDefaultValue=1.5\nPDOMapping=0"),
    ("real64-decimal", "0x0011", "LowLimit=-1e3\nHighLimit=1E6\nDefaultValue=3.25\nPDOMapping=0"),
    ("real32-integral-decimal", "0x0008", "LowLimit=-5\nHighLimit=65535\nDefaultValue=2\nPDOMapping=0"),
)


def probe_file(entries: str, data_type: str) -> str:
    """lintkit's complete EDS with its object 2000h replaced by a probe of one value kind."""
    from lintkit import BASE

    probe = f"[2000]\nParameterName=Probe\nObjectType=0x7\nDataType={data_type}\nAccessType=rw\n{entries}\n\n"
    return BASE[: BASE.index("[2000]")] + probe + BASE[BASE.index("[2001]") :]


def real_probes(folder: Path) -> list[Path]:
    """The REAL probes written into `folder`, one EDS each."""
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for name, data_type, entries in REAL_PROBES:
        path = folder / f"{name}.eds"
        path.write_text(probe_file(entries, data_type), encoding="ascii")
        paths.append(path)
    return paths


def judge_all(files: list[Path], folder: Path, full: bool = True, workers: int | None = None) -> list[FileResult]:
    """`judge` over many files in worker processes (the peers are pure Python and single-threaded)."""
    from concurrent.futures import ProcessPoolExecutor

    jobs = [(path, folder / str(n), full) for n, path in enumerate(files)]
    with ProcessPoolExecutor(max_workers=workers or os.cpu_count() or 1) as pool:
        return list(pool.map(_judge_job, jobs))


def _judge_job(job: tuple[Path, Path, bool]) -> FileResult:
    return judge(*job)
