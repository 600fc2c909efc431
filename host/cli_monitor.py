"""``hexbot monitor``: decoded events as lines, or JSON lines with --json."""

from __future__ import annotations

import argparse
import json
import queue
import sys
import time

from hexbot.host.cli_common import session
from hexbot.host.describe import describe_event, describe_tx, event_json
from hexbot.host.endpoints import add_port_arguments
from hexbot.host.host import Observed


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="one JSON object per line")
    parser.add_argument("--duration", type=float, default=None, metavar="S",
                        help="stop after S seconds (default: until Ctrl-C)")
    parser.add_argument("--tx", action="store_true",
                        help="also show what this host sends (nothing unless scripted)")
    add_port_arguments(parser)


def format_line(obs: Observed) -> str:
    return f"{obs.t:9.3f} {obs.port:<5} {describe_event(obs.event)}"


def format_json(obs: Observed) -> str:
    return json.dumps({"t": round(obs.t, 3), "port": obs.port, **event_json(obs.event)})


def run(args: argparse.Namespace) -> int:
    lines: queue.Queue[str] = queue.Queue()
    fmt = format_json if args.json else format_line

    def listener(kind: str, port: str, payload: object) -> None:
        if kind == "event":
            lines.put(fmt(payload))  # type: ignore[arg-type]
        elif kind == "tx" and args.tx:
            t, data = payload  # type: ignore[misc]
            lines.put(json.dumps({"t": round(t, 3), "port": port, "kind": "tx",
                                  "raw": data.hex()}) if args.json
                      else f"{t:9.3f} {port:<5} > {describe_tx(data)}")

    with session(args, wait_s=0.0, listener=listener, wait_boot=False):
        end = None if args.duration is None else time.monotonic() + args.duration
        while end is None or time.monotonic() < end:
            try:
                line = lines.get(timeout=0.1)
            except queue.Empty:
                continue
            print(line, flush=True)
        while not lines.empty():
            print(lines.get_nowait(), flush=True)
    sys.stdout.flush()
    return 0
