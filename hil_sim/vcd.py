"""VCD trace of actuator, selector and LED pins, for GTKWave (written by pyvcd).

One scope per module: ``sel`` (the selector index Y, 3 bits), the joints
``j1..j6`` (1 = solenoid energised), the magnet lines ``s1p..s6p`` and
``s1n..s6n``, and the comm board's status LEDs (active low, as on the pins).
Time is in microseconds of simulated time. No date in the header, so two
runs of one scenario give byte-identical files.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, TextIO

from vcd import VCDWriter

from hexbot.protocol.pins import SELECTOR_PORT

from .module import (
    JOINT_PINS,
    LED_PINS,
    MAGNET_NEG_PINS,
    MAGNET_POS_PINS,
    Pin,
    selector_index,
)
from .simulator import Simulator


@dataclass
class _Signal:
    var: Any  # a pyvcd variable
    board: str
    pin: Pin | None  # None: the selector vector


@dataclass
class VcdWriter:
    sim: Simulator
    out: TextIO
    signals: dict[int, list[_Signal]] = field(default_factory=dict)
    _ports: dict[tuple[int, str], dict[str, int]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        # date="" leaves the date out: the file depends on the run alone
        self._vcd = VCDWriter(self.out, timescale="1 us", date="", version="hexbot hil_sim")
        top = self.sim.scenario.name.replace("-", "_")
        for module_id in sorted(self.sim.modules):
            scope = (top, f"module_{module_id}")
            named: list[tuple[str, str, Pin | None]] = [("sel", "comm", None)]
            named += [(f"j{i}", "control", p) for i, p in enumerate(JOINT_PINS, 1)]
            named += [(f"s{i}p", "control", p) for i, p in enumerate(MAGNET_POS_PINS, 1)]
            named += [(f"s{i}n", "control", p) for i, p in enumerate(MAGNET_NEG_PINS, 1)]
            named += [(name, "comm", p) for name, p in LED_PINS.items()]
            self.signals[module_id] = [
                _Signal(self._vcd.register_var(scope, name, "wire", 1 if pin else 3, init=0),
                        board, pin)
                for name, board, pin in named
            ]
            self._ports[(module_id, "comm")] = {}
            self._ports[(module_id, "control")] = {}
        self._vcd.flush()  # the header and the initial values, before any change
        self.sim.pin_sinks.append(self.on_changes)

    def on_changes(self, changes: list[tuple[int, int, str, str, int]]) -> None:
        for cycle, module_id, board, port, value in changes:
            ports = self._ports.setdefault((module_id, board), {})  # also rf12
            ports[port] = value
            t = round(cycle * 1_000_000 / self.sim.hz)
            for s in self.signals[module_id]:
                if s.board != board:
                    continue
                if s.pin is None:
                    new = selector_index(ports.get(SELECTOR_PORT, 0))
                elif s.pin[0] != port:
                    continue
                else:
                    new = value >> s.pin[1] & 1
                self._vcd.change(s.var, t, new)  # written only if the value changed

    def close(self) -> None:
        if self.on_changes in self.sim.pin_sinks:
            self.sim.pin_sinks.remove(self.on_changes)
        # the end time, so that viewers show the trace up to the end
        self._vcd.close(round(self.sim.cycle * 1_000_000 / self.sim.hz))
        self.out.flush()
