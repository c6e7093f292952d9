"""`cantools-od lint`: check files, print findings, optionally fix what is safe to fix."""

from __future__ import annotations

import sys
from collections import Counter
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import TYPE_CHECKING, NamedTuple

import click

from .batch import config_option, config_path, file_size, jobs_option, run_each
from .canopennode import load_stack_config, stack_config_option
from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Progress, Rewritten

if TYPE_CHECKING:
    from ..lint import Finding, LintOptions, Selection
    from ..model import Device


def _typed(values: tuple[str, ...]) -> tuple[str, ...]:
    """The comma-separated selectors, as typed."""
    return tuple(code.strip() for value in values for code in value.split(",") if code.strip())


def _codes(values: tuple[str, ...]) -> tuple[str, ...]:
    return tuple(code.upper() for code in _typed(values))


@click.command(name="lint")
@click.argument("files", nargs=-1, required=True, type=Rewritten())  # rewritten with --fix
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
@click.option(
    "--unsafe-fixes", is_flag=True, help="With --fix, also apply the fixes that change what a peer reads (shown)."
)
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
@config_option
@jobs_option
def command(
    files: tuple[str, ...],
    fmt: str,
    select: tuple[str, ...],
    ignore: tuple[str, ...],
    fix: bool,
    unsafe_fixes: bool,
    can_fd: bool,
    node_id: int | None,
    network: bool,
    defines: tuple[str, ...],
    profile: str | None,
    stack_files: tuple[str, ...],
    config: str | None,
    jobs: int | None,
) -> None:
    """Check EDS/DCF/XDD/XDC FILES. Exit 0 without errors, 1 with errors, 2 on usage errors or when a file cannot be
    read (every other file is still checked and reported)."""
    from ..lint import LintOptions
    from ..lint.config import check_selectors
    from ..names import UnknownName

    try:
        check_selectors(_typed(select) + _typed(ignore))
    except UnknownName as error:
        click.echo(f"error: --select/--ignore: {error}", err=True)
        sys.exit(EXIT_USAGE)
    options = LintOptions(can_fd=can_fd, node_id=node_id, profile=profile)
    fixing = 2 if fix and unsafe_fixes else int(fix)
    buses = [name for name in files if Path(name).suffix.lower() in BUS_SUFFIXES]
    if buses and not network:
        click.echo(f"{buses[0]}: error: a bus description is checked as a network: add --network", err=True)
        sys.exit(EXIT_USAGE)
    findings: list[Finding] = []
    for bus in buses:
        findings.extend(_bus_findings(bus, defines, _selection(bus, config, select, ignore)))
    tasks = [
        _Task(name, _options_for(name, options, stack_files), _selection(name, config, select, ignore), fixing, network)
        for name in files
        if name not in buses
    ]
    progress = Progress("lint", len(tasks)) if len(tasks) > 1 else None
    checked = run_each(_check, tasks, 1 if network else jobs, progress, cost=lambda task: file_size(task.name))
    findings += [finding for one in checked for finding in one.findings]
    for one in checked:
        if one.message:
            click.echo(one.message, err=True)
    if network and tasks:
        from ..lint.runner import lint_network

        devices = [one.device for one in checked if one.device is not None]
        findings.extend(lint_network(devices, options, tasks[0].selection))
    from ..lint import has_errors

    unread = sum(not one.read for one in checked)
    click.echo(_render(fmt, findings, len(files) - unread, unread), nl=False)
    worst = max((one.status for one in checked), default=EXIT_OK)
    sys.exit(max(worst, EXIT_FINDINGS if has_errors(findings) else EXIT_OK))


def _options_for(name: str, options: LintOptions, stack_files: tuple[str, ...]) -> LintOptions:
    """The canopennode profile follows the build configuration each project declares beside its file."""
    if options.profile != "canopennode":
        return options
    return options._replace(stack=load_stack_config(name, stack_files))


def _selection(name: str, config: str | None, select: tuple[str, ...], ignore: tuple[str, ...]) -> Selection:
    """The selection for one file: its configuration (exit 2 when malformed) and the command line's choices."""
    from ..lint import load_selection

    try:
        selection = load_selection(config_path(name or ".", config))
    except ValueError as error:
        click.echo(f"error: configuration: {error}", err=True)
        sys.exit(EXIT_USAGE)
    return selection.merged(_codes(select), _codes(ignore))


