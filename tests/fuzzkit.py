"""Every command on randomly damaged device descriptions, in-process: the fuzz test and bench/fuzz.py.

A case is one source file, one chain of mutations (drawn from a `random.Random` with a fixed seed)
and one command. It holds when the command ends with a documented exit code, prints no traceback
and no Python message, and leaves its input as it was, byte for byte and mode for mode (`fmt` and
`lint --fix` may rewrite it, but only into a file that reads back without errors).
"""

from __future__ import annotations

import os
import random
import re
import stat
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from click.testing import CliRunner

from cantools_od.cli import main

from support import CORPUS, EXAMPLES

XDD_CORPUS = CORPUS.parent / "xdd"

# Small real files of every kind (EDS, DCF, XDD, XDC), so that a case takes milliseconds.
SMALL_SOURCES = (
    "eds-dcf-net__max_subnumber.eds",
    "oresat-canmon__test.eds",
    "eds-file-viewer__test.eds",
    "node-canopen__example.eds",
    "canopen-bench__CiA301Base.eds",
    "python-canopen__all_datatypes.eds",
    "lely-core__co-emcy.dcf",
    "lely-core__co-pdo-transmit.dcf",
    "eds-dcf-net__modular_device.dcf",
)
SMALL_XML = ("eds-dcf-net__minimal.xdc", "eds-dcf-net__sample_device.xdd")


def sources() -> dict[str, bytes]:
    """Source name → bytes: the examples, a JSON model, and the small corpus files present here."""
    from cantools_od import dumps, load

    found = {path.name: path.read_bytes() for path in (EXAMPLES / "io_device.eds", EXAMPLES / "cia402_drive.eds")}
    found["io_device.json"] = dumps(load(EXAMPLES / "io_device.eds"), "json")
    for folder, names in ((CORPUS, SMALL_SOURCES), (XDD_CORPUS, SMALL_XML)):
        for name in names:
            if (folder / name).is_file():
                found[name] = (folder / name).read_bytes()
    return found


# --- mutations ---------------------------------------------------------------------------------

UNICODE_DIGITS = "²³¹⁰₁١٣۴߁०৪๓𝟙①⑩Ⅷ½〇"
UNICODE_LETTERS = "éßΩİ\u0131ﬁ\u212a€ÿ\u00a0\u2028\u200b"  # dotless i, Kelvin sign: case folding
NUMBER = re.compile(rb"0[xX][0-9A-Fa-f]+|[0-9]+")


def _at(rng: random.Random, data: bytes) -> int:
    return rng.randrange(len(data) + 1)


def flip(rng: random.Random, data: bytes) -> bytes:
    if not data:
        return data
    out = bytearray(data)
    for _ in range(rng.randint(1, 4)):
        out[rng.randrange(len(out))] ^= 1 << rng.randrange(8)
    return bytes(out)


def unicode_digit(rng: random.Random, data: bytes) -> bytes:
    """A Unicode digit in place of an ASCII one (in a key, a value, a section name) or anywhere."""
    char = rng.choice(UNICODE_DIGITS).encode("utf-8")
    digits = [m.start() for m in re.finditer(rb"[0-9]", data)]
    if digits and rng.random() < 0.8:
        at = rng.choice(digits)
        return data[:at] + char + data[at + 1 :]
    at = _at(rng, data)
    return data[:at] + char + data[at:]


def unicode_letter(rng: random.Random, data: bytes) -> bytes:
    at = _at(rng, data)
    return data[:at] + rng.choice(UNICODE_LETTERS).encode("utf-8") + data[at:]


def huge_number(rng: random.Random, data: bytes) -> bytes:
    """A number replaced by one of thousands of digits, decimal or hex."""
    numbers = list(NUMBER.finditer(data))
    if not numbers:
        return data
    found = rng.choice(numbers)
    digits = rng.choice((70, 400, 4301, 5000, 100_000 if rng.random() < 0.1 else 6000))
    text = (b"0x" + b"F" * digits) if rng.random() < 0.5 else (b"7" * digits)
    return data[: found.start()] + (b"-" if rng.random() < 0.2 else b"") + text + data[found.end() :]


def truncate(rng: random.Random, data: bytes) -> bytes:
    return data[: _at(rng, data)]


def encoding(rng: random.Random, data: bytes) -> bytes:
    """Another encoding for all or part of the file: Windows-1252 bytes, a BOM, UTF-16, stray bytes."""
    text = data.decode("utf-8", "replace")
    choice = rng.randrange(6)
    if choice == 0:
        return text.encode("cp1252", "replace")
    if choice == 1:
        return b"\xef\xbb\xbf" + data
    if choice == 2:
        return text.encode("utf-16")
    if choice == 3:  # one stray Windows-1252 byte in UTF-8 with non-ASCII letters
        at = _at(rng, data)
        return "Müller ".encode() + data[:at] + bytes([rng.choice((0xB9, 0x94, 0xFC, 0x81, 0xA0))]) + data[at:]
    if choice == 4:
        return data.replace(b"\r\n", b"\n").replace(b"\n", rng.choice((b"\r\n", b"\r")))
    at = _at(rng, data)
    return data[:at] + bytes(rng.randrange(256) for _ in range(rng.randint(1, 8))) + data[at:]


def lines(rng: random.Random, data: bytes) -> bytes:
    """A line deleted, duplicated or moved."""
    parts = data.splitlines(keepends=True)
    if not parts:
        return data
    i, j = rng.randrange(len(parts)), rng.randrange(len(parts))
    choice = rng.randrange(3)
    if choice == 0:
        del parts[i]
    elif choice == 1:
        parts.insert(j, parts[i])
    else:
        parts[i], parts[j] = parts[j], parts[i]
    return b"".join(parts)


