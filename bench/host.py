"""Host throughput: capture writing, capture replay through parser and
cluster model, and the console's terminal rendering.

    hexbot bench host [--repeat N]

Prints one JSON object. For scale: the IR link carries 30 bytes/s
(300 baud), a control board's debug port 480 bytes/s.
"""

from __future__ import annotations

import argparse
import json
import tempfile
import time
from pathlib import Path

from hexbot.cli_args import count
from hexbot.host.capture import CaptureWriter, read_capture
from hexbot.host.console.terminal import Entry, render_entry
from hexbot.host.host import Host

CAPTURE = Path(__file__).resolve().parents[1] / "tests" / "host" / "data" / "flower7_session.hbcap"


def add_arguments(ap: argparse.ArgumentParser) -> None:
    ap.add_argument("--repeat", type=count, default=50)


def run(args: argparse.Namespace) -> int:
    records = list(read_capture(CAPTURE))
    rx_bytes = sum(len(r.data) for r in records if r.kind == "rx")

    t0 = time.perf_counter()
    events = 0
    for _ in range(args.repeat):
        host = Host()
        host.replay(records)
        events += host.mark()
    replay_s = time.perf_counter() - t0

    with tempfile.TemporaryDirectory() as tmp:
        writer = CaptureWriter(Path(tmp) / "c.hbcap")
        chunk = bytes(range(32))
        t0 = time.perf_counter()
        n = 20000
        for _ in range(n):
            writer.record("ir", "rx", chunk)
        write_s = time.perf_counter() - t0
        writer.close()

    host = Host()
    host.replay(records)
    entries = [Entry(o.t, "event", event=o.event) for o in host.since(0)]
    t0 = time.perf_counter()
    for _ in range(args.repeat):
        for e in entries:
            render_entry(e, "decoded")
    render_s = time.perf_counter() - t0

    print(json.dumps({
        "replay_rx_bytes_per_s": round(rx_bytes * args.repeat / replay_s),
        "replay_events_per_s": round(events / replay_s),
        "capture_records_per_s_flushed": round(n / write_s),
        "terminal_lines_rendered_per_s": round(len(entries) * args.repeat / render_s),
        "capture": CAPTURE.name, "repeat": args.repeat,
    }, indent=1))
    return 0
