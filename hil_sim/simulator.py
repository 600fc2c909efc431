"""The simulator: a cluster of modules, the IR medium, the plant and the PC.

It owns the time loop. The C core runs every MCU in lock-step and returns at
the first quantum boundary after a watched UART byte completes; in between,
this loop moves bytes (debug ports, PC), reads the pin logs (selectors,
actuators, LEDs) of the MCUs the core reports as changed, and lets the plant
resolve rotations. Everything is in virtual time: a run is as fast as the
host allows and the same scenario and seed give the same trace.

IR bytes between modules are routed by the core itself (hil_sim/core/
ir_medium.c): this loop gives it, per comm board and selector index, who
hears the byte (from the plant's geometry, again after every move), and it
hands back the bytes for the PC and the collision/drop/garble events. A
scenario with IR fault injection, or a cluster without that API (the unit
tests' double), keeps the whole medium in Python (hil_sim/ir_bus.py), which
delivers at the boundary after a byte's end instead of in the middle of its
stop bit. ``Simulator(..., ir_in_c=False)`` asks for the Python medium.

The quantum defaults to the lookahead of the fastest wire the core routes
itself (a module's board link): no byte can start and reach the middle of its
stop bit within one quantum, so every delivery on it is exact. Each MCU runs
on its own clock (scenario ``clock_ppm`` / ``clock_spread_ppm``); cycles
everywhere are cycles of the nominal clock ``F_CPU``.

``threads`` (argument, else the scenario's ``threads``, else 1) is how many
threads the core runs each quantum's MCUs on, with the GIL released; the
trace does not depend on it (docs/simulator-core.md, "Threads").
"""

from __future__ import annotations

import random
from collections import deque
from collections.abc import Callable
from pathlib import Path
from typing import Any

from hexbot.errors import HexBotError, HexBotTimeoutError, ScenarioError
from hexbot.protocol.header import SCHEMA_HASH
from hexbot.protocol.image_mark import ImageMark, mismatch, read_mark
from hexbot.protocol.pins import (
    COMM_PORTS,
    CONTROL_PORTS,
    DIP_PORT,
    RF12_IRQ_PIN,
    RF12_LINK_UART,
    RF12_SPI_PINS,
    SELECTOR_PINS,
    SELECTOR_PORT,
)
from hexbot.protocol.timing import (
    BAUD_BOARD,
    BAUD_DEBUG,
    BAUD_IR,
    BYTE_BITS,
    CLOCK_TOLERANCE,
    F_CPU,
    bit_cycles,
)

from .geometry import CENTRE, CHANNEL_SIDE, SIDE_CHANNEL, Cell, facing, neighbor, to_body, to_global
from .ir_bus import PC_FRAME, AirByte, Frame, IrMedium
from .module import Mcu, Module, decode_actuators, decode_leds
from .plant import Plant, Timing
from .radio import RadioMedium
from .scenario import PC, Scenario, load_scenario

DEBUG_FRAME = Frame(float(BAUD_DEBUG))
HISTORY_S = 2.0  # selector history kept, far more than one 300-baud byte


def lookahead_cycles(hz: int = F_CPU) -> int:
    """Shortest time from a byte's start bit to the middle of its stop bit on a
    wire the core routes (the board link), on the fastest clock allowed: the
    largest quantum that still delivers every byte on its exact cycle."""
    bits_to_mid_stop = 9.5  # start + 8 data + half a stop bit
    # the USART's bit, not the nominal baud's: 208 cycles at 4800, 1,881 to
    # mid-stop at +5 % (the nominal 208.3 made 1,884, two cycles too long)
    return int(bits_to_mid_stop * bit_cycles(BAUD_BOARD, hz) / (1 + CLOCK_TOLERANCE))


def _load_core() -> Any:
    try:
        from hexbot.hil_sim import _avr  # type: ignore[attr-defined]
    except ImportError as exc:
        raise HexBotError(
            "the simulator's C extension hexbot.hil_sim._avr is not built "
            f"({exc}); build it with `pip install -e .` in the repository"
        ) from exc
    return _avr


