"""The Markdown import report: sources, counts, conflicts with both locations, inferred values, problems."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ..model import Device, Diagnostic, ObjectKind, Severity
from .entries import ReadResult
from .merge import Conflict, MergeResult, Policy, display
from .overrides import Overrides


@dataclass
class ImportResult:
    device: Device
    merged: MergeResult
    reads: list[ReadResult]
    diagnostics: list[Diagnostic]
    policy: Policy
    overrides: Overrides | None = None
    lint_explained: dict[str, str] = field(default_factory=dict)

    @property
    def errors(self) -> list[Diagnostic]:
        return [d for d in self.diagnostics if d.severity is Severity.ERROR]

    def report(self) -> str:
        """The Markdown import report."""
        return render(self)


def _cell(text: str) -> str:
    return text.replace("|", "\\|").replace("\n", " ")


def _where(index: int, sub: int | None) -> str:
    return f"{index:04X}h" if sub is None else f"{index:04X}h sub {sub}"


def _conflict_row(conflict: Conflict) -> str:
    parts = []
    for i, candidate in enumerate(conflict.candidates):
        places = (
            ", ".join(
                f"{Path(s.file).name or 'overrides'}:{s.line} ({s.layout})" for s in candidate.sources[:4] if s.line
            )
            or "structure"
        )
        mark = "**" if i == conflict.chosen else ""
        parts.append(f"{mark}{_cell(display(candidate.value, conflict.field))}{mark} — {_cell(places)}")
    resolution = conflict.resolution + (f": {conflict.reason}" if conflict.reason else "")
    return f"| {_where(conflict.index, conflict.sub)} | {conflict.field} | {'<br>'.join(parts)} | {_cell(resolution)} |"


def render(result: ImportResult) -> str:
    merged = result.merged
    device = result.device
    lines = ["# Import report", ""]
    lines.append("| Source | Layout | Entries read |")
    lines.append("|---|---|---|")
    for read in result.reads:
        lines.append(f"| {_cell(read.file)} | {read.layout} | {len(read.entries)} |")
    pairs = sum(max(1, len(obj.subs)) for obj in device.objects.values())
    lines += [
        "",
        f"Objects: {len(device.objects)}; (index, sub-index) pairs: {pairs}; "
        f"conflicts: {len(merged.conflicts)} ({sum(1 for c in merged.conflicts if c.field != 'name')} "
        f"outside names); inferred values: {len(merged.inferred)}.",
        "",
        "Policy for conflicts without an override: "
        f"`{result.policy}` (docs/import-table.md). The chosen value is in **bold**.",
        "",
    ]
    value_conflicts = [c for c in merged.conflicts if c.field != "name"]
    name_conflicts = [c for c in merged.conflicts if c.field == "name"]
    for title, conflicts in (("Conflicts", value_conflicts), ("Name variants", name_conflicts)):
        lines += [f"## {title}", ""]
        if not conflicts:
            lines += ["None.", ""]
            continue
        lines += ["| Entry | Field | Values and sources | Resolution |", "|---|---|---|---|"]
        lines += [_conflict_row(c) for c in conflicts]
        lines.append("")
    lines += [
        "## Inferred values",
        "",
        "Not stated by any source as a value: filled in from CiA 301 so that the EDS is well-formed, or entries a "
        "capacity stated in the manual's prose creates (the sentence is quoted).",
        "",
    ]
    if merged.inferred:
        lines += ["| Entry | Field | Value |", "|---|---|---|"]
        for index, sub, field_name, value in merged.inferred:
            lines.append(f"| {_where(index, sub)} | {field_name} | {_cell(value)} |")
    else:
        lines.append("None.")
    lines.append("")
    if merged.excluded:
        lines += ["## Excluded objects", "", "| Object | Reason |", "|---|---|"]
        for index, reason in sorted(merged.excluded.items()):
            lines.append(f"| {index:04X}h | {_cell(reason)} |")
        lines.append("")
    if merged.excluded_entries:
        lines += ["## Excluded entries", "", "| Entry | Reason |", "|---|---|"]
        for index, sub, reason in merged.excluded_entries:
            lines.append(f"| {_where(index, sub)} | {_cell(reason)} |")
        lines.append("")
    stated = [(r.file, i, c) for r in result.reads for i, c in r.excluded.items() if i in device.objects]
    if stated:
        lines += [
            "## Objects the manual leaves out of its own EDS",
            "",
            "Imported, because the manual documents them; exclude them in the overrides file if wanted.",
            "",
        ]
        for file, index, cell in stated:
            lines.append(f"- {index:04X}h — {Path(file).name}:{cell.line}: {_cell(cell.text)}")
        lines.append("")
    lines += ["## Diagnostics", ""]
    lines += [f"- {_cell(_diag(d))}" for d in result.diagnostics] or ["None."]
    lines.append("")
    lines += ["## Objects", "", "| Index | Name | Kind | Sub-indices | Sources |", "|---|---|---|---|---|"]
    for index, obj in device.objects.items():
        merged_obj = merged.objects.get(index)
        sources = ""
        if merged_obj is not None:
            places = sorted({f"{Path(s.file).name}:{s.line}" for s in merged_obj.sources if s.line})
            sources = ", ".join(places[:6]) + (" …" if len(places) > 6 else "")
        kind = obj.kind.name if obj.kind is not ObjectKind.VAR else "VAR"
        lines.append(f"| {index:04X}h | {_cell(obj.name)} | {kind} | {len(obj.subs)} | {_cell(sources)} |")
    lines.append("")
    return "\n".join(lines)


def _diag(diagnostic: Diagnostic) -> str:
    return diagnostic.format()
