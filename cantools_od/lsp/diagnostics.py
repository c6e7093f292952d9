"""Lint findings as LSP diagnostics: the same codes, severities and messages as `lint --format json`."""

from __future__ import annotations

from lsprotocol import types

from ..lint import RULES, Finding
from ..model import Severity
from .document import Analysis
from .positions import Lines

SOURCE = "cantools-od"
_SEVERITY = {
    Severity.ERROR: types.DiagnosticSeverity.Error,
    Severity.WARNING: types.DiagnosticSeverity.Warning,
    Severity.INFO: types.DiagnosticSeverity.Information,
}


def rule_link(code: str, base: str | None) -> types.CodeDescription | None:
    """The rule's section of docs/rules.md under `base` (its anchor is `code-name`, as ruledocs writes it)."""
    from ..lint.codes import find

    found = find(code) if base else None
    if found is None or base is None:
        return None
    return types.CodeDescription(href=f"{base}#{code.lower()}-{found.name}")


def diagnostic(finding: Finding, lines: Lines, base: str | None) -> types.Diagnostic:
    where = finding.location
    fix = finding.fix
    return types.Diagnostic(
        range=lines.rest_of_line(where.line, where.column),
        message=finding.message,
        severity=_SEVERITY[finding.severity],
        code=finding.code,
        code_description=rule_link(finding.code, base),
        source=SOURCE,
        data={"fix": fix.message, "safe": fix.safe} if fix is not None else None,
    )


def diagnostics(analysis: Analysis, lines: Lines, base: str | None) -> list[types.Diagnostic]:
    """Every finding of the analysis; a refused text or a bad configuration is one diagnostic at the start."""
    start = types.Range(types.Position(0, 0), types.Position(0, 0))
    if analysis.config_error is not None:
        return [types.Diagnostic(start, analysis.config_error, types.DiagnosticSeverity.Error, source=SOURCE)]
    if analysis.refusal is not None:
        code, reason = analysis.refusal
        severity = types.DiagnosticSeverity.Error
        return [
            types.Diagnostic(start, reason, severity, code, rule_link(code, base) if code in RULES else None, SOURCE)
        ]
    return [diagnostic(finding, lines, base) for finding in analysis.findings]
