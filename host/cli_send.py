"""``hexbot send CODE [ARGS...]``: one message, its decoded replies, an exit code.

Exit 0 when the replies the addressing implies arrived and acknowledge the
command (from each ``--module``, which is selected first with code 69);
otherwise the reason on stderr and the exit status of its kind: 1 refused
(ERR, unused code, control board time-out), 3 no reply in time, 4 port lost.
How long to wait comes from the protocol (each function's own duration);
``--timeout`` overrides it.
"""

from __future__ import annotations

import argparse
import json
import sys

from hexbot.host.cli_common import session
from hexbot.host.commands import parse_command
from hexbot.host.describe import describe_event, event_json
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.events import Observed
from hexbot.host.session import select


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("function", metavar="CODE", help="function code or name (hexbot codes)")
    parser.add_argument("args", nargs="*", metavar="ARG", help="argument bytes")
    parser.add_argument("--module", type=int, action="append", metavar="ID",
                        help="select this module first (code 69) and expect its reply; "
                             "repeat for several")
    parser.add_argument("--expect", type=int, default=None, metavar="N",
                        help="replies to wait for without --module (default: what the "
                             "addressing implies; 1 before any Select)")
    parser.add_argument("--timeout", type=float, default=None, metavar="S",
                        help="seconds to wait for the replies (default: as long as the "
                             "protocol says the function takes)")
    parser.add_argument("--json", action="store_true", help="print replies as JSON lines")
    parser.add_argument("--linger", type=float, default=0.0, metavar="S",
                        help="after the ACK, keep printing events for S seconds "
                             "(e.g. localization reports)")
    parser.add_argument("--unchecked", action="store_true",
                        help="send codes/arguments outside the table's ranges (tests the "
                             "firmware's own checks)")
    add_port_arguments(parser, debug=False)


def run(args: argparse.Namespace) -> int:
    command = parse_command([args.function, *args.args], strict=not args.unchecked)
    with session(args) as sess:
        mark = sess.host.mark()
        steps = [(select(*args.module), args.module)] if args.module else []
        steps.append((command, args.module))
        for cmd, modules in steps:
            out = sess.exchange(cmd, modules=modules,
                                count=None if modules else args.expect,
                                timeout=args.timeout, strict=not args.unchecked)
            if not args.linger:
                for obs in out.replies:
                    _print(obs, args.json)
            elif not out.ok:
                for obs in sess.host.since(mark):
                    _print(obs, args.json)
            out.raise_for_status()
        if args.linger > 0:
            sess.sleep(args.linger)
            for obs in sess.host.since(mark):  # in the order they arrived
                _print(obs, args.json)
    print(f"ok: {command}", file=sys.stderr)
    return 0


def _print(obs: Observed, as_json: bool) -> None:
    if as_json:
        print(json.dumps({"t": round(obs.t, 3), "port": obs.port, **event_json(obs.event)}),
              flush=True)
    else:
        print(f"{obs.t:8.3f} {obs.port:<5} {describe_event(obs.event)}", flush=True)


