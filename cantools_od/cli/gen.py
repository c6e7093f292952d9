"""`cantools-od gen`: C, Rust, Python, Markdown and CANopenNode OD.h/OD.c from one object dictionary."""

from __future__ import annotations

import itertools
import re
import sys
from collections.abc import Iterator
from dataclasses import replace
from pathlib import Path
from typing import TYPE_CHECKING

import click

from ..files import Content, Generated
from ..model import Device, Severity
from ..model.device import blocking_errors
from .canopennode import keep_editor_readable, stack_config_option
from .common import (
    EXIT_FINDINGS,
    EXIT_OK,
    EXIT_USAGE,
    Output,
    Progress,
    check_extension,
    force_option,
    identifiers_for,
    node_id_option,
    pins_option,
    read_device,
    report,
    write_outputs,
)

if TYPE_CHECKING:
    from ..identifiers import Identifiers
    from ..views.codegen import DeviceView


NAME_RULE = (
    "Base name of the generated files and symbols, in snake_case: lower-case letters and digits in words joined "
    "by single _, starting with a letter, no C, C++, Rust or Python keyword (default: FILE's stem in snake_case). "
    "-t canopennode alone takes any C identifier (default OD)."
)


def default_name(file: str) -> str:
    from ..identifiers import snake_case

    return snake_case(Path(file).stem, fallback="od")


