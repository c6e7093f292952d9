"""`cantools-od diff`: what changed between two device descriptions, and what it breaks.

Also a git external diff driver (git passes 7 or 9 arguments) and `--git REV1 REV2 PATH`.
"""

from __future__ import annotations

import os
import subprocess
import sys
import tempfile
from collections.abc import Mapping
from pathlib import Path
from typing import NoReturn

import click

from ..model import Device
from .batch import jobs_option
from .common import EXIT_FINDINGS, EXIT_OK, EXIT_USAGE, Progress, node_id_option, read_device
from .diff_parts import NULL_DEVICE, found_in, missing_side, read_pins, reading_note, refusal, render

DEVICE_SUFFIXES = (".eds", ".dcf", ".json", ".xdd", ".xdc", ".xpd")


def _fail(message: str) -> NoReturn:
    click.echo(f"error: {message}", err=True)
    sys.exit(EXIT_USAGE)


@click.command(name="diff")
@click.argument("args", nargs=-1, metavar="OLD NEW")
@click.option("--format", "fmt", type=click.Choice(["text", "json", "markdown"]), default="text", show_default=True)
@click.option(
    "--fail-on",
    type=click.Choice(["wire", "code", "breaking", "any", "never"]),
    default="never",
    show_default=True,
    help="Exit 1 when a change that breaks the bus (wire), generated code (code), either (breaking), or any change "
    "is found; never: exit 0 whatever changed.",
)
@click.option("--git", "git_mode", is_flag=True, help="ARGS are REV1 REV2 PATH (or REV PATH: against the work tree).")
@node_id_option
@click.option("--old-pins", type=click.Path(dir_okay=False), help="Pin file for OLD; default: OLD's stem + .ids.toml.")
@click.option("--new-pins", type=click.Path(dir_okay=False), help="Pin file for NEW; default: NEW's stem + .ids.toml.")
@click.option("--color/--no-color", default=None, help="Colour the text report; default: when stdout is a terminal.")
@jobs_option
def command(
    args: tuple[str, ...],
    fmt: str,
    fail_on: str,
    git_mode: bool,
    node_id: int | None,
    old_pins: str | None,
    new_pins: str | None,
    color: bool | None,
    jobs: int | None,
) -> None:
    """Compare OLD and NEW (EDS, DCF, XDD, XDC or JSON, in any mix) object by object, and class each
    change as breaking (for the bus, generated code or both), compatible, value or cosmetic.
    Differences of spelling only (radix, key case, section order) are no changes. Two folders: every
    device description under either, paired by relative path; only pairs that changed are reported.
    As a git external diff driver it takes git's 7 arguments."""
    try:
        _run(args, fmt, fail_on, git_mode, node_id, (old_pins, new_pins), color, jobs)
    except Exception as error:  # a failure of ours: one line and exit 2, never a traceback nor exit 1
        reason = " ".join(str(error).split())[:200]
        _fail(f"internal error: {type(error).__name__}{': ' + reason if reason else ''} (please report it)")


def _run(
    args: tuple[str, ...],
    fmt: str,
    fail_on: str,
    git_mode: bool,
    node_id: int | None,
    pin_files: tuple[str | None, str | None],
    color: bool | None,
    jobs: int | None,
) -> None:
    from ..changes import compare

    if not git_mode and len(args) == 2 and any(Path(arg).is_dir() for arg in args):
        _folders(args, fmt, fail_on, node_id, pin_files, jobs, color)
    old_pins, new_pins = pin_files
    progress = Progress("diff")  # on a terminal: what it is doing while large files are read and compared
    progress.step("reading")
    if git_mode:
        if len(args) not in (2, 3):
            _fail("--git takes REV1 REV2 PATH, or REV PATH")
        old, new = _git_sides(args, node_id)
    elif len(args) in (7, 9):
        # GIT_EXTERNAL_DIFF: path old-file old-hex old-mode new-file new-hex new-mode [new-path similarity]
        if Path(args[0]).suffix.lower() not in DEVICE_SUFFIXES:
            _text_diff(args)  # GIT_EXTERNAL_DIFF sends every file: others get an ordinary diff
            sys.exit(EXIT_OK)
        old, new = _external_sides(args, node_id)
    elif len(args) == 2:
        old, new = _file_side(args[0], node_id, old_pins), _file_side(args[1], node_id, new_pins)
    else:
        _fail("give OLD and NEW (or --git REV1 REV2 PATH)")
    pins = [_explicit_pins(old_pins), _explicit_pins(new_pins)]
    progress.step("comparing")
    result = compare(old.device, new.device, node_id, pins[0] or old.pins, pins[1] or new.pins)
    progress.clear()
    click.echo(render(result, fmt), color=color if fmt == "text" else False)
    sys.exit(EXIT_FINDINGS if found_in(result, fail_on) else EXIT_OK)


def _folders(
    args: tuple[str, ...],
    fmt: str,
    fail_on: str,
    node_id: int | None,
    pin_files: tuple[str | None, str | None],
    jobs: int | None,
    color: bool | None,
) -> NoReturn:
    from .diff_folders import Options, run

    if not all(Path(arg).is_dir() for arg in args):
        _fail("give two files or two folders as OLD and NEW")
    if any(pin_files):
        _fail("--old-pins and --new-pins name the pin file of one file: with folders, each file's own is used")
    run(args[0], args[1], Options(fmt, fail_on, node_id), jobs, color)


