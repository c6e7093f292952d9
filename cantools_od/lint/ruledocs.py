"""docs/rules.md, generated from the code registry: `python -m cantools_od.lint.ruledocs > docs/rules.md`.

Each code has its family, name, severity and summary; each rule its why, its failing example with
the line lint reports (found by running the example), its fixed example, what `--fix` does, and the
sections of the standards it rests on.
"""

from __future__ import annotations

from .codes import FAMILIES, Code, codes
from .exampleset import Outcome, default_name, parse, run_example
from .rules import Clause

_HEAD = """# Rules

Every code `cantools-od` can print, generated from its registry (`cantools_od/lint/codes.py`) by
`python -m cantools_od.lint.ruledocs > docs/rules.md`; a test keeps this file current.
`cantools-od rules CODE` (or its name) shows the same text. Select codes with `--select`/`--ignore`
by code, prefix or family name. Each example is run (the tests do the same): an EDS fragment through
`lint` inside a minimal valid EDS (the canopennode codes with `--profile canopennode`, the frame then
holding the objects the stack requires), an XDD fragment inside a minimal valid XDD. In an example,
`; file: NAME` starts another file, `; whole file: NAME` one used as it stands, `; no [Section]` leaves
a section out of the frame, `; encoding:` names the file's encoding, and `; $` gives the command line
that reports the code. The failing example reports its code (and the ones `; also:` names, which come
with it by design) and nothing else, at the line shown; the fixed one reports nothing else.

"""


_TAIL = """Every code names the clause that gives it its severity, with the peer or the misbehaviour (the tests hold
each code to its clause's severity). The peers are python-canopen, lely's dcfchk and dcfgen, CANopenEditor and the
CANopenNode stack. A rule may report its milder cases one step down and says so in its text."""


def _policy() -> list[str]:
    rows = [f"| {clause.severity.value} | `{clause.value}` | {clause.meaning} |" for clause in Clause]
    return ["## Severity policy", "", "| severity | clause | when |", "|---|---|---|", *rows, "", _TAIL, ""]


def _block(text: str, language: str = "ini") -> list[str]:
    return [f"```{language}", *text.splitlines(), "```"]


def profile_of(code: Code) -> str | None:
    """The target profile an example runs with: the canopennode codes run under `lint --profile canopennode`."""
    return "canopennode" if code.family == "canopennode" else None


def run_code_example(code: Code, text: str) -> Outcome:
    return run_example(text, code.family, profile_of(code))


def _language(code: Code, text: str) -> str:
    example = parse(text, default_name(code.family))
    kinds = {file.kind for file in example.files}
    if example.commands or len(kinds) != 1:
        return "text"
    return {"eds": "ini", "xdd": "xml"}.get(kinds.pop() or "", "text")


def _failing(code: Code) -> tuple[list[str], str | None]:
    """The example's lines and the fix safety its findings show; nothing for a code without one."""
    example = code.rule.example
    if not example:
        return [], None
    out = ["Example:", "", *_block(example, _language(code, example)), ""]
    if parse(example).commands:
        return out, None
    outcome = run_code_example(code, example)
    mine = [finding for finding, _ in outcome.findings if finding.code == code.code]
    lines = sorted({n for n in outcome.lines(code.code) if n})
    if lines:
        out += [f"Reported at line {', '.join(map(str, lines))} of the example.", ""]
    elif mine:
        out += ["Reported for the file as a whole.", ""]
    fixes = {(f.fix.message, f.fix.safe) for f in mine if f.fix is not None}
    safety = None
    if fixes:
        safe = all(is_safe for _, is_safe in fixes)
        safety = ("Safe: `--fix` applies it" if safe else "Unsafe: shown; applied only by `--fix --unsafe-fixes`") + (
            f" ({'; '.join(sorted(message for message, _ in fixes))})."
        )
    return out, safety


def explain(code: Code) -> str:
    """One code's documentation, as `cantools-od rules CODE` prints it."""
    return "\n".join(_body(code)).rstrip() + "\n"


def _code(code: Code) -> list[str]:
    rule = code.rule
    return [f"### {code.code} `{code.name}`", "", f"**{rule.summary}** — {rule.severity.value}", "", *_body(code)]


def _body(code: Code) -> list[str]:
    rule = code.rule
    clause, reason = rule.placed
    out = [rule.description, "", f"Severity: {rule.severity.value}, by `{clause.value}`: {reason}.", ""]
    failing, derived = _failing(code)
    out += failing
    if rule.fixed:
        out += ["Fixed:", "", *_block(rule.fixed, _language(code, rule.fixed)), ""]
    # A check whose example's findings carry no fix has none; a code reported while reading, importing or
    # generating says what can be done in its declaration.
    fix = rule.fix_safety or derived or ("No automatic fix." if rule.check is not None else "")
    if fix:
        out += [f"Fix: {fix}", ""]
    refs = "; ".join(r for r in (rule.refs, FAMILIES[code.family].refs) if r)
    if refs:
        out += [f"References: {refs}.", ""]
    return out


def markdown() -> str:
    table = codes()
    out = [_HEAD, *_policy()]
    for family, info in FAMILIES.items():
        members = [c for c in table.values() if c.family == family]
        if not members:
            continue
        out += [f"## {family}: {info.title}", ""]
        out += [f"- [{c.code}](#{c.code.lower()}-{c.name}) `{c.name}`: {c.summary}" for c in members] + [""]
        for code in members:
            out += _code(code)
    return "\n".join(out).rstrip() + "\n"


if __name__ == "__main__":
    import sys

    sys.stdout.write(markdown())
