"""Import vendor object-dictionary tables: `import_tables(sources) -> ImportResult`."""

from __future__ import annotations

import os
from pathlib import Path

from ..model import Diagnostic, Severity
from .build import BuildInfo, build
from .capacity import Capacity, apply_capacities, read_capacities
from .entries import ReadResult, loc
from .facts import expand
from .manual import TEXT_LAYOUTS, detect_text_layout, read_manual
from .merge import MergeOptions, Policy, display, merge
from .overrides import Overrides, load_overrides
from .report import ImportResult
from .tables import TABLE_LAYOUTS, read_delimited, read_markdown, read_xlsx
from .text import read_text

LAYOUTS = TABLE_LAYOUTS + TEXT_LAYOUTS


class UnreadableInput(Exception):
    """An input could not be read at all (the CLI exits with 2)."""

    def __init__(self, diagnostics: list[Diagnostic]) -> None:
        super().__init__("; ".join(d.format() for d in diagnostics))
        self.diagnostics = diagnostics


def detect_layout(path: str, data: bytes) -> str:
    """The layout of a source, from its extension, else its content."""
    suffix = Path(path).suffix.lower()
    if suffix in (".xlsx", ".xlsm") or data[:4] == b"PK\x03\x04":
        return "xlsx"
    if suffix == ".csv":
        return "csv"
    if suffix in (".tsv", ".tab"):
        return "tsv"
    if suffix in (".md", ".markdown"):
        return "markdown"
    text = read_text(data)
    head = [line for line in text.splitlines()[:200] if line.strip()]
    if head and sum(1 for line in head if line.lstrip().startswith("|")) > len(head) // 2:
        return "markdown"
    return detect_text_layout(text)


def read_source(path: str, data: bytes, layout: str | None = None) -> ReadResult:
    """One source read with the given or detected layout."""
    chosen = layout or detect_layout(path, data)
    if chosen == "xlsx":
        return read_xlsx(path, data)
    text = read_text(data)
    if chosen == "csv":
        return read_delimited(path, text, ",", "csv")
    if chosen == "tsv":
        return read_delimited(path, text, "\t", "tsv")
    if chosen == "markdown":
        return read_markdown(path, text)
    return read_manual(path, text, chosen)


def import_tables(
    sources: list[str | os.PathLike[str]],
    overrides: str | os.PathLike[str] | None = None,
    layout: str | None = None,
    policy: Policy | None = None,
    comments: bool = True,
    output_name: str = "",
) -> ImportResult:
    """Read every source, merge them, apply the overrides and build a device.

    Raises UnreadableInput when a source or the overrides file cannot be read at all."""
    if layout is not None and layout not in LAYOUTS:
        raise ValueError(f"unknown layout {layout!r}; one of {', '.join(LAYOUTS)}")
    fatal: list[Diagnostic] = []
    reads: list[ReadResult] = []
    capacities: list[Capacity] = []
    for given in sources:
        path = os.fspath(given)
        try:
            data = Path(path).read_bytes()
        except OSError as error:
            fatal.append(_fatal(path, f"cannot read: {error.strerror or error}"))
            continue
        reads.append(read_source(path, data, layout))
        if reads[-1].layout in TEXT_LAYOUTS:  # a manual's prose may state how many entries it lists
            capacities += read_capacities(path, read_text(data))
    loaded: Overrides | None = None
    if overrides is not None:
        opath = os.fspath(overrides)
        try:
            loaded = load_overrides(opath, Path(opath).read_bytes())
        except OSError as error:
            fatal.append(_fatal(opath, f"cannot read: {error.strerror or error}", "IMP003"))
        else:
            fatal.extend(d for d in loaded.diagnostics if d.severity is Severity.ERROR)
    fatal.extend(d for r in reads for d in r.diagnostics if d.code == "IMP001")
    if fatal:
        raise UnreadableInput(fatal)
    options = loaded.options if loaded is not None else MergeOptions()
    if policy is not None:
        options.policy = policy
    facts, reads = expand(reads)
    merged = merge(facts, options, [r.file for r in reads])
    apply_capacities(merged, capacities)
    vendor = (loaded.vendor_name if loaded else None) or next((r.vendor_name for r in reads if r.vendor_name), None)
    info = BuildInfo(
        vendor_name=vendor,
        product_name=loaded.product_name if loaded else None,
        description="Imported from " + ", ".join(Path(r.file).name for r in reads),
        file_name=output_name,
        sources=[f"{r.file} ({r.layout})" for r in reads],
        comments=comments,
        dummy_usage=loaded.dummy_usage if loaded else None,
        baud_rates=loaded.baud_rates if loaded else {},
    )
    device, problems = build(merged, info)
    diagnostics = [d for r in reads for d in r.diagnostics] + problems
    for override in merged.unused_overrides:
        diagnostics.append(
            Diagnostic(
                code="IMP040",
                severity=Severity.WARNING,
                message=f"override of {override.index:04X}h"
                + (f" sub {override.sub}" if override.sub is not None else "")
                + f" {override.field} matches no imported entry",
                location=loc(override.source.file, override.source.line),
            )
        )
    for conflict in merged.conflicts:
        if conflict.resolution.startswith("policy") and conflict.field != "name":
            chosen = conflict.candidates[conflict.chosen]
            first = chosen.sources[0]
            others = [c for i, c in enumerate(conflict.candidates) if i != conflict.chosen]
            other = others[0].sources[0] if others and others[0].sources else None
            where = f"{conflict.index:04X}h" + (f" sub {conflict.sub}" if conflict.sub is not None else "")
            diagnostics.append(
                Diagnostic(
                    code="IMP020",
                    severity=Severity.WARNING,
                    message=f"{where} {conflict.field}: sources disagree; took "
                    f"{_show(chosen.value, conflict.field)} by {conflict.resolution}"
                    + (
                        f" over {_show(others[0].value, conflict.field)} ({Path(other.file).name}:{other.line})"
                        if other is not None
                        else ""
                    ),
                    location=loc(first.file, first.line),
                )
            )
    return ImportResult(
        device=device,
        merged=merged,
        reads=reads,
        diagnostics=diagnostics,
        policy=options.policy,
        overrides=loaded,
        lint_explained=loaded.lint if loaded else {},
    )


def _show(value: object, field_name: str) -> str:
    return display(value, field_name)  # type: ignore[arg-type]


def _fatal(path: str, message: str, code: str = "IMP001") -> Diagnostic:
    return Diagnostic(code=code, severity=Severity.ERROR, message=message, location=loc(path, 0))
