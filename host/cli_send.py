"""``hexbot send CODE [ARGS...]``: one message, its decoded replies, an exit code.

Exit 0 when the expected ACK arrived (from ``--module`` if given, which is
selected first with code 69), 1 otherwise with the reason on stderr.
"""

from __future__ import annotations

import argparse
import json
import sys
import time

from hexbot.errors import HexBotError, HexBotTimeoutError
from hexbot.host import commands
from hexbot.host.cli_common import session
from hexbot.host.describe import describe_event, event_json
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.host import Observed


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("function", metavar="CODE", help="function code or name (hexbot codes)")
    parser.add_argument("args", nargs="*", metavar="ARG", help="argument bytes")
    parser.add_argument("--module", type=int, action="append", metavar="ID",
                        help="select this module first (code 69) and expect its reply; "
                             "repeat for several")
    parser.add_argument("--expect", type=int, default=1, metavar="N",
                        help="replies to wait for without --module (default 1)")
    parser.add_argument("--timeout", type=float, default=5.0, metavar="S",
                        help="seconds to wait for the replies (default 5)")
    parser.add_argument("--json", action="store_true", help="print replies as JSON lines")
    parser.add_argument("--linger", type=float, default=0.0, metavar="S",
                        help="after the ACK, keep printing events for S seconds "
                             "(e.g. localization reports)")
    parser.add_argument("--unchecked", action="store_true",
                        help="send codes/arguments outside the table's ranges (tests the "
                             "firmware's own checks)")
    add_port_arguments(parser, debug=False)


def run(args: argparse.Namespace) -> int:
    command = commands.parse_command([args.function, *args.args], strict=not args.unchecked)
    with session(args) as host:
        steps = []
        if args.module:
            steps.append((commands.select(*args.module), args.module))
        steps.append((command, args.module))
        for cmd, modules in steps:
            mark = host.mark()
            out = commands.exchange(host, cmd, modules=modules, count=args.expect,
                                    timeout=args.timeout, strict=not args.unchecked)
            for obs in out.replies:
                _print(obs, args.json)
            if not out.ok:
                if len(out.replies) == 0 or "replies within" in out.message:
                    raise HexBotTimeoutError(out.message)
                raise HexBotError(f"{cmd}: unexpected reply: {out.message}")
        if args.linger > 0:
            shown = {o.seq for o in out.replies}
            time.sleep(args.linger)
            for obs in host.since(mark):
                if obs.seq not in shown:
                    _print(obs, args.json)
    print(f"ok: {command}", file=sys.stderr)
    return 0


def _print(obs: Observed, as_json: bool) -> None:
    if as_json:
        print(json.dumps({"t": round(obs.t, 3), "port": obs.port, **event_json(obs.event)}),
              flush=True)
    else:
        print(f"{obs.t:8.3f} {obs.port:<5} {describe_event(obs.event)}", flush=True)


