"""The embedded simulator as a pyserial port.

    serial.serial_for_url("hexbot-sim://flower7?seed=3&speed=0")

opens a simulated cluster in this process and returns a port on the PC's
IR transceiver, exactly as ``/dev/ttyUSB0`` would be on hardware (register
the URL scheme first: :func:`hexbot.hil_sim.urlhandler.register`). URL forms:

``hexbot-sim://SCENARIO[?seed=N][&speed=X][&firmware=DIR][&radio=1]``
    a new cluster of a built-in scenario or a TOML file
    (``hexbot-sim:///abs/path.toml``). ``radio=1`` makes the port the PC's
    RF12 radio (at the scenario's ``pc_radio`` cell) instead of its IR
    transceiver: bytes written go out in radio packets, the link bytes of the
    packets heard come back; modules with a wireless board running the
    ``rflink`` image pass them to and from their comm board (docs/simulator.md,
    "The RF12 radio"). The port speaks 300 baud 8N1 like the IR one.
    ``speed=0`` is *stepped*: virtual time advances only while someone
    waits for bytes (``read`` with a time-out, counted in simulated
    seconds) or calls ``hexbot_sim.advance``, so the same calls give the
    same trace. ``speed=N`` (default 1) runs the cluster on its own thread
    at N times real time. ``firmware=DIR`` runs every module on DIR's
    comm.elf and control.elf instead of the scenario's images (a
    regression matrix over firmware builds).
``hexbot-sim://@INSTANCE/uart1/ID``
    module ID's control-board debug port (UART1, 4800 baud) on a cluster
    this process already opened (``hexbot_sim.uart1_url(ID)`` makes it).

Line settings and modem lines are accepted as a USB adapter accepts them.
The simulated transceiver speaks 300 baud 8N1 (a debug port 4800 8N1): a
port set otherwise reads and sends what a real UART would, garbled bytes
(:mod:`hexbot.hil_sim.uart_line`), so a wrong setting shows here before it
is met on the bench. Modem lines are not wired on HexBot's converter:
setting DTR/RTS does nothing, CTS/DSR/CD read high. What only a simulator knows (plant
verdicts, true positions, actuators) is offered through ``port.hexbot_sim``
(:class:`~hexbot.protocol.simulation.SimulatorAccess`); nothing else about
this port differs from hardware. The cluster is not thread-safe: every
access goes through one lock.
"""

from __future__ import annotations

import itertools
import threading
import time
import weakref
from collections.abc import Callable
from pathlib import Path
from urllib.parse import parse_qs, urlsplit

from serial.serialutil import PortNotOpenError, SerialBase, SerialException

from hexbot.errors import HexBotError
from hexbot.hil_sim.uart_line import LineSettings, resample
from hexbot.hil_sim.urlhandler import SCHEME
from hexbot.protocol import wire
from hexbot.protocol.simulation import Placement, PlantVerdict, verdict_from_record

SLICE_S = 0.01  # simulated time per step: well under one 300-baud byte (33 ms)
RADIO = "radio"  # the line of a radio=1 port (None: IR, an int: a module's UART1)
Line = int | str | None
_instances: dict[int, weakref.ref[SimCluster]] = {}
_numbers = itertools.count(1)