@click.command(name="gen")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option(
    "-t", "--target", "targets", multiple=True, required=True,
    type=click.Choice(["c", "rust", "python", "markdown", "html", "canopennode", "dbc"]),
    help="What to generate; repeat for several (dbc: the PDOs at the node-ID, for trace tools).",
)  # fmt: skip
@click.option("-o", "--output", "outdir", required=True, type=Output(file_okay=False), help="Output folder.")
@click.option("--name", help=NAME_RULE)
@click.option("--can-fd", is_flag=True, help="Allow PDOs up to 512 bits (CAN FD).")
@click.option("--depfile", type=Output(dir_okay=False), help="Write a Makefile-style depfile for build systems.")
@click.option("--explain", is_flag=True, help="List every CANopenNode setting that was inferred (-t canopennode).")
@click.option(
    "--keep-going", is_flag=True,
    help="Generate what errors in FILE do not touch, list what is left out, and exit 0.",
)  # fmt: skip
@force_option
@stack_config_option
@node_id_option
@pins_option
def command(
    file: str,
    targets: tuple[str, ...],
    outdir: str,
    name: str | None,
    can_fd: bool,
    depfile: str | None,
    explain: bool,
    keep_going: bool,
    node_id: int | None,
    pin_file: str | None,
    stack_files: tuple[str, ...],
    force: bool,
) -> None:
    """Generate code and documents for FILE into OUTDIR. Files are rewritten only when
    their content changes, and all of them or none. A file in OUTDIR that cantools-od did not
    generate is not replaced (exit 2) unless --force, nor is any file the command reads.

    An error in FILE that touches what is generated (an invalid value, a broken section, a
    PDO that cannot be packed) fails the command with exit 1 and writes nothing; with
    --keep-going the rest is generated and what was left out is listed, in the files'
    header comments and on stderr."""
    from ..eds.where import damaged_objects
    from ..identifiers import is_identifier, pin_file_for
    from ..model.cia301.pdo import frame_bits
    from ..views.partial import unfit_values
    from ..xdd import refused
    from .canopennode import prepare_canopennode

    if explain and "canopennode" not in targets:
        raise click.BadParameter(
            "it lists the settings -t canopennode infers; add -t canopennode", param_hint="--explain"
        )
    base = name or default_name(file)
    stack_only = set(targets) == {"canopennode"}  # the stack's own names: OD, OD1 (any C identifier)
    if name and {"c", "canopennode"} <= set(targets):
        raise click.BadParameter("-t c and -t canopennode would both write NAME.h/NAME.c; run them apart",
                                 param_hint="--name")  # fmt: skip
    if not (is_identifier(base) or (stack_only and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", base))):
        rule = "snake_case: lower-case letters and digits in words joined by single _, and no keyword"
        raise click.BadParameter(f"{base!r} is not a valid identifier ({rule})", param_hint="--name")
    check_extension(file, "input")
    device = read_device(file, node_id)
    if refused(device):  # no model of the file exists: an empty output would pass a build that must fail
        report(device.diagnostics, minimum=Severity.ERROR)
        click.echo(f"{file}: error: nothing generated: the file could not be read", err=True)
        sys.exit(EXIT_FINDINGS)
    unfit = unfit_values(device)  # values no generated code can spell: errors of gen's own (GEN001)
    damaged = set(damaged_objects(device))
    if stack_only:
        keep_editor_readable(device, damaged)
    damaged |= set(unfit)
    device._original = None  # the file's bytes, which only the search for damage needs: gen writes no EDS
    identifiers = identifiers_for(device, file, pin_file)
    extra_inputs = prepare_canopennode(device, file, explain, stack_files) if "canopennode" in targets else []
    # The reader's errors about peers on values it read whole (`0x80+$NODEID`) are lint's to report: the code is right.
    report([*blocking_errors(device), *itertools.chain.from_iterable(unfit.values())], minimum=Severity.ERROR)
    # PDO code needs the PDOs to be packable; the stack checks PDOs itself.
    view, left_out = _view(device, damaged, base, node_id, identifiers, frame_bits(can_fd), not stack_only)
    if left_out:
        shown = "; ".join(left_out[:10]) + (f"; and {len(left_out) - 10} more" if len(left_out) > 10 else "")
        if not keep_going:
            why = f"{file}: error: nothing generated: errors touch {shown}"
            click.echo(f"{why} (--keep-going generates the rest)", err=True)
            sys.exit(EXIT_FINDINGS)
        click.echo(f"{file}: warning: left out of the generated files: {shown}", err=True)
    code_targets = tuple(target for target in targets if target != "dbc")
    files: Iterator[tuple[Path, Content]] = _files(view, code_targets, name, Path(outdir), left_out)
    if "dbc" in targets:
        files = itertools.chain(files, [Generated(Path(outdir) / f"{base}.dbc", [_dbc(device, file, node_id, base)])])
    if depfile:
        pins = pin_file_for(file, pin_file)
        files = _with_depfile(files, Path(depfile), [file, *([str(pins)] if pins else []), *extra_inputs, *stack_files])
    # Each file is rendered as it is written; a failure anywhere leaves every output as it was.
    write_outputs(_counted(files), force=force)
    sys.exit(EXIT_OK)


def _dbc(device: Device, file: str, node_id: int | None, base: str) -> bytes:
    """The device's PDOs as a DBC; a device without a node-ID has no CAN-IDs to give them (exit 2)."""
    from ..model.cia301.cobid import known_node_id
    from ..network.dbc import device_dbc
    from ..network.plan import device_pdos

    known = known_node_id(device, node_id)
    if known is None:
        click.echo(f"{file}: error: -t dbc needs the node-ID its COB-IDs stand for: give --node-id", err=True)
        sys.exit(EXIT_USAGE)
    return device_dbc(device_pdos(device, known, base), base)


def _view(
    device: Device,
    damaged: set[int],
    base: str,
    node_id: int | None,
    identifiers: Identifiers,
    max_pdo_bits: int,
    pdo_code: bool,
) -> tuple[DeviceView, list[str]]:
    """The view to render without the `damaged` objects, and what errors made it leave out (objects, then PDOs)."""
    from ..views.codegen import build_view
    from ..views.partial import left_out_objects, without, without_failed_pdos

    # Identifiers come from the whole device, so that leaving an object out renames nothing else.
    view = build_view(without(device, damaged), base, node_id, identifiers, max_pdo_bits=max_pdo_bits)
    left_out = left_out_objects(device, damaged)
    if view.problems and pdo_code:
        report(view.problems)
        view, pdos = without_failed_pdos(view)
        left_out += pdos
    return view, left_out


def _files(
    view: DeviceView, targets: tuple[str, ...], name: str | None, outdir: Path, left_out: list[str]
) -> Iterator[tuple[Path, Content]]:
    """Every target's files, each as its encoded text in pieces (rendered when read), in target order."""
    from ..render import streamer
    from ..render.notes import left_out_note

    for target in dict.fromkeys(targets):
        # CANopenNode's files are OD.h/OD.c unless named: the stack includes "OD.h".
        target_view = replace(view, name=name or "OD") if target == "canopennode" else view
        for filename, pieces in streamer(target)(target_view).items():
            text = itertools.chain([left_out_note(filename, left_out)], pieces)
            yield Generated(outdir / filename, (piece.encode("utf-8") for piece in text))


def _counted(files: Iterator[tuple[Path, Content]]) -> Iterator[tuple[Path, Content]]:
    """`files`, each named on a terminal as it is rendered (large devices take seconds a file)."""
    progress = Progress("gen")
    for output in files:
        path, content = output
        counted = _stepped(progress, path.name, content)
        yield Generated(path, counted) if isinstance(output, Generated) else (path, counted)


def _stepped(progress: Progress, name: str, content: Content) -> Iterator[bytes]:
    """`content`, its file counted on the terminal when it starts to be rendered."""
    progress.step(name)
    yield from [content] if isinstance(content, bytes) else content
    progress.clear()


def _with_depfile(
    files: Iterator[tuple[Path, Content]], depfile: Path, inputs: list[str]
) -> Iterator[tuple[Path, Content]]:
    """`files`, then a Makefile-style depfile naming them as the targets of `inputs`."""
    written = []
    for output in files:
        written.append(output[0])
        yield output
    rule = " ".join(_escape(str(p)) for p in written) + ": " + " ".join(_escape(i) for i in inputs) + "\n"
    yield depfile, [rule.encode("utf-8")]


def _escape(path: str) -> str:
    return path.replace("\\", "/").replace(" ", "\\ ").replace("$", "$$").replace("#", "\\#")
