"""The `cantools-od` command. Each subcommand lives in a module of its own and is
imported only when it runs, so that `--version` starts quickly."""

from __future__ import annotations

import atexit
import contextlib
import errno
import functools
import importlib
import os
import sys
import threading
from collections.abc import Sequence
from typing import Any, NoReturn

import click

from .. import __version__, collector

# command name → (module, help line)
COMMANDS = {
    "dump": ("dump", "Show the object dictionary of an EDS, DCF, XDD, XDC or JSON file as a table or as JSON."),
    "fmt": ("fmt", "Rewrite files in canonical form."),
    "convert": ("convert", "Convert between EDS, DCF, XDD, XDC and JSON."),
    "pdo": ("pdo", "Show the PDO map with bit layouts."),
    "gen": ("gen", "Generate C, Rust, Python, Markdown, HTML, CANopenNode OD.h/OD.c and a DBC from an OD."),
    "ids": ("ids", "Print the identifiers generated code uses, as a pin file."),
    "lint": ("lint", "Check EDS/DCF/XDD/XDC files against CiA 306/311/301 and PDO rules."),
    "lsp": ("lsp", "Language server for editors: lint, hover, definitions, fixes, formatting."),
    "rules": ("rules", "List the lint rules, or explain one."),
    "cmake-dir": ("cmake_dir", "Print the folder of the CMake package."),
    "diff": ("diff", "Show what changed between two device descriptions, and what it breaks."),
    "network": ("network", "Turn a bus description (bus.yml) into the master's configuration, bus load and DBC."),
    "simulate": ("simulate", "Serve the node a description describes on a CAN bus (python-can)."),
    "probe": ("probe", "Read a live node over SDO and report where it differs from its description."),
    "import-table": ("import_table", "Import vendor OD tables (manual text, CSV/TSV, XLSX, Markdown) into an EDS."),
}


class _StartUp:
    """The cyclic garbage collector paused while a command's modules load: importing pydantic, the model and the
    command makes some 100,000 objects that all live as long as the process, and a collector pass every 700 of
    them took about 8 % of a short command's CPU time."""

    paused = False

    @classmethod
    def pause(cls) -> None:
        cls.paused = collector.pause()

    @classmethod
    def end(cls) -> None:
        """Collect again; what start-up made goes to the oldest generation at once."""
        if cls.paused:
            cls.paused = False
            collector.resume()


EXIT_INTERRUPTED = 130  # 128 + SIGINT, as shells report a program Ctrl-C ended


class Interrupted(BaseException):
    """Ctrl-C while a command ran."""


def _interrupted() -> NoReturn:
    """One line and exit 130; on a terminal the line starts below the `^C` the terminal echoed."""
    with contextlib.suppress(OSError, ValueError):
        start = "\n" if sys.stderr.isatty() else ""
        print(f"{start}cantools-od: interrupted", file=sys.stderr, flush=True)
    sys.exit(EXIT_INTERRUPTED)


def _note_named_inputs(command: click.Command) -> None:
    """Every path the command line gives a command to read is an input no output may replace, read or not (a
    `--stack-config` that only `-t canopennode` reads): its callback notes them first (see files.py)."""
    from .common import Output

    callback = command.callback
    if callback is None or getattr(callback, "notes_inputs", False):
        return
    named = [p.name for p in command.params if isinstance(p.type, click.Path) and not isinstance(p.type, Output)]

    @functools.wraps(callback)
    def noting(**params: Any) -> Any:
        from ..files import note_inputs

        for name in named:
            value = params.get(name)
            note_inputs([value] if isinstance(value, str) else value or [])
        return callback(**params)

    noting.notes_inputs = True  # type: ignore[attr-defined]
    command.callback = noting


