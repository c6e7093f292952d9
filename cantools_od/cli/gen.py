"""`cantools-od gen`: C, Rust, Python and Markdown from one object dictionary."""

from __future__ import annotations

import sys
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
    type=click.Choice(["c", "rust", "python", "markdown"]), help="What to generate; repeat for several.",
)  # fmt: skip
@click.option("-o", "--output", "outdir", required=True, type=click.Path(file_okay=False), help="Output folder.")
@click.option("--name", help="Base name of the generated files and symbols (default: FILE's stem).")
@click.option("--can-fd", is_flag=True, help="Allow PDOs up to 512 bits (CAN FD).")
@click.option("--depfile", type=click.Path(dir_okay=False), help="Write a Makefile-style depfile for build systems.")
@node_id_option
@pins_option
def command(
    file: str,
    targets: tuple[str, ...],
    outdir: str,
    name: str | None,
    can_fd: bool,
    depfile: str | None,
    node_id: int | None,
    pin_file: str | None,
) -> None:
    """Generate code and documents for FILE into OUTDIR. Files are rewritten only when
    their content changes; nothing is written when FILE cannot be generated from
    (exit 1, with the reasons as diagnostics)."""
    from ..api import write_if_changed
    from ..identifiers import is_identifier, pin_file_for
    from ..model import Severity
    from ..model.cia301.pdo import frame_bits
    from ..render import renderer
    from ..views.codegen import build_view

    base = name or default_name(file)
    if not is_identifier(base):
        raise click.BadParameter(f"{base!r} is not a valid identifier", param_hint="--name")
    device = read_device(file, node_id)
    identifiers = identifiers_for(device, file, pin_file)
    view = build_view(device, base, node_id, identifiers, max_pdo_bits=frame_bits(can_fd))
    # Read errors are shown; they fail the command only when they make generation impossible.
    report(device.diagnostics, minimum=Severity.ERROR)
    if view.problems:
        report(view.problems)
        click.echo(f"{file}: error: nothing generated", err=True)
        sys.exit(EXIT_FINDINGS)
    outputs: dict[Path, str] = {}
    for target in dict.fromkeys(targets):
        for filename, text in renderer(target)(view).items():
            outputs[Path(outdir) / filename] = text
    for path, text in outputs.items():  # everything rendered before anything is written
        write_if_changed(path, text.encode("utf-8"))
    if depfile:
        pins = pin_file_for(file, pin_file)
        inputs = [file, *([str(pins)] if pins else [])]
        rule = " ".join(_escape(str(p)) for p in outputs) + ": " + " ".join(_escape(i) for i in inputs) + "\n"
        write_if_changed(Path(depfile), rule.encode("utf-8"))
    sys.exit(EXIT_OK)


def _escape(path: str) -> str:
    return path.replace("\\", "/").replace(" ", "\\ ").replace("$", "$$").replace("#", "\\#")
