"""``hexbot console``: the Textual console on hardware or the embedded simulator."""

from __future__ import annotations

import argparse
from pathlib import Path

from hexbot.host import endpoints
from hexbot.host.capture import read_capture
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.host import Host
from hexbot.host.session_log import CAPTURE_NAME


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--timeout", type=float, default=5.0, metavar="S",
                        help="seconds to wait for each reply in workflows (default 5)")
    parser.add_argument("--replay", type=Path, metavar="CAPTURE",
                        help="show a recorded session (capture file or session folder) in "
                             "real time instead of opening ports")
    add_port_arguments(parser)


def parse(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="hexbot console")
    add_arguments(parser)
    return parser.parse_args(argv)


def make_opener(args: argparse.Namespace):
    """What the console calls (in a worker thread) to open its session:
    starting the simulator must not freeze the UI."""

    def opener():
        ends = endpoints.resolve(args)
        try:
            return endpoints.open_host(args, ends), ends
        except BaseException:
            ends.close()
            raise

    return opener


def run(args: argparse.Namespace) -> int:
    from hexbot.host.console.app import HexBotConsole

    if args.replay is not None:
        path = args.replay / CAPTURE_NAME if args.replay.is_dir() else args.replay
        records = list(read_capture(path))  # bad files fail here, before the UI starts
        HexBotConsole(Host(), replay=records, start_ports=False).run()
        return 0
    HexBotConsole(opener=make_opener(args), reply_timeout=args.timeout).run()
    return 0
