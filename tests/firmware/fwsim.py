"""Talk to simulated modules the way a PC does: through the host's session
on the simulator's pyserial URL (``hexbot-sim://...?speed=0``), frames out
on the PC's IR transceiver, replies parsed from what comes back.

Shared by the firmware tests; everything runs in virtual time (no
wall-clock waits).
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from hexbot.hil_sim import Simulator
from hexbot.hil_sim.module import decode_actuators
from hexbot.hil_sim.plant import OFF
from hexbot.host.endpoints import sim_url
from hexbot.host.events import Traffic, TrafficDirection
from hexbot.host.host import IR, Host
from hexbot.host.link import PortSettings
from hexbot.host.session import OutcomeKind, Session
from hexbot.protocol import frames, parser, wire
from hexbot.protocol.timing import boot_seconds

ROOT = Path(__file__).resolve().parents[2]
FIRMWARE = ROOT / "firmware"
BUILD = FIRMWARE / "build"

REPLY_KINDS = (parser.Ack, parser.ErrorReply, parser.StatusReport)
#: Listen this long after the replies a test expects, so an extra reply would show.
QUIET_S = 0.8


def build_firmware(build_dir: Path = BUILD, version: str | None = None) -> Path:
    """Run the firmware Makefile (incremental); return the build directory."""
    cmd = ["make", "-s", "-C", str(FIRMWARE), f"BUILD={build_dir}", "all"]
    if version:
        cmd.append(f"VERSION={version}")
    subprocess.run(cmd, check=True, capture_output=True, text=True)
    return build_dir


def scenario_file(tmp: Path, modules: list[tuple[int, tuple[int, int], int]], *,
                  comm: Path | None = None, control: Path | None = None,
                  base: int | None = None, bit_error_rate: float = 0.0) -> Path:
    """Write a scenario TOML: modules as (id, (x, y), orientation)."""
    lines = ['name = "test"', "seed = 1", f"base = {base or modules[0][0]}"]
    if bit_error_rate:
        lines += ["[faults]", f"bit_error_rate = {bit_error_rate}"]
    if comm or control:
        lines.append("[firmware]")
        lines.append(f'comm = "{comm or BUILD / "comm.elf"}"')
        lines.append(f'control = "{control or BUILD / "control.elf"}"')
    for ident, (x, y), orientation in modules:
        lines += ["[[module]]", f"id = {ident}", f"position = [{x}, {y}]",
                  f"orientation = {orientation}"]
    path = tmp / "scenario.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


class Bench:
    """A booted cluster behind a stepped ``hexbot-sim://`` port, driven
    through the host's one send-and-wait layer (:class:`Session`) in
    virtual time, plus every byte the PC heard since the last ``drain``
    (for what a terminal would show: boot texts, garbage)."""

    def __init__(self, host: Host, session: Session) -> None:
        self.host, self.session = host, session
        self.heard = bytearray()
        host.add_listener(self._hear)

    def _hear(self, event: object) -> None:
        if (isinstance(event, Traffic) and event.direction is TrafficDirection.RX
                and event.port == IR):
            self.heard += event.data

    def actuators(self, module: int = 1) -> tuple[tuple[bool, ...], tuple[int, ...]]:
        """(joints, magnets) of ``module``'s control board, read from its ports."""
        control = self.sim.modules[module].control
        return decode_actuators({p: control.port(p)[1] for p in "ABD"})

    def all_off(self, module: int = 1) -> bool:
        """No joint open and no magnet energised on ``module``."""
        joints, magnets = self.actuators(module)
        return not any(joints) and all(m == OFF for m in magnets)

    @property
    def sim(self) -> Simulator:
        """The simulator itself, through the port's simulator-only interface
        (pins, positions, events)."""
        return self.host.simulator.simulator  # type: ignore[union-attr]

    @classmethod
    def boot(cls, scenario: str | Path, seed: int = 1, boot_s: float | None = None,
             version: str = "0.1.0") -> Bench:
        """Open the scenario and wait until every module said ``COMM.
        LISTENING`` (or, with ``boot_s``, let exactly that much time pass)."""
        host = Host(None)
        _OPEN.append(host)
        host.add_port(IR, PortSettings(sim_url(str(scenario), seed, 0.0)))
        host.start(5.0)
        ids = host.simulator.module_ids()  # type: ignore[union-attr]
        bench = cls(host, Session(host, ids))
        if boot_s is not None:
            bench.run(boot_s)
        else:
            # By boot_seconds at the latest: beyond eight ids the boot slots
            # wrap and some texts collide (test_boot.py), so not all are heard.
            bench.session.wait_booted(ids, timeout=boot_seconds(ids, version))
        return bench

    def run(self, seconds: float) -> None:
        self.session.sleep(seconds)

    def drain(self) -> bytes:
        """Everything heard so far, forgotten afterwards."""
        data = bytes(self.heard)
        self.heard.clear()
        return data

    def send(self, data: bytes) -> int:
        """Bytes out without waiting; the journal mark to wait from."""
        return self.session.send(data)

    def debug_read(self, module_id: int) -> bytes:
        """What module ``module_id``'s control board sent on its UART1 debug port."""
        return self.host.simulator.take(module_id, 1 << 20)  # type: ignore[union-attr]

    def debug_write(self, module_id: int, data: bytes) -> None:
        """Bytes into that debug port (4800 baud 8N1)."""
        self.host.simulator.write(module_id, data)  # type: ignore[union-attr]

    def events(self) -> list[parser.Event]:
        return parser.parse_all(bytes(self.heard))

    def replies(self) -> list[parser.Event]:
        return [e for e in self.events() if isinstance(e, REPLY_KINDS)]

    def command(self, key: int | str, *args: int, strict: bool = True,
                **exchange) -> list[parser.Event]:
        """``Session.exchange`` of one command (``settle``, ``count``,
        ``timeout``... pass through): its replies, and with ``settle`` any
        extra reply, in order. AssertionError unless answered or refused."""
        return self._replies(frames.make(key, *args, strict=strict), **exchange)

    def frame(self, data: bytes, timeout: float = 8.0, settle: float = QUIET_S,
              **exchange) -> list[parser.Event]:
        """The same for raw bytes (bad input on purpose): any ACK/ERR/STA
        answers them; ``settle`` shows what else came."""
        return self._replies(data, timeout=timeout, settle=settle, **exchange)

    def _replies(self, command: frames.Command | bytes, **exchange) -> list[parser.Event]:
        self.drain()  # from here on, what this command made the PC hear
        out = self.session.exchange(command, strict=False, **exchange)
        if out.kind not in (OutcomeKind.ACKNOWLEDGED, OutcomeKind.REFUSED):
            raise AssertionError(f"{out.reason}; PC heard {bytes(self.heard)!r}")
        return [o.event for o in sorted(out.replies + out.extra, key=lambda o: o.seq)]