class LazyGroup(click.Group):
    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(COMMANDS)

    def get_command(self, ctx: click.Context, cmd_name: str) -> click.Command | None:
        entry = COMMANDS.get(cmd_name)
        if entry is None:
            return None
        try:
            module = importlib.import_module(f"{__name__}.{entry[0]}")
        finally:
            _StartUp.end()
        command: click.Command = module.command
        _note_named_inputs(command)
        return command

    def main(
        self,
        args: Sequence[str] | None = None,
        prog_name: str | None = None,
        complete_var: str | None = None,
        standalone_mode: bool = True,
        **extra: Any,
    ) -> Any:
        """As click's, but a usage error is one line (`cantools-od CMD: error: REASON`), exit 2."""
        from ..files import record_reads

        record_reads()  # every file the command reads from now on is an input no output may replace
        _StartUp.pause()
        try:
            return self._main(args, prog_name, complete_var, standalone_mode, **extra)
        finally:
            _StartUp.end()

    def _main(
        self,
        args: Sequence[str] | None,
        prog_name: str | None,
        complete_var: str | None,
        standalone_mode: bool,
        **extra: Any,
    ) -> Any:
        if not standalone_mode:
            return super().main(args, prog_name, complete_var, False, **extra)
        try:
            result = super().main(args, prog_name, complete_var, False, **extra)
        except click.UsageError as error:
            if type(error).__name__ == "NoArgsIsHelpError":  # the help text, not an error
                error.show()
            else:
                where = error.ctx.command_path if error.ctx is not None else "cantools-od"
                reason = " ".join(error.format_message().split())
                click.echo(f"{where}: error: {reason} (see --help)", err=True)
            sys.exit(error.exit_code)
        except click.ClickException as error:
            error.show()
            sys.exit(error.exit_code)
        except (Interrupted, click.Abort):  # Ctrl-C (click turns one while it parses into Abort)
            _interrupted()
        sys.exit(result if isinstance(result, int) else 0)

    def invoke(self, ctx: click.Context) -> Any:
        """As click's, but Ctrl-C leaves as `Interrupted`, which click does not catch: it would print a blank line
        and "Aborted!" and exit 1, the code of findings."""
        try:
            return super().invoke(ctx)
        except KeyboardInterrupt:
            raise Interrupted from None

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        rows = [(name, COMMANDS[name][1]) for name in self.list_commands(ctx)]
        with formatter.section("Commands"):
            formatter.write_dl(rows)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "--version", prog_name="cantools-od")
def main() -> None:
    """Read, check and generate code from CANopen object dictionaries.

    Exit codes: 0 ok, 1 findings, 2 usage error, unreadable input or an output refused or not written
    (docs/outputs.md), 130 interrupted (Ctrl-C)."""


def run() -> NoReturn:
    """The `cantools-od` program (console script, `python -m cantools_od`): `main`, then `leave`."""
    try:
        main(prog_name="cantools-od")
    except SystemExit as end:
        code = end.code
    except KeyboardInterrupt:  # Ctrl-C before or after click ran the command
        _interrupted()
    except OSError as error:
        if error.filename is not None or error.errno not in _OUTPUT_FAILED:
            raise
        _output_failed(error)
    else:  # pragma: no cover - standalone click always exits
        code = 0
    if code is None or isinstance(code, int):
        leave(code or 0)
    raise SystemExit(code)


# What writing to standard output fails with, where the commands' own files carry a file name in the error.
_OUTPUT_FAILED = {errno.ENOSPC, errno.EPIPE, errno.EIO, errno.EFBIG, errno.EDQUOT}


def _output_failed(error: OSError) -> NoReturn:
    """Standard output could not be written (/dev/full, a full disk): one line, exit 2, as for any output that
    cannot be written. A closed pipe (`| head`) is how a reader says it has read enough: no message, exit 1."""
    if error.errno != errno.EPIPE:
        with contextlib.suppress(OSError):  # stderr may be as full
            print(f"cantools-od: error: cannot write standard output: {error.strerror}", file=sys.stderr, flush=True)
    atexit._run_exitfuncs()
    os._exit(1 if error.errno == errno.EPIPE else 2)  # what stdout still holds cannot be written either


def leave(code: int) -> NoReturn:
    """Ends the program as the interpreter would, but without freeing each of its objects first.

    That teardown was 4 % of a `lint` (58 M of 1,466 M instructions for the Sevcon Nano EDS, 58 M of 897 M for a
    small file) and shows nothing to anyone. Whatever else the interpreter does at exit that can be seen is done
    here first: the atexit callbacks (with weakref finalizers) run, stdout and stderr are flushed. Every file the
    commands write is closed before they return. Where that cannot be done so (another thread still runs, a flush
    fails: a closed pipe), the interpreter ends the program as usual, with its own messages and exit code.
    Never from `main`: a caller that runs it in-process (click's CliRunner, the tests) gets SystemExit."""
    if threading.active_count() == 1:
        atexit._run_exitfuncs()
        try:
            for stream in (sys.stdout, sys.stderr):
                if stream is not None:
                    stream.flush()
        except (OSError, ValueError):
            sys.exit(code)
        os._exit(code)
    sys.exit(code)
