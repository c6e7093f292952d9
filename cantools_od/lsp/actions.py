"""Code actions and formatting: the fixes `lint --fix` applies, and `fmt`'s canonical form, as text edits."""

from __future__ import annotations

from pathlib import Path

from lsprotocol import types

from ..api import dumps, format_for
from ..cli.common import errors_to_fix
from ..eds.decode import decode_as
from ..lint import Finding, LintOptions, lint
from ..lint.config import load_int_style
from .document import Analysis, Encoding, path_of, read, selection_for
from .edits import edits, one_edit


def _same(a: Finding, b: Finding) -> bool:
    return (a.code, a.location, a.message) == (b.code, b.location, b.message)


def _path(uri: str) -> Path:
    return path_of(uri) or Path(uri.rsplit("/", 1)[-1])


def fixed_text(uri: str, analysis: Analysis, encoding: Encoding, options: LintOptions, chosen: list[Finding]) -> str:
    """The document with the fixes of `chosen` applied as `lint --fix` applies them: each to the model read
    afresh from the same text, then written back by the preserving writer."""
    device = read(uri, encoding.bytes(analysis.text))
    fresh = lint(device, options, selection_for(uri))
    for finding in fresh:
        if finding.fix is not None and any(_same(finding, wanted) for wanted in chosen):
            finding.fix.apply(device)
    return decode_as(dumps(device, format_for(_path(uri))))[0]


def _title(finding: Finding) -> str:
    assert finding.fix is not None
    label = "" if finding.fix.safe else " (unsafe: lint --fix leaves it; check the result)"
    return f"{finding.code}: {finding.fix.message}{label}"


def code_actions(
    uri: str,
    analysis: Analysis,
    encoding: Encoding,
    options: LintOptions,
    lines: tuple[int, int],
    diagnostics: list[types.Diagnostic],
) -> list[types.CodeAction]:
    """A quick fix for each finding with a fix on the lines (from 1) asked about, safe ones preferred,
    and `lint --fix` of the whole document when it has safe fixes."""
    first, last = lines
    here = [f for f in analysis.findings if f.fix is not None and first <= max(f.location.line, 1) <= last]
    actions = []
    for finding in sorted(here, key=lambda f: f.fix is None or not f.fix.safe):
        new = fixed_text(uri, analysis, encoding, options, [finding])
        related = [d for d in diagnostics if d.code == finding.code and d.message == finding.message]
        actions.append(
            types.CodeAction(
                title=_title(finding),
                kind=types.CodeActionKind.QuickFix,
                diagnostics=related or None,
                is_preferred=bool(finding.fix and finding.fix.safe),
                edit=types.WorkspaceEdit(changes={uri: one_edit(analysis.text, new)}),
            )
        )
    safe = [f for f in analysis.findings if f.fix is not None and f.fix.safe]
    if safe:
        new = fixed_text(uri, analysis, encoding, options, safe)
        actions.append(
            types.CodeAction(
                title=f"Apply the {len(safe)} safe fix{'es' if len(safe) != 1 else ''} (lint --fix)",
                kind=types.CodeActionKind.SourceFixAll,
                edit=types.WorkspaceEdit(changes={uri: one_edit(analysis.text, new)}),
            )
        )
    return actions


class NotFormatted(Exception):
    """fmt leaves the document as it is; the message says why, in one line."""


def formatted(uri: str, analysis: Analysis, encoding: Encoding) -> str:
    """The document as `fmt` writes it: canonical form, integers by the nearest `[tool.cantools-od]`."""
    device = analysis.device
    if device is None:
        raise NotFormatted(analysis.refusal[1] if analysis.refusal else analysis.config_error or "not read")
    problems = errors_to_fix(device)
    if problems:
        raise NotFormatted(f"not formatted: {problems}")
    path = _path(uri)
    try:
        style = load_int_style(path.parent if path_of(uri) is not None else Path.cwd())
    except ValueError as error:
        raise NotFormatted(f"configuration: {error}") from None
    fresh = read(uri, encoding.bytes(analysis.text))  # dumps may not change the device linted, but it is not ours
    return dumps(fresh, format_for(path), style="canonical", int_style=style).decode("utf-8")


def format_edits(uri: str, analysis: Analysis, encoding: Encoding, within: types.Range | None) -> list[types.TextEdit]:
    """fmt's changes: for the whole document one edit (the lines between the common head and tail); for a
    range, the runs of changed lines (difflib's) that touch it."""
    new = formatted(uri, analysis, encoding)
    if within is None:
        return one_edit(analysis.text, new)
    found = edits(analysis.text, new)
    first, last = within.start.line, within.end.line
    return [e for e in found if e.range.start.line <= last and e.range.end.line >= first]