def _text_diff(args: tuple[str, ...]) -> None:
    """A unified diff of a file that is no device description, as git would show it."""
    import difflib

    path, new_path = args[0], args[7] if len(args) == 9 else args[0]
    try:
        old_lines, new_lines = (Path(name).read_bytes().decode("utf-8", "replace") for name in (args[1], args[4]))
    except OSError as error:
        _fail(f"{path}: cannot read: {error.strerror or error}")
    lines = difflib.unified_diff(
        old_lines.splitlines(keepends=True), new_lines.splitlines(keepends=True), f"a/{path}", f"b/{new_path}"
    )
    sys.stdout.writelines(line if line.endswith("\n") else line + "\n" for line in lines)


class Side:
    """One side of the comparison: the device and the pins found beside it (None: none)."""

    def __init__(self, device: Device, pins: Mapping[str, str] | None) -> None:
        self.device = device
        self.pins = pins


def _note_errors(device: Device, name: str) -> None:
    """The reading note on stderr; exit 2 with one line when the file was refused."""
    refused = refusal(device, name)
    if refused:
        click.echo(refused, err=True)
        sys.exit(EXIT_USAGE)
    note = reading_note(device, name)
    if note:
        click.echo(note, err=True)


def _pins_file(path: Path | None) -> Mapping[str, str] | None:
    if path is None:
        return None
    try:
        return read_pins(path)
    except ValueError as error:
        _fail(str(error))


def _explicit_pins(path: str | None) -> Mapping[str, str] | None:
    return _pins_file(Path(path)) if path is not None else None


def _file_side(path: str, node_id: int | None, explicit_pins: str | None) -> Side:
    from ..identifiers import pin_file_for

    if path == NULL_DEVICE:
        return Side(missing_side(), None)
    device = read_device(path, node_id)
    _note_errors(device, path)
    return Side(device, None if explicit_pins else _pins_file(pin_file_for(path)))


def _external_sides(args: tuple[str, ...], node_id: int | None) -> tuple[Side, Side]:
    from ..identifiers import pin_file_for

    path, old_file, new_file = args[0], args[1], args[4]
    pins = _pins_file(pin_file_for(path))  # the temporary files git hands over have no pin file beside them
    old, new = _file_side(old_file, node_id, "-"), _file_side(new_file, node_id, "-")
    if old_file != NULL_DEVICE:  # git's /dev/null stays the name of the missing side of a new or deleted file
        old.device.source = f"a/{path}"
    if new_file != NULL_DEVICE:
        new.device.source = f"b/{args[7] if len(args) == 9 else path}"
    return Side(old.device, pins), Side(new.device, pins)


def _git_show(revision: str, path: Path) -> bytes | None:
    """The file at a revision, None when it does not exist there; exits 2 when git cannot answer."""
    # From the file's folder when it exists (the path then also works from outside the repository),
    # else from here: a folder deleted from the work tree may still be in the revision.
    folder = path.parent if path.parent.is_dir() else Path(".")
    spec = f"{revision}:./{path.name if folder == path.parent else path.as_posix()}"
    try:
        result = subprocess.run(["git", "show", spec], cwd=folder, capture_output=True, check=False)
    except OSError as error:
        _fail(f"cannot run git: {error.strerror or error}")
    if result.returncode == 0:
        return result.stdout
    message = result.stderr.decode("utf-8", "replace").strip().splitlines()
    if any("exists on disk, but not in" in line or "does not exist in" in line for line in message):
        return None
    _fail(f"git show {spec}: {message[-1] if message else 'failed'}")


def _git_side(revision: str | None, path: Path, node_id: int | None) -> Side:
    """PATH at a revision (None: the work tree), read from a copy of the same name so that the file
    name decides the format as it does for `load`; the pin file beside it at the same revision."""
    from ..api import load

    name = os.fspath(path)
    if revision is None:
        return _file_side(name, node_id, None)
    data = _git_show(revision, path)
    if data is None:
        _fail(f"{name} does not exist at {revision}")
    source = f"{revision}:{name}"
    pin_data = _git_show(revision, path.with_suffix(".ids.toml"))
    with tempfile.TemporaryDirectory() as folder:
        copy = Path(folder) / path.name
        copy.write_bytes(data)
        try:
            device = load(copy, node_id=node_id)
        except ValueError as error:
            _fail(f"{source}: not a cantools-od model: {error}")
        pins = None
        if pin_data is not None:
            pin_path = copy.with_suffix(".ids.toml")
            pin_path.write_bytes(pin_data)
            pins = _pins_file(pin_path)
    device.source = source
    _note_errors(device, source)
    return Side(device, pins)


def _git_sides(args: tuple[str, ...], node_id: int | None) -> tuple[Side, Side]:
    path = Path(args[-1])
    if len(args) == 2:
        return _git_side(args[0], path, node_id), _git_side(None, path, node_id)
    return _git_side(args[0], path, node_id), _git_side(args[1], path, node_id)
