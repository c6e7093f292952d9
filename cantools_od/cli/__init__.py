"""The `cantools-od` command. Each subcommand lives in a module of its own and is
imported only when it runs, so that `--version` starts quickly."""

from __future__ import annotations

import importlib
import sys
from collections.abc import Sequence
from typing import Any

import click

from .. import __version__, collector

# command name → (module, help line)
COMMANDS = {
    "dump": ("dump", "Show the object dictionary of an EDS, DCF, XDD, XDC or JSON file as a table or as JSON."),
    "fmt": ("fmt", "Rewrite files in canonical form."),
    "convert": ("convert", "Convert between EDS, DCF, XDD, XDC and JSON."),
    "pdo": ("pdo", "Show the PDO map with bit layouts."),
    "gen": ("gen", "Generate C, Rust, Python, Markdown, CANopenNode OD.h/OD.c and a DBC from an object dictionary."),
    "ids": ("ids", "Print the identifiers generated code uses, as a pin file."),
    "lint": ("lint", "Check EDS/DCF/XDD/XDC files against CiA 306/311/301 and PDO rules."),
    "lsp": ("lsp", "Language server for editors: lint, hover, definitions, fixes, formatting."),
    "rules": ("rules", "List the lint rules, or explain one."),
    "cmake-dir": ("cmake_dir", "Print the folder of the CMake package."),
    "diff": ("diff", "Show what changed between two device descriptions, and what it breaks."),
    "network": ("network", "Turn a bus description (bus.yml) into the master's configuration, bus load and DBC."),
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
        except click.Abort:
            click.echo("Aborted!", err=True)
            sys.exit(1)
        sys.exit(result if isinstance(result, int) else 0)

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        rows = [(name, COMMANDS[name][1]) for name in self.list_commands(ctx)]
        with formatter.section("Commands"):
            formatter.write_dl(rows)


@click.group(cls=LazyGroup, context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, "--version", prog_name="cantools-od")
def main() -> None:
    """Read, check and generate code from CANopen object dictionaries."""