#: Hosts opened by Bench.boot; tests/firmware/conftest.py closes them after each test.
_OPEN: list[Host] = []


def close_all() -> None:
    while _OPEN:
        _OPEN.pop().close()


def pc_frame(code: int, *args: int) -> bytes:
    """A PC frame with any byte values, unchecked (for bad input on purpose)."""
    body = list(args) + [wire.UNUSED] * (wire.PC_ARGS - len(args))
    return bytes([wire.START, code, *body, wire.END])


def replies_to(bench: Bench, mark: int, count: int, timeout: float) -> list:
    """The first ``count`` replies (ACK, ERR, STA) heard after journal
    position ``mark``, as observed (with their times)."""
    got: list = []

    def enough(obs) -> bool:
        if isinstance(obs.event, (parser.Ack, parser.ErrorReply, parser.StatusReport)):
            got.append(obs)
        return len(got) >= count

    assert bench.session.wait_for(enough, mark, timeout) is not None, got
    return got


def single_ack(events: list, code: int) -> parser.Ack:
    assert len(events) == 1, f"expected one reply, got {events}"
    (event,) = events
    assert isinstance(event, parser.Ack), f"expected ACK {code}, got {event}"
    assert event.code == code, f"expected ACK {code}, got {event.describe()}"
    return event
