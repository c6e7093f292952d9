"""`cantools-od lint`: check files, print findings, optionally fix what is safe to fix."""

from __future__ import annotations

import sys
from collections import Counter
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

import click

from .canopennode import load_stack_config, stack_config_option
from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Progress, read_device, write_outputs

if TYPE_CHECKING:
    from ..lint import Finding
    from ..lint.config import Selection


def _codes(values: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(code.strip().upper() for value in values for code in value.split(",") if code.strip())


@click.command(name="lint")
@click.argument("files", nargs=-1, required=True, type=click.Path(dir_okay=False))
@click.option(
    "--format", "fmt", type=click.Choice(["text", "json", "sarif", "github"]), default="text", show_default=True
)
@click.option(
    "--select", multiple=True, help="Only these codes, code prefixes, rule names or families (comma-separated)."
)
@click.option(
    "--ignore", multiple=True, help="Skip these codes, code prefixes, rule names or families (comma-separated)."
)
@click.option("--fix", is_flag=True, help="Apply safe fixes in place; only the touched lines change.")
@click.option("--can-fd", is_flag=True, help="Allow PDOs up to 512 bits (CAN FD).")
@click.option("--node-id", type=click.IntRange(1, 127), help="Node-ID that $NODEID stands for.")
@click.option(
    "--network", is_flag=True,
    help="Also check the files together as one network (DCFs), or the network a bus.yml describes.",
)  # fmt: skip
@click.option("--define", "defines", multiple=True, metavar="NAME=VALUE", help="@NAME@ of a bus.yml (--network).")
@click.option(
    "--profile", type=click.Choice(["canopennode"]), help="Also apply a target's rules (canopennode: the CNO codes)."
)
@stack_config_option
def command(
    files: tuple[str, ...],
    fmt: str,
    select: tuple[str, ...],
    ignore: tuple[str, ...],
    fix: bool,
    can_fd: bool,
    node_id: int | None,
    network: bool,
    defines: tuple[str, ...],
    profile: str | None,
    stack_files: tuple[str, ...],
) -> None:
    """Check EDS/DCF/XDD/XDC FILES. Exit 0 without errors, 1 with errors, 2 on usage errors."""
    from ..api import dumps, format_for
    from ..lint import LintOptions, has_errors, lint, load_selection
    from ..lint.config import check_selectors
    from ..names import UnknownName

    try:
        selection = load_selection(Path.cwd())
    except ValueError as error:
        click.echo(f"error: configuration: {error}", err=True)
        sys.exit(EXIT_USAGE)
    try:
        check_selectors(_codes(select) + _codes(ignore))
    except UnknownName as error:
        click.echo(f"error: --select/--ignore: {error}", err=True)
        sys.exit(EXIT_USAGE)
    selection = selection.merged(_codes(select), _codes(ignore))
    options = LintOptions(can_fd=can_fd, node_id=node_id, profile=profile)
    findings: list[Finding] = []
    devices = []
    buses = [name for name in files if Path(name).suffix.lower() in BUS_SUFFIXES]
    if buses and not network:
        click.echo(f"{buses[0]}: error: a bus description is checked as a network: add --network", err=True)
        sys.exit(EXIT_USAGE)
    for bus in buses:
        findings.extend(_bus_findings(bus, defines, selection))
    devices_files = [name for name in files if name not in buses]
    for name in Progress("lint", len(devices_files)).over(devices_files) if len(devices_files) > 1 else devices_files:
        device = read_device(name, node_id)
        if profile == "canopennode":  # the configuration each project declares beside its file
            options = replace(options, stack=load_stack_config(name, stack_files))
        result = lint(device, options, selection)
        if fix and any(f.fix is not None and f.fix.safe for f in result):
            fixed = Counter(f.code for f in result if f.fix is not None and f.fix.safe)
            for finding in result:
                if finding.fix is not None and finding.fix.safe:
                    finding.fix.apply(device)
            write_outputs({Path(name): dumps(device, format_for(Path(name)))})
            said = ", ".join(f"{code} ({count})" if count > 1 else code for code, count in sorted(fixed.items()))
            click.echo(f"{name}: fixed {said}", err=True)
            device = read_device(name, node_id)
            result = lint(device, options, selection)
        devices.append(device)
        findings.extend(result)
    if network and devices:
        from ..lint.runner import lint_network

        findings.extend(lint_network(devices, options, selection))
    click.echo(_render(fmt, findings, len(files)), nl=False)
    sys.exit(EXIT_FINDINGS if has_errors(findings) else EXIT_OK)


BUS_SUFFIXES = (".yml", ".yaml")


def _bus_findings(bus: str, defines: tuple[str, ...], selection: Selection) -> list[Finding]:
    """COB011 findings of the network a bus description states; one that cannot be read exits 2."""
    from ..lint.network import lint_bus
    from .network import load_network, make_plan

    network, devices = load_network(bus, defines, ())
    findings = lint_bus(make_plan(network, devices, parameter_values=True))
    return [finding for finding in findings if selection.enabled(finding.code, bus)]


def _render(fmt: str, findings: list[Finding], files: int) -> str:
    from ..lint import output

    if fmt == "json":
        return output.as_json(findings)
    if fmt == "sarif":
        return output.sarif(findings)
    if fmt == "github":
        return output.github(findings)
    return output.text(findings, files)
