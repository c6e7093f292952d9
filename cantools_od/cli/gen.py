"""`cantools-od gen`: C, Rust, Python, Markdown and CANopenNode OD.h/OD.c from one object dictionary."""

from __future__ import annotations

import re
import sys
from dataclasses import replace
from pathlib import Path

import click

from .common import EXIT_FINDINGS, EXIT_OK, identifiers_for, node_id_option, pins_option, read_device, report


def default_name(file: str) -> str:
    from ..identifiers import snake_case

    return snake_case(Path(file).stem, fallback="od")


@click.command(name="gen")
@click.argument("file", type=click.Path(dir_okay=False))
@click.option(
    "-t", "--target", "targets", multiple=True, required=True,
    type=click.Choice(["c", "rust", "python", "markdown", "canopennode"]), help="What to generate; repeat for several.",
)  # fmt: skip
@click.option("-o", "--output", "outdir", required=True, type=click.Path(file_okay=False), help="Output folder.")
@click.option("--name", help="Base name of the generated files and symbols (default: FILE's stem).")
@click.option("--can-fd", is_flag=True, help="Allow PDOs up to 512 bits (CAN FD).")
@click.option("--depfile", type=click.Path(dir_okay=False), help="Write a Makefile-style depfile for build systems.")
@click.option("--explain", is_flag=True, help="List every CANopenNode setting that was inferred (-t canopennode).")
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
    node_id: int | None,
    pin_file: str | None,
) -> None:
    """Generate code and documents for FILE into OUTDIR. Files are rewritten only when
    their content changes; nothing is written when FILE cannot be generated from
    (exit 1, with the reasons as diagnostics)."""
    from ..api import write_if_changed
    from ..identifiers import is_identifier, pin_file_for
    from ..model import Severity
    from ..render import renderer
    from ..views.codegen import build_view
    from .canopennode import prepare_canopennode

    base = name or default_name(file)
    stack_only = set(targets) == {"canopennode"}  # the stack's own names: OD, OD1 (any C identifier)
    if name and {"c", "canopennode"} <= set(targets):
        raise click.BadParameter("-t c and -t canopennode would both write NAME.h/NAME.c; run them apart",
                                 param_hint="--name")  # fmt: skip
    if not (is_identifier(base) or (stack_only and re.fullmatch(r"[A-Za-z_][A-Za-z0-9_]*", base))):
        raise click.BadParameter(f"{base!r} is not a valid identifier", param_hint="--name")
    device = read_device(file, node_id)
    identifiers = identifiers_for(device, file, pin_file)
    extra_inputs = prepare_canopennode(device, file, explain) if "canopennode" in targets else []
    view = build_view(device, base, node_id, identifiers, max_pdo_bits=512 if can_fd else 64)
    # Read errors are shown; they fail the command only when they make generation impossible.
    report(device.diagnostics, minimum=Severity.ERROR)
    if view.problems and not stack_only:  # PDO code needs them; the stack checks PDOs itself
        report(view.problems)
        click.echo(f"{file}: error: nothing generated", err=True)
        sys.exit(EXIT_FINDINGS)
    outputs: dict[Path, str] = {}
    for target in dict.fromkeys(targets):
        # CANopenNode's files are OD.h/OD.c unless named: the stack includes "OD.h".
        target_view = replace(view, name=name or "OD") if target == "canopennode" else view
        for filename, text in renderer(target)(target_view).items():
            outputs[Path(outdir) / filename] = text
    for path, text in outputs.items():  # everything rendered before anything is written
        write_if_changed(path, text.encode("utf-8"))
    if depfile:
        pins = pin_file_for(file, pin_file)
        inputs = [file, *([str(pins)] if pins else []), *extra_inputs]
        rule = " ".join(_escape(str(p)) for p in outputs) + ": " + " ".join(_escape(i) for i in inputs) + "\n"
        write_if_changed(Path(depfile), rule.encode("utf-8"))
    sys.exit(EXIT_OK)


def _escape(path: str) -> str:
    return path.replace("\\", "/").replace(" ", "\\ ").replace("$", "$$").replace("#", "\\#")
