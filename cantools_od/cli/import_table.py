"""`cantools-od import-table`: vendor OD tables (manual text, CSV/TSV, XLSX, Markdown) → EDS."""

from __future__ import annotations

import sys
from pathlib import Path

import click

from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Output, check_extension, write_outputs

OUTPUT_SUFFIXES = (".eds", ".xdd", ".xpd", ".json")  # a DCF or XDC is for one node: convert makes it

LAYOUT_CHOICES = ["auto", "text", "cells", "csv", "tsv", "xlsx", "markdown"]


@click.command(name="import-table")
@click.argument("sources", nargs=-1, required=True, type=click.Path(dir_okay=False))
@click.option(
    "-o", "--output", required=True, type=Output(dir_okay=False),
    help="File to write: .eds, .xdd/.xpd, or .json (the model with its manual line numbers).",
)  # fmt: skip
@click.option("--overrides", type=click.Path(dir_okay=False), help="TOML file resolving conflicts (see docs).")
@click.option("--report", "report_file", type=Output(dir_okay=False), help="Write a Markdown import report.")
@click.option(
    "--layout", type=click.Choice(LAYOUT_CHOICES), default="auto", show_default=True,
    help="Force the layout of every SOURCE instead of detecting it.",
)  # fmt: skip
@click.option(
    "--policy", type=click.Choice(["detail", "summary", "first", "last"]), default=None,
    help="How conflicts without an override are resolved [default: detail, or the overrides file's].",
)  # fmt: skip
@click.option("--strict", is_flag=True, help="Exit 1 when a conflict was resolved by the policy, not an override.")
@click.option("--no-comments", is_flag=True, help="Leave the provenance comments out of the EDS.")
@click.option("-q", "--quiet", is_flag=True, help="Print errors only.")
def command(
    sources: tuple[str, ...],
    output: str,
    overrides: str | None,
    report_file: str | None,
    layout: str,
    policy: str | None,
    strict: bool,
    no_comments: bool,
    quiet: bool,
) -> None:
    """Import the object dictionary described by SOURCE files into an EDS.

    Exit status: 0 written; 1 written, but with --strict a conflict was left to the policy or
    an entry lacks a data type or access the sources never state; 2 a source or the overrides
    file could not be read, or no object was found."""
    from ..api import dumps, format_for
    from ..model import Severity
    from ..tableimport import UnreadableInput, import_tables
    from ..tableimport.merge import POLICIES

    check_extension(output, "output", OUTPUT_SUFFIXES)
    chosen_policy = next((p for p in POLICIES if p == policy), None)
    try:
        result = import_tables(
            list(sources),
            overrides=overrides,
            layout=None if layout == "auto" else layout,
            policy=chosen_policy,
            comments=not no_comments,
            output_name=Path(output).name,
        )
    except UnreadableInput as error:
        for diagnostic in error.diagnostics:
            click.echo(diagnostic.format(), err=True)
        sys.exit(EXIT_USAGE)
    for diagnostic in result.diagnostics:
        if not quiet or diagnostic.severity is Severity.ERROR:
            click.echo(diagnostic.format(), err=True)
    if not result.device.objects:
        click.echo(f"{output}: error: no object found in the sources; nothing written [IMP002]", err=True)
        sys.exit(EXIT_USAGE)
    outputs = {Path(output): dumps(result.device, format_for(Path(output)), "canonical")}
    if report_file:
        outputs[Path(report_file)] = result.report().encode("utf-8")
    write_outputs(outputs)
    merged = result.merged
    policy_resolved = [c for c in merged.conflicts if c.resolution.startswith("policy") and c.field != "name"]
    if not quiet:
        pairs = sum(max(1, len(obj.subs)) for obj in result.device.objects.values())
        click.echo(
            f"{output}: {len(result.device.objects)} objects, {pairs} entries; {len(merged.conflicts)} conflicts "
            f"({len(policy_resolved)} resolved by policy), {len(merged.inferred)} inferred values",
            err=True,
        )
    gaps = [d for d in result.diagnostics if d.code == "IMP031"]
    failed = bool(result.errors) or (strict and bool(policy_resolved or gaps))
    sys.exit(EXIT_FINDINGS if failed else EXIT_OK)
