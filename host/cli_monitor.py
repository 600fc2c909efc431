"""``hexbot monitor``: decoded events as lines, or JSON lines with --json."""

from __future__ import annotations

import argparse
import json
import queue
import sys

from hexbot.cli_args import seconds
from hexbot.errors import LinkUnavailableError
from hexbot.host.cli_common import session
from hexbot.host.describe import describe_event, event_json
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.events import HostEvent, Observed


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="one JSON object per line")
    parser.add_argument("--duration", type=seconds, default=None, metavar="S",
                        help="stop after S seconds (default: until Ctrl-C)")
    add_port_arguments(parser)


def format_line(obs: Observed) -> str:
    return f"{obs.t:9.3f} {obs.port:<5} {describe_event(obs.event)}"


def format_json(obs: Observed) -> str:
    return json.dumps({"t": round(obs.t, 3), "port": obs.port, **event_json(obs.event)})


def run(args: argparse.Namespace) -> int:
    lines: queue.Queue[str] = queue.Queue()
    fmt = format_json if args.json else format_line

    # (it sends nothing, so there is no --tx: the option once offered showed
    # nothing; `send` and the console's terminal show what a host sends)
    def listener(event: HostEvent) -> None:
        if isinstance(event, Observed):
            lines.put(fmt(event))

    def flush() -> bool:
        while not lines.empty():
            print(lines.get_nowait(), flush=True)
        return False

    # Ports must open at the start (exit 4 otherwise, as send); one lost
    # later is retried while monitoring, and exit 4 if it is still lost at the end.
    with session(args, listener=listener, wait_boot=False, default_speed=1.0) as sess:
        # The session's clock keeps time (virtual with --sim-speed 0); print
        # as events come, at most a tenth of a second late.
        end = None if args.duration is None else sess.now() + args.duration
        while end is None or sess.now() < end:
            sess.host.clock.wait(lambda: not lines.empty(),
                                 0.1 if end is None else max(0.0, min(0.1, end - sess.now())))
            flush()
        flush()
        lost = [name for name, ch in sess.host.channels.items() if not ch.link.connected]
    sys.stdout.flush()
    if lost:  # retried to the end: the monitor saw nothing there, which is not a pass
        print(f"error: port lost and not back when the monitor ended: {', '.join(lost)}",
              file=sys.stderr)
        return LinkUnavailableError.exit_status
    return 0
