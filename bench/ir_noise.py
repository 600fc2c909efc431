"""Integrity of commands on a noisy IR link: legacy frames against MAVLink 2.

    hexbot bench ir-noise [--commands 1000] [--rates 3e-4,1e-3,3e-3,1e-2,3e-2]
                          [--framings legacy,mavlink] [--seed 1] [--json]

One simulated module (the real firmware images); noise on the PC -> module
link only. At a noise level ``ber`` every data bit flips with probability
``ber``, and besides, per byte, with the same probability: a framing error,
a spurious byte on the idle line after it, the start of a 12-bit noise
burst (hil_sim/ir_bus.py). The host sends ``commands`` random control-board
functions (no rotations: a single module has nothing to rotate about), one
at a time through the session (``Session.exchange``), and waits for the
reply as the protocol says; after a command that got no reply it selects
the module again (``Select(1)``), because a corrupted legacy frame may have
been a Select of another module or an IrSel that turned the receiver away.

What ran is read from the control board's debug port, not from replies:
the control board prints ``ACK code`` and ``MSG code a1..a4`` for every
board frame it takes, and runs it unless it answered ``ACK N``. Per
command: *executed* when exactly the command ran, *wrong* when anything
else ran in its place or besides, *lost* when nothing ran. Goodput is
executed commands per minute of simulated time, re-selection included.

:func:`trial` is the unit the bench (and the sweep of issue #17) loops over.
"""

from __future__ import annotations

import argparse
import json
import random
import tempfile
from pathlib import Path

from hexbot.cli_args import comma_list, count, finite, one_of
from hexbot.hil_sim.scenario import fault_rate_problem
from hexbot.host.endpoints import sim_url
from hexbot.host.host import IR, Host
from hexbot.host.link import PortSettings
from hexbot.host.session import Session, select
from hexbot.protocol import frames, timing, wire
from hexbot.protocol.codes import CODES, Board
from hexbot.protocol.mavlink_codec import Framing
from hexbot.protocol.parser import (
    Ack,
    ControlMessage,
    ReplyParser,
    reply_ack,
    reply_error,
    reply_status,
)

RATES = (3e-4, 1e-3, 3e-3, 1e-2, 3e-2)
FRAMINGS = ("legacy", "mavlink")
MODULE = 1
ROTATIONS = {"MCW", "MCCW", "SCW", "SCCW"}
#: Repetitions and delays of the walking tests stay small: a run of
#: thousands of commands must not spend its time in one JTest.
SHORT_COUNT, SHORT_DELAY = 3, 5


def _scenario(folder: Path, ber: float, seed: int) -> Path:
    path = folder / "ir_noise.toml"
    path.write_text("\n".join([
        'name = "ir-noise"', f"seed = {seed}", f"base = {MODULE}",
        "[[faults.link]]", 'from = "pc"', f"to = {MODULE}",
        f"bit_error_rate = {ber}", f"framing_error_rate = {ber}",
        f"spurious_byte_rate = {ber}", f"burst_rate = {ber}",
        "[[module]]", f"id = {MODULE}", "position = [0, 0]", "orientation = 0", ""]))
    return path


def random_commands(seed: int, n: int) -> list[frames.Command]:
    """Random control-board functions with valid, short arguments."""
    rng = random.Random(seed)
    table = [fn for fn in CODES.values()
             if fn.executable and fn.board is Board.CONTROL and fn.name not in ROTATIONS]
    out = []
    for _ in range(n):
        fn = rng.choice(table)
        args = []
        for a in fn.args:
            hi = SHORT_COUNT if a.name == "n" else SHORT_DELAY if a.name == "t" else a.hi
            args.append(rng.randint(a.lo, min(a.hi, hi)))
        out.append(frames.make(fn.code, *args))
    return out


def board_frame(command: frames.Command) -> tuple[int, tuple[int, ...]]:
    """What the control board logs for a command: code and its four bytes."""
    args = tuple(command.args) + (wire.UNUSED,) * (wire.BOARD_ARGS - len(command.args))
    return command.code, args[:wire.BOARD_ARGS]


class _ActuatorLog:
    """The control board's debug port: which board frames it ran."""

    def __init__(self, host: Host) -> None:
        self.sim = host.simulator
        self.parser = ReplyParser()
        self._echo: int | None = None

    def ran(self) -> list[tuple[int, tuple[int, ...]]]:
        out = []
        for ev in self.parser.feed(self.sim.take(MODULE, 1 << 20)):
            if isinstance(ev, Ack) and ev.role is None:
                self._echo = ev.code
            elif isinstance(ev, ControlMessage):
                if self._echo is not None and self._echo != wire.UNUSED:
                    out.append((ev.code, tuple(ev.args)))
                self._echo = None
        return out


