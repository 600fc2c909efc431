"""``hexbot console``: the Textual console on hardware or the embedded simulator.

Without ``--port`` the embedded simulator runs in this process
(``hexbot-sim://``), paced at real time unless ``--sim-speed`` says
otherwise, so the console shows what the robot would do when it would.
"""

from __future__ import annotations

import argparse
from collections.abc import Iterable
from pathlib import Path

from hexbot.host import endpoints
from hexbot.host.capture import read_capture
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.events import Listener
from hexbot.host.host import Host
from hexbot.host.script import timeout_seconds
from hexbot.host.session_log import CAPTURE_NAME


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--timeout", type=timeout_seconds, default=None, metavar="S",
                        help="seconds to wait for the replies to a single command "
                             "(default: the protocol's bound for the function)")
    parser.add_argument("--replay", type=Path, metavar="CAPTURE",
                        help="show a recorded session (capture file or session folder) in "
                             "real time instead of opening ports")
    add_port_arguments(parser)


def parse(argv: list[str]) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="hexbot console")
    add_arguments(parser)
    return parser.parse_args(argv)


#: The console paces the embedded simulator at real time (``--sim-speed``).
DEFAULT_SIM_SPEED = 1.0


def make_opener(args: argparse.Namespace):
    """What the console calls (in a worker thread) to open its ports:
    starting the simulator must not freeze the UI. ``listeners`` are
    attached before the first byte (the boot texts)."""

    def opener(listeners: Iterable[Listener] = ()) -> tuple[Host, endpoints.Endpoints]:
        ends = endpoints.resolve(args, default_speed=DEFAULT_SIM_SPEED)
        try:
            return endpoints.open_host(args, ends, listeners), ends
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
    ends = endpoints.resolve(args, default_speed=DEFAULT_SIM_SPEED)  # usage errors before the UI
    endpoints.check_log_dir(args)
    endpoints.check_scenario(ends)  # a scenario that cannot load: exit 4, not retried in the UI
    app = HexBotConsole(opener=make_opener(args), reply_timeout=args.timeout)
    app.run()
    return app.failure_status or 0  # the session could not go on: say so to the shell
