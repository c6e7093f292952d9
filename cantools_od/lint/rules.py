"""Rules, findings and fixes: what every rule family module builds on.

A family module declares its rules with the `rule` decorator; each check
receives a `Context` and yields `Finding`s. Codes are stable: a code, once
released, keeps its meaning.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field

from ..model import Device, Location, Object, Section, Severity, SubObject, Variable


@dataclass(frozen=True)
class Fix:
    """A change that resolves a finding. Safe fixes are applied by `--fix`; others are only shown."""

    message: str
    safe: bool
    apply: Callable[[Device], None] = field(compare=False, repr=False)


@dataclass(frozen=True)
class Finding:
    code: str
    severity: Severity
    message: str
    location: Location
    fix: Fix | None = None

    def format(self) -> str:
        return f"{self.location}: {self.severity.value}: {self.message} [{self.code}]"


@dataclass(frozen=True)
class LintOptions:
    can_fd: bool = False
    node_id: int | None = None
    profile: str | None = None
    """A target's extra rules to run too: "canopennode" (lint --profile, and gen -t canopennode)."""

    @property
    def max_pdo_bits(self) -> int:
        return 512 if self.can_fd else 64


class Context:
    """One device under check, with helpers that turn model parts into locations."""

    def __init__(self, device: Device, options: LintOptions) -> None:
        self.device = device
        self.options = options

    def report(self, code: str, message: str, location: Location, fix: Fix | None = None) -> Finding:
        """A finding of rule `code`, with the rule's severity."""
        return Finding(code, RULES[code].severity, message, location, fix)

    def at(self, section: Section | None, key: str | None = None) -> Location:
        """The key's line, or the section header when the key is absent or not given."""
        if section is None or section.origin is None:
            return Location(file=self.device.source, line=0, column=0)
        return section.origin.key(key) if key else section.origin.header()

    def value_at(self, section: Section | None, key: str) -> Location:
        if section is None or section.origin is None:
            return self.at(section)
        return section.origin.value(key)

    def variables(self) -> Iterator[tuple[Object, int, Variable]]:
        """Every VAR object (sub-index 0) and every sub-object, with its owner."""
        for obj in self.device.objects.values():
            if obj.has_subs:
                for subindex, sub in obj.subs.items():
                    yield obj, subindex, sub
            else:
                yield obj, 0, obj

    def section_of(self, owner: Object, var: Variable) -> Section:
        """Where to report on `var`: itself, or its owner when it has no section (CompactSubObj)."""
        if isinstance(var, SubObject) and var.implicit:
            return owner
        return var


Check = Callable[[Context], Iterable[Finding]]


@dataclass(frozen=True)
class Rule:
    code: str
    severity: Severity
    summary: str
    description: str
    example: str
    family: str
    check: Check | None  # None: reported while reading (see the reader codes)


RULES: dict[str, Rule] = {}


def rule(code: str, severity: Severity, summary: str, description: str, example: str = "") -> Callable[[Check], Check]:
    """Register a check function under a code. The family is the module's last name part."""

    def register(check: Check) -> Check:
        family = check.__module__.rsplit(".", 1)[-1]
        if code in RULES:
            raise ValueError(f"rule {code} declared twice")
        RULES[code] = Rule(code, severity, summary, description.strip(), example.strip(), family, check)
        return check

    return register


def declare(
    code: str, severity: Severity, summary: str, description: str, example: str = "", family: str = "reader"
) -> None:
    """Document a code that the reader reports, so `rules` lists it and `--select` knows it."""
    if code in RULES:
        raise ValueError(f"rule {code} declared twice")
    RULES[code] = Rule(code, severity, summary, description.strip(), example.strip(), family, None)


def find(code: str) -> Rule:
    return RULES[code]
