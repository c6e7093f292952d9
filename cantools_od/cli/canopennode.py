"""The CANopenNode steps of `gen -t canopennode`: overrides, the stack's configuration, the lint profile, --explain."""

from __future__ import annotations

import sys

import click

from ..canopennode.editor import editor_entry_type, editor_reads
from ..canopennode.overrides import STACK_TABLE, SUFFIX, apply_overrides, override_file_for, read_settings, stack_config
from ..canopennode.profile import SWITCH_PREFIX, StackConfig
from ..model import Device, RawValue, Severity
from .common import EXIT_FINDINGS, EXIT_USAGE

stack_config_option = click.option(
    "--stack-config", "stack_files", multiple=True, type=click.Path(dir_okay=False),
    help=f"The project's CO_driver_target.h (or 301/CO_config.h): its {SWITCH_PREFIX}* decide the objects the "
    f"CANopenNode stack needs (repeatable; the first definition wins; a [{STACK_TABLE}] table in the {SUFFIX} wins).",
)  # fmt: skip


def load_stack_config(file: str, stack_files: tuple[str, ...]) -> StackConfig:
    """The build configuration for FILE: `--stack-config` headers and its .canopennode.toml [stack] table.

    Exits 2 when one of them cannot be read.
    """
    path = override_file_for(file)
    try:
        table = read_settings(path).get(STACK_TABLE) if path is not None else None
        return stack_config(list(stack_files), table, str(path or ""))
    except ValueError as error:
        click.echo(f"error: stack configuration: {error}", err=True)
        sys.exit(EXIT_USAGE)


def prepare_canopennode(device: Device, file: str, explain: bool, stack_files: tuple[str, ...] = ()) -> list[str]:
    """Apply `<stem>.canopennode.toml`, refuse what the stack cannot run, explain inferences.

    Returns the extra input files (for the depfile). Exits 2 on a bad override or stack
    configuration file, 1 when the canopennode profile finds errors.
    """
    from ..lint import load_selection
    from ..lint.canopennode import profile_findings
    from ..lint.runner import has_errors
    from ..views.canopennode import build_node_view, keep_editor_pdo_bits
    from .batch import config_path

    path = override_file_for(file)
    stack = load_stack_config(file, stack_files)
    applied: list[str] = []
    if path is not None:
        try:
            applied = apply_overrides(device, path)
        except (OSError, ValueError) as error:
            click.echo(f"{path}: error: {getattr(error, 'strerror', None) or error}", err=True)
            sys.exit(EXIT_USAGE)
    if stack.editor_pdo:
        applied += keep_editor_pdo_bits(device)
    try:  # the project's [tool.cantools-od] ignore applies, e.g. for a stack built without EM history
        ignore = load_selection(config_path(file, None)).ignore
    except ValueError as error:
        click.echo(f"error: configuration: {error}", err=True)
        sys.exit(EXIT_USAGE)
    findings = profile_findings(device, device.node_id, ignore, stack)
    for finding in findings:
        if explain or finding.severity is not Severity.INFO:
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


def keep_editor_readable(device: Device, damaged: set[int]) -> None:
    """For the canopennode target alone: objects whose only errors are defaults CANopenEditor reads (a DOMAIN's,
    `0` as an OCTET_STRING, `1.5f` as a REAL) are not damaged, and those errors are not reported: the view reads
    them as CANopenEditor does, and --explain says how."""
    from ..eds.where import damaged_objects

    for index, diagnostics in damaged_objects(device).items():
        obj = device.objects.get(index)
        if obj is None or index not in damaged or any(d.code != "EDS030" for d in diagnostics):
            continue
        entries = obj.subs.values() if obj.has_subs else [obj]
        raw = [
            (var.default, editor_entry_type(device, var, obj)) for var in entries if isinstance(var.default, RawValue)
        ]
        if raw and all(isinstance(v, RawValue) and t is not None and editor_reads(t, v.text) for v, t in raw):
            damaged.discard(index)
            device.diagnostics = [d for d in device.diagnostics if not any(d is e for e in diagnostics)]
