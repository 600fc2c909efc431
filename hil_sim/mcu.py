"""Thin Python conveniences over the C core ``hexbot.hil_sim._avr``.

The Cluster (C) owns all simulation state; :class:`Mcu` is a handle naming
one MCU in it, with time given in seconds as well as cycles.  The bus, plant
and scenario code may use the raw Cluster API directly (docs/simulator-core.md).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from hexbot.hil_sim._avr import Cluster, raw_simavr_run
from hexbot.protocol.timing import F_CPU

__all__ = ["Cluster", "Mcu", "UartByte", "cycles_to_seconds", "raw_simavr_run", "seconds_to_cycles"]

DEFAULT_FREQUENCY = F_CPU


def cycles_to_seconds(cycles: int, frequency: int = DEFAULT_FREQUENCY) -> float:
    return cycles / frequency


def seconds_to_cycles(seconds: float, frequency: int = DEFAULT_FREQUENCY) -> int:
    """Nearest whole cycle; negative times are an error, not a wrap-around."""
    if seconds < 0:
        raise ValueError(f"negative time {seconds!r} s")
    return round(seconds * frequency)


@dataclass(frozen=True)
class UartByte:
    """One frame as it left a USART: first start-bit edge to end of stop bit."""

    start: int
    end: int
    value: int


@dataclass(frozen=True)
class Mcu:
    """Handle on MCU ``index`` of ``cluster``."""

    cluster: Cluster
    index: int

    @classmethod
    def load(cls, cluster: Cluster, elf: str | Path, name: str) -> Mcu:
        return cls(cluster, cluster.add_mcu(str(elf), name))

    @property
    def name(self) -> str:
        return self.cluster.name(self.index)

    @property
    def state(self) -> str:
        return self.cluster.state(self.index)

    @property
    def cycle(self) -> int:
        return self.cluster.mcu_cycle(self.index)

    @property
    def time(self) -> float:
        return cycles_to_seconds(self.cycle, self.cluster.frequency)

    def port(self, name: str) -> tuple[int, int, int]:
        """(DDRx, PORTx, PINx)."""
        return self.cluster.port(self.index, name)

    def output(self, name: str) -> int:
        """Levels the MCU drives: PORTx bits whose DDRx bit is set."""
        ddr, port, _ = self.port(name)
        return port & ddr

    def set_input(self, name: str, mask: int, value: int) -> None:
        self.cluster.set_input(self.index, name, mask, value)

    def watch_uart(self, uart: int) -> None:
        self.cluster.watch_uart(self.index, uart)

    def uart_take(self, uart: int) -> list[UartByte]:
        return [UartByte(*t) for t in self.cluster.uart_take(self.index, uart)]

    def uart_put(self, uart: int, byte: int, framing_error: bool = False) -> bool:
        return self.cluster.uart_put(self.index, uart, byte, framing_error)

    def uart_config(self, uart: int) -> dict:
        return self.cluster.uart_config(self.index, uart)

    def pin_log(self) -> list[tuple[int, str, int]]:
        return self.cluster.pin_log(self.index)

    def reset(self) -> None:
        self.cluster.reset(self.index)

    def last_error(self) -> str:
        return self.cluster.last_error(self.index)
