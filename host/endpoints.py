"""Where the host connects: shared CLI options and the session they open.

``--port`` / ``--debug-port`` name hardware or any pyserial URL; without
``--port`` the embedded simulator runs in this process behind a
``hexbot-sim://`` URL (``--scenario``, ``--seed``, ``--sim-speed``), opened
exactly like hardware. Every session writes its logs (see
:mod:`hexbot.host.session_log`) unless ``--no-log``.
"""

from __future__ import annotations

import argparse
import errno
import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path
from urllib.parse import quote

from hexbot.cli_args import port_name, scenario_name, seconds, sim_speed
from hexbot.errors import HexBotError, UsageError
from hexbot.host.events import Listener
from hexbot.host.host import DEBUG, IR, Host
from hexbot.host.link import PortSettings, cannot_open
from hexbot.host.session_log import SessionLog, default_log_root, new_session_dir
from hexbot.protocol import timing, wire
from hexbot.protocol.mavlink_codec import Framing

DEFAULT_SCENARIO = "flower7"


def add_port_arguments(parser: argparse.ArgumentParser, *, debug: bool = True) -> None:
    g = parser.add_argument_group("ports (default: the embedded simulator)")
    g.add_argument("--port", metavar="DEVICE_OR_URL", type=port_name,
                   help="IR transceiver: /dev/ttyUSB0, socket://host:port, rfc2217://, loop://")
    g.add_argument("--baud", type=baud_rate, default=wire.BAUD_IR,
                   help=f"IR baud rate (default {wire.BAUD_IR}; "
                        f"{timing.BAUD_MIN}..{timing.BAUD_MAX})")
    g.add_argument("--parity", default="N", choices=list("NEOMS"))
    g.add_argument("--data-bits", type=int, default=8, choices=[5, 6, 7, 8])
    g.add_argument("--stop-bits", type=float, default=1, choices=[1, 1.5, 2])
    if debug:
        g.add_argument("--debug-port", metavar="DEVICE_OR_URL", type=port_name,
                       help="a control board's UART1 debug port")
        g.add_argument("--debug-baud", type=baud_rate, default=wire.BAUD_DEBUG,
                       help=f"debug port baud rate (default {wire.BAUD_DEBUG}; "
                            f"{timing.BAUD_MIN}..{timing.BAUD_MAX})")
        g.add_argument("--debug-module", type=int, metavar="ID",
                       help="simulator: whose UART1 to open (default: lowest id)")
    g.add_argument("--scenario", default=None, type=scenario_name,
                   help=f"simulator scenario when no --port is given (default {DEFAULT_SCENARIO})")
    g.add_argument("--seed", type=int, default=None, help="simulator seed")
    g.add_argument("--sim-speed", type=sim_speed, default=None, metavar="X",
                   help="simulator speed, times real time (0 = virtual time, as fast as it "
                        "goes; default: 0 for send/run/plan, 1 for console/monitor)")
    g.add_argument("--framing", choices=[f.value for f in Framing], default="legacy",
                   help="commands as legacy '*'...'#' frames or MAVLink 2 frames (dialect "
                        "protocol/hexbot.xml); auto: probe with a Status request first "
                        "(replies of both framings are always read)")
    g.add_argument("--retry", type=seconds, default=1.0, metavar="S",
                   help="seconds between reconnection attempts (default 1)")
    lg = parser.add_argument_group("session log")
    lg.add_argument("--log-dir", type=Path, default=None,
                    help="folder for session folders (default $HEXBOT_LOG_DIR or "
                         "$XDG_STATE_HOME/hexbot/sessions)")
    lg.add_argument("--no-log", action="store_true", help="write no session log")


def baud_rate(text: str) -> int:
    """argparse type of a port's baud rate: one a module's UART can make
    (``protocol.timing.BAUD_MIN..BAUD_MAX``); another talks to no module,
    and a huge one made the simulator's resampling of each 300-baud bit
    take minutes before session 37."""
    try:
        value = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a whole number: {text!r}") from None
    if not timing.BAUD_MIN <= value <= timing.BAUD_MAX:
        raise argparse.ArgumentTypeError(
            f"a module's UART runs at {timing.BAUD_MIN}..{timing.BAUD_MAX} baud "
            f"(ATmega162 at {timing.F_CPU / 1e6:g} MHz), got {value}")
    return value


@dataclass
class Endpoints:
    ir: PortSettings | None
    debug: PortSettings | None = None
    scenario: str | None = None  # the embedded simulator's, when no --port
    debug_module: int | None = None
    notes: list[str] = field(default_factory=list)

    def close(self) -> None:
        """Nothing to stop: an embedded simulator closes with its port."""


def _sim_target(scenario: str) -> str:
    """What a ``hexbot-sim://`` URL names: a TOML file's absolute path, or
    the built-in (or generated) name as it is."""
    from hexbot.hil_sim.scenario import is_scenario_file

    return str(Path(scenario).resolve()) if is_scenario_file(scenario) else scenario


def sim_url(scenario: str, seed: int | None = None, speed: float = 0.0,
            firmware: str | Path | None = None) -> str:
    """The ``hexbot-sim://`` URL of a scenario (a built-in name or a TOML file),
    optionally with every module on the images of the ``firmware`` folder."""
    target = _sim_target(scenario)
    query = [f"speed={speed:g}"] + ([f"seed={seed}"] if seed is not None else [])
    if firmware is not None:
        query.append(f"firmware={quote(str(Path(firmware).resolve()))}")
    return f"hexbot-sim://{target}?{'&'.join(query)}"


