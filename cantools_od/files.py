"""Writing files without making things worse: every command that writes goes through here.

A write is atomic (a temporary file in the same folder, flushed to disk, renamed over the
target), keeps an existing file's mode (and owner, where the process may set it), gives a new
file the mode `0666 & ~umask` like any other tool, and leaves a file whose content is already
right untouched. A symbolic link is written through: its target gets the new content and the
link stays a link. A set of outputs is written all or nothing.
"""

from __future__ import annotations

import contextlib
import errno
import os
import secrets
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path


class CannotWrite(Exception):
    """A file could not be written; nothing of the set it belongs to was."""

    def __init__(self, path: Path, reason: str) -> None:
        super().__init__(f"cannot write {path}: {reason}")
        self.path = path
        self.reason = reason


@dataclass
class _Pending:
    path: Path  # as the caller named it, for messages
    target: Path  # the file that is replaced: `path`, or what its symbolic link points to
    data: bytes
    temp: Path | None = None


def write_if_changed(path: str | os.PathLike[str], data: bytes) -> bool:
    """Atomically replace `path` with `data` unless it already holds exactly that; True when written.

    Raises CannotWrite with the reason when the file cannot be written."""
    return bool(write_all([(Path(path), data)]))


def write_all(outputs: Iterable[tuple[Path, bytes]]) -> list[Path]:
    """Write every output whose content changes, or none of them; the paths written.

    Every temporary file is written and flushed before the first one is renamed, so a full disk,
    a read-only folder or a path that is a folder leaves every target as it was and no temporary
    file behind. Raises CannotWrite naming the first output that failed."""
    pending = [_Pending(path, _target(path), data) for path, data in outputs]
    changed = [p for p in pending if not _holds(p.target, p.data)]
    created: list[Path] = []  # folders made for the outputs, removed again when the set fails
    try:
        for item in changed:
            _make_folder(item, created)
            item.temp = _write_temp(item)
        for item in changed:
            _rename(item)
    except BaseException:
        for item in changed:
            if item.temp is not None:
                with contextlib.suppress(OSError):
                    item.temp.unlink()
        for folder in reversed(created):
            with contextlib.suppress(OSError):
                folder.rmdir()  # only when empty
        raise
    for folder in {item.target.parent for item in changed}:
        _sync_folder(folder)
    return [item.path for item in changed]


def _target(path: Path) -> Path:
    """The file a write replaces: a symbolic link's target (links are written through, not replaced)."""
    try:
        if path.is_symlink():
            return Path(os.path.realpath(path))
    except OSError:
        pass
    return path


def _holds(path: Path, data: bytes) -> bool:
    try:
        if path.stat().st_size != len(data):
            return False
        return path.read_bytes() == data
    except OSError:
        return False  # missing, a folder, unreadable: the write decides


def _write_temp(item: _Pending) -> Path:
    target = item.target
    if target.is_dir():
        raise CannotWrite(item.path, "it is a folder")
    try:
        existing = target.stat()
    except FileNotFoundError:
        existing = None
    except OSError as error:
        raise CannotWrite(item.path, _reason(error)) from None
    try:
        temp, fd = _create_temp(target)
    except OSError as error:
        raise CannotWrite(item.path, _reason(error)) from None
    item.temp = temp
    try:
        with os.fdopen(fd, "wb") as handle:
            if existing is not None:
                _keep_owner_and_mode(handle.fileno(), existing)
            handle.write(item.data)
            handle.flush()
            os.fsync(handle.fileno())
    except OSError as error:
        raise CannotWrite(item.path, _reason(error)) from None
    return temp


def _make_folder(item: _Pending, created: list[Path]) -> None:
    missing = [folder for folder in [item.target.parent, *item.target.parent.parents] if not folder.exists()]
    for folder in reversed(missing):
        try:
            folder.mkdir()
        except FileExistsError:
            continue
        except OSError as error:
            raise CannotWrite(item.path, _reason(error)) from None
        created.append(folder)


def _create_temp(target: Path) -> tuple[Path, int]:
    """A new file beside `target`, created with 0666 so that the umask gives a new file its usual mode."""
    while True:
        temp = target.with_name(f".{target.name}.{secrets.token_hex(4)}.tmp")
        try:
            return temp, os.open(temp, os.O_WRONLY | os.O_CREAT | os.O_EXCL | getattr(os, "O_BINARY", 0), 0o666)
        except FileExistsError:
            continue


def _keep_owner_and_mode(fd: int, existing: os.stat_result) -> None:
    if hasattr(os, "fchown") and (existing.st_uid, existing.st_gid) != (os.getuid(), os.getgid()):
        with contextlib.suppress(OSError):  # only root (or the owner, for the group) may
            os.fchown(fd, existing.st_uid, existing.st_gid)
    if hasattr(os, "fchmod"):
        os.fchmod(fd, existing.st_mode & 0o7777)


def _rename(item: _Pending) -> None:
    assert item.temp is not None
    try:
        os.replace(item.temp, item.target)
    except OSError as error:
        raise CannotWrite(item.path, _reason(error)) from None
    item.temp = None


def _sync_folder(folder: Path) -> None:
    """Make the renames durable; not every system can open a folder, which is fine."""
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _reason(error: OSError) -> str:
    if error.errno == errno.EISDIR:
        return "it is a folder"
    if error.errno in (errno.ENOTDIR, errno.EEXIST) and error.filename is not None:
        return f"{error.filename} is not a folder"
    return error.strerror or str(error)
