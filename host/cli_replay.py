"""``hexbot replay CAPTURE``: a session capture played back through the parser."""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from hexbot.host.capture import read_capture
from hexbot.host.describe import describe_event, describe_tx, event_json
from hexbot.host.session_log import CAPTURE_NAME
from hexbot.protocol.mavlink_codec import FramedParser


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("capture", type=Path,
                        help=f"a capture file, or a session folder holding {CAPTURE_NAME}")
    parser.add_argument("--json", action="store_true", help="one JSON object per line")
    parser.add_argument("--port", action="append", metavar="NAME",
                        help="only this port (ir, debug); repeatable")
    parser.add_argument("--realtime", action="store_true",
                        help="wait between records as the original session did")
    parser.add_argument("--no-tx", action="store_true", help="hide what the PC sent")


def run(args: argparse.Namespace) -> int:
    path = args.capture / CAPTURE_NAME if args.capture.is_dir() else args.capture
    parsers: dict[str, FramedParser] = {}
    start = time.monotonic()
    last_t = 0.0

    def emit(t: float, port: str, kind: str, text: str, obj: dict) -> None:
        if args.json:
            print(json.dumps({"t": round(t, 3), "port": port, **obj}), flush=True)
        else:
            print(f"{t:9.3f} {port:<5} {kind} {text}", flush=True)

    for rec in read_capture(path):
        if args.port and rec.port not in args.port:
            continue
        if args.realtime and rec.t > last_t:
            time.sleep(max(0.0, rec.t - (time.monotonic() - start)))
        last_t = rec.t
        if rec.kind == "rx":
            parser = parsers.setdefault(rec.port, FramedParser())  # both framings
            for ev in parser.feed(rec.data):
                emit(rec.t, rec.port, "<", describe_event(ev), event_json(ev))
        elif rec.kind == "tx" and not args.no_tx:
            emit(rec.t, rec.port, ">", describe_tx(rec.data),
                 {"kind": "tx", "decoded": describe_tx(rec.data), "raw": rec.data.hex()})
        elif rec.kind in ("state", "note"):
            emit(rec.t, rec.port, "!" if rec.kind == "state" else "#", rec.text,
                 {"kind": rec.kind, "text": rec.text})
    for port, parser in parsers.items():
        for ev in parser.flush():
            emit(last_t, port, "<", describe_event(ev), event_json(ev))
    return 0
