"""Results of expensive, deterministic work shared by every process of one test run: the pytest-xdist workers and
the process pools they start. One file a result, named by a hash of everything the result depends on (the input
file's bytes among them), under the run's base temporary folder; written atomically (a temporary file renamed), so a
reader sees a whole result or none. The first process to miss a key claims it (a file made with O_EXCL) and the
others wait for its result, so each result is made once; a claim whose maker died is waited on for WAIT seconds at
most, then the waiting process makes the result itself.

The folder is set by tests/conftest.py for the session (CANTOOLS_OD_TEST_CACHE, inherited by child processes); with
it unset (bench/, a module run outside pytest) nothing is cached.
"""

from __future__ import annotations

import hashlib
import os
import pickle
import time
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

ENV = "CANTOOLS_OD_TEST_CACHE"
T = TypeVar("T")


def folder() -> Path | None:
    value = os.environ.get(ENV)
    return Path(value) if value else None


def key(*parts: bytes | str) -> str:
    digest = hashlib.sha256()
    for part in parts:
        data = part.encode("utf-8") if isinstance(part, str) else part
        digest.update(len(data).to_bytes(8, "little"))  # lengths first: no two part lists hash alike
        digest.update(data)
    return digest.hexdigest()


def cached(kind: str, parts: tuple[bytes | str, ...], compute: Callable[[], T]) -> T:
    """compute(), or what it returned for the same `kind` and `parts` earlier in this run, in any process."""
    base = folder()
    if base is None:
        return compute()
    path = base / kind / key(kind, *parts)
    path.parent.mkdir(parents=True, exist_ok=True)
    found = _stored(path)
    if found is not None:
        return found[0]  # type: ignore[no-any-return]
    claim = path.with_name(path.name + ".claim")
    try:
        os.close(os.open(claim, os.O_CREAT | os.O_EXCL | os.O_WRONLY))
    except FileExistsError:  # another process is making it: wait for its result rather than make it twice
        found = _waited(path, claim)
        if found is not None:
            return found[0]  # type: ignore[no-any-return]
        return compute()  # that process died or took too long: make it here, leave its claim alone
    try:
        value = compute()
        partial = path.with_name(f"{path.name}.{os.getpid()}.part")
        partial.write_bytes(pickle.dumps(value, protocol=pickle.HIGHEST_PROTOCOL))
        os.replace(partial, path)
    finally:
        claim.unlink()
    return value


WAIT = 600.0  # seconds a process waits for another's result: longer than any single reading takes under load


def _stored(path: Path) -> tuple[Any] | None:
    try:
        with path.open("rb") as stored:
            return (pickle.load(stored),)
    except FileNotFoundError:
        return None


def _waited(path: Path, claim: Path) -> tuple[Any] | None:
    deadline = time.monotonic() + WAIT
    while time.monotonic() < deadline:
        found = _stored(path)
        if found is not None or not claim.exists():
            return found if found is not None else _stored(path)
        time.sleep(0.02)
    return None


PATH_MARK = "\x00path\x00"


def cached_for_file(kind: str, path: Path, parts: tuple[bytes | str, ...], compute: Callable[[], T]) -> T:
    """`cached` for work on one file whose result depends on the file's bytes and suffix only, except that a
    message in it may name the file: that name is stored as a mark and given back as the caller's path."""
    name = os.fspath(path)

    def portable() -> T:
        return _swap(compute(), name, PATH_MARK)

    value = cached(kind, (path.suffix.lower(), path.read_bytes(), *parts), portable)
    return _swap(value, PATH_MARK, name)


def _swap(value: T, old: str, new: str) -> T:
    return value.replace(old, new) if isinstance(value, str) else value  # type: ignore[return-value]