class SimCluster:
    """One simulated cluster shared by the ports opened on it; implements
    :class:`~hexbot.protocol.simulation.SimulatorAccess`."""

    def __init__(self, scenario: str, seed: int | None, speed: float,
                 firmware: str | None = None) -> None:
        from hexbot.hil_sim import Simulator, load_scenario

        if not speed >= 0 or speed == float("inf"):  # nan too: it never runs
            raise HexBotError(f"speed must be a number 0 or more, not {speed:g}")
        spec = load_scenario(scenario)
        if firmware:
            spec = spec.with_firmware(Path(firmware))
        self.simulator = Simulator(spec, seed)
        self.scenario = scenario
        self.seed = self.simulator.seed
        self.base = self.simulator.scenario.base
        self.image_notes = tuple(self.simulator.image_notes)
        self.speed = speed
        self.number = next(_numbers)
        _instances[self.number] = weakref.ref(self)
        self._lock = threading.RLock()
        self.changed = threading.Condition(self._lock)
        self._ir = bytearray()
        self._radio: bytearray | None = None  # once a radio=1 port opened
        self._uart1: dict[int, bytearray] = {m: bytearray() for m in self.simulator.modules}
        self._verdicts: list[PlantVerdict] = []
        self._records_seen = 0
        self._subscribers: list[Callable[[PlantVerdict], None]] = []
        self._tickers: list[Callable[[], None]] = []
        self._closed = threading.Event()
        self.failure = ""  # why the simulator stopped on its own ("" while it runs)
        self._thread: threading.Thread | None = None
        if speed > 0:
            self._thread = threading.Thread(target=self._pace, daemon=True,
                                            name=f"{SCHEME} {scenario}")
            self._thread.start()

    # --- SimulatorAccess ---------------------------------------------------

    @property
    def stepped(self) -> bool:
        return self.speed == 0

    def now(self) -> float:
        with self._lock:
            return self.simulator.time

    def advance(self, seconds: float) -> None:
        if not self.stepped:
            raise HexBotError("advance() is for stepped clusters (speed=0); this one "
                              f"runs on its own at {self.speed:g}x real time")
        self._run(seconds)

    def module_ids(self) -> list[int]:
        return sorted(self.simulator.modules)

    def placements(self) -> dict[int, Placement]:
        with self._lock:
            return {m: Placement(mod.position, mod.orientation)
                    for m, mod in self.simulator.modules.items()}

    def verdicts(self, since: int = 0) -> list[PlantVerdict]:
        with self._lock:
            return self._verdicts[since:]

    def subscribe(self, callback: Callable[[PlantVerdict], None]) -> None:
        self._subscribers.append(callback)

    def on_advance(self, callback: Callable[[], None]) -> None:
        self._tickers.append(callback)

    def actuators(self, module_id: int) -> dict[str, list[int]]:
        with self._lock:
            return self.simulator.actuators(module_id)

    def uart1_url(self, module_id: int) -> str:
        if module_id not in self._uart1:
            raise HexBotError(f"scenario {self.scenario} has no module {module_id} "
                              f"(modules {self.module_ids()})")
        return f"{SCHEME}://@{self.number}/uart1/{module_id}"

    # --- the ports' side ---------------------------------------------------

    def buffer(self, uart1: Line) -> bytearray:
        if uart1 == RADIO:
            if self._radio is None:
                self._radio = bytearray()
            return self._radio
        return self._ir if uart1 is None else self._uart1[uart1]  # type: ignore[index]

    def write(self, uart1: Line, data: bytes) -> None:
        with self._lock:
            if uart1 == RADIO:
                self.buffer(RADIO)
                self.simulator.pc_radio_write(data)
            elif uart1 is None:
                self.simulator.pc_write(data)
            else:
                self.simulator.debug_write(uart1, data)  # type: ignore[arg-type]

    def take(self, uart1: Line, size: int) -> bytes:
        with self._lock:
            buf = self.buffer(uart1)
            data = bytes(buf[:size])
            del buf[:size]
            return data

    def wait_bytes(self, uart1: Line, size: int, timeout: float | None) -> None:
        """Until ``size`` bytes wait in the buffer or ``timeout`` passed:
        simulated seconds when stepped, wall seconds when paced."""
        buf = self.buffer(uart1)
        if self.stepped:
            if timeout is None:
                while len(buf) < size and not self._closed.is_set():
                    self._run(SLICE_S)
                return
            end = self.now() + timeout
            while len(buf) < size and (left := end - self.now()) > 1e-9:
                self._run(min(SLICE_S, left))
            return
        with self.changed:
            self.changed.wait_for(lambda: len(buf) >= size or self._closed.is_set(), timeout)

    def close(self) -> None:
        if self._closed.is_set():
            return
        self._closed.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=5.0)
        with self.changed:
            self.changed.notify_all()
        _instances.pop(self.number, None)

    # --- running -------------------------------------------------------------

    def _run(self, seconds: float) -> None:
        with self._lock:
            if self.failure:
                raise SerialException(self.failure)
            try:
                self.simulator.run(seconds)
                fresh = self._collect()
            except Exception as exc:  # noqa: BLE001 - any fault of the simulator ends it
                # The cluster is gone as a pulled cable is: its ports fail from
                # now on with the reason, and nobody silently starts another.
                self.failure = f"the simulator stopped: {type(exc).__name__}: {exc}"
                self._closed.set()
                self.changed.notify_all()
                raise SerialException(self.failure) from exc
            self.changed.notify_all()
        for verdict in fresh:
            for callback in list(self._subscribers):
                callback(verdict)
        for tick in list(self._tickers):
            tick()

    def _collect(self) -> list[PlantVerdict]:
        sim = self.simulator
        self._ir += sim.pc_read()
        if self._radio is not None:
            self._radio += sim.pc_radio_read()
        for module_id, buf in self._uart1.items():
            buf += sim.debug_read(module_id)
        fresh = [v for record in sim.events[self._records_seen:]
                 if (v := verdict_from_record(record)) is not None]
        self._records_seen = len(sim.events)
        self._verdicts += fresh
        return fresh

    def _pace(self) -> None:
        wall0, sim0 = time.monotonic(), self.now()
        while not self._closed.is_set():
            try:
                self._run(SLICE_S)
            except SerialException:
                return  # failure recorded: the ports report it
            ahead = (self.now() - sim0) / self.speed - (time.monotonic() - wall0)
            if ahead > 0:
                self._closed.wait(ahead)


