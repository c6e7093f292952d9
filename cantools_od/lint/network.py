"""Rule family: checks across the nodes of one network (several DCFs)."""

from __future__ import annotations

from ..model import Device
from .rules import Finding, LintOptions


def lint_network(devices: list[Device], options: LintOptions) -> list[Finding]:
    return []
