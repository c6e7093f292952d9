"""Rules, findings and fixes: what every rule family module builds on.

A family module declares its rules with the `rule` decorator; each check
receives a `Context` and yields `Finding`s. Codes are stable: a code, once
released, keeps its meaning.
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator
from dataclasses import dataclass, field
from enum import Enum
from functools import cached_property
from typing import Any, NamedTuple, TypeVar

from ..canopennode.profile import StackConfig
from ..model import Device, Dialect, Location, Object, Section, Severity, SubObject, Variable
from ..model.cia301.pdo import frame_bits
from ..model.source import location

_T = TypeVar("_T")


@dataclass(frozen=True)
class Fix:
    """A change that resolves a finding. Safe fixes are applied by `--fix`; others are only shown."""

    message: str
    safe: bool
    apply: Callable[[Device], None] = field(compare=False, repr=False)
    lines: tuple[int, ...] = ()
    """Lines of the file the fix rewrites or removes besides the finding's own (lines it adds are not named)."""


class Finding(NamedTuple):
    code: str
    severity: Severity
    message: str
    location: Location
    fix: Fix | None = None

    def format(self) -> str:
        return f"{self.location}: {self.severity.value}: {self.message} [{self.code}]"


CANOPENNODE = "canopennode"
"""The profile of the CANopenNode v4 stack (lint --profile canopennode, gen -t canopennode)."""


class LintOptions(NamedTuple):
    can_fd: bool = False
    node_id: int | None = None
    profile: str | None = None
    """A target's extra rules to run too: "canopennode" (lint --profile, and gen -t canopennode)."""
    stack: StackConfig | None = None
    """The CANopenNode build configuration the project declares (CO_CONFIG_*), for the canopennode profile."""

    @property
    def max_pdo_bits(self) -> int:
        return frame_bits(self.can_fd)


class Context:
    """One device under check, with helpers that turn model parts into locations."""

    def __init__(self, device: Device, options: LintOptions) -> None:
        self.device = device
        self.options = options
        self.memo: dict[str, Any] = {}
        """What several rules of a family derive from the device alike (walks of its entries), made once for the
        family (see `forget`)."""

    @property
    def for_canopennode(self) -> bool:
        """The device is built with the CANopenNode stack: checked with its profile, or written by CANopenEditor
        (an XDD with CO_* properties, an EDS with its `;StorageLocation=` lines)."""
        return self.options.profile == CANOPENNODE or self.device.dialect is Dialect.CANOPENNODE

    def once(self, key: str, make: Callable[[], _T]) -> _T:
        """`make()`, made once for every rule of a family that asks under `key`."""
        if key not in self.memo:
            self.memo[key] = make()
        found: _T = self.memo[key]
        return found

    def forget(self) -> None:
        """Drop what `once` made: the runner calls this between rule families. A walk holds an item per entry
        of the device, so keeping every family's walks at once was the peak memory of checking a large file;
        making one again for a later family costs a walk, not a rule's work."""
        self.memo.clear()

    def report(self, code: str, message: str, location: Location, fix: Fix | None = None) -> Finding:
        """A finding of rule `code`, with the rule's severity."""
        return Finding(code, RULES[code].severity, message, location, fix)

    def at(self, section: Section | None, key: str | None = None) -> Location:
        """The key's line, or the section header when the key is absent or not given."""
        if section is None or section.origin is None:
            return location(self.device.source, 0, 0)
        return section.origin.key(key) if key else section.origin.header()

    def value_at(self, section: Section | None, key: str) -> Location:
        if section is None or section.origin is None:
            return self.at(section)
        return section.origin.value(key)

    def written_at(self, owner: Object, var: Variable, key: str) -> Location:
        """Where `var`'s `key` is written: its own line, the [xxxxValue]/[xxxxName] entry that holds a
        CompactSubObj value, or the owner's header for an entry the file implies without writing it."""
        implicit = isinstance(var, SubObject) and var.implicit
        if implicit and (var.origin is None or var.origin.where(key) is None):
            return self.at(owner)
        return self.value_at(var, key)

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


class Clause(Enum):
    """The clauses of the severity policy (docs/rules.md): why a code has its severity. A file's findings judge the
    file by the peers (python-canopen, lely's dcfchk/dcfgen, CANopenEditor, the CANopenNode stack); the codes a
    command reports about its own run (import-table, gen, lint) judge the run."""

    PEER_CANNOT_LOAD = "peer-cannot-load"
    PEER_READS_OTHERWISE = "peer-reads-otherwise"
    DEVICE_MISBEHAVES = "device-misbehaves"
    NOT_DONE = "not-done"
    PORTABILITY = "portability"
    STYLE = "style"
    BEYOND_THE_PEERS = "beyond-the-peers"
    LEFT_OUT = "left-out"
    DECISION = "decision"

    @property
    def severity(self) -> Severity:
        return CLAUSES[self][0]

    @property
    def meaning(self) -> str:
        return CLAUSES[self][1]


