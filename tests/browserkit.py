"""Headless Chromium, driven over the DevTools protocol through a pipe: open a file, run a script in it, take
a screenshot. Only the standard library: Chromium reads commands from its descriptor 3 and writes answers to
its descriptor 4 (`--remote-debugging-pipe`), each message JSON ended by a NUL byte.

A test that needs the browser skips with one line where Debian's chromium (or CHROMIUM) is not installed.
"""

from __future__ import annotations

import base64
import fcntl
import json
import os
import shutil
import struct
import subprocess
import tempfile
import zlib
from collections.abc import Iterator
from contextlib import contextmanager, suppress
from pathlib import Path
from typing import Any

import pytest

LOADED = "new Promise(done => document.readyState === 'complete' ? done(1) : addEventListener('load', () => done(1)))"


def chromium() -> str | None:
    return shutil.which(os.environ.get("CHROMIUM", "chromium")) or shutil.which("chromium-browser")


class Page:
    """One tab, attached with a flat session: commands carry its session id."""

    def __init__(self, browser: Browser, session: str) -> None:
        self._browser = browser
        self._session = session

    def send(self, method: str, **params: Any) -> dict[str, Any]:
        return self._browser.send(method, params, self._session)

    def open(self, path: Path, width: int = 1280, height: int = 900) -> None:
        self.send("Emulation.setDeviceMetricsOverride", width=width, height=height, deviceScaleFactor=1, mobile=False)
        self.send("Page.navigate", url=path.resolve().as_uri())
        self.evaluate(LOADED)

    def evaluate(self, expression: str) -> Any:
        answer = self.send("Runtime.evaluate", expression=expression, returnByValue=True, awaitPromise=True)
        if "exceptionDetails" in answer:
            raise AssertionError(f"script failed: {answer['exceptionDetails']}")
        return answer["result"].get("value")

    def screenshot(self) -> bytes:
        """What the window shows, as PNG."""
        return base64.b64decode(self.send("Page.captureScreenshot", format="png")["data"])


class Browser:
    def __init__(self, process: subprocess.Popen[bytes], commands: int, answers: int) -> None:
        self._process = process
        self._commands = os.fdopen(commands, "wb", buffering=0)
        self._answers = os.fdopen(answers, "rb", buffering=0)
        self._pending = b""
        self._next = 0

    def send(self, method: str, params: dict[str, Any], session: str | None = None) -> dict[str, Any]:
        self._next += 1
        message: dict[str, Any] = {"id": self._next, "method": method, "params": params}
        if session:
            message["sessionId"] = session
        self._commands.write(json.dumps(message).encode() + b"\0")
        while True:
            answer = self._read()
            if answer.get("id") == self._next:
                if "error" in answer:
                    raise AssertionError(f"{method}: {answer['error']}")
                result: dict[str, Any] = answer.get("result", {})
                return result

    def _read(self) -> dict[str, Any]:
        while b"\0" not in self._pending:
            chunk = self._answers.read(1 << 16)
            if not chunk:
                raise AssertionError("Chromium closed its DevTools pipe")
            self._pending += chunk
        message, _, self._pending = self._pending.partition(b"\0")
        found: dict[str, Any] = json.loads(message)
        return found

    def page(self) -> Page:
        target = self.send("Target.createTarget", {"url": "about:blank"})["targetId"]
        session = self.send("Target.attachToTarget", {"targetId": target, "flatten": True})["sessionId"]
        return Page(self, session)

    def close(self) -> None:
        with suppress(AssertionError):
            self.send("Browser.close", {})
        try:
            self._process.wait(timeout=10)
        except subprocess.TimeoutExpired:
            self._process.kill()
        self._commands.close()
        self._answers.close()


def _above_four(fd: int) -> int:
    """The same pipe end at a number above 4, so that placing two at 3 and 4 in the child cannot overwrite one."""
    high = fcntl.fcntl(fd, fcntl.F_DUPFD_CLOEXEC, 10)
    os.close(fd)
    return high