def trial(framing: str, ber: float, seed: int, commands: int) -> dict:
    """One run: ``commands`` random commands at noise level ``ber`` in
    ``framing`` ("legacy" or "mavlink"); counts of executed, wrong and lost
    commands and goodput per simulated minute."""
    if framing not in FRAMINGS:
        raise ValueError(f"framing must be one of {', '.join(FRAMINGS)}, got {framing!r}")
    with tempfile.TemporaryDirectory(prefix="hexbot-ir-noise-") as tmp:
        url = sim_url(str(_scenario(Path(tmp), ber, seed)), seed, 0.0)
        host = Host(None)
        try:
            host.add_port(IR, PortSettings(url))
            host.start(5.0)
            session = Session(host, [MODULE])
            session.wait_booted([MODULE])
            host.set_framing(Framing(framing))
            log = _ActuatorLog(host)
            _reselect(session)
            log.ran()
            started = session.now()
            counts = {"executed": 0, "wrong": 0, "lost": 0, "reselects": 0}
            for command in random_commands(seed, commands):
                out = session.exchange(command)
                ran = log.ran()
                expected = board_frame(command)
                if any(r != expected for r in ran):
                    counts["wrong"] += 1
                elif ran:
                    counts["executed"] += 1
                else:
                    counts["lost"] += 1
                if not out.replies:
                    counts["reselects"] += 1
                    _reselect(session)
                    if any(r != expected for r in log.ran()):
                        counts["wrong"] += 1  # late: a frame that ran during the re-selection
            minutes = (session.now() - started) / 60.0
        finally:
            host.close()
    return {"framing": framing, "ber": ber, "seed": seed, "commands": commands, **counts,
            "sim_minutes": round(minutes, 2),
            "goodput_per_min": round(counts["executed"] / minutes, 2) if minutes else 0.0}


def _reselect(session: Session, tries: int = 5) -> None:
    for _ in range(tries):
        if session.exchange(select(MODULE)).ok:
            return


def noise_rate(text: str) -> float:
    """argparse type of a noise level: each of the scenario's fault rates is
    set to it (:func:`_scenario`), so it must pass their rule."""
    value = finite(text)
    for key in ("bit_error_rate", "framing_error_rate", "spurious_byte_rate", "burst_rate"):
        problem = fault_rate_problem(key, value)
        if problem:
            raise argparse.ArgumentTypeError(
                f"each fault rate of the run's scenario is set to it: {problem}")
    return value


def add_arguments(ap: argparse.ArgumentParser) -> None:
    ap.add_argument("--commands", type=count, default=1000, help="commands per rate and framing")
    ap.add_argument("--rates", type=comma_list(noise_rate),
                    default=",".join(f"{r:g}" for r in RATES),
                    help="noise levels (bit error rates), comma-separated")
    ap.add_argument("--framings", type=comma_list(one_of(FRAMINGS)), default=",".join(FRAMINGS))
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--json", action="store_true", help="one JSON object per trial")
    ap.add_argument("--air-time", action="store_true",
                    help="only print the air time of each message at 300 baud, both framings")


def air_times() -> list[tuple[str, int, int | None]]:
    """(message, MAVLink bytes, legacy bytes) as packed by pymavlink."""
    from hexbot.protocol import hexbot_mavlink as m
    from hexbot.protocol.mavlink_codec import MavlinkEncoder

    enc = MavlinkEncoder()
    mav = m.MAVLink(None, srcSystem=MODULE, srcComponent=1)
    rows = []
    for name, args in (("Status", ()), ("JxOpen", (3,)), ("JTest", (3, 5)),
                       ("MCW", (4, 10, 20, 30)), ("CW", (1, 10, 20, 30, 4, 10, 20, 30)),
                       ("Select", (1,))):
        cmd = frames.make(name, *args)
        rows.append((f"HEXBOT_COMMAND {cmd}", len(enc.encode(cmd, target=MODULE)),
                     wire.PC_FRAME_LEN))
    # the legacy replies as the firmware sends them (the parser's encoders, the
    # localization report of protocol/timing.py)
    replies = (
        ("HEXBOT_ACK done", m.MAVLink_hexbot_ack_message(1, 1, 0, 0),
         len(reply_ack(1, "M", MODULE))),
        ("HEXBOT_ACK error", m.MAVLink_hexbot_ack_message(1, 1, 1, 1),
         len(reply_error(1, 1, "M", MODULE))),
        ("HEXBOT_STATUS", m.MAVLink_hexbot_status_message(0xD3A1B21B, 2, 1, -3, 2, 1, 0, 0),
         len(reply_status(MODULE, "S", True, -3, 2, 1, 0, "S", 0xD3A1B21B))),
        ("HEXBOT_LOCALIZED", m.MAVLink_hexbot_localized_message(4, 1, -3, 2),
         len(timing.LOCALIZE_REPORT)),
    )
    for name, msg, legacy in replies:
        rows.append((name, len(msg.pack(mav)), legacy))
    return rows


def run(args: argparse.Namespace) -> int:
    if args.air_time:
        byte_ms = 1000 * timing.BYTE_BITS / wire.BAUD_IR
        print(f"{'message':<44} {'MAVLink':>13} {'legacy':>13}")
        for name, mav_len, legacy in air_times():
            print(f"{name:<44} {mav_len:3d} B {mav_len * byte_ms:4.0f} ms "
                  f"{legacy:3d} B {legacy * byte_ms:4.0f} ms")
        return 0
    rates, framings = args.rates, args.framings
    if not args.json:
        print(f"{'ber':>7} {'framing':<8} {'commands':>8} {'executed':>8} {'wrong':>6} "
              f"{'lost':>6} {'goodput/min':>11}")
    for ber in rates:
        for framing in framings:
            row = trial(framing, ber, args.seed, args.commands)
            if args.json:
                print(json.dumps(row), flush=True)
            else:
                print(f"{ber:7.0e} {framing:<8} {row['commands']:8d} {row['executed']:8d} "
                      f"{row['wrong']:6d} {row['lost']:6d} {row['goodput_per_min']:11.1f}",
                      flush=True)
    return 0
