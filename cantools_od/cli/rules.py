"""`cantools-od rules`: the rule catalogue, or one rule explained."""

from __future__ import annotations

import sys

import click

from .common import EXIT_USAGE


@click.command(name="rules")
@click.argument("code", required=False)
def command(code: str | None) -> None:
    """List every rule, or explain CODE."""
    from ..lint import RULES
    from ..lint.catalog import load

    load()
    if code is None:
        for rule in sorted(RULES.values(), key=lambda r: r.code):
            click.echo(f"{rule.code}  {rule.severity.value:<7}  {rule.family:<11}  {rule.summary}")
        return
    found = RULES.get(code.upper())
    if found is None:
        click.echo(f"error: no rule {code}; `cantools-od rules` lists them", err=True)
        sys.exit(EXIT_USAGE)
    click.echo(f"{found.code}: {found.summary}\n\nseverity: {found.severity.value}   family: {found.family}\n")
    click.echo(found.description)
    if found.example:
        click.echo("\nExample:\n\n" + "\n".join("    " + line for line in found.example.splitlines()))