class _Task(NamedTuple):
    name: str
    options: LintOptions
    selection: Selection
    fixing: int  # 0: no fix, 1: safe fixes, 2: safe and unsafe fixes
    keep: bool  # return the device (for --network)


@dataclass
class _Checked:
    findings: list[Finding] = field(default_factory=list)
    status: int = EXIT_OK  # EXIT_USAGE when the file could not be read or written
    message: str = ""  # a line for stderr
    device: Device | None = None
    read: bool = True  # False: the file could not be read at all


def _check(task: _Task) -> _Checked:
    """One file: read, lint, fix (written at once), lint again. Runs in a worker process: what it returns
    holds no function, so it can travel back."""
    from ..api import load
    from ..lint import lint
    from ..sniff import NotADeviceDescription

    try:
        device = load(task.name, node_id=task.options.node_id)
    except OSError as error:
        return _unreadable(task, error)
    except NotADeviceDescription as error:
        return _not_a_device(task, error)
    result = lint(device, task.options, task.selection)
    said = ""
    if task.fixing and any(_applies(f, task.fixing) for f in result):
        failure = _fix(task, device, result)
        if failure:
            return _Checked([_sent(f) for f in result], EXIT_USAGE, failure)
        fixed = Counter(f.code for f in result if _applies(f, task.fixing))
        said = f"{task.name}: fixed " + ", ".join(
            f"{code} ({n})" if n > 1 else code for code, n in sorted(fixed.items())
        )
        device = load(task.name, node_id=task.options.node_id)
        result = lint(device, task.options, task.selection)
    return _Checked([_sent(f) for f in result], message=said, device=device if task.keep else None)


def _unreadable(task: _Task, error: OSError) -> _Checked:
    """A file that cannot be read (missing, a folder, no permission): an EDS000 finding in the report, in every
    format, whatever is selected (nothing of it was checked); exit 2 once every other file is checked."""
    from ..lint.rules import RULES, Finding
    from ..model.source import location
    from ..sniff import NOT_A_DEVICE_DESCRIPTION as code
    from .common import unreadable

    finding = Finding(code, RULES[code].severity, f"cannot read: {unreadable(error)}", location(task.name, 1, 1))
    return _Checked([finding], EXIT_USAGE, read=False)


def _not_a_device(task: _Task, error: Exception) -> _Checked:
    """A file that is no device description: an EDS000 finding like any other (exit 2 unless ignored)."""
    from ..lint.rules import RULES, Finding
    from ..model.source import location

    code = getattr(error, "code", "EDS000")
    if not task.selection.enabled(code, task.name):
        return _Checked()
    finding = Finding(code, RULES[code].severity, str(error), location(task.name, 1, 1))
    return _Checked([finding], EXIT_USAGE)


def _applies(finding: Finding, fixing: int) -> bool:
    return finding.fix is not None and (finding.fix.safe or fixing > 1)


def _fix(task: _Task, device: Device, result: list[Finding]) -> str:
    """Apply the fixes chosen and write the file; the reason when it cannot be written."""
    from ..api import dumps, format_for
    from ..files import CannotWrite, write_all
    from .common import guard

    for finding in result:
        if finding.fix is not None and _applies(finding, task.fixing):
            finding.fix.apply(device)
    path = Path(task.name)
    try:
        write_all([(path, dumps(device, format_for(path)))], guard(rewrites=[path], ours=None))
    except CannotWrite as error:
        return f"error: {error}"
    return ""


def _sent(finding: Finding) -> Finding:
    """The finding without its fix's function (which cannot leave the process), its message and safety kept."""
    if finding.fix is None:
        return finding
    return finding._replace(fix=replace(finding.fix, apply=_applied))


def _applied(device: Device) -> None:
    """A fix that was already applied, or not chosen: nothing left to do."""


BUS_SUFFIXES = (".yml", ".yaml")


def _bus_findings(bus: str, defines: tuple[str, ...], selection: Selection) -> list[Finding]:
    """COB011 findings of the network a bus description states; one that cannot be read exits 2."""
    from ..lint.network import lint_bus
    from .network import load_network, make_plan

    network, devices = load_network(bus, defines, ())
    findings = lint_bus(make_plan(network, devices, parameter_values=True))
    return [finding for finding in findings if selection.enabled(finding.code, bus)]


def _render(fmt: str, findings: list[Finding], files: int, unread: int) -> str:
    from ..lint import output

    return output.render(fmt, findings, files, unread)