MUTATIONS: dict[str, Callable[[random.Random, bytes], bytes]] = {
    "flip": flip,
    "unicode-digit": unicode_digit,
    "unicode-letter": unicode_letter,
    "huge-number": huge_number,
    "truncate": truncate,
    "encoding": encoding,
    "lines": lines,
}


def mutated(rng: random.Random, data: bytes) -> tuple[list[str], bytes]:
    """One to three mutations of `data`, by name, and the result."""
    names = [rng.choice(sorted(MUTATIONS)) for _ in range(rng.choice((1, 1, 1, 2, 3)))]
    for name in names:
        data = MUTATIONS[name](rng, data)
    return names, data


# --- commands ------------------------------------------------------------------------------------

# Arguments after the input file; "{orig}" is the unmutated source, written beside it.
COMMANDS: dict[str, list[str]] = {
    "dump": ["dump", "{file}"],
    "dump-json": ["dump", "{file}", "--format", "json"],
    "fmt": ["fmt", "{file}"],
    "fmt-check": ["fmt", "--check", "--diff", "{file}"],
    "lint": ["lint", "{file}"],
    "lint-fix": ["lint", "--fix", "{file}"],
    "convert-xdd": ["convert", "{file}", "-o", "out.xdd"],
    "convert-dcf": ["convert", "{file}", "-o", "out.dcf", "--node-id", "5"],
    "convert-json": ["convert", "{file}", "-o", "out.json"],
    "pdo": ["pdo", "{file}", "--format", "json", "--node-id", "3"],
    "ids": ["ids", "{file}"],
    "gen": ["gen", "{file}", "-t", "c", "-t", "python", "-o", "gen"],
    "gen-keep-going": ["gen", "{file}", "-t", "rust", "-t", "markdown", "-o", "gen", "--keep-going"],
    "gen-canopennode": ["gen", "{file}", "-t", "canopennode", "-o", "gen"],
    "diff": ["diff", "{orig}", "{file}", "--format", "json"],
}
WRITES_INPUT = ("fmt", "lint-fix")
EXIT_CODES = (0, 1, 2)  # docs/cli.md: 0 ok, 1 findings, 2 usage error or input that cannot be read
# Python speaking instead of the tool: exception names, int()'s messages, the digit limit.
PYTHON_TALK = re.compile(
    r"Traceback|\b(?:Value|Type|Key|Index|Attribute|Unicode\w*|Overflow|Recursion|Assertion)Error\b"
    r"|invalid literal|set_int_max_str_digits|\[LNT001\]"
)


@dataclass(frozen=True)
class Case:
    seed: int
    source: str
    mutations: tuple[str, ...]
    command: str

    def __str__(self) -> str:
        return f"seed {self.seed}: {self.command} on {self.source} after {', '.join(self.mutations)}"


def cases(seed: int, count: int, names: list[str]) -> list[tuple[Case, bytes]]:
    """`count` cases from `seed`: sources and commands in turn (from a command that depends on the seed),
    mutations at random."""
    rng = random.Random(seed)
    found = sources()
    chosen = [name for name in names if name in found] or sorted(found)
    out = []
    commands = sorted(COMMANDS)
    for number in range(count):
        source = chosen[number % len(chosen)]
        command = commands[(number // len(chosen) + seed) % len(commands)]  # each seed starts elsewhere
        case_rng = random.Random(rng.getrandbits(64))
        mutations, data = mutated(case_rng, found[source])
        out.append((Case(seed, source, tuple(mutations), command), data))
    return out


def run(case: Case, data: bytes, original: bytes, folder: Path) -> list[str]:
    """What is wrong with running `case` on `data` in the empty `folder` (chdir'd into by the caller)."""
    folder.mkdir(parents=True, exist_ok=True)
    suffix = Path(case.source).suffix
    target, orig = folder / f"input{suffix}", folder / f"original{suffix}"
    target.write_bytes(data)
    orig.write_bytes(original)
    os.chmod(target, 0o640)
    args = [arg.format(file=target, orig=orig) for arg in COMMANDS[case.command]]
    result = CliRunner().invoke(main, args, catch_exceptions=True)
    problems = []
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        problems.append(f"raised {type(result.exception).__name__}: {str(result.exception)[:200]}")
    if result.exit_code not in EXIT_CODES:
        problems.append(f"exit code {result.exit_code}")
    output = result.stdout + result.stderr
    talk = PYTHON_TALK.search(output)
    if talk is not None:
        problems.append(f"Python speaks: {output[max(0, talk.start() - 100) : talk.end() + 100]!r}")
    if stat.S_IMODE(target.stat().st_mode) != 0o640:
        problems.append("input's mode changed")
    after = target.read_bytes()
    if after != data:
        problems += _rewritten(case, result.exit_code, after)
    return problems


def _rewritten(case: Case, exit_code: int, after: bytes) -> list[str]:
    """A changed input is right only from fmt or lint --fix, and only into a file that reads back."""
    from cantools_od import loads
    from cantools_od.model import Severity
    from cantools_od.sniff import NotADeviceDescription

    if case.command not in WRITES_INPUT:
        return ["input changed by a command that only reads it"]
    if case.command == "fmt" and exit_code != 0:
        return [f"input changed although fmt exited {exit_code}"]
    try:
        device = loads(after, source="rewritten" + Path(case.source).suffix)
    except NotADeviceDescription as refusal:
        return [f"rewritten into no device description: {refusal}"]
    # fmt keeps a file's code page (EDS100 stays); it repairs the other errors it writes through (READ_WHOLE)
    errors = [d.format() for d in device.diagnostics if d.severity is Severity.ERROR and d.code != "EDS100"]
    if case.command == "fmt" and errors:
        return [f"fmt wrote a file with errors: {errors[:2]}"]
    return []
