"""One HexBot module: its two MCUs (plus an optional wireless board) and the
board pin maps the simulator reads.

A module is a communication MCU and a control MCU joined UART0 to UART0, with
its id on the control board's DIP switches (port C). It reads actuators,
LEDs and the IR selector at the pins of :mod:`hexbot.protocol.pins`, the
same map the firmware is built from (Tables 3-3, 3-4, 3-5).
"""

from __future__ import annotations

import bisect
from dataclasses import dataclass, field
from typing import Any

from hexbot.protocol.pins import (  # noqa: F401 - the simulator's view of the boards
    COMM_PORTS,
    CONTROL_PORTS,
    JOINT_PINS,
    LED_JOINT_PINS,
    LED_PINS,
    LED_SIDE_NEG_PINS,
    LED_SIDE_POS_PINS,
    MAGNET_NEG_PINS,
    MAGNET_POS_PINS,
    SELECTOR_PINS,
    Pin,
)

from .geometry import CHANNEL_SIDE, Cell
from .plant import NEG, OFF, POS, SHORT, Body, Joints, Magnets


def _bit(ports: dict[str, int], pin: Pin) -> bool:
    return bool(ports.get(pin[0], 0) >> pin[1] & 1)


def decode_actuators(ports: dict[str, int]) -> tuple[Joints, Magnets]:
    """Control PORTA/B/D output values -> (joints open?, magnet polarity) per index 1..6."""
    joints = tuple(_bit(ports, pin) for pin in JOINT_PINS)
    magnets = []
    for pos_pin, neg_pin in zip(MAGNET_POS_PINS, MAGNET_NEG_PINS, strict=True):
        pos, neg = _bit(ports, pos_pin), _bit(ports, neg_pin)
        magnets.append(SHORT if pos and neg else POS if pos else NEG if neg else OFF)
    return joints, tuple(magnets)  # type: ignore[return-value]


def decode_leds(ddr: dict[str, int], ports: dict[str, int]) -> dict[str, list[int]]:
    """Comm DDRx and PORTx -> which status LEDs are lit (1) per index 1..6.
    The LEDs are active low: lit is an output pin driven to 0 (after reset
    every pin is an input and every LED is dark)."""
    def lit(pins: tuple[Pin, ...]) -> list[int]:
        return [int(_bit(ddr, pin) and not _bit(ports, pin)) for pin in pins]
    return {"led_joints": lit(LED_JOINT_PINS), "led_pos": lit(LED_SIDE_POS_PINS),
            "led_neg": lit(LED_SIDE_NEG_PINS)}


def selector_index(porta: int) -> int:
    """Y = 4C + 2B + A from the comm board's PORTA."""
    a, b, c = (porta >> bit & 1 for _, bit in SELECTOR_PINS)
    return 4 * c + 2 * b + a


@dataclass
class Mcu:
    """A handle on one simulated MCU of the cluster."""

    cluster: Any
    index: int
    name: str

    def port(self, name: str) -> tuple[int, int, int]:
        """(DDRx, PORTx, PINx)."""
        return self.cluster.port(self.index, name)

    @property
    def state(self) -> str:
        return self.cluster.state(self.index)

    def uart_config(self, uart: int) -> dict:
        return self.cluster.uart_config(self.index, uart)


@dataclass
class Module:
    id: int
    comm: Mcu
    control: Mcu
    body: Body
    rf12: Mcu | None = None  # the wireless board, if the module has one
    control_ports: dict[str, int] = field(default_factory=lambda: dict.fromkeys(CONTROL_PORTS, 0))
    comm_ports: dict[str, int] = field(default_factory=lambda: dict.fromkeys(COMM_PORTS, 0))
    # Selector history: parallel lists of change cycles and channel (side/0/None).
    _sel_cycles: list[int] = field(default_factory=lambda: [0])
    _sel_channels: list[int | None] = field(default_factory=lambda: [CHANNEL_SIDE[0]])
    _resets: list[int] = field(default_factory=list)  # comm board resets, recent ones
    #: the comm board's UART1 receiver: (cycle, on) of its changes, the first
    #: the state before the rest; None: not known (the tests' double), on
    _rx: list[tuple[int, bool]] | None = None
    rx_log_lost: int = 0  # of those changes, lost by the core before they were taken

    @property
    def position(self) -> Cell:
        return self.body.cell

    @property
    def orientation(self) -> int:
        return self.body.orientation

    @property
    def fixed(self) -> bool:
        return self.body.fixed

    @property
    def channel(self) -> int | None:
        """Side 1..6 the IR selector listens on now, 0 for centre, None for Y7."""
        return self._sel_channels[-1]

    def record_selector(self, cycle: int, porta: int, keep_from: int) -> None:
        channel = CHANNEL_SIDE[selector_index(porta)]
        if channel != self._sel_channels[-1]:
            self._sel_cycles.append(cycle)
            self._sel_channels.append(channel)
        # Forget history nobody can ask about any more (bytes older than keep_from).
        drop = bisect.bisect_right(self._sel_cycles, keep_from) - 1
        if drop > 0:
            del self._sel_cycles[:drop]
            del self._sel_channels[:drop]

    def channel_at(self, cycle: int) -> int | None:
        """The channel at ``cycle``, a change logged on that very cycle
        included: a selector write on a byte's first cycle sends it on the
        new side (docs/simulator.md, the IR medium; the core does the same)."""
        at = bisect.bisect_right(self._sel_cycles, cycle) - 1
        return self._sel_channels[max(at, 0)]

    def channel_changes(self, after: int, until: int) -> list[tuple[int, int | None]]:
        """(cycle, channel) of each selector change in (after, until]."""
        lo = bisect.bisect_right(self._sel_cycles, after)
        hi = bisect.bisect_right(self._sel_cycles, until)
        return list(zip(self._sel_cycles[lo:hi], self._sel_channels[lo:hi], strict=True))

    def record_resets(self, cycles: list[int], keep_from: int) -> None:
        """The comm board reset at ``cycles`` (its IR byte on the air stops)."""
        self._resets = [c for c in self._resets if c >= keep_from] + cycles

    def resets(self, after: int, until: int) -> list[int]:
        return [c for c in self._resets if after < c <= until]

    def record_rx(self, changes: list[tuple[int, bool]], keep_from: int) -> None:
        """The comm board's UART1 receiver came on or went off at these
        cycles (``Cluster.uart_rx_log``: RXEN, resets); it boots off."""
        if self._rx is None:
            self._rx = [(0, False)]
        if not changes:
            return
        rx = self._rx + [(int(c), bool(on)) for c, on in changes]
        # fold what nobody can ask about any more into the first entry
        first = max(0, bisect.bisect_right(rx, (keep_from, True)) - 1)
        self._rx = rx[first:]

    def rx_since(self, before: float) -> int | None:
        """The cycle the receiver came on last by its changes before
        ``before``, if it is on then; None: off."""
        if self._rx is None:
            return 0
        return receiver_on_since(self._rx, before)

    def rx_went_off(self, after: float) -> bool:
        """Whether the receiver went off at or after ``after`` by the
        changes recorded so far."""
        for cycle, state in reversed(self._rx or ()):
            if cycle < after:
                break
            if not state:
                return True
        return False


def receiver_on_since(changes, before: float, on: bool = False) -> int | None:
    """Folded receiver changes ``(cycle, on)``, in cycle order: the cycle the
    receiver came on last before ``before`` if it is on then (0: on from
    the start, as ``on`` says); None: off."""
    since = 0
    for cycle, state in changes:
        if cycle >= before:
            break
        if state and not on:
            since = cycle
        on = state
    return since if on else None
