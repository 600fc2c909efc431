"""The ``hexbot`` command: one entry point, one subcommand per tool.

Each subcommand lives in its own module, which provides
``add_arguments(parser)`` and ``run(args) -> int``. Modules are imported
only when their command runs, so a broken optional part (say, the simulator
extension) does not stop the others from working.
"""

from __future__ import annotations

import argparse
import importlib
import os
import signal
import sys
import threading
from types import ModuleType

from hexbot import __version__
from hexbot.errors import HexBotError, Terminated

# name -> (module, one-line help). Keep sorted by workflow, not alphabet.
COMMANDS: dict[str, tuple[str, str]] = {
    "codes": ("hexbot.protocol.cli_codes", "list the function codes of the HexBot protocol"),
    "gen-header": (
        "hexbot.protocol.cli_gen_header",
        "regenerate the firmware header and the docs table from the protocol table",
    ),
    "sim": ("hexbot.hil_sim.cli_sim", "run simulated modules behind pseudo-terminals (--pty)"),
    "bench": ("hexbot.bench.cli", "run a benchmark (`bench sim --json`; `bench --help`: the list)"),
    "console": ("hexbot.host.cli_console", "the Textual console (default: on the simulator)"),
    "send": ("hexbot.host.cli_send", "send one message and check its acknowledgement"),
    "monitor": ("hexbot.host.cli_monitor", "print decoded events from the ports"),
    "ports": ("hexbot.host.cli_ports", "list serial ports, simulator URLs and running sim ptys"),
    "run": ("hexbot.host.cli_run", "run a HexBot script (.hbs) of commands and expectations"),
    "replay": ("hexbot.host.cli_replay", "play a session capture back through the parser"),
    "flash": ("hexbot.host.flash.cli", "program a board's ATmega162 through avrdude (ISP)"),
    "locomotion": (
        "hexbot.planning.locomotion.cli",
        "square-lattice locomotion rule engine (Salvador, Otero rule sets)",
    ),
    "plan": ("hexbot.planning.cli_plan", "plan a hex reconfiguration (thesis or robust planner)"),
    "sweep": ("hexbot.sweep.cli", "run a sweep file on Dask (`sweep report RESULTS`: its tables)"),
    "traverse": ("hexbot.planning.traversal.cli",
                 "cross a surface with bridges, layering algorithm (Ivanov & Walter)"),
}


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="hexbot",
        description="HexBot toolchain: console, simulator, flashing, planning.",
    )
    parser.add_argument("--version", action="version", version=f"hexbot {__version__}")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, (module_name, help_text) in COMMANDS.items():
        p = sub.add_parser(name, help=help_text, description=help_text)
        p.set_defaults(_module=module_name)
        # Arguments are added lazily in main() for the chosen command only,
        # except for --help of the top level, which needs names alone.
    return parser


def load_command(
    prog: str, module_name: str, help_text: str, argv: list[str]
) -> tuple[ModuleType, argparse.Namespace]:
    """Import a command's module and parse its arguments (exits on a usage error)."""
    module = importlib.import_module(module_name)
    parser = argparse.ArgumentParser(prog=prog, description=help_text)
    module.add_arguments(parser)
    return module, parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    parser = build_parser()
    if not argv or argv[0].startswith("-") or argv[0] not in COMMANDS:
        args = parser.parse_args(argv)
        parser.print_help()
        return 2 if argv else 0
    name = argv[0]
    module_name, help_text = COMMANDS[name]
    status = 0  # until the command has one
    try:
        try:
            # the import takes up to a second: a Ctrl-C in it printed a traceback
            module, args = load_command(f"hexbot {name}", module_name, help_text, argv[1:])
            with _terminated_raises():
                status = int(module.run(args) or 0)
        except HexBotError as exc:
            status = exc.exit_status
            print(f"hexbot {name}: error: {exc}", file=sys.stderr)
        except KeyboardInterrupt:  # commands that say more catch it themselves
            status = INTERRUPTED
            print(f"hexbot {name}: interrupted (Ctrl-C)", file=sys.stderr)
        except Terminated:
            status = TERMINATED
            print(f"hexbot {name}: terminated (SIGTERM)", file=sys.stderr)
        if sys.stdout is not None:  # None: started with stdout closed (a daemon, `>&-`)
            sys.stdout.flush()  # a reader gone shows here, not as a traceback at exit
    except BrokenPipeError:  # output piped into `head` and the like
        return closed_pipe(status)
    return status


#: The statuses of a command stopped by Ctrl-C or by SIGTERM (128 + the signal,
#: as a shell reports a program that the signal killed).
INTERRUPTED = 128 + signal.SIGINT
TERMINATED = 128 + signal.SIGTERM


class _terminated_raises:
    """SIGTERM raises :class:`Terminated` in the main thread while the command
    runs (a command that installs its own handler, ``hexbot sim``, keeps it).
    The default handler killed the process at once: temporary folders of
    ``traverse --execute`` and ``flash --all`` stayed behind."""

    def __enter__(self) -> None:
        self._installed = threading.current_thread() is threading.main_thread()
        if self._installed:
            # None: a handler not set from Python; the default is what it had
            self._previous = signal.signal(signal.SIGTERM, self._raise) or signal.SIG_DFL

    def __exit__(self, *exc: object) -> None:
        if self._installed:
            signal.signal(signal.SIGTERM, self._previous)

    @staticmethod
    def _raise(signum: int, frame: object) -> None:
        raise Terminated


#: The status of a command whose output pipe closed before it finished (128 + SIGPIPE,
#: what a shell reports for a program that signal stopped).
BROKEN_PIPE = 141


def closed_pipe(status: int) -> int:
    """Quiet end of a command whose reader went away (``hexbot ... | head``):
    no traceback, and no second error when Python flushes stdout at exit. The
    status is the command's own when it had failed before the pipe broke,
    else ``BROKEN_PIPE``: the output was cut short, so never 0."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        os.close(devnull)
    except (OSError, ValueError):  # no real stdout (tests): nothing to silence
        pass
    return status or BROKEN_PIPE


if __name__ == "__main__":
    sys.exit(main())