def _attach(url: str) -> tuple[SimCluster, Line, bool]:
    """(cluster, UART1 module id, RADIO or None for the IR port, whether this
    port owns it)."""
    parts = urlsplit(url)
    if parts.scheme != SCHEME:
        raise SerialException(f"expected a {SCHEME}:// URL, got {url!r}")
    target = parts.netloc + parts.path
    if target.startswith("@"):
        try:
            number, kind, ident = target[1:].split("/")
            if kind != "uart1":
                raise ValueError(kind)
            cluster = _instances[int(number)]()
            module_id = int(ident)
        except (ValueError, KeyError) as exc:
            raise SerialException(f"{url}: no such simulated port in this process "
                                  f"(expected {SCHEME}://@N/uart1/ID of an open cluster)") from exc
        if cluster is None:
            raise SerialException(f"{url}: the simulated cluster was closed")
        if module_id not in cluster.module_ids():
            raise SerialException(f"{url}: no module {module_id} in this cluster")
        return cluster, module_id, False
    if not target:
        raise SerialException(f"{url}: name a scenario, e.g. {SCHEME}://flower7?speed=0")
    options = {k: v[-1] for k, v in parse_qs(parts.query, keep_blank_values=True).items()}
    unknown = set(options) - {"seed", "speed", "firmware", "radio"}
    if unknown:
        raise SerialException(f"{url}: unknown option(s) {', '.join(sorted(unknown))} "
                              "(seed, speed, firmware, radio)")
    if options.get("radio", "0") not in ("0", "1"):
        raise SerialException(f"{url}: radio must be 0 (IR transceiver) or 1 (the PC's radio)")
    try:
        seed = int(options["seed"]) if "seed" in options else None
        speed = float(options.get("speed", "1"))
    except ValueError as exc:
        raise SerialException(f"{url}: seed must be an integer and speed a number") from exc
    line = RADIO if options.get("radio") == "1" else None
    try:
        cluster = SimCluster(target, seed, speed, options.get("firmware"))
    except HexBotError as exc:  # bad scenario (file:line), missing firmware or C extension
        raise SerialException(str(exc)) from exc
    if line == RADIO:
        if not any(m.rf12 for m in cluster.simulator.modules.values()):
            cluster.close()
            raise SerialException(f"{url}: no module of {target} has a wireless board "
                                  "(scenario [firmware] rf12 = \"build/rflink.elf\")")
        with cluster._lock:
            cluster.buffer(RADIO)
            cluster.simulator.pc_radio_read()  # the PC's radio is on the air from now on
    return cluster, line, True


