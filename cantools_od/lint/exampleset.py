"""A rule example as the files (and, for other commands, the command line) it stands for.

An example is text. Most are one fragment of an EDS that `examples.frame` completes into a whole,
clean file; comment lines of the form below say what else the example needs, so that the text the
documentation shows is the text the tests run:

- `; file: NAME` starts a file named NAME (a DCF, a second node, an XDD, a CSV table); without
  it the example is one file, `example.eds` (`example.xdd` for the XDD reader's codes). An EDS, DCF
  or XDD/XDC file is framed: what it does not give, the frame adds.
- `; whole file: NAME` starts a file that is used as it stands, unframed.
- `; no [Section], [Section]` says the file lacks these sections: the frame leaves them out.
- `; encoding: NAME` says the file is saved in that encoding (not UTF-8).
- `; also: CODE, CODE` names the codes that always come with this one, by design.
- `; $ COMMAND` is a command line to run in a folder holding the files, with the installed
  `cantools-od`; an example with commands runs them instead of `lint`.

`run_example` reads and lints the files in-process (`lint`, `lint --network` for several files,
`lint --profile canopennode` for the canopennode codes) and maps each finding back to the line of
the example it stems from.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from pathlib import PurePath

from ..api import loads
from ..model import Severity
from ..model.source import location
from ..sniff import NotADeviceDescription
from .examples import framed_lines
from .rules import Finding, LintOptions
from .runner import lint, lint_network
from .xddframe import framed_xdd

_DIRECTIVE = re.compile(r"^;\s*(file|whole file|no|encoding|also|\$)(?::\s*|\s+)(.*)$")
_SECTION_NAME = re.compile(r"\[([^\]]+)\]")
_CODE = re.compile(r"\b[A-Z]{3}\d{3}\b")
_FRAMED = {".eds": "eds", ".dcf": "eds", ".xdd": "xdd", ".xdc": "xdd"}


@dataclass
class ExampleFile:
    name: str
    lines: list[tuple[str, int]] = field(default_factory=list)  # (text, line of the example)
    whole: bool = False
    encoding: str = "utf-8"
    omit: set[str] = field(default_factory=set)  # sections the frame leaves out (lower case)

    @property
    def kind(self) -> str | None:
        """How the file is framed: "eds" or "xdd", or None for a file used as it stands."""
        return None if self.whole else _FRAMED.get(PurePath(self.name).suffix.lower())

    def content(self, profile: str | None = None) -> tuple[bytes, dict[int, int]]:
        """The file's bytes, and for each of its lines that the example gives, the example's line."""
        fragment = self.lines
        if self.kind == "eds":
            text, origin = framed_lines(fragment, self.omit, profile)
        elif self.kind == "xdd":
            text, origin = framed_xdd(fragment)
        else:
            text = "".join(line + "\n" for line, _ in fragment)
            origin = {n: number for n, (_, number) in enumerate(fragment, 1)}
        return text.encode(self.encoding), origin


@dataclass
class Example:
    files: list[ExampleFile]
    commands: list[str]
    also: tuple[str, ...]


def parse(text: str, default_name: str = "example.eds") -> Example:
    """The example's files, commands and companion codes."""
    files: list[ExampleFile] = []
    commands: list[str] = []
    also: list[str] = []
    current: ExampleFile | None = None
    pending = ExampleFile(default_name)  # what `; no` and `; encoding` say before the first file starts
    for number, line in enumerate(text.splitlines(), 1):
        directive = _DIRECTIVE.match(line.strip())
        if directive is None:
            if current is None:
                current = pending
                files.append(current)
            current.lines.append((line, number))
            continue
        keyword, value = directive.groups()
        if keyword in ("file", "whole file"):
            current = ExampleFile(value.strip(), [], keyword == "whole file", pending.encoding, set(pending.omit))
            files.append(current)
        elif keyword == "no":
            (current or pending).omit.update(n.lower() for n in _SECTION_NAME.findall(value))
        elif keyword == "encoding":
            (current or pending).encoding = value.strip()
        elif keyword == "also":
            also += _CODE.findall(value)
        else:
            commands.append(value.strip())
    if not files and not commands:
        files.append(pending)
    return Example(files, commands, tuple(also))


@dataclass(frozen=True)
class Outcome:
    """What lint reports for an example: each finding with the example line it stems from: 0 for the
    file as a whole (its line 0 or 1, when the frame wrote that line), None for another line the frame
    added."""

    findings: list[tuple[Finding, int | None]]

    def codes(self) -> set[str]:
        return {finding.code for finding, _ in self.findings}

    def lines(self, code: str) -> list[int | None]:
        return [line for finding, line in self.findings if finding.code == code]


def default_name(family: str) -> str:
    return "example.xdd" if family == "xdd" else "example.eds"


def run_example(text: str, family: str = "", profile: str | None = None) -> Outcome:
    """Read and lint the example's files in-process, as `lint` (several files: `lint --network`)."""
    example = parse(text, default_name(family))
    options = LintOptions(profile=profile)
    found: list[tuple[Finding, int | None]] = []
    devices = []
    origins: dict[str, dict[int, int]] = {}
    for file in example.files:
        data, origin = file.content(profile)
        origins[file.name] = origin
        try:
            device = loads(data, source=file.name)
        except NotADeviceDescription as refused:
            finding = Finding(refused.code, Severity.ERROR, str(refused), location(file.name, 0, 0))
            found.append((finding, 0))
            continue
        devices.append(device)
        found += [(f, _example_line(origin, f.location.line)) for f in lint(device, options)]
    if len(devices) > 1:
        network = lint_network(devices, options)
        found += [(f, _example_line(origins[f.location.file], f.location.line)) for f in network]
    return Outcome(found)


def _example_line(origin: dict[int, int], line: int) -> int | None:
    if line in origin:
        return origin[line]
    return 0 if line <= 1 else None