def resolve(args: argparse.Namespace, default_speed: float = 1.0) -> Endpoints:
    """Port settings from the options: hardware or a URL with ``--port``,
    else the embedded simulator (a ``hexbot-sim://`` URL). Opens nothing:
    options that do not fit are a UsageError here, before any port opens."""
    frame = dict(parity=args.parity, data_bits=args.data_bits, stop_bits=args.stop_bits)
    debug_url = getattr(args, "debug_port", None)
    debug_baud = getattr(args, "debug_baud", wire.BAUD_DEBUG)
    if args.port and args.scenario:
        raise UsageError("--scenario starts the simulator; it cannot be combined with --port")
    if args.port and getattr(args, "debug_module", None) is not None:
        raise UsageError("--debug-module picks a simulated module's UART1; with --port, "
                         "give its --debug-port")
    debug = PortSettings(debug_url, debug_baud) if debug_url else None
    if args.port:
        return Endpoints(PortSettings(args.port, args.baud, **frame), debug)
    scenario = args.scenario or DEFAULT_SCENARIO
    speed = args.sim_speed if args.sim_speed is not None else default_speed
    ir = PortSettings(sim_url(scenario, args.seed, speed), args.baud, **frame)
    debug_module = getattr(args, "debug_module", None)
    if debug_module is not None:
        _check_debug_module(debug_module, scenario)
    return Endpoints(ir, debug, scenario, debug_module, [f"simulator scenario {scenario}"])


def _check_debug_module(ident: int, scenario: str) -> None:
    """``--debug-module`` must be one of the scenario's modules (not another
    module's UART1 behind the user's back): a usage error before any port
    opens, read from the scenario file (no simulator runs for it)."""
    from hexbot.hil_sim.scenario import load_scenario

    try:
        ids = sorted(m.id for m in load_scenario(scenario).modules)
    except HexBotError:
        return  # a bad scenario: opening the simulator says why (exit 4, as without the option)
    if ident not in ids:
        raise UsageError(f"--debug-module {ident}: scenario {scenario} has "
                         f"modules {', '.join(map(str, ids))}")


def check_scenario(ends: Endpoints) -> None:
    """The embedded simulator's scenario exists, loads and has its images
    (a simulator is built from it, 10 ms for flower7, and dropped); else
    the error opening its port gives (``cannot open URL: reason``, exit 4),
    before anything starts. For the console, which opens its ports in the
    UI, where a scenario that can never load stood as an alert until quit
    (session 37); a serial port that is unplugged still retries there, as
    it may come back."""
    if ends.scenario is None or ends.ir is None:
        return
    from hexbot.hil_sim import Simulator, load_scenario

    try:
        Simulator(load_scenario(_sim_target(ends.scenario)))
    except HexBotError as exc:
        raise cannot_open(ends.ir.url, exc) from None


def check_log_dir(args: argparse.Namespace) -> None:
    """An explicit ``--log-dir`` that cannot hold a session folder is a usage
    error before anything starts: the console opens its ports in the UI, and
    a console that opened on a status line saying so, then exited 2 at ``q``,
    was no use (the same test :func:`_session_log` makes, without the session's
    folder)."""
    if args.no_log or args.log_dir is None:
        return
    root = Path(args.log_dir)
    try:
        root.mkdir(parents=True, exist_ok=True)
        if not os.access(root, os.W_OK | os.X_OK):
            raise PermissionError(errno.EACCES, os.strerror(errno.EACCES))
    except OSError as exc:
        raise UsageError(f"--log-dir {args.log_dir}: cannot create a session folder: "
                         f"{exc.strerror or exc}") from None


def _session_log(args: argparse.Namespace) -> tuple[SessionLog | None, str]:
    """The session's log and, when the default folder cannot hold one, why
    the session runs without. An explicit ``--log-dir`` that cannot is a
    usage error (before any port opens); the default (``$HEXBOT_LOG_DIR``,
    ~/.local/state) only warns: a stale environment must not stop sessions."""
    if args.no_log:
        return None, ""
    try:
        return SessionLog(new_session_dir(args.log_dir)), ""
    except OSError as exc:
        reason = exc.strerror or str(exc)
        if args.log_dir is not None:
            raise UsageError(f"--log-dir {args.log_dir}: cannot create a session folder: "
                             f"{reason}") from None
        return None, (f"session log folder {default_log_root()}: {reason}; "
                      "running without a session log")


def open_host(args: argparse.Namespace, endpoints: Endpoints,
              listeners: Iterable[Listener] = ()) -> Host:
    """A host with the endpoints' ports, started, ``listeners`` attached
    before the first byte. An embedded simulator's debug port (UART1 of
    ``--debug-module``, default the lowest id) is added once its cluster
    is open."""
    log, log_problem = _session_log(args)
    host = Host(log)
    host.set_framing(Framing(getattr(args, "framing", Framing.LEGACY.value)))
    for listener in listeners:
        host.add_listener(listener)
    if log_problem:
        host.warn(0.0, log_problem)
    try:
        for note in endpoints.notes:
            if log:
                log.note("host", note)
        if endpoints.ir is not None:
            host.add_port(IR, endpoints.ir, args.retry)
        if endpoints.debug is not None:
            host.add_port(DEBUG, endpoints.debug, args.retry)
        host.start()
        sim = host.simulator
        if sim is not None and endpoints.debug is None and hasattr(args, "debug_port"):
            # --debug-module: one of the scenario's ids (checked by resolve)
            ident = (endpoints.debug_module if endpoints.debug_module is not None
                     else min(sim.module_ids()))
            host.add_port(DEBUG, PortSettings(sim.uart1_url(ident),
                                              getattr(args, "debug_baud", wire.BAUD_DEBUG)),
                          args.retry).link.start()
    except BaseException:
        host.close()
        raise
    return host
