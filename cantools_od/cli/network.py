"""`cantools-od network`: a bus description (bus.yml) into the master's configuration, a bus load
report and a DBC."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..model import Severity
from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Output, errors_to_fix, force_option, report, write_outputs

if TYPE_CHECKING:
    from ..files import Content
    from ..model import Device
    from ..network.model import Network
    from ..network.plan import NetworkPlan


def configuration_file(path: Path) -> bool:
    """Whether a file in the output folder is one `network` (or lely's dcfgen) makes, to be replaced by the new one.

    Their formats carry no banner: master.dcf is byte for byte what dcfgen writes, and a concise DCF is binary. So
    a DCF (a [DeviceComissioning] section near its top) and a concise DCF (exactly the writes its count announces)
    are taken as made by a generator; any other file is refused (see docs/outputs.md)."""
    from ..eds.keys import COMMISSIONING_SPELLINGS
    from ..files import has_banner
    from ..model.cia301.master import NotConcise, read_concise_dcf

    try:
        data = path.read_bytes()
    except OSError:
        return False
    if path.suffix.lower() == ".bin":
        try:
            read_concise_dcf(data)
        except NotConcise:
            return False
        return True
    head = data[: 64 * 1024].lower()
    return any(f"[{name}]".encode() in head for name in COMMISSIONING_SPELLINGS) or has_banner(path)


def _defines(values: tuple[str, ...]) -> dict[str, str]:
    defines = {}
    for value in values:
        name, sep, text = value.partition("=")
        if not sep or not name:
            click.echo(f"cantools-od network: error: --define takes NAME=VALUE, not {value!r}", err=True)
            sys.exit(EXIT_USAGE)
        defines[name] = text
    return defines


def load_network(
    bus: str, defines: tuple[str, ...], dcf_dirs: tuple[str, ...], keep_going: bool = False, cogen: bool = True
) -> tuple[Network, dict[str, Device]]:
    """The network and each slave's device; any failure is one line and exit 2. Errors in reading a
    node's file refuse the network, unless `keep_going` (then they are printed and the rest goes on).
    The description's warnings (keys without effect where they stand) are printed."""
    from ..api import load
    from ..network.read import read_network
    from ..network.yamltree import NetworkError
    from ..sniff import NotADeviceDescription

    try:
        network = read_network(bus, _defines(defines), [Path(d) for d in dcf_dirs], cogen)
    except NetworkError as error:
        click.echo(str(error), err=True)
        sys.exit(EXIT_USAGE)
    for warning in network.warnings:
        click.echo(warning, err=True)
    devices: dict[str, Device] = {}
    for slave in network.slaves:
        where = f"{bus}:{slave.line_of('dcf')}"
        try:
            device = load(slave.dcf_file, node_id=slave.node_id)
        except OSError as error:
            click.echo(f"{where}: error: {slave.name}: cannot read {slave.dcf_file}: {error.strerror}", err=True)
            sys.exit(EXIT_USAGE)
        except NotADeviceDescription as error:
            click.echo(f"{where}: error: {slave.name}: {slave.dcf_file}: {error}", err=True)
            sys.exit(EXIT_USAGE)
        problem = errors_to_fix(device) or _repeated_section(device)
        if problem and keep_going:
            if not report(device.diagnostics, minimum=Severity.ERROR):
                click.echo(f"{where}: warning: {slave.name}: {slave.dcf_file}: {problem}", err=True)
        elif problem:
            click.echo(
                f"{where}: error: {slave.name}: {slave.dcf_file}: {problem} (cantools-od lint; --keep-going)", err=True
            )
            sys.exit(EXIT_USAGE)
        devices[slave.name] = device
    return network, devices


def _repeated_section(device: Device) -> str | None:
    """A section written twice (EDS002): the reader merges its keys, but which the device holds is not
    known, so the network is refused, as dcfgen refuses such a file."""
    for diagnostic in device.diagnostics:
        if diagnostic.code == "EDS002" and diagnostic.message.startswith("section ["):
            line = diagnostic.location.line
            return f"line {line}: {diagnostic.message.split(';')[0]}: which one the device holds is unknown"
    return None


def make_plan(
    network: Network, devices: dict[str, Device], parameter_values: bool, notes_on_stderr: bool = True
) -> NetworkPlan:
    """The plan; its warnings are printed on stderr, what the master checks of each slave at boot on
    stderr too (`lint --network`, whose report is stdout) or on stdout (`network`)."""
    from ..network.plan import plan_network
    from ..network.yamltree import NetworkError

    try:
        plan = plan_network(network, devices, parameter_values)
    except NetworkError as error:
        click.echo(str(error), err=True)
        sys.exit(EXIT_USAGE)
    from ..network.boot import explain

    for slave in plan.slaves:
        for warning in slave.warnings:
            click.echo(warning, err=True)
    for slave in plan.slaves:
        who = f"{slave.slave.name} (node-ID {slave.node_id})"
        for line in explain(slave.checks, who, f"{network.file}:{slave.slave.line}"):
            click.echo(line, err=notes_on_stderr)
    return plan


def _bus_copy(bus: str, target: str) -> Path:
    """Where --write-bus goes: never over the description being read."""
    path = Path(target)
    if path.exists() and path.resolve() == Path(bus).resolve():
        click.echo(f"cantools-od network: error: --write-bus {target} is the bus description itself", err=True)
        sys.exit(EXIT_USAGE)
    return path


def _expanded(bus: str, defines: tuple[str, ...]) -> bytes:
    from ..network.cogen import expanded

    return expanded(Path(bus).read_text(encoding="utf-8"), _defines(defines)).encode("utf-8")


def _remove(paths: list[Path]) -> None:
    """The files an earlier run wrote that this one does not (a node left the bus); each removal is said."""
    for path in paths:
        try:
            path.unlink()
        except OSError as error:
            click.echo(f"{path}: warning: not removed, though no longer written: {error.strerror}", err=True)
        else:
            click.echo(f"{path}: removed (written by an earlier run, no longer part of the network)", err=True)


def _outputs(
    plan: NetworkPlan,
    bus: str,
    defines: tuple[str, ...],
    outdir: str | None,
    dbc: str | None,
    svg: str | None,
    write_bus: str | None,
    data_bitrate: int | None,
    no_node_dcf: bool,
    remote_pdo: bool,
) -> tuple[list[tuple[Path, Content]], list[Path]]:
    """Every file the options ask for, and the files an earlier run wrote into OUTDIR that this one does not."""
    files: list[tuple[Path, Content]] = []
    removed: list[Path] = []
    if outdir is not None:
        from ..files import Generated
        from ..network.outputs import MANIFEST, manifest, outputs, stale

        made = outputs(plan, Path(outdir), node_dcfs=not no_node_dcf, remote_pdo=remote_pdo)
        removed = stale(Path(outdir), made)
        files.extend(Generated(path, data) for path, data in made.items())
        files.append((Path(outdir) / MANIFEST, manifest(made)))
    if dbc is not None:
        from ..network.dbc import network_dbc

        files.append((Path(dbc), network_dbc(plan)))
    if write_bus is not None:
        files.append((_bus_copy(bus, write_bus), _expanded(bus, defines)))
    if svg is not None:
        from ..network.picture import bus_picture
        from ..render.bus_svg import render

        banner = f"Generated by cantools-od network from {Path(bus).name}; regenerate it rather than editing it."
        files.append((Path(svg), render(bus_picture(plan, data_bitrate), banner).encode("utf-8")))
    return files, removed


@click.command(name="network")
@click.argument("bus", type=click.Path(dir_okay=False))
@click.option(
    "-o", "--output", "outdir", type=Output(file_okay=False), help="Write master.dcf, <node>.bin, <node>.dcf here."
)
@click.option(
    "--define", "defines", multiple=True, metavar="NAME=VALUE", help="Value of an @NAME@ placeholder (repeatable)."
)
@click.option(
    "--dcf-dir",
    "dcf_dirs",
    multiple=True,
    type=click.Path(file_okay=False),
    help="Also look for nodes' `dcf` files here.",
)
@click.option(
    "--no-cogen",
    is_flag=True,
    help="Read `defaults`/`nodes` as written (a node's key over `defaults`, file order), not as ros2_canopen's cogen.",
)
@click.option("--no-parameter-values", is_flag=True, help="Do not write the DCFs' ParameterValues at boot (as dcfgen).")
@click.option("-r", "--remote-pdo", is_flag=True, help="Also write lely's remote PDO objects (dcfgen -r).")
@click.option("--no-node-dcf", is_flag=True, help="Do not write a DCF per node.")
@click.option("--load", "show_load", is_flag=True, help="Print the bus load per bit rate.")
@click.option(
    "--data-bitrate", type=click.IntRange(1, 20_000), help="CAN FD data phase in kbit/s (--load, PDOs above 8 bytes)."
)
@click.option(
    "--threshold", type=click.FloatRange(1, 100), default=70.0, show_default=True, help="Warn above this load (%)."
)
@click.option("--dbc", type=Output(dir_okay=False), help="Write every PDO of the network as a DBC file.")
@click.option(
    "--svg", type=Output(dir_okay=False), help="Draw the bus: who sends which PDO, SYNC and heartbeat to whom."
)
@click.option(
    "--write-bus",
    type=Output(dir_okay=False),
    help="Also write BUS as ros2_canopen's build installs it (cogen's expansion, placeholders replaced).",
)
@click.option("--keep-going", is_flag=True, help="Go on despite errors in reading the nodes' files (printed).")
@click.option("--check/--no-check", default=True, show_default=True, help="Refuse a network the checks find errors in.")
@force_option
def command(
    bus: str,
    outdir: str | None,
    defines: tuple[str, ...],
    dcf_dirs: tuple[str, ...],
    no_cogen: bool,
    no_parameter_values: bool,
    remote_pdo: bool,
    no_node_dcf: bool,
    show_load: bool,
    data_bitrate: int | None,
    threshold: float,
    dbc: str | None,
    write_bus: str | None,
    svg: str | None,
    keep_going: bool,
    check: bool,
    force: bool,
) -> None:
    """Turn the bus description BUS (lely dcfgen's bus.yml, ros2_canopen's included) into the master's
    configuration: master.dcf, one concise DCF (<node>.bin, CiA 302-3) per slave the master
    configures at boot, and one DCF per node. All files or none; never over a file the command reads,
    nor over a file in OUTDIR that is no DCF or concise DCF (unless --force). Exit 0, 1 with load above the
    threshold or network errors, 2 when BUS cannot be turned into a network or an output is refused."""
    if outdir is None and not show_load and dbc is None and svg is None and write_bus is None:
        click.echo(
            "cantools-od network: error: nothing to do: give -o OUTDIR, --load, --dbc FILE, --svg FILE or"
            " --write-bus FILE (see --help)",
            err=True,
        )
        sys.exit(EXIT_USAGE)
    network, devices = load_network(bus, defines, dcf_dirs, keep_going, cogen=not no_cogen)
    plan = make_plan(network, devices, not no_parameter_values, notes_on_stderr=False)
    failed = False
    if check:
        from ..lint.network import lint_bus

        findings = lint_bus(plan)
        for finding in findings:
            click.echo(finding.format(), err=True)
        failed = any(f.severity.value == "error" for f in findings)
        if failed:
            click.echo(f"{bus}: error: the network has errors: nothing written (--no-check writes anyway)", err=True)
            sys.exit(EXIT_FINDINGS)
    files, removed = _outputs(plan, bus, defines, outdir, dbc, svg, write_bus, data_bitrate, no_node_dcf, remote_pdo)
    if files:
        from ..network.outputs import MANIFEST

        manifest = [Path(outdir) / MANIFEST] if outdir is not None else []  # read, then rewritten by design
        write_outputs(files, force=force, ours=configuration_file, rewrites=manifest)
    _remove(removed)
    if show_load:
        from ..network.load import bus_load, format_load

        report = bus_load(plan, data_bitrate)
        click.echo(format_load(report, threshold), nl=False)
        failed = failed or report.peak_percent > threshold
    sys.exit(EXIT_FINDINGS if failed else EXIT_OK)
