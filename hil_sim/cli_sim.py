"""``hexbot sim``: run a scenario behind pseudo-terminals until told to stop.

    hexbot sim pair --pty --speed 1 --events events.jsonl --vcd pins.vcd

The first stdout line is one JSON object naming the ports:
``{"ir": "/dev/pts/N", "uart1": {"<module id>": "/dev/pts/M", ...},
"isp": {"<module id>": {"comm": PATH, "control": PATH}}}`` (STK500v2
programmer ports for avrdude, see docs/flashing.md).
SIGINT or SIGTERM end the run cleanly (files flushed, ptys closed, exit 0).
"""

from __future__ import annotations

import argparse
import json
import select
import signal
import sys
import time
from contextlib import ExitStack
from pathlib import Path
from types import FrameType
from typing import Any, TextIO

from hexbot.cli_args import output_file, seconds, sim_speed, tcp_port
from hexbot.errors import HexBotError, UsageError
from hexbot.protocol.wire import BAUD_IR

from .pty_bridge import PtyBridge
from .scenario import MAX_THREADS, builtin_names, load_scenario
from .simulator import Simulator
from .vcd import VcdWriter

SLICE_S = 0.01  # simulated time between two looks at the ports


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument(
        "scenario",
        nargs="?",
        default="single",
        help=f"built-in name ({', '.join(builtin_names())}) or path to a TOML file",
    )
    parser.add_argument(
        "--pty", action="store_true", help="serve the IR and debug ports on pseudo-terminals"
    )
    parser.add_argument(
        "--rfc2217", type=tcp_port, metavar="TCP_PORT",
        help="serve the IR port over RFC 2217 on localhost:TCP_PORT (0: any free port): "
             "modem lines, parity and baud as a USB adapter takes them",
    )
    parser.add_argument(
        "--speed", type=sim_speed, default=1.0,
        help="times real time (default 1; 0 = as fast as possible)",
    )
    parser.add_argument("--seed", type=int, help="override the scenario's seed")
    parser.add_argument(
        "--threads", type=_threads,
        help="host threads that run each quantum's MCUs (default: the scenario's "
             "threads, else 1); the trace is the same with any number",
    )
    parser.add_argument("--events", type=output_file,
                        help="write plant and bus events as JSON lines")
    parser.add_argument("--vcd", type=output_file,
                        help="write actuator, selector and LED pins as VCD")
    parser.add_argument(
        "--wait-client", action="store_true",
        help="with --pty: start simulating only once a client opened the IR port",
    )
    parser.add_argument(
        "--duration", type=seconds,
        help="stop after this many simulated seconds (default: run until SIGINT/SIGTERM)",
    )


