"""Findings as text (gcc style), JSON, SARIF 2.1.0 or GitHub workflow annotations."""

from __future__ import annotations

import json
from collections import Counter
from typing import Any

from .. import __version__
from ..model import Severity
from ..model.source import capped
from .rules import RULES, Finding


def render(fmt: str, findings: list[Finding], files: int, unread: int = 0) -> str:
    """The findings in the `--format` chosen: text, json, sarif or github."""
    if fmt == "json":
        return as_json(findings)
    if fmt == "sarif":
        return sarif(findings)
    if fmt == "github":
        return github(findings)
    return text(findings, files, unread)


def text(findings: list[Finding], files: int, unread: int = 0) -> str:
    """gcc-style lines, at most a few per code and file (the rest counted), and a summary of all: the files
    checked, and those that could not be read (`unread`, each an EDS000 finding)."""
    shown, notes = capped(findings)
    lines = [finding.format() + _fix_note(finding) for finding in shown] + notes
    counts = Counter(f.severity for f in findings)
    summary = ", ".join(f"{counts[s]} {s.value}{'s' if counts[s] != 1 else ''}" for s in Severity if counts[s])
    checked = f"{files} file{'s' if files != 1 else ''} checked" + (f", {unread} not read" if unread else "")
    lines.append(f"{checked}: {summary or 'no findings'}")
    return "\n".join(lines) + "\n"


def _fix_note(finding: Finding) -> str:
    if finding.fix is None:
        return ""
    kind = "fix" if finding.fix.safe else "unsafe fix, applied only with --unsafe-fixes"
    return f"\n    {kind}: {finding.fix.message}"


def as_json(findings: list[Finding]) -> str:
    items: list[dict[str, Any]] = []
    for f in findings:
        line, column = f.location.shown
        item: dict[str, Any] = {
            "file": f.location.file,
            "line": line,
            "column": column,
            "code": f.code,
            "severity": f.severity.value,
            "message": f.message,
        }
        if f.fix is not None:
            item["fix"] = {"message": f.fix.message, "safe": f.fix.safe}
        items.append(item)
    return json.dumps(items, indent=2) + "\n"


_SARIF_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "note"}


def sarif(findings: list[Finding]) -> str:
    used = sorted({f.code for f in findings} | set(RULES))
    rules = [
        {
            "id": code,
            "name": code,
            "shortDescription": {"text": RULES[code].summary},
            "fullDescription": {"text": RULES[code].description},
            "help": {
                "text": RULES[code].description
                + ("\n\nExample:\n" + RULES[code].example if RULES[code].example else "")
            },
            "defaultConfiguration": {"level": _SARIF_LEVEL[RULES[code].severity]},
            "properties": {"family": RULES[code].family},
        }
        for code in used
        if code in RULES
    ]
    index = {rule["id"]: n for n, rule in enumerate(rules)}
    results = []
    for f in findings:
        line, column = f.location.shown
        location: dict[str, Any] = {
            "artifactLocation": {"uri": f.location.file},
            "region": {"startLine": line, "startColumn": column},
        }
        result: dict[str, Any] = {
            "ruleId": f.code,
            "level": _SARIF_LEVEL[f.severity],
            "message": {"text": f.message},
            "locations": [{"physicalLocation": location}],
        }
        if f.code in index:
            result["ruleIndex"] = index[f.code]
        results.append(result)
    log = {
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [
            {
                "tool": {
                    "driver": {
                        "name": "cantools-od",
                        "version": __version__,
                        "informationUri": "https://pypi.org/project/cantools-od/",
                        "rules": rules,
                    }
                },
                "results": results,
            }
        ],
    }
    return json.dumps(log, indent=2) + "\n"


_GITHUB_LEVEL = {Severity.ERROR: "error", Severity.WARNING: "warning", Severity.INFO: "notice"}


def github(findings: list[Finding]) -> str:
    lines = []
    for f in findings:
        message = f.message.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")
        file = f.location.file.replace(",", "%2C").replace(":", "%3A")
        line, column = f.location.shown
        lines.append(f"::{_GITHUB_LEVEL[f.severity]} file={file},line={line},col={column},title={f.code}::{message}")
    return "\n".join(lines) + ("\n" if lines else "")