@contextmanager
def browser() -> Iterator[Browser]:
    """A headless Chromium for the duration; the calling test skips where there is none."""
    program = chromium()
    if program is None:
        pytest.skip("Chromium is not installed (apt-get install chromium, or set CHROMIUM)")
    to_browser, from_us = os.pipe()
    to_us, from_browser = os.pipe()
    to_browser, from_browser = _above_four(to_browser), _above_four(from_browser)

    def descriptors() -> None:  # in the child: its 3 reads our commands, its 4 carries its answers
        os.dup2(to_browser, 3)
        os.dup2(from_browser, 4)

    with tempfile.TemporaryDirectory() as profile:
        process = subprocess.Popen(
            [program, "--headless", "--no-sandbox", "--disable-gpu", "--remote-debugging-pipe", "--no-first-run",
             "--hide-scrollbars", "--font-render-hinting=none", f"--user-data-dir={profile}", "about:blank"],
            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
            preexec_fn=descriptors, close_fds=False,  # 3 and 4 are not close-on-exec; the rest are
        )  # fmt: skip
        os.close(to_browser)
        os.close(from_browser)
        driven = Browser(process, from_us, to_us)
        try:
            yield driven
        finally:
            driven.close()


def png_pixels(data: bytes) -> tuple[int, int, list[bytes]]:
    """Width, height and rows (RGB or RGBA bytes) of an 8-bit, non-interlaced PNG, as Chromium writes them."""
    assert data[:8] == b"\x89PNG\r\n\x1a\n", "not a PNG"
    position, idat = 8, b""
    width = height = channels = 0
    while position < len(data):
        length, kind = struct.unpack(">I4s", data[position : position + 8])
        body = data[position + 8 : position + 8 + length]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert depth == 8 and colour in (2, 6), (depth, colour)
            channels = 3 if colour == 2 else 4
        elif kind == b"IDAT":
            idat += body
        position += 12 + length
    raw = zlib.decompress(idat)
    stride = width * channels
    rows: list[bytes] = []
    previous = bytearray(stride)
    for y in range(height):
        kind = raw[y * (stride + 1)]
        line = bytearray(raw[y * (stride + 1) + 1 : (y + 1) * (stride + 1)])
        _unfilter(kind, line, previous, channels)
        rows.append(bytes(line))
        previous = line
    return width, height, rows


def _unfilter(kind: int, line: bytearray, above: bytearray, step: int) -> None:
    for i in range(len(line)):
        left = line[i - step] if i >= step else 0
        up = above[i]
        corner = above[i - step] if i >= step else 0
        if kind == 1:
            line[i] = (line[i] + left) & 0xFF
        elif kind == 2:
            line[i] = (line[i] + up) & 0xFF
        elif kind == 3:
            line[i] = (line[i] + (left + up) // 2) & 0xFF
        elif kind == 4:
            guess = left + up - corner
            near = min((abs(guess - left), 0, left), (abs(guess - up), 1, up), (abs(guess - corner), 2, corner))
            line[i] = (line[i] + near[2]) & 0xFF


def difference(first: bytes, second: bytes) -> float:
    """The share of pixels that differ by more than a little between two PNGs of the same size (1.0: sizes differ)."""
    width, height, rows = png_pixels(first)
    other_width, other_height, other_rows = png_pixels(second)
    if (width, height) != (other_width, other_height):
        return 1.0
    step = len(rows[0]) // width if rows else 3
    other_step = len(other_rows[0]) // width if other_rows else 3
    differ = 0
    for row, other in zip(rows, other_rows, strict=True):
        for x in range(width):
            a, b = row[x * step : x * step + 3], other[x * other_step : x * other_step + 3]
            if max(abs(p - q) for p, q in zip(a, b, strict=True)) > 48:
                differ += 1
    return differ / max(1, width * height)