CLAUSES: dict[Clause, tuple[Severity, str]] = {
    Clause.PEER_CANNOT_LOAD: (Severity.ERROR, "a peer tool cannot load the file (or build from it)"),
    Clause.PEER_READS_OTHERWISE: (
        Severity.ERROR,
        "the file breaks CiA 306/311/301, and a peer tool reads another value, type or object than it says",
    ),
    Clause.DEVICE_MISBEHAVES: (
        Severity.ERROR,
        "a device built or configured from the file misbehaves, or refuses what a master does by it",
    ),
    Clause.NOT_DONE: (Severity.ERROR, "the command cannot do what was asked: nothing is written (exit 2)"),
    Clause.PORTABILITY: (
        Severity.WARNING,
        "a form that is not CiA 306's (every peer reads one meaning), or one that is right by CiA 306 or a dialect "
        "while a peer's limitation, named, reads it otherwise",
    ),
    Clause.STYLE: (Severity.WARNING, "nothing is read otherwise: a stale count, an ignored value, a likely typo"),
    Clause.BEYOND_THE_PEERS: (Severity.WARNING, "the peers read it alike; a tool beyond them may not"),
    Clause.LEFT_OUT: (Severity.WARNING, "the command did its work and left out what it names"),
    Clause.DECISION: (Severity.INFO, "a decision worth knowing; nothing is wrong"),
}


class Placement(NamedTuple):
    """Where the severity policy puts a code: the clause, and the peer or the misbehaviour that puts it there."""

    clause: Clause
    reason: str


Text = str | Callable[[], str]
"""An example as text, or a function that makes it: one built with `examples`' builders is made when
the documentation or a test reads it, not each time `lint` imports the rule modules."""


@dataclass(frozen=True)
class Rule:
    code: str
    severity: Severity
    summary: str
    description: str
    example_text: Text
    family: str
    check: Check | None  # None: reported while reading (see the reader codes)
    placed: Placement  # the clause of the severity policy that gives the code its severity, and why
    fixed_text: Text = ""
    fix_safety: str = ""  # what `--fix` does about it, and whether that is safe
    refs: str = ""  # the standard's sections, beyond the family's
    per_object: bool = False
    """The rule's findings on an object's lines depend on that object alone (with the data-type definitions,
    the sections that are no object's and the options), and its other findings on no object: after an edit
    of one object, its findings elsewhere stand (runner.py reuses them) and a check of that object finds the rest."""

    @cached_property
    def example(self) -> str:
        """A fragment of an EDS that triggers the rule (see `exampleset`)."""
        return _made(self.example_text)

    @cached_property
    def fixed(self) -> str:
        """The example corrected: it does not trigger the rule."""
        return _made(self.fixed_text)


def _made(text: Text) -> str:
    return (text if isinstance(text, str) else text()).strip()


RULES: dict[str, Rule] = {}


def rule(
    code: str,
    severity: Severity,
    summary: str,
    description: str,
    example: Text = "",
    *,
    fixed: Text = "",
    fix_safety: str = "",
    refs: str = "",
    per_object: bool = False,
    placed: Placement,
) -> Callable[[Check], Check]:
    """Register a check function under a code. The family is the module's last name part.

    `description` says why the rule exists; `example` is a fragment of an EDS that triggers it,
    `fixed` the same fragment corrected (the documentation runs both). `per_object`: see `Rule.per_object`.
    `placed`: the clause of the severity policy that gives `severity`, with the peer or the misbehaviour."""

    def register(check: Check) -> Check:
        family = check.__module__.rsplit(".", 1)[-1]
        _add(Rule(code, severity, summary, description.strip(), example, family, check, placed, fixed,
                  fix_safety.strip(), refs.strip(), per_object))  # fmt: skip
        return check

    return register


def declare(
    code: str,
    severity: Severity,
    summary: str,
    description: str,
    example: Text = "",
    family: str = "reader",
    *,
    fixed: Text = "",
    fix_safety: str = "",
    refs: str = "",
    placed: Placement,
) -> None:
    """Document a code that the reader reports, so `rules` lists it and `--select` knows it."""
    _add(Rule(code, severity, summary, description.strip(), example, family, None, placed, fixed,
              fix_safety.strip(), refs.strip()))  # fmt: skip


def _add(declared: Rule) -> None:
    if declared.code in RULES:
        raise ValueError(f"rule {declared.code} declared twice")
    RULES[declared.code] = declared


def find(code: str) -> Rule:
    return RULES[code]
