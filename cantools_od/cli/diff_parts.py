"""What `diff` of two files and `diff` of two folders (diff_folders.py) share: a side's reading notes and refusal,
pin files, the report in each format and whether it fails the run."""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path

from ..model import Device
from ..model.device import blocking_errors

NULL_DEVICE = "/dev/null"  # git's name for the missing side of an added or deleted file


def found_in(result: object, fail_on: str) -> bool:
    """Whether a change at or above `--fail-on` is in the result."""
    from ..changes import Breaks, DeviceDiff

    assert isinstance(result, DeviceDiff)
    if fail_on in ("wire", "code"):
        return result.hurts(Breaks(fail_on))
    if fail_on == "breaking":
        return result.breaking
    return fail_on == "any" and not result.empty


def render(result: object, fmt: str, names: tuple[str, str] | None = None) -> str:
    """The report in a format; `names`: the sides as a Markdown title shows them (default: the files' names)."""
    from ..changes import DeviceDiff, jsonout, markdown, text

    assert isinstance(result, DeviceDiff)
    if fmt == "json":
        return jsonout.render(result)
    if fmt == "markdown":
        return markdown.render(result, names)
    return text.render(result)


def reading_note(device: Device, name: str) -> str:
    """The note that reading found errors (their values are compared as written); "" when it found none. Errors
    about peers on a file read whole (a key given twice) leave no value unread: they are lint's to report."""
    errors = len(blocking_errors(device))
    if not errors:
        return ""
    return (
        f"{name}: note: {errors} error{'s' if errors != 1 else ''} while reading; unreadable values are "
        f"compared as written (see `cantools-od lint {name}`)"
    )


def refusal(device: Device, name: str) -> str:
    """Why no side can be made of the device, "" when one can: the reader refused the file (XML that is not
    well-formed, hostile or not CiA 311), so no model of it exists and every object would show as removed."""
    from ..xdd import refusal as reader_refusal

    found = reader_refusal(device)
    if found is None:
        return ""
    line, column = found.location.shown  # named as the user named the file: under --git it is a temporary copy
    return f"{name}:{line}:{column}: error: {found.message} [{found.code}]; nothing compared"


def read_pins(path: Path) -> Mapping[str, str]:
    """A pin file's identifiers; ValueError with the one-line reason when it cannot be read or is none."""
    from ..identifiers import load_pins

    try:
        return load_pins(path)
    except OSError as error:
        raise ValueError(f"{path}: cannot read: {error.strerror or error}") from None


def missing_side() -> Device:
    """The side of an added or deleted file: an empty device named /dev/null. Made without validation, which would
    build the device's schema first: a cost at every start of the command."""
    return Device.model_construct(source=NULL_DEVICE)
