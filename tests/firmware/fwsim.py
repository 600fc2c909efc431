"""Talk to simulated modules the way the thesis GUI did: frames out on the
PC's IR transceiver, replies parsed from what comes back.

Shared by the firmware tests; every helper runs the simulator in virtual
time only (no wall-clock waits).
"""

from __future__ import annotations

import subprocess
from dataclasses import dataclass, field
from pathlib import Path

from hexbot.hil_sim import Simulator, load_scenario
from hexbot.protocol import frames, parser, wire
from hexbot.protocol.timing import boot_seconds  # noqa: F401 - the tests import it from here

ROOT = Path(__file__).resolve().parents[2]
FIRMWARE = ROOT / "firmware"
BUILD = FIRMWARE / "build"

REPLY_KINDS = (parser.Ack, parser.ErrorReply, parser.StatusReport)


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


@dataclass
class Bench:
    """A booted simulator plus the bytes the PC has heard so far."""

    sim: Simulator
    heard: bytearray = field(default_factory=bytearray)

    @classmethod
    def boot(cls, scenario: str | Path, seed: int = 1, boot_s: float | None = None,
             version: str = "0.1.0") -> Bench:
        sim = Simulator(load_scenario(scenario), seed=seed)
        bench = cls(sim)
        bench.run(boot_s if boot_s is not None else boot_seconds(sim.modules, version))
        return bench

    def run(self, seconds: float) -> None:
        self.sim.run(seconds)
        self.heard += self.sim.pc_read()

    def drain(self) -> bytes:
        """Everything heard so far, forgotten afterwards."""
        data = bytes(self.heard)
        self.heard.clear()
        return data

    def send(self, data: bytes) -> None:
        self.sim.pc_write(data)

    def events(self) -> list[parser.Event]:
        return parser.parse_all(bytes(self.heard))

    def replies(self) -> list[parser.Event]:
        return [e for e in self.events() if isinstance(e, REPLY_KINDS)]

    def until(self, predicate, timeout: float, step: float = 0.05) -> None:
        """Run until ``predicate(self)`` holds; AssertionError after ``timeout`` s."""
        end = self.sim.time + timeout
        while not predicate(self):
            if self.sim.time >= end:
                raise AssertionError(
                    f"not met within {timeout} s of simulated time; PC heard {bytes(self.heard)!r}"
                )
            self.run(step)

    def exchange(self, frame: bytes, replies: int = 1, timeout: float = 8.0,
                 quiet: float = 0.8) -> list[parser.Event]:
        """Send a frame, wait for ``replies`` ACK/ERR/STA replies and then
        ``quiet`` more seconds (so extra replies would show); return them."""
        self.drain()
        self.send(frame)
        self.until(lambda b: len(b.replies()) >= replies, timeout)
        self.run(quiet)
        found = self.replies()
        self.drain()
        return found

    def command(self, key: int | str, *args: int, strict: bool = True, **kw) -> list:
        return self.exchange(frames.encode_pc(frames.make(key, *args, strict=strict),
                                              strict=strict), **kw)


def pc_frame(code: int, *args: int) -> bytes:
    """A PC frame with any byte values, unchecked (for bad input on purpose)."""
    body = list(args) + [wire.UNUSED] * (wire.PC_ARGS - len(args))
    return bytes([wire.START, code, *body, wire.END])


def single_ack(events: list, code: int) -> parser.Ack:
    assert len(events) == 1, f"expected one reply, got {events}"
    (event,) = events
    assert isinstance(event, parser.Ack), f"expected ACK {code}, got {event}"
    assert event.code == code, f"expected ACK {code}, got {event.describe()}"
    return event
