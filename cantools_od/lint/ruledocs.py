"""docs/rules.md, generated from the code registry: `python -m cantools_od.lint.ruledocs > docs/rules.md`.

Each code has its family, name, severity and summary; each rule its why, its failing example with
the line lint reports (found by running the example), its fixed example, what `--fix` does, and the
sections of the standards it rests on.
"""

from __future__ import annotations

from .codes import FAMILIES, Code, codes
from .examples import fragment_line, run

_HEAD = """# Rules

Every code `cantools-od` can print, generated from its registry (`cantools_od/lint/codes.py`) by
`python -m cantools_od.lint.ruledocs > docs/rules.md`; a test keeps this file current.
`cantools-od rules CODE` (or its name) shows the same text. Select codes with `--select`/`--ignore`
by code, prefix or family name. Each example is run through `lint` inside a minimal valid EDS
(the tests do the same): the failing one triggers its rule at the line shown, the fixed one is clean.
"""


def _block(text: str, language: str = "ini") -> list[str]:
    return [f"```{language}", *text.splitlines(), "```"]


def _failing(code: Code) -> tuple[list[str], str | None]:
    """The example's lines and the fix safety its findings show; nothing for a code without one."""
    example = code.rule.example
    if not example:
        return [], None
    if not FAMILIES[code.family].eds_examples:
        return ["Example:", "", *_block(example, "text"), ""], None
    text, findings = run(example)
    mine = [f for f in findings if f.code == code.code]
    lines = sorted({n for f in mine if (n := fragment_line(example, text, f.location.line)) is not None})
    out = ["Example:", "", *_block(example), ""]
    if lines:
        out += [f"Reported at line {', '.join(map(str, lines))} of the example.", ""]
    elif mine:
        out += ["Reported for the file as a whole.", ""]
    fixes = {(f.fix.message, f.fix.safe) for f in mine if f.fix is not None}
    safety = None
    if fixes:
        safe = all(is_safe for _, is_safe in fixes)
        safety = ("Safe: `--fix` applies it" if safe else "Unsafe: shown, never applied by `--fix`") + (
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
    out = [rule.description, ""]
    failing, derived = _failing(code)
    out += failing
    if rule.fixed:
        out += ["Fixed:", "", *_block(rule.fixed), ""]
    fix = rule.fix_safety or derived or ("No automatic fix." if rule.check is not None else "")
    if fix:
        out += [f"Fix: {fix}", ""]
    refs = "; ".join(r for r in (rule.refs, FAMILIES[code.family].refs) if r)
    if refs:
        out += [f"References: {refs}.", ""]
    return out


def markdown() -> str:
    table = codes()
    out = [_HEAD]
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