def _threads(text: str) -> int:
    """Host threads per quantum: the core takes 1..MAX_THREADS."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if not 1 <= value <= MAX_THREADS:
        raise argparse.ArgumentTypeError(f"threads must be 1..{MAX_THREADS}, got {value}")
    return value


class _Stop:
    def __init__(self) -> None:
        self.requested = False

    def __call__(self, signum: int, frame: FrameType | None) -> None:
        self.requested = True


def _open(path: str, stack: ExitStack) -> TextIO:
    try:
        return stack.enter_context(Path(path).open("w", encoding="utf-8"))
    except OSError as exc:
        raise HexBotError(f"cannot write {path}: {exc.strerror}") from exc


def run(args: argparse.Namespace) -> int:
    if args.wait_client and not args.pty:  # ignored, it started at once (session 37)
        raise UsageError("--wait-client waits for a client of the --pty ports: give --pty")
    if args.rfc2217 is not None:
        return _serve_rfc2217(args)
    if not args.pty and args.duration is None:
        raise UsageError("nothing to do: give --pty to serve ports, or --duration to run")
    sim = Simulator(load_scenario(args.scenario), seed=args.seed, threads=args.threads)
    for note in sim.image_notes:
        print(f"warning: {note}", file=sys.stderr, flush=True)
    stop = _Stop()
    previous = {s: signal.signal(s, stop) for s in (signal.SIGINT, signal.SIGTERM)}
    with ExitStack() as stack:
        stack.callback(lambda: [signal.signal(s, h) for s, h in previous.items()])
        if args.events:
            events = _open(args.events, stack)

            def write_event(event: dict) -> None:
                events.write(json.dumps(event) + "\n")
                events.flush()

            sim.event_sinks.append(write_event)
        if args.vcd:
            vcd = VcdWriter(sim, _open(args.vcd, stack))
            stack.callback(vcd.close)
        bridge = isp = None
        if args.pty:
            from .isp.cluster import open_simulator_isp

            bridge = stack.enter_context(PtyBridge(sim))
            isp = stack.enter_context(open_simulator_isp(sim))
            print(json.dumps({**bridge.names(), "isp": isp.ports_json()}), flush=True)
            if args.wait_client and not bridge.wait_for_client(lambda: not stop.requested):
                return 0
        else:
            print(json.dumps({"scenario": sim.scenario.name}), flush=True)
        _loop(sim, bridge, isp, args.speed, args.duration, stop)
    return 0


def _serve_rfc2217(args: argparse.Namespace) -> int:
    """The IR port of the embedded simulator's URL port, served over RFC 2217."""
    import serial

    from . import urlhandler
    from .rfc2217_server import Rfc2217Server

    if args.pty or args.events or args.vcd or args.duration is not None or args.threads:
        raise UsageError("--rfc2217 serves one port until stopped: it does not combine "
                         "with --pty, --events, --vcd, --duration or --threads (the "
                         "scenario's threads key applies)")
    urlhandler.register()
    target = Path(args.scenario)
    name = str(target.resolve()) if target.suffix == ".toml" else args.scenario
    query = f"speed={args.speed:g}" + (f"&seed={args.seed}" if args.seed is not None else "")
    try:
        port = serial.serial_for_url(f"{urlhandler.SCHEME}://{name}?{query}",
                                     baudrate=BAUD_IR, timeout=0.1)
    except serial.SerialException as exc:
        raise HexBotError(f"cannot start the simulator: {exc}") from exc
    stop = _Stop()
    previous = {s: signal.signal(s, stop) for s in (signal.SIGINT, signal.SIGTERM)}
    server = Rfc2217Server(port, args.rfc2217)
    try:
        print(json.dumps({"rfc2217": server.url}), flush=True)
        server.serve(lambda: not stop.requested)
    finally:
        server.close()
        port.close()
        for s, h in previous.items():
            signal.signal(s, h)
    return 0


def _loop(
    sim: Simulator,
    bridge: PtyBridge | None,
    isp: Any,
    speed: float,
    duration: float | None,
    stop: _Stop,
) -> None:
    wall0, sim0 = time.monotonic(), sim.time
    while not stop.requested:
        if duration is not None and sim.time - sim0 >= duration - 1e-9:
            break
        if bridge:
            bridge.pump_in()
        if isp:
            isp.poll()  # ISP programming, on this thread like every Cluster access
        step = SLICE_S if duration is None else min(SLICE_S, duration - (sim.time - sim0))
        sim.run(step)
        if bridge:
            bridge.pump_out()
        if speed > 0:
            ahead = (sim.time - sim0) / speed - (time.monotonic() - wall0)
            if ahead > 0:
                # Sleep, but wake as soon as a client writes something.
                fds = (bridge.fds() if bridge else []) + (isp.fds() if isp else [])
                try:
                    select.select(fds, [], [], ahead)
                except InterruptedError:
                    pass


def main() -> None:  # pragma: no cover - for `python -m hexbot.hil_sim.cli_sim`
    parser = argparse.ArgumentParser(prog="hexbot sim")
    add_arguments(parser)
    sys.exit(run(parser.parse_args()))


if __name__ == "__main__":  # pragma: no cover
    main()
