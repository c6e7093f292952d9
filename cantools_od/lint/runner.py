"""Runs the rule catalogue over a device and filters by selection and suppressions."""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, NamedTuple

from ..collector import paused
from ..model import Device, Severity
from ..model.cia301.objects import DATA_TYPE_AREA
from ..xdd import refused
from .codes import load as load_families
from .config import Selection
from .reader import reader_fix
from .rules import RULES, Context, Finding, LintOptions, Rule
from .suppress import Suppressions

if TYPE_CHECKING:
    from collections.abc import Iterator

# Families about the CiA 306 INI text itself (key spelling, object lists, EDS reader disagreements):
# an XDD/XDC has none of it.
_EDS_TEXT_FAMILIES = frozenset({"syntax", "objlists", "portability"})
_ORDER = {Severity.ERROR: 0, Severity.WARNING: 1, Severity.INFO: 2}


@dataclass(frozen=True)
class Edit:
    """An edit inside the sections of one object (lsp/incremental.py): the object's index, the lines (from 1)
    of its sections before and after the edit, the lines above the first one changed and the lines it added
    (below 0: removed). Every line below the changed ones moved by that many."""

    index: int
    old_lines: set[int]
    new_lines: set[int]
    start: int
    delta: int


class Linted(NamedTuple):
    """A device's findings, with what the next check after an edit of one object may take from them: each
    per-object rule's findings (selected, not yet suppressed), for the options and selection they were found with."""

    findings: list[Finding]
    per_object: dict[str, list[Finding]]
    options: LintOptions
    selection: Selection


def lint(device: Device, options: LintOptions | None = None, selection: Selection | None = None) -> list[Finding]:
    """Every enabled finding for one device, in file order."""
    return linted(device, options, selection).findings


def linted(
    device: Device,
    options: LintOptions | None = None,
    selection: Selection | None = None,
    since: tuple[Linted, Edit] | None = None,
) -> Linted:
    """`lint`'s findings, kept for the next check. `since`: the check of the text before an edit of one object
    and that edit; the per-object rules then judge the edited object alone and keep their findings elsewhere
    (moved with their lines), which is the same as judging the whole device."""
    load_families()
    options = options or LintOptions()
    selection = selection or Selection()
    # Rules judge the device as built: objects the project leaves out (CO_disabled) are not on the bus.
    built = device.as_built()
    context = Context(built, options)
    findings = [
        Finding(d.code, d.severity, d.message, d.location, reader_fix(context, d))
        for d in device.diagnostics
        if selection.enabled(d.code, device.source)
    ]
    reuse = None
    if since is not None and since[0].options == options and since[0].selection == selection:
        reuse = (since[0], since[1], Context(_view(built, since[1].index), options))
    per_object: dict[str, list[Finding]] = {}
    with paused():  # the walks are acyclic; a full collector pass over a large device took a fifth of its check
        for rule, found, ok in _checked(device, selection, context, reuse):
            if rule.per_object and ok:
                per_object[rule.code] = found
            findings.extend(found)
    suppressions = Suppressions(device)
    kept = [f for f in findings if not suppressions.silenced(f.code, f.location.line)]
    return Linted(sorted(set(kept), key=_sort_key), per_object, options, selection)


def _checked(
    device: Device, selection: Selection, context: Context, reuse: tuple[Linted, Edit, Context] | None
) -> Iterator[tuple[Rule, list[Finding], bool]]:
    """Each enabled rule with its findings and whether it ran to its end; a family's shared walks are dropped
    when the next family starts (`Context.forget`)."""
    family = ""
    for rule in _enabled(device, selection):
        if rule.family != family:
            family = rule.family
            context.forget()
        found, ok = _per_object(rule, context, selection, reuse) if rule.per_object else _run(rule, context, selection)
        yield rule, found, ok


def _enabled(device: Device, selection: Selection) -> Iterator[Rule]:
    # A file the reader refused (XDD001-XDD004) has no model: rules would report what is merely unread.
    for rule in () if refused(device) else RULES.values():
        if rule.check is None or not selection.enabled(rule.code, device.source):
            continue
        if device.file_format != "eds" and rule.family in _EDS_TEXT_FAMILIES:
            continue
        yield rule


def _run(rule: Rule, context: Context, selection: Selection) -> tuple[list[Finding], bool]:
    """The rule's selected findings, and whether it ran to its end (a rule's bug must not hide every other finding)."""
    assert rule.check is not None
    file = context.device.source
    try:
        return [f for f in rule.check(context) if selection.enabled(f.code, file)], True
    except Exception as error:
        message = f"rule {rule.code} failed: {type(error).__name__}: {error}"
        return [Finding("LNT001", Severity.ERROR, message, context.at(None))], False


def _per_object(
    rule: Rule, context: Context, selection: Selection, reuse: tuple[Linted, Edit, Context] | None
) -> tuple[list[Finding], bool]:
    """A per-object rule's findings: after an edit, those of the edited object's lines found in `view` (the device
    with that object and the data-type definitions only) and the earlier ones of every other line, moved."""
    before = reuse[0].per_object.get(rule.code) if reuse is not None else None
    if reuse is None or before is None:
        return _run(rule, context, selection)
    _, edit, view = reuse
    found, ok = _run(rule, view, selection)
    if not ok:
        return _run(rule, context, selection)  # say it as the whole device's check says it
    kept = [moved(f, edit.start, edit.delta) for f in before if f.location.line not in edit.old_lines]
    return kept + [f for f in found if f.location.line in edit.new_lines], True


def _view(device: Device, index: int) -> Device:
    """The device with only object `index` and the data-type definitions (what may type its values)."""
    objects = {number: obj for number, obj in device.objects.items() if number == index or number in DATA_TYPE_AREA}
    return device.model_copy(update={"objects": objects})


def moved(finding: Finding, start: int, delta: int) -> Finding:
    """A finding of the text before an edit, on the line it moved to: lines below `start` moved by `delta`."""
    where = finding.location
    if delta == 0 or where.line <= start:
        return finding
    fix = finding.fix
    if fix is not None and fix.lines:
        fix = replace(fix, lines=tuple(line + delta if line > start else line for line in fix.lines))
    return finding._replace(location=where.model_copy(update={"line": where.line + delta}), fix=fix)


def _sort_key(finding: Finding) -> tuple[str, int, int, str, str]:
    where = finding.location
    return (where.file, where.line, where.column, finding.code, finding.message)


def has_errors(findings: list[Finding]) -> bool:
    return any(f.severity is Severity.ERROR for f in findings)


def lint_network(devices: list[Device], options: LintOptions, selection: Selection | None = None) -> list[Finding]:
    """Findings across the nodes of one network, filtered like a single file's."""
    from .network import lint_network as network_findings

    selection = selection or Selection()
    suppressions = {device.source: Suppressions(device) for device in devices}
    kept = []
    for finding in network_findings(devices, options):
        where = suppressions.get(finding.location.file)
        if not selection.enabled(finding.code, finding.location.file):
            continue
        if where is not None and where.silenced(finding.code, finding.location.line):
            continue
        kept.append(finding)
    return sorted(kept, key=_sort_key)
