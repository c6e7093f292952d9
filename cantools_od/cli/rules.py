"""`cantools-od rules`: the code registry, or one code explained."""

from __future__ import annotations

import sys

import click

from .common import EXIT_USAGE


@click.command(name="rules")
@click.argument("code", required=False)
def command(code: str | None) -> None:
    """List every code cantools-od can print, or explain CODE (a code or its name)."""
    from ..lint.codes import codes, find
    from ..lint.config import RULE_CUTOFF
    from ..lint.ruledocs import explain
    from ..names import suggest

    if code is None:
        for found in codes().values():
            click.echo(
                f"{found.code}  {found.severity.value:<7}  {found.family:<11}  {found.name:<34}  {found.summary}"
            )
        return
    explained = find(code)
    if explained is None:
        known = [name for found in codes().values() for name in (found.code, found.name)]
        closest = suggest(code, known, "`cantools-od rules` lists them", RULE_CUTOFF)
        click.echo(f"error: no rule {code}; {closest}", err=True)
        sys.exit(EXIT_USAGE)
    rule = explained.rule
    click.echo(f"{rule.code} ({explained.name}): {rule.summary}\n")
    click.echo(f"severity: {rule.severity.value}   family: {explained.family}\n")
    click.echo(explain(explained), nl=False)