class Serial(SerialBase):
    """A pyserial port on a simulated cluster (see the module docstring)."""

    hexbot_sim: SimCluster

    def open(self) -> None:
        if self.is_open:
            raise SerialException("port is already open")
        if self._port is None:
            raise SerialException("port must be configured before it can be used")
        self.hexbot_sim, self._uart1, self._owner = _attach(self._port)
        self._received = bytearray()  # resampled, for a port set unlike the line
        self.is_open = True
        self._reconfigure_port()

    def close(self) -> None:
        if not self.is_open:
            return
        self.is_open = False
        if self._owner:
            self.hexbot_sim.close()

    def _reconfigure_port(self, force_update: bool = False) -> None:
        """Any settings a USB adapter takes are taken; they decide what this
        end of the simulated wire reads and sends."""
        try:
            self._line = LineSettings(int(self._baudrate), int(self._bytesize), self._parity,
                                      float(self._stopbits))
        except ValueError as exc:
            raise SerialException(f"{self._port}: {exc}") from exc
        line = getattr(self, "_uart1", None)
        baud = wire.BAUD_IR if line is None or line == RADIO else wire.BAUD_DEBUG
        self._wire = LineSettings(baud)  # what the modules' UARTs speak

    @property
    def line_matches(self) -> bool:
        return self._line == self._wire

    def _resampled(self) -> None:
        """Move what the wire carried into ``_received`` as this port reads it."""
        data = self.hexbot_sim.take(self._uart1, len(self.hexbot_sim.buffer(self._uart1)))
        self._received += resample(data, self._wire, self._line)

    @property
    def in_waiting(self) -> int:
        self._check_open()
        if self.line_matches:
            return len(self.hexbot_sim.buffer(self._uart1))
        self._resampled()
        return len(self._received)

    def read(self, size: int = 1) -> bytes:
        self._check_open()
        if size <= 0:
            return b""
        if self.line_matches:
            self.hexbot_sim.wait_bytes(self._uart1, size, self._timeout)
            return self.hexbot_sim.take(self._uart1, size)
        self._resampled()
        if not self._received:
            self.hexbot_sim.wait_bytes(self._uart1, 1, self._timeout)
            self._resampled()
        data = bytes(self._received[:size])
        del self._received[:size]
        return data

    def write(self, data: bytes) -> int:
        self._check_open()
        data = bytes(data)
        self.hexbot_sim.write(self._uart1, resample(data, self._line, self._wire))
        return len(data)

    def flush(self) -> None:
        self._check_open()

    def reset_input_buffer(self) -> None:
        self._check_open()
        self.hexbot_sim.take(self._uart1, len(self.hexbot_sim.buffer(self._uart1)))
        self._received.clear()

    def reset_output_buffer(self) -> None:
        self._check_open()

    # Modem lines: nothing is wired to them on HexBot's RS232 converter.
    def _update_rts_state(self) -> None:
        pass

    def _update_dtr_state(self) -> None:
        pass

    def _update_break_state(self) -> None:
        pass

    @property
    def cts(self) -> bool:
        return True

    @property
    def dsr(self) -> bool:
        return True

    @property
    def ri(self) -> bool:
        return False

    @property
    def cd(self) -> bool:
        return True

    def _check_open(self) -> None:
        if not self.is_open:
            raise PortNotOpenError()
        if self.hexbot_sim._closed.is_set():
            raise SerialException(self.hexbot_sim.failure or "the simulated cluster was closed")
