"""Runs the rule catalogue over a device and filters by selection and suppressions."""

from __future__ import annotations

from ..model import Device, Severity
from ..xdd import refused
from .codes import load as load_families
from .config import Selection
from .reader import reader_fix
from .rules import RULES, Context, Finding, LintOptions
from .suppress import Suppressions

# Families about the CiA 306 INI text itself (key spelling, object lists, EDS reader disagreements):
# an XDD/XDC has none of it.
_EDS_TEXT_FAMILIES = frozenset({"syntax", "objlists", "portability"})
_ORDER = {Severity.ERROR: 0, Severity.WARNING: 1, Severity.INFO: 2}


def lint(device: Device, options: LintOptions | None = None, selection: Selection | None = None) -> list[Finding]:
    """Every enabled finding for one device, in file order."""
    load_families()
    options = options or LintOptions()
    selection = selection or Selection()
    file = device.source
    context = Context(device, options)
    findings = [
        Finding(d.code, d.severity, d.message, d.location, reader_fix(context, d))
        for d in device.diagnostics
        if selection.enabled(d.code, file)
    ]
    # A file the reader refused (XDD001-XDD004) has no model: rules would report what is merely unread.
    for rule in () if refused(device) else RULES.values():
        if rule.check is None or not selection.enabled(rule.code, file):
            continue
        if device.file_format != "eds" and rule.family in _EDS_TEXT_FAMILIES:
            continue
        try:
            findings.extend(f for f in rule.check(context) if selection.enabled(f.code, file))
        except Exception as error:  # a rule's bug must not hide every other finding
            findings.append(
                Finding(
                    "LNT001",
                    Severity.ERROR,
                    f"rule {rule.code} failed: {type(error).__name__}: {error}",
                    context.at(None),
                )
            )
    suppressions = Suppressions(device)
    kept = [f for f in findings if not suppressions.silenced(f.code, f.location.line)]
    return sorted(set(kept), key=_sort_key)


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
