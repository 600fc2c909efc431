"""VCD trace of actuator, selector and LED pins, for GTKWave.

One scope per module: ``sel`` (the selector index Y, 3 bits), the joints
``j1..j6`` (1 = solenoid energised), the magnet lines ``s1p..s6p`` and
``s1n..s6n``, and the comm board's status LEDs (active low, as on the pins).
Time is in microseconds of simulated time. No date in the header, so two
runs of one scenario give byte-identical files.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import TextIO

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
    code: str
    name: str
    width: int
    board: str
    pin: Pin | None  # None: the selector vector
    value: int = 0


def _code(index: int) -> str:
    chars = [chr(33 + index % 94)]
    index //= 94
    while index:
        chars.append(chr(33 + index % 94))
        index //= 94
    return "".join(chars)


@dataclass
class VcdWriter:
    sim: Simulator
    out: TextIO
    signals: dict[int, list[_Signal]] = field(default_factory=dict)
    _ports: dict[tuple[int, str], dict[str, int]] = field(default_factory=dict)
    _last_time: int = -1

    def __post_init__(self) -> None:
        index = 0
        for module_id in sorted(self.sim.modules):
            sigs = [_Signal(_code(index), "sel", 3, "comm", None)]
            index += 1
            named: list[tuple[str, str, Pin]] = []
            named += [(f"j{i}", "control", p) for i, p in enumerate(JOINT_PINS, 1)]
            named += [(f"s{i}p", "control", p) for i, p in enumerate(MAGNET_POS_PINS, 1)]
            named += [(f"s{i}n", "control", p) for i, p in enumerate(MAGNET_NEG_PINS, 1)]
            named += [(name, "comm", p) for name, p in LED_PINS.items()]
            for name, board, pin in named:
                sigs.append(_Signal(_code(index), name, 1, board, pin))
                index += 1
            self.signals[module_id] = sigs
            self._ports[(module_id, "comm")] = {}
            self._ports[(module_id, "control")] = {}
        self._header()
        self.sim.pin_sinks.append(self.on_changes)

    def _header(self) -> None:
        w = self.out.write
        w("$version hexbot hil_sim $end\n$timescale 1us $end\n")
        w(f"$scope module {self.sim.scenario.name.replace('-', '_')} $end\n")
        for module_id, sigs in self.signals.items():
            w(f"$scope module module_{module_id} $end\n")
            for s in sigs:
                w(f"$var wire {s.width} {s.code} {s.name} $end\n")
            w("$upscope $end\n")
        w("$upscope $end\n$enddefinitions $end\n#0\n$dumpvars\n")
        for sigs in self.signals.values():
            for s in sigs:
                w(self._value(s))
        w("$end\n")
        self._last_time = 0

    @staticmethod
    def _value(s: _Signal) -> str:
        if s.width == 1:
            return f"{s.value}{s.code}\n"
        return f"b{s.value:b} {s.code}\n"

    def on_changes(self, changes: list[tuple[int, int, str, str, int]]) -> None:
        for cycle, module_id, board, port, value in changes:
            ports = self._ports[(module_id, board)]
            ports[port] = value
            lines = []
            for s in self.signals[module_id]:
                if s.board != board:
                    continue
                if s.pin is None:
                    new = selector_index(ports.get("A", 0))
                elif s.pin[0] != port:
                    continue
                else:
                    new = value >> s.pin[1] & 1
                if new != s.value:
                    s.value = new
                    lines.append(self._value(s))
            if lines:
                t = round(cycle * 1_000_000 / self.sim.hz)
                if t != self._last_time:
                    self.out.write(f"#{t}\n")
                    self._last_time = t
                self.out.write("".join(lines))

    def close(self) -> None:
        if self.on_changes in self.sim.pin_sinks:
            self.sim.pin_sinks.remove(self.on_changes)
        end = round(self.sim.cycle * 1_000_000 / self.sim.hz)
        if end > self._last_time:
            self.out.write(f"#{end}\n")  # so viewers show the trace up to the end
        self.out.flush()
