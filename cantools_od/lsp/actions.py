"""Code actions: the fixes `lint --fix` applies, as text edits computed when an action is chosen.

Offering actions costs a look at the findings of the lines asked about; the edit of each (reading the text
again, fixing and writing it back) is made by `codeAction/resolve`, so moving the cursor never waits for it.
A client that cannot resolve gets the edits at once.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from lsprotocol import types

from ..api import dumps, format_for
from ..eds.decode import decode_as
from ..lint import Finding, LintOptions, lint
from .document import Analysis, Encoding, path_of, read, selection_for
from .edits import one_edit

ALL = "all"
"""The key of the action that applies every safe fix."""


class NotFixed(Exception):
    """The fix cannot be made; the message says why, in one line."""


def _key(finding: Finding) -> list[Any]:
    return [finding.code, finding.location.line, finding.location.column, finding.message]


def _path(uri: str) -> Path:
    return path_of(uri) or Path(uri.rsplit("/", 1)[-1])


def fixed_text(uri: str, analysis: Analysis, encoding: Encoding, options: LintOptions, chosen: list[Any]) -> str:
    """The document with the fixes of the findings keyed `chosen` (ALL: every safe fix) applied as `lint --fix`
    applies them: each to the model read afresh from the same text, then written back by the preserving writer."""
    mangled = encoding.mangled(analysis.text)
    if mangled:
        raise NotFixed(mangled)
    device = read(uri, encoding.bytes(analysis.text))
    fresh = lint(device, options, selection_for(uri))
    for finding in fresh:
        if finding.fix is not None and (finding.fix.safe if chosen == [ALL] else _key(finding) in chosen):
            finding.fix.apply(device)
    return decode_as(dumps(device, format_for(_path(uri))))[0]


def _title(finding: Finding) -> str:
    assert finding.fix is not None
    label = "" if finding.fix.safe else " (unsafe: lint --fix leaves it; check the result)"
    return f"{finding.code}: {finding.fix.message}{label}"


def code_actions(
    uri: str, analysis: Analysis, lines: tuple[int, int], diagnostics: list[types.Diagnostic]
) -> list[types.CodeAction]:
    """A quick fix for each finding with a fix on the lines (from 1) asked about, safe ones preferred, and
    `lint --fix` of the whole document when it has safe fixes; each without its edit, which `resolve` makes."""
    first, last = lines
    here = [f for f in analysis.findings if f.fix is not None and first <= max(f.location.line, 1) <= last]
    actions = []
    for finding in sorted(here, key=lambda f: f.fix is None or not f.fix.safe):
        related = [d for d in diagnostics if d.code == finding.code and d.message == finding.message]
        actions.append(
            types.CodeAction(
                title=_title(finding),
                kind=types.CodeActionKind.QuickFix,
                diagnostics=related or None,
                is_preferred=bool(finding.fix and finding.fix.safe),
                data={"uri": uri, "fix": [_key(finding)]},
            )
        )
    safe = sum(1 for f in analysis.findings if f.fix is not None and f.fix.safe)
    if safe:
        actions.append(
            types.CodeAction(
                title=f"Apply the {safe} safe fix{'es' if safe != 1 else ''} (lint --fix)",
                kind=types.CodeActionKind.SourceFixAll,
                data={"uri": uri, "fix": [ALL]},
            )
        )
    return actions


def wanted(action: types.CodeAction) -> tuple[str, list[list[Any]]] | None:
    """The document and the findings' keys an action offered by `code_actions` stands for."""
    data = action.data
    if not isinstance(data, dict) or not isinstance(data.get("uri"), str) or not isinstance(data.get("fix"), list):
        return None
    return data["uri"], data["fix"]


def resolve(action: types.CodeAction, analysis: Analysis, encoding: Encoding, options: LintOptions) -> types.CodeAction:
    """The action with its edit, made from the document's last analysis."""
    found = wanted(action)
    if found is None:
        return action
    uri, chosen = found
    new = fixed_text(uri, analysis, encoding, options, chosen)
    action.edit = types.WorkspaceEdit(changes={uri: one_edit(analysis.text, new)})
    return action
