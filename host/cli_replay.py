"""``hexbot replay CAPTURE``: a session capture played back through the parser."""

from __future__ import annotations

import argparse
import json
import sys
import threading
from pathlib import Path

from hexbot.cli_args import positive, seconds_or_zero
from hexbot.host.capture import PORTS, read_capture
from hexbot.host.describe import describe_event, describe_tx, event_json
from hexbot.host.host import ReplayDecoders
from hexbot.host.replay_control import ReplayControl
from hexbot.host.session_log import CAPTURE_NAME

#: What a capture's records name (capture.PORTS): the two ports and the
#: sources of notes. A name outside these would filter every record away and
#: print nothing.
RECORD_PORTS = PORTS


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("capture", type=Path,
                        help=f"a capture file, or a session folder holding {CAPTURE_NAME}")
    parser.add_argument("--json", action="store_true", help="one JSON object per line")
    parser.add_argument("--port", action="append", metavar="NAME", choices=RECORD_PORTS,
                        help="only this port (ir, debug; host and sim: their notes); "
                             "repeatable")
    parser.add_argument("--speed", type=positive, metavar="X",
                        help="pace the records at X times the recorded speed "
                             "(default: as fast as it prints)")
    parser.add_argument("--realtime", dest="speed", action="store_const", const=1.0,
                        help="the same as --speed 1")
    parser.add_argument("--from", dest="start", type=seconds_or_zero, default=0.0, metavar="T",
                        help="seek: print from T seconds on (earlier bytes still go "
                             "through the parser, so a reply across T decodes whole)")
    parser.add_argument("--to", dest="stop", type=seconds_or_zero, metavar="T",
                        help="stop after T seconds")
    parser.add_argument("--no-tx", action="store_true", help="hide what the PC sent")


def run(args: argparse.Namespace) -> int:
    path = args.capture / CAPTURE_NAME if args.capture.is_dir() else args.capture
    if args.stop is not None and args.stop < args.start:
        print(f"hexbot replay: error: --to {args.stop:g} is before --from {args.start:g}",
              file=sys.stderr)
        return 2  # a usage error, as argparse's own
    decoders = ReplayDecoders()  # both framings, held text cut as live
    control = ReplayControl(args.speed, args.start) if args.speed else None
    never = threading.Event()

    def emit(t: float, port: str, kind: str, text: str, obj: dict) -> None:
        if t < args.start:
            return
        if args.json:
            print(json.dumps({"t": round(t, 3), "port": port, **obj}), flush=True)
        else:
            print(f"{t:9.3f} {port:<5} {kind} {text}", flush=True)

    for rec in read_capture(path):
        if args.port and rec.port not in args.port:
            continue
        if args.stop is not None and rec.t > args.stop:
            return 0  # a reply cut by the window is not garbage: no flush
        if control is not None:
            control.wait_until(rec.t, never)
        for t, ev in decoders.play(rec):  # rx and cut records
            emit(t, rec.port, "<", describe_event(ev), event_json(ev))
        if rec.kind == "tx" and not args.no_tx:
            emit(rec.t, rec.port, ">", describe_tx(rec.data),
                 {"kind": "tx", "decoded": describe_tx(rec.data), "raw": rec.data.hex()})
        elif rec.kind in ("state", "note"):
            emit(rec.t, rec.port, "!" if rec.kind == "state" else "#", rec.text,
                 {"kind": rec.kind, "text": rec.text})
    for port, t, ev in decoders.flush():
        emit(t, port, "<", describe_event(ev), event_json(ev))
    return 0
