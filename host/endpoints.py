"""Where the host connects: shared CLI options and the session they open.

``--port`` / ``--debug-port`` name hardware or any pyserial URL; without
``--port`` the embedded simulator is started (``--scenario``) and its ptys
are used. Every session writes its logs (see
:mod:`hexbot.host.session_log`) unless ``--no-log``.
"""

from __future__ import annotations

import argparse
from dataclasses import dataclass, field
from pathlib import Path

from hexbot.errors import HexBotError
from hexbot.host.host import DEBUG, IR, Host
from hexbot.host.link import PortSettings
from hexbot.host.session_log import SessionLog, new_session_dir
from hexbot.host.simproc import DEFAULT_SCENARIO, SimProcess
from hexbot.protocol import wire


def add_port_arguments(parser: argparse.ArgumentParser, *, debug: bool = True) -> None:
    g = parser.add_argument_group("ports (default: the embedded simulator)")
    g.add_argument("--port", metavar="DEVICE_OR_URL",
                   help="IR transceiver: /dev/ttyUSB0, socket://host:port, rfc2217://, loop://")
    g.add_argument("--baud", type=int, default=wire.BAUD_IR, help="IR baud rate (default 300)")
    g.add_argument("--parity", default="N", choices=list("NEOMS"))
    g.add_argument("--data-bits", type=int, default=8, choices=[5, 6, 7, 8])
    g.add_argument("--stop-bits", type=float, default=1, choices=[1, 1.5, 2])
    if debug:
        g.add_argument("--debug-port", metavar="DEVICE_OR_URL",
                       help="a control board's UART1 debug port")
        g.add_argument("--debug-baud", type=int, default=wire.BAUD_DEBUG,
                       help="debug port baud rate (default 4800)")
        g.add_argument("--debug-module", type=int, metavar="ID",
                       help="simulator: whose UART1 to open (default: lowest id)")
    g.add_argument("--scenario", default=None,
                   help=f"simulator scenario when no --port is given (default {DEFAULT_SCENARIO})")
    g.add_argument("--seed", type=int, default=None, help="simulator seed")
    g.add_argument("--sim-speed", type=float, default=1.0, metavar="X",
                   help="simulator speed, times real time (default 1; 0 = flat out)")
    g.add_argument("--retry", type=float, default=1.0, metavar="S",
                   help="seconds between reconnection attempts (default 1)")
    lg = parser.add_argument_group("session log")
    lg.add_argument("--log-dir", type=Path, default=None,
                    help="folder for session folders (default $HEXBOT_LOG_DIR or "
                         "$XDG_STATE_HOME/hexbot/sessions)")
    lg.add_argument("--no-log", action="store_true", help="write no session log")


@dataclass
class Endpoints:
    ir: PortSettings | None
    debug: PortSettings | None = None
    sim: SimProcess | None = None
    notes: list[str] = field(default_factory=list)

    def close(self) -> None:
        if self.sim is not None:
            self.sim.close()


def resolve(args: argparse.Namespace) -> Endpoints:
    """Port settings from the options, starting the simulator if needed."""
    frame = dict(parity=args.parity, data_bits=args.data_bits, stop_bits=args.stop_bits)
    debug_url = getattr(args, "debug_port", None)
    debug_baud = getattr(args, "debug_baud", wire.BAUD_DEBUG)
    if args.port and args.scenario:
        raise HexBotError("--scenario starts the simulator; it cannot be combined with --port")
    if args.port:
        ir = PortSettings(args.port, args.baud, **frame)
        debug = PortSettings(debug_url, debug_baud) if debug_url else None
        return Endpoints(ir, debug)
    scenario = args.scenario or DEFAULT_SCENARIO
    sim = SimProcess(scenario, seed=args.seed, speed=args.sim_speed)
    ir = PortSettings(sim.ports.ir, args.baud, **frame)
    debug = None
    if debug_url:
        debug = PortSettings(debug_url, debug_baud)
    elif sim.ports.uart1 and hasattr(args, "debug_port"):
        wanted = getattr(args, "debug_module", None)
        ident = wanted if wanted in sim.ports.uart1 else min(sim.ports.uart1)
        debug = PortSettings(sim.ports.uart1[ident], debug_baud)
    return Endpoints(ir, debug, sim, [f"simulator scenario {scenario}"])


def open_host(args: argparse.Namespace, endpoints: Endpoints) -> Host:
    log = None
    if not args.no_log:
        log = SessionLog(new_session_dir(args.log_dir))
    host = Host(log)
    if endpoints.sim is not None:
        host.model.seed_truth(_scenario_cells(endpoints.sim.scenario))
        endpoints.sim.on_event = host.sim_event
    for note in endpoints.notes:
        if log:
            log.note("host", note)
    if endpoints.ir is not None:
        host.add_port(IR, endpoints.ir, args.retry)
    if endpoints.debug is not None:
        host.add_port(DEBUG, endpoints.debug, args.retry)
    return host


def _scenario_cells(name: str) -> dict[int, tuple[tuple[int, int], int]]:
    """Where the simulator starts each module: the lattice's ground truth
    until plant events move them."""
    from hexbot.hil_sim.scenario import load_scenario

    sc = load_scenario(name)
    return {m.id: ((m.position[0], m.position[1]), m.orientation) for m in sc.modules}


def scenario_module_ids(name: str) -> set[int]:
    """The module ids of a simulator scenario (to know when all have booted)."""
    return set(_scenario_cells(name))
