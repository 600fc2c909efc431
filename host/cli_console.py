"""``hexbot console``: the Textual console on hardware or the embedded simulator."""

from __future__ import annotations

import argparse

from hexbot.host import endpoints
from hexbot.host.endpoints import add_port_arguments


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--timeout", type=float, default=5.0, metavar="S",
                        help="seconds to wait for each reply in workflows (default 5)")
    add_port_arguments(parser)


def run(args: argparse.Namespace) -> int:
    from hexbot.host.console.app import HexBotConsole

    def opener():
        # Runs in a worker thread: starting the simulator must not freeze the UI.
        ends = endpoints.resolve(args)
        try:
            return endpoints.open_host(args, ends), ends
        except BaseException:
            ends.close()
            raise

    HexBotConsole(opener=opener, reply_timeout=args.timeout).run()
    return 0
