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
from typing import BinaryIO


class CannotWrite(Exception):
    """A file could not be written; nothing of the set it belongs to was."""

    def __init__(self, path: Path, reason: str) -> None:
        super().__init__(f"cannot write {path}: {reason}")
        self.path = path
        self.reason = reason


Content = bytes | Iterable[bytes]
"""A file's new content: bytes, or chunks of bytes as they are produced (then never all in memory)."""


@dataclass
class _Pending:
    path: Path  # as the caller named it, for messages
    target: Path  # the file that is replaced: `path`, or what its symbolic link points to
    temp: Path | None = None


def write_if_changed(path: str | os.PathLike[str], data: Content) -> bool:
    """Atomically replace `path` with `data` unless it already holds exactly that; True when written.

    Raises CannotWrite with the reason when the file cannot be written."""
    return bool(write_all([(Path(path), data)]))


def write_all(outputs: Iterable[tuple[Path, Content]]) -> list[Path]:
    """Write every output whose content changes, or none of them; the paths written.

    Outputs are taken one at a time, and chunked content is compared with the file it replaces as
    it comes, so that a set of large outputs never has to be held in memory. Every temporary file
    is written and flushed before the first one is renamed, so a full disk, a read-only folder, a
    path that is a folder or a failure while producing content leaves every target as it was and
    no temporary file behind. Raises CannotWrite naming the first output that failed."""
    started: list[_Pending] = []
    created: list[Path] = []  # folders made for the outputs, removed again when the set fails
    try:
        for path, content in outputs:
            item = _Pending(path, _target(path))
            started.append(item)
            if not _write_temp_if_changed(item, content, created):
                started.pop()
        for item in started:
            _rename(item)
    except BaseException:
        for item in started:
            if item.temp is not None:
                with contextlib.suppress(OSError):
                    item.temp.unlink()
        for folder in reversed(created):
            with contextlib.suppress(OSError):
                folder.rmdir()  # only when empty
        raise
    for folder in {item.target.parent for item in started}:
        _sync_folder(folder)
    return [item.path for item in started]


def _target(path: Path) -> Path:
    """The file a write replaces: a symbolic link's target (links are written through, not replaced)."""
    try:
        if path.is_symlink():
            return Path(os.path.realpath(path))
    except OSError:
        pass
    return path


class _Existing:
    """The file an output replaces, read alongside the new content: how much of it the content matched."""

    def __init__(self, path: Path) -> None:
        self.matched = 0
        try:
            self.handle: BinaryIO | None = open(path, "rb")  # noqa: SIM115 (closed by close())
        except OSError:
            self.handle = None  # missing, a folder, unreadable: the write decides

    def holds(self, chunk: bytes) -> bool:
        """True when the file continues with `chunk`."""
        if self.handle is None:
            return False
        try:
            same = self.handle.read(len(chunk)) == chunk
        except OSError:
            same = False
        if same:
            self.matched += len(chunk)
        return same

    def ends(self) -> bool:
        """True when the file has nothing after what the content matched."""
        if self.handle is None:
            return False
        try:
            return self.handle.read(1) == b""
        except OSError:
            return False

    def copy_matched(self, item: _Pending, out: BinaryIO) -> None:
        """The part of the file the content matched, into `out`: it is the content's start."""
        if not self.matched:
            return
        assert self.handle is not None
        try:
            self.handle.seek(0)
            left = self.matched
            while left:
                block = self.handle.read(min(left, 1 << 20))
                if not block:
                    raise OSError(errno.EIO, "the file changed while it was read")
                out.write(block)
                left -= len(block)
        except OSError as error:
            raise CannotWrite(item.path, _reason(error, item.path)) from None

    def close(self) -> None:
        if self.handle is not None:
            self.handle.close()


def _write_temp_if_changed(item: _Pending, content: Content, created: list[Path]) -> bool:
    """Write `content` into a temporary file beside the target unless the target holds exactly it;
    True when the temporary file was written (its path is then in `item.temp`)."""
    chunks = [content] if isinstance(content, bytes) else content
    existing = _Existing(item.target)
    out: BinaryIO | None = None
    try:
        for chunk in chunks:
            if out is None:
                if existing.holds(chunk):
                    continue
                out = _open_temp(item, created)
                existing.copy_matched(item, out)
            _write(item, out, chunk)
        if out is None:
            if existing.ends():
                return False
            out = _open_temp(item, created)
            existing.copy_matched(item, out)
        try:
            out.flush()
            os.fsync(out.fileno())
        except OSError as error:
            raise CannotWrite(item.path, _reason(error, item.path)) from None
        return True
    finally:
        existing.close()
        if out is not None:
            with contextlib.suppress(OSError):
                out.close()


def _write(item: _Pending, out: BinaryIO, chunk: bytes) -> None:
    try:
        out.write(chunk)
    except OSError as error:
        raise CannotWrite(item.path, _reason(error, item.path)) from None


def _open_temp(item: _Pending, created: list[Path]) -> BinaryIO:
    """A new temporary file beside the target (its folders made first), with the target's owner and mode."""
    _make_folder(item, created)
    target = item.target
    if target.is_dir():
        raise CannotWrite(item.path, "it is a folder")
    try:
        existing = target.stat()
    except FileNotFoundError:
        existing = None
    except OSError as error:
        raise CannotWrite(item.path, _reason(error, item.path)) from None
    try:
        temp, fd = _create_temp(target)
    except OSError as error:
        raise CannotWrite(item.path, _reason(error, item.path)) from None
    item.temp = temp
    try:
        handle = os.fdopen(fd, "wb")
    except OSError as error:
        os.close(fd)
        raise CannotWrite(item.path, _reason(error, item.path)) from None
    if existing is not None:
        try:
            _keep_owner_and_mode(handle.fileno(), existing)
        except OSError as error:
            handle.close()
            raise CannotWrite(item.path, _reason(error, item.path)) from None
    return handle


def _make_folder(item: _Pending, created: list[Path]) -> None:
    missing = [folder for folder in [item.target.parent, *item.target.parent.parents] if not folder.exists()]
    for folder in reversed(missing):
        try:
            folder.mkdir()
        except FileExistsError:
            continue
        except OSError as error:
            raise CannotWrite(item.path, _reason(error, item.path)) from None
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
        raise CannotWrite(item.path, _reason(error, item.path)) from None
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


def _reason(error: OSError, path: Path) -> str:
    if error.errno == errno.EISDIR:
        return "it is a folder"
    if error.errno in (errno.ENOTDIR, errno.EEXIST):
        blocking = _not_a_folder(path)
        if blocking is not None:
            return f"{blocking} is not a folder"
    return error.strerror or str(error)


def _not_a_folder(path: Path) -> Path | None:
    """The first folder on the way to `path` that is a file instead (`regfile` of `regfile/out.xdd`)."""
    for parent in reversed(path.parents):
        if parent != Path(".") and parent.exists() and not parent.is_dir():
            return parent
    return None