def frame_of(config: dict, clock: int | None = None, nominal: int | None = None) -> Frame:
    """A USART's settings (``Cluster.uart_config``). With its MCU's clock and
    the nominal clock (Hz), also its bit time in cluster cycles: its own
    cycles per bit times nominal over its clock, not rounded (decision,
    docs/simulator.md "Bit times off nominal"). One division of exact
    integers, as the core's ``m162_bit_time``: the same double."""
    bit = None
    if clock and nominal and "bit_cycles" in config:
        bit = int(config["bit_cycles"]) * int(nominal) / int(clock)
    return Frame(
        float(config["baud"]),
        int(config["data_bits"]),
        str(config["parity"]),
        int(config["stop_bits"]),
        bit,
    )


class Simulator:
    """A scenario running on simulated MCUs; see docs/simulator.md for the contract."""

    def __init__(
        self,
        scenario: Scenario,
        seed: int | None = None,
        *,
        quantum_cycles: int | None = None,
        hz: int = F_CPU,
        timing: Timing | None = None,
        cluster: Any = None,
        ir_in_c: bool = True,
        threads: int | None = None,
    ) -> None:
        self.scenario = scenario
        self.seed = scenario.seed if seed is None else seed
        if cluster is None:
            threads = scenario.threads if threads is None else threads
            try:
                cluster = _load_core().Cluster(quantum_cycles or lookahead_cycles(hz),
                                               threads=threads)
            except ValueError as exc:
                raise HexBotError(f"simulator threads: {exc}") from exc
        self.cluster = cluster
        self.hz = int(getattr(self.cluster, "frequency", hz))
        self.events: list[dict] = []
        self.event_sinks: list[Callable[[dict], None]] = []
        # (cycle, module id, "comm"|"control", port, value) for VCD writers and the like
        self.pin_sinks: list[Callable[[list[tuple[int, int, str, str, int]]], None]] = []
        self.plant = Plant(float(hz), timing or Timing(), emit=self._emit)
        self.modules: dict[int, Module] = {}
        self._by_comm: dict[int, Module] = {}
        self._boards: dict[int, tuple[Module, str]] = {}  # MCU index -> module, board
        self._garbage = random.Random(self.seed ^ 0x5EED)
        #: IR between modules routed in the core; fault injection needs the Python medium
        self.ir_in_c = bool(ir_in_c) and hasattr(self.cluster, "ir_attach") and not any(
            f.active for f in (scenario.faults, *scenario.link_faults.values()))
        self._geometry_version = -1
        #: what the images' marks say is wrong but may be meant (another
        #: board's firmware, or built from another protocol): one line each,
        #: for the host to warn about
        self.image_notes: list[str] = []
        self._marks: dict[Path, ImageMark | None] = {}
        clocks = scenario.clocks(self.seed)
        for spec in sorted(scenario.modules, key=lambda m: m.id):
            for board in ("comm", "control"):
                image = getattr(spec.firmware, board)
                if not image.is_file():
                    raise ScenarioError(
                        f"{scenario.where(spec.line)}: module {spec.id}: {board} image "
                        f"{image} does not exist (build it with `make -C firmware`)"
                    )
                self._check_image(image, (board,), f"{scenario.where(spec.line)}: "
                                  f"module {spec.id}: {board} image {image}")
            try:  # not an ELF, not for the AVR, built for another AVR, too big
                comm = self.cluster.add_mcu(str(spec.firmware.comm), f"comm{spec.id}")
                control = self.cluster.add_mcu(str(spec.firmware.control), f"control{spec.id}")
            except ValueError as exc:
                raise ScenarioError(f"{scenario.where(spec.line)}: module {spec.id}: {exc}") \
                    from None
            self.cluster.connect_uart(comm, 0, control, 0)
            if self.ir_in_c:
                self.cluster.ir_attach(comm, 1, SELECTOR_PORT, tuple(b for _, b in SELECTOR_PINS))
                # the plant must see actuator changes when they happen, not
                # at the next IR byte as before
                self.cluster.wake_on_pins(control, "".join(CONTROL_PORTS))
            else:
                self.cluster.watch_uart(comm, 1)
            self.cluster.watch_uart(control, 1)
            self.cluster.set_input(control, DIP_PORT, 0xFF, spec.id)  # DIP switches
            self.plant.add(spec.id, spec.position, spec.orientation, spec.id == scenario.base)
            module = Module(
                spec.id,
                Mcu(self.cluster, comm, f"comm{spec.id}"),
                Mcu(self.cluster, control, f"control{spec.id}"),
                self.plant.bodies[spec.id],
            )
            self.modules[spec.id] = module
            if hasattr(self.cluster, "uart_rx_log"):
                module.record_rx([], 0)  # its receiver's changes come from the core
            self._by_comm[comm] = module
            self._boards[comm] = (module, "comm")
            self._boards[control] = (module, "control")
            for index, board in ((comm, "comm"), (control, "control")):
                ppm = clocks[(spec.id, board)]
                if ppm:
                    self.cluster.set_clock(index, hz * (1 + ppm / 1e6))
            if spec.firmware.rf12 is not None:
                self._add_rf12(module, spec.firmware.rf12, scenario.where(spec.line))
        self.medium = IrMedium(
            self, self.seed, faults_for=scenario.faults_for, emit=self._emit, hz=self.hz
        )
        self._ir_frame_cycles = round(BYTE_BITS * hz / BAUD_IR)
        self._debug_frame_cycles = round(BYTE_BITS * hz / BAUD_DEBUG)
        self._pc_tx: deque[tuple[int, int, int]] = deque()  # (start, end, byte)
        self._pc_tx_free = 0  # cycle the PC's transmitter is free again
        self._debug_tx: dict[int, deque[tuple[int, int]]] = {m: deque() for m in self.modules}
        self._debug_tx_free: dict[int, int] = dict.fromkeys(self.modules, 0)
        # control boards by module id, wireless boards by (module id, "rf12")
        self._debug_rx: dict[int | tuple[int, str], bytearray] = {
            m: bytearray() for m in self.modules}
        self._debug_rx.update({(m, "rf12"): bytearray()
                               for m, mod in self.modules.items() if mod.rf12})
        self._pc_rx = bytearray()
        self._cycle = 0
        self.radio = RadioMedium(
            self.cluster, {m.id: m.rf12.index for m in self.modules.values() if m.rf12},
            self.position, scenario.radio_range, self.seed, self._emit,
        )
        if self.ir_in_c:
            self.cluster.ir_seed(self.seed)
            self._send_ir_routes()

    def _check_image(self, image: Path, boards: tuple[str, ...], what: str) -> None:
        """Note an image that is another board's firmware or was built from
        another protocol: both may be meant (an old build against this host, a
        test bench with a program in a board's place), neither is silent."""
        if image not in self._marks:
            try:
                self._marks[image] = read_mark(image.read_bytes())
            except OSError as exc:
                raise ScenarioError(f"{what}: cannot read: {exc.strerror or exc}") from None
        for problem in mismatch(self._marks[image], boards, SCHEMA_HASH):
            note = f"{image}: {problem}"
            if problem and note not in self.image_notes:  # an image many modules run: once
                self.image_notes.append(note)

    def _add_rf12(self, module: Module, image: Any, where: str) -> None:
        """The module's wireless board: an MCU with an RF12 part on its SPI pins
        (nominal clock; its UART1 is a debug port like the control board's)."""
        if not image.is_file():
            raise ScenarioError(f"{where}: module {module.id}: rf12 image {image} does not "
                                "exist (build it with `make -C firmware`)")
        self._check_image(image, ("rf12", "rflink"),
                          f"{where}: module {module.id}: rf12 image {image}")
        try:
            index = self.cluster.add_mcu(str(image), f"rf12{module.id}")
        except ValueError as exc:
            raise ScenarioError(f"{where}: module {module.id}: {exc}") from None
        (port, sel), (_, sdi), (_, sdo), (_, sck) = RF12_SPI_PINS
        self.cluster.attach_rf12(index, (port, sel, sdi, sdo, sck), RF12_IRQ_PIN)
        self.cluster.watch_uart(index, 1)
        self.cluster.watch_uart(index, RF12_LINK_UART)  # to the comm board's centre input
        module.rf12 = Mcu(self.cluster, index, f"rf12{module.id}")
        self._boards[index] = (module, "rf12")

    @classmethod
    def from_name(cls, name: str, seed: int | None = None, **kwargs: Any) -> Simulator:
        return cls(load_scenario(name), seed, **kwargs)

    # --- time ------------------------------------------------------------------

    @property
    def cycle(self) -> int:
        return self._cycle

    @property
    def time(self) -> float:
        return self._cycle / self.hz

    def run(self, seconds: float) -> None:
        """Advance virtual time by ``seconds``."""
        self.run_to_cycle(self._cycle + round(seconds * self.hz))

    def run_to_cycle(self, target: int) -> None:
        while self._cycle < target:
            stop = target
            if self.ir_in_c:
                stop = min(stop, self._ir_stop())
            elif self._pc_tx:
                stop = min(stop, self._pc_tx[0][1])
            for queue in self._debug_tx.values():
                if queue:
                    stop = min(stop, queue[0][0])
            radio_end = self.radio.next_end(self._cycle) if self.radio.active else None
            if radio_end is not None and radio_end > self._cycle:
                stop = min(stop, radio_end)  # deliver radio bytes on their exact cycle
            reached = self.cluster.run(max(stop, self._cycle + 1))
            self._cycle = max(reached, self._cycle)
            self._collect()

    def run_until(
        self, predicate: Callable[[Simulator], bool], timeout: float, step: float = 0.01
    ) -> None:
        """Advance until ``predicate(sim)`` holds; HexBotTimeoutError after ``timeout`` s."""
        deadline = self._cycle + round(timeout * self.hz)
        while not predicate(self):
            if self._cycle >= deadline:
                raise HexBotTimeoutError(
                    f"condition not met after {timeout} s of simulated time (t={self.time:.3f})"
                )
            self.run_to_cycle(min(deadline, self._cycle + round(step * self.hz)))

    def wait_event(self, name: str, timeout: float, **match: Any) -> dict:
        """Run until an event called ``name`` (with the given fields) appears; return it."""
        seen = len(self.events)

        def found(sim: Simulator) -> bool:
            return any(_matches(e, name, match) for e in sim.events[seen:])

        self.run_until(found, timeout)
        return next(e for e in self.events[seen:] if _matches(e, name, match))

    def _ir_stop(self) -> int:
        """Hand the core the PC's bytes that have started; the cycle to stop at
        for the next one, or for the plant's next decision."""
        stop = 1 << 62
        while self._pc_tx and self._pc_tx[0][0] <= self._cycle:
            start, end, value = self._pc_tx.popleft()
            self.cluster.ir_send_from_pc(start, end, value)
        if self._pc_tx:
            stop = self._pc_tx[0][0]
        deadline = self.plant.next_deadline(self._cycle)
        if deadline is not None:
            stop = min(stop, deadline)
        return stop

    def _send_ir_routes(self) -> None:
        """Tell the core who hears each comm board on each selector index
        (Table 3-5) in the present geometry."""
        self._geometry_version = self.plant.geometry_version
        for module in self.modules.values():
            routes: list[tuple] = []
            for y in range(8):
                channel = CHANNEL_SIDE[y]
                if channel is None:
                    routes.append(("none",))
                    continue
                if channel == CENTRE:
                    routes.append(("pc",))
                    continue
                side = to_global(channel, module.orientation)
                other_id = self.plant.module_at(neighbor(module.position, side))
                if other_id is None:
                    routes.append(("none",))
                    continue
                other = self.modules[other_id]
                need = SIDE_CHANNEL[to_body(facing(side), other.orientation)]
                routes.append(("mcu", other.comm.index, need))
            self.cluster.ir_routes(module.comm.index, routes)

    # --- the PC's IR transceiver and the debug ports ---------------------------

    def pc_write(self, data: bytes) -> None:
        """Queue bytes on the PC's IR transceiver, sent back to back at 300 baud 8N1."""
        start = max(self._pc_tx_free, self._cycle)
        for value in data:
            end = start + self._ir_frame_cycles
            self._pc_tx.append((start, end, value))
            start = end
        self._pc_tx_free = start

    def pc_read(self) -> bytes:
        """Every byte the PC's IR transceiver received and nothing could still corrupt."""
        data = bytes(self._pc_rx) + self.medium.pc_take()
        self._pc_rx.clear()
        return data

    def expect(self, pattern: bytes, timeout: float) -> bytes:
        """Run until ``pattern`` arrives at the PC; return and consume the bytes up to it."""
        buffered = self._pc_rx

        def seen(sim: Simulator) -> bool:
            buffered.extend(sim.medium.pc_take())
            return pattern in buffered

        try:
            self.run_until(seen, timeout)
        except HexBotTimeoutError as exc:
            raise HexBotTimeoutError(
                f"{pattern!r} not received by the PC in {timeout} s; got {bytes(buffered)!r}"
            ) from exc
        cut = buffered.index(pattern) + len(pattern)
        head = bytes(buffered[:cut])
        del buffered[:cut]
        return head

    def debug_write(self, module_id: int, data: bytes) -> None:
        """Bytes into the control board's UART1 debug port (4800 baud 8N1)."""
        start = max(self._debug_tx_free[module_id], self._cycle)
        for value in data:
            start += self._debug_frame_cycles
            self._debug_tx[module_id].append((start, value))
        self._debug_tx_free[module_id] = start

    def debug_read(self, module_id: int, board: str = "control") -> bytes:
        """What the board's UART1 debug port sent (``board="rf12"``: the
        wireless board's)."""
        key = module_id if board == "control" else (module_id, board)
        data = bytes(self._debug_rx[key])
        self._debug_rx[key].clear()
        return data

    def pc_radio_write(self, data: bytes) -> None:
        """Bytes out of the PC's radio (``scenario.pc_radio``), in the
        listing's packets; the first call puts the radio on the air."""
        self.radio.add_pc(self.scenario.pc_radio, self.hz).write(data, self._cycle)

    def pc_radio_read(self) -> bytes:
        """Link bytes of the packets the PC's radio heard intact."""
        pc = self.radio.add_pc(self.scenario.pc_radio, self.hz)
        data = bytes(pc.received)
        pc.received.clear()
        return data

    # --- state -----------------------------------------------------------------

    def positions(self) -> dict[int, Cell]:
        return {m: mod.position for m, mod in self.modules.items()}

    def module_at(self, cell: Cell) -> int | None:
        return self.plant.module_at(cell)

    def actuators(self, module_id: int) -> dict:
        """The boards' outputs now: joints open (J1..J6) and magnet polarity per
        side (1 positive, -1 negative, 0 off, 2 both lines on) of the control
        board, and the comm board's status LEDs lit (joint, side +, side -)."""
        module = self.modules[module_id]
        joints, magnets = decode_actuators(module.control_ports)
        return {"joints": list(joints), "magnets": list(magnets),
                **decode_leds(*self._comm_registers(module))}

    @staticmethod
    def _comm_registers(module: Module) -> tuple[dict[str, int], dict[str, int]]:
        """The comm board's DDRx and PORTx now, read from the core."""
        regs = {name: module.comm.port(name) for name in COMM_PORTS}
        return ({n: r[0] for n, r in regs.items()}, {n: r[1] for n, r in regs.items()})

    def _frame(self, mcu: Mcu, uart: int) -> Frame:
        """The USART's settings, with its bit time in cluster cycles (its
        MCU's clock: ``frame_of``)."""
        clock = getattr(self.cluster, "clock", None)  # the tests' double has none
        return frame_of(mcu.uart_config(uart), clock(mcu.index) if clock else None, self.hz)

    # --- the Air protocol of the IR medium ---------------------------------------

    def channel_at(self, module: int, cycle: int) -> int | None:
        # The selector picks a body side; the medium routes by global side.
        mod = self.modules[module]
        channel = mod.channel_at(cycle)
        if channel is None or channel == CENTRE:
            return channel
        return to_global(channel, mod.orientation)

    def channel_changes(self, module: int, after: int, until: int) -> list[tuple[int, int | None]]:
        mod = self.modules[module]
        return [(cycle, channel if channel is None or channel == CENTRE
                 else to_global(channel, mod.orientation))
                for cycle, channel in mod.channel_changes(after, until)]

    def resets(self, module: int, after: int, until: int) -> list[int]:
        return self.modules[module].resets(after, until)

    def rx_since(self, module: int, before: float) -> int | None:
        return self.modules[module].rx_since(before)

    def rx_went_off(self, module: int, after: float) -> bool:
        return self.modules[module].rx_went_off(after)

    def drop(self, module: int) -> None:
        count = getattr(self.cluster, "uart_drop", None)  # the tests' double has none
        if count is not None:
            count(self.modules[module].comm.index, 1)

    def position(self, module: int) -> Cell:
        return self.modules[module].position

    def listeners(self) -> list[int]:
        return list(self.modules)

    def rx_frame(self, module: int) -> Frame:
        return self._frame(self.modules[module].comm, 1)

    def deliver(self, module: int, value: int, framing_error: bool) -> bool:
        return bool(self.cluster.uart_put(self.modules[module].comm.index, 1, value, framing_error))

    # --- the loop body -------------------------------------------------------------

    def _emit(self, cycle: int, event: dict) -> None:
        record = {"t": round(cycle / self.hz, 6), **event}
        self.events.append(record)
        for sink in self.event_sinks:
            sink(record)

    def _collect(self) -> None:
        now = self._cycle
        keep_from = now - round(HISTORY_S * self.hz)
        changes: list[tuple[int, int, str, str, int]] = []
        # Only the MCUs the core says changed: the cost follows activity, not size.
        changed = [self._boards[i] for i in sorted(self.cluster.changed())]
        for module, board in changed:
            for cycle, port, value in self.cluster.pin_log(getattr(module, board).index):
                changes.append((cycle, module.id, board, port, value))
                if board == "comm":
                    module.comm_ports[port] = value
                    if port == SELECTOR_PORT:
                        module.record_selector(cycle, value, keep_from)
        for module, board in changed:
            if board == "comm" and hasattr(self.cluster, "resets"):
                module.record_resets(self.cluster.resets(module.comm.index), keep_from)
            if board == "comm" and hasattr(self.cluster, "uart_rx_log"):
                rx = self.cluster.uart_rx_log(module.comm.index, 1)
                if rx and not self.ir_in_c:
                    self._check_rx_log(module)
                module.record_rx(rx, keep_from)
        changes.sort(key=lambda c: (c[0], c[1], c[2]))
        for cycle, module_id, board, port, value in changes:
            if board != "control":
                continue
            ports = self.modules[module_id].control_ports
            if ports.get(port) == value:
                continue
            ports[port] = value
            joints, magnets = decode_actuators(ports)
            self.plant.set_outputs(module_id, cycle, joints, magnets)
        self.plant.step(now)
        for sink in self.pin_sinks:
            sink(changes)

        air: list[AirByte] = []
        if self.ir_in_c:
            if self.plant.geometry_version != self._geometry_version:
                self._send_ir_routes()
            self._ir_events()
            for index, start, end, value in self.cluster.ir_take_pc():
                module = self._by_comm[index]
                frame = self._frame(module.comm, 1)
                air.append(AirByte(module.id, start, end, value, frame))
                if module.rf12:  # the centre input is wired to the wireless board too
                    self._radio_link(module, [(start, end, value)], frame, to_comm=False)
        for module, board in changed:
            if board == "comm":
                if self.ir_in_c:
                    continue
                taken = self.cluster.uart_take(module.comm.index, 1)
                if taken:
                    frame = self._frame(module.comm, 1)
                    air.extend(AirByte(module.id, s, e, b, frame) for s, e, b in taken)
                    if module.rf12:
                        self._radio_link(module, taken, frame, to_comm=False)
            else:
                mcu = module.control if board == "control" else module.rf12
                debug = self.cluster.uart_take(mcu.index, 1)
                if debug:
                    self._debug_received(module, debug, board)
                if board == "rf12":
                    taken = self.cluster.uart_take(mcu.index, RF12_LINK_UART)
                    if taken:
                        self._radio_link(module, taken, self._frame(mcu, RF12_LINK_UART),
                                         to_comm=True)
        while self._pc_tx and self._pc_tx[0][1] <= now:
            start, end, value = self._pc_tx.popleft()
            air.append(AirByte(PC, start, end, value, PC_FRAME))
        air.sort(key=lambda b: (b.end, b.start, str(b.sender)))
        for byte in air:
            if self.ir_in_c:
                self.medium.transmit_to(byte, PC)  # the core routed it to the centre
            else:
                self.medium.transmit(byte)
        self.medium.settle(now)
        self.radio.step(now)

        for module_id, queue in self._debug_tx.items():
            while queue and queue[0][0] <= now:
                _, value = queue.popleft()
                self._debug_send(self.modules[module_id], value)

    def _check_rx_log(self, module: Module) -> None:
        """The core keeps the last 64 changes of a receiver between two
        looks (``uart_rx_log``); firmware that switches RXEN more often than
        that within one run loses the older ones, and the Python medium
        could then judge a byte by a wrong state: say so (the core's own
        medium keeps every change it needs)."""
        lost = int(self.cluster.uart_config(module.comm.index, 1).get("rx_log_lost", 0))
        if lost > module.rx_log_lost:
            self._emit(self._cycle, {
                "event": "sim-error", "module": module.id,
                "reason": f"comm UART1 receiver log overflowed: {lost - module.rx_log_lost} "
                          "RXEN changes lost; bytes it received around them may be judged "
                          "by a wrong receiver state"})
            module.rx_log_lost = lost

    def _radio_link(self, module: Module, taken: list[tuple[int, int, int]], frame: Frame,
                    to_comm: bool) -> None:
        """The wire between the wireless board's USART0 and the comm board's
        IR multiplexer (protocol/pins.py RF12_LINK_*): it carries bytes only
        while the selector is on the centre. A byte sent at another rate or
        format arrives as the receiver reads it (``Frame.read_by``)."""
        rf12 = module.rf12
        assert rf12 is not None
        target, uart = (module.comm, 1) if to_comm else (rf12, RF12_LINK_UART)
        receiver = self._frame(target, uart)
        for _start, end, value in taken:
            if module.channel_at(end) != CENTRE:
                continue
            read = frame.read_by(receiver, value, self._garbage)
            if read is not None:
                self.cluster.uart_put(target.index, uart, *read)

    def _ir_events(self) -> None:
        """The core medium's events, as the Python medium words them."""
        def who(index: int) -> int | str:
            return PC if index < 0 else self._by_comm[index].id

        for name, end, sender, receiver, value, others in self.cluster.ir_events():
            event: dict[str, Any] = {"event": name, "from": who(sender),
                                     "to": who(receiver), "byte": value}
            if name == "ir-collision":
                event["other"] = sorted((who(o) for o in others), key=str)
            elif name == "ir-dropped":
                event["reason"] = "receiver off (RXEN) or overrun"
            else:
                sent = PC_FRAME if sender < 0 else self.rx_frame(who(sender))  # type: ignore[arg-type]
                event["reason"] = f"sender {sent}, receiver {self.rx_frame(who(receiver))}"  # type: ignore[arg-type]
            self._emit(end, event)

    def _debug_received(self, module: Module, taken: list[tuple[int, int, int]],
                        board: str) -> None:
        mcu = module.control if board == "control" else module.rf12
        frame = self._frame(mcu, 1)
        rx = self._debug_rx[module.id if board == "control" else (module.id, board)]
        for _start, end, value in taken:
            if not frame.matches(DEBUG_FRAME):
                self._emit(end, {"event": "debug-garbled", "module": module.id,
                                 "reason": f"control UART1 at {frame}, port at {DEBUG_FRAME}"})
            read = frame.read_by(DEBUG_FRAME, value, self._garbage)
            if read is not None:
                rx.append(read[0])

    def _debug_send(self, module: Module, value: int) -> None:
        frame = self._frame(module.control, 1)
        read = DEBUG_FRAME.read_by(frame, value, self._garbage)
        if read is None:
            return  # the board's UART found no start bit in it
        value, framing_error = read
        if not self.cluster.uart_put(module.control.index, 1, value, framing_error):
            self._emit(self._cycle, {"event": "debug-dropped", "module": module.id,
                                     "byte": value, "reason": "receiver off (RXEN) or overrun"})

    def trace(self) -> dict:
        """Everything observable, for comparing runs."""
        return {
            "cycle": self._cycle,
            "events": list(self.events),
            "positions": {str(k): list(v) for k, v in self.positions().items()},
            "orientations": {str(k): m.orientation for k, m in self.modules.items()},
        }


def _matches(event: dict, name: str, match: dict) -> bool:
    return event.get("event") == name and all(event.get(k) == v for k, v in match.items())
