"""The CANopenNode steps of `gen -t canopennode`: overrides, the lint profile, --explain."""

from __future__ import annotations

import sys

import click

from ..model import Device
from .common import EXIT_FINDINGS, EXIT_USAGE


def prepare_canopennode(device: Device, file: str, explain: bool) -> list[str]:
    """Apply `<stem>.canopennode.toml`, refuse what the stack cannot run, explain inferences.

    Returns the extra input files (for the depfile). Exits 2 on a bad override file, 1 when
    the canopennode profile finds errors.
    """
    from ..canopennode_overrides import apply_overrides, override_file_for
    from ..lint import load_selection
    from ..lint.canopennode import profile_findings
    from ..lint.runner import has_errors
    from ..views.canopennode import build_node_view
    from .batch import config_path

    path = override_file_for(file)
    applied: list[str] = []
    if path is not None:
        try:
            applied = apply_overrides(device, path)
        except (OSError, ValueError) as error:
            click.echo(f"{path}: error: {getattr(error, 'strerror', None) or error}", err=True)
            sys.exit(EXIT_USAGE)
    try:  # the project's [tool.cantools-od] ignore applies, e.g. for a stack built without EM history
        ignore = load_selection(config_path(file, None)).ignore
    except ValueError as error:
        click.echo(f"error: configuration: {error}", err=True)
        sys.exit(EXIT_USAGE)
    findings = profile_findings(device, device.node_id, ignore)
    for finding in findings:
        click.echo(finding.format(), err=True)
    if has_errors(findings):
        click.echo(f"{file}: error: the CANopenNode stack cannot use it; nothing generated", err=True)
        sys.exit(EXIT_FINDINGS)
    if explain:
        for line in applied:
            click.echo(f"{file}: set: {line}", err=True)
        for inference in build_node_view(device, explain=True).inferences:
            click.echo(f"{file}: inferred: {inference.format()}", err=True)
    return [str(path)] if path is not None else []
