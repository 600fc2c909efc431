"""The 433 MHz air between RF12 radios: who hears which byte, and intact or not.

Each wireless board's RF12 is a part in the C core (``hil_sim/core/rf12_part.c``):
it decodes the command words the firmware clocks in (band, frequency, data
rate, transmitter and receiver on/off), shifts bytes out at the data rate and
logs them in cluster cycles. The core returns to Python at the first quantum
boundary after a byte left the air; :meth:`RadioMedium.step` then routes it:

- a receiver hears a byte only if its receiver is on, it is on the same band,
  frequency word and data rate as the byte was sent on, and it lies within
  ``range_cells`` lattice steps of the transmitter (no fading inside, nothing
  beyond);
- two transmitters on one channel whose bytes overlap in time, both in range
  of a receiver, garble the byte there: it arrives as a seeded random value
  (no capture effect);
- a byte cut short (transmitter switched off mid-byte) is not delivered but
  still occupies the air.

The PC's radio (:class:`PcRadio`, a ``radio=1`` port) is one more radio on
the air, modelled in Python: it sends the host's bytes in the listing's
packets (``protocol/radio.py``) and gives back the link bytes of the
packets it hears with a good sum.

The simulator stops the cluster at the end of every byte on the air
(:meth:`RadioMedium.next_end`), so a byte reaches its receivers on the cycle
its last bit ends; by then every byte that overlaps it has started and is
known here, so collisions are decided exactly. Only the first byte of a
transmission can be late (by less than a quantum): its carrier becomes known
at the boundary after the transmitter was switched on. The same seed gives
the same trace.
"""

from __future__ import annotations

import random
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from hexbot.protocol import radio as rf
from hexbot.protocol.lattice import distance
from hexbot.protocol.timing import BAUD_IR, BYTE_BITS

from .geometry import Cell

Channel = tuple[int, int, int]  # band, frequency word, data rate byte
PC_RADIO = 0  # the PC radio's sender id on the air (module ids are 1..255)


@dataclass(frozen=True)
class RadioByte:
    """One byte on the air, in cluster cycles."""

    sender: int  # module id
    start: int
    end: int
    value: int
    cut: bool
    channel: Channel

    def overlaps(self, other: RadioByte) -> bool:
        return self.start < other.end and other.start < self.end


class PcRadio:
    """The PC's radio: an RF12 on the listing's channel at ``cell``, fed by
    the host. It sends the bytes written to it in packets of at most
    ``LINK_BYTES`` link bytes, and no faster than the wireless board can pass
    them on to its comm board at the IR rate (as a USB radio with flow
    control would), so the bridge's 31-byte ring cannot overflow."""

    def __init__(self, cell: Any, hz: int) -> None:
        self.cell = cell
        self.channel: Channel = rf.channel()
        self._div = rf.rate_divider()
        self._hz = hz
        self._ir_byte = round(BYTE_BITS * hz / BAUD_IR)
        self.tx: deque[tuple[int, int, int]] = deque()  # (start, end, byte)
        self._free = 0
        self.rx = rf.PacketReceiver(gap=2 * self._byte_end(0, 0))
        self.received = bytearray()

    def _byte_end(self, origin: int, k: int) -> int:
        """End of byte k of a transmission started at ``origin`` (the chip's
        arithmetic: 8 bits at 10 MHz / 29 / (R + 1))."""
        return origin + (k + 1) * 8 * self._hz * self._div // rf.XTAL_HZ

    def write(self, data: bytes, now: int) -> None:
        origin = max(self._free, now)
        for payload in rf.payloads(data):
            air = rf.packet(payload)
            start = origin
            for k, value in enumerate(air):
                end = self._byte_end(origin, k)
                self.tx.append((start, end, value))
                start = end
            # the next packet waits for the bridge to pass this one on
            origin = max(start, origin + payload[0] * self._ir_byte)
        self._free = origin

    def transmitting(self, cycle: int) -> bool:
        return bool(self.tx) and self.tx[0][0] <= cycle

    def carrier(self, now: int) -> RadioByte | None:
        if self.tx and self.tx[0][0] <= now < self.tx[0][1]:
            start, end, value = self.tx[0]
            return RadioByte(PC_RADIO, start, end, value, False, self.channel)
        return None

    def next_end(self) -> int | None:
        return self.tx[0][1] if self.tx else None

    def take(self, now: int) -> list[RadioByte]:
        out = []
        while self.tx and self.tx[0][1] <= now:
            start, end, value = self.tx.popleft()
            out.append(RadioByte(PC_RADIO, start, end, value, False, self.channel))
        return out

    def hear(self, end: int, value: int) -> None:
        self.received += self.rx.push(end, value)


class RadioMedium:
    """Routes the RF12 bytes of the modules in ``radios`` (module id -> MCU
    index of its wireless board) through the air, deterministically."""

    def __init__(
        self,
        cluster: Any,
        radios: dict[int, int],
        position: Callable[[int], Cell],
        range_cells: int,
        seed: int,
        emit: Callable[[int, dict], None],
    ) -> None:
        self.cluster = cluster
        self.radios = dict(sorted(radios.items()))
        self.position = position
        self.range_cells = range_cells
        self.emit = emit
        self._rng = random.Random(seed ^ 0x0F5C)
        self._recent: list[RadioByte] = []  # bytes that may still overlap new ones
        self._colliding: set[int] = set()  # receivers inside a collision now
        self._routed: dict[int, int] = {}  # sender -> start of its last routed byte
        self.delivered = 0
        self.garbled = 0
        self.pc: PcRadio | None = None

    def add_pc(self, cell: Any, hz: int) -> PcRadio:
        """The PC's radio at ``cell`` (added on first use: without it the air
        and its random sequence are as before)."""
        if self.pc is None:
            self.pc = PcRadio(cell, hz)
        return self.pc

    @property
    def active(self) -> bool:
        return bool(self.radios) or self.pc is not None

    def _cell(self, sender: int) -> Cell:
        return self.pc.cell if sender == PC_RADIO and self.pc else self.position(sender)

    def in_range(self, a: int, b: int) -> bool:
        return distance(self._cell(a), self._cell(b)) <= self.range_cells

    def _carriers(self, now: int) -> list[RadioByte]:
        on_air = [RadioByte(m, s, e, v, c, ch) for m, i in self.radios.items()
                  if (rec := self.cluster.radio_carrier(i)) is not None
                  for s, e, v, c, ch in [rec]]
        if self.pc is not None and (byte := self.pc.carrier(now)) is not None:
            on_air.append(byte)
        return on_air

    def next_end(self, now: int) -> int | None:
        """Cluster cycle the next byte on the air ends (None: the air is quiet)."""
        pc_end = self.pc.next_end() if self.pc is not None else None
        return min([b.end for b in self._carriers(now)] + ([pc_end] if pc_end else []),
                   default=None)

    def step(self, now: int) -> None:
        """Route every byte that left the air by cluster cycle ``now``."""
        carriers = self._carriers(now)
        ended: list[RadioByte] = []
        for module, index in self.radios.items():
            for start, end, value, cut, channel in self.cluster.radio_take(index):
                ended.append(RadioByte(module, start, end, value, cut, channel))
        if self.pc is not None:
            ended += self.pc.take(now)
        # a byte ending exactly now may not be logged yet (its MCU stopped
        # just short of the cycle its timer fires on): it is over all the same
        ended += [b for b in carriers if b.end <= now]
        on_air = [b for b in carriers if b.end > now]
        ended = [b for b in ended if b.start > self._routed.get(b.sender, -1)]
        if not ended:
            return
        ended.sort(key=lambda b: (b.end, b.start, b.sender))
        for byte in ended:
            self._routed[byte.sender] = max(byte.start, self._routed.get(byte.sender, -1))
        self._recent.extend(ended)
        states = {m: self.cluster.radio_state(i) for m, i in self.radios.items()}
        for byte in ended:
            if not byte.cut:
                self._route(byte, states, on_air)
        # a byte that ends later is on the air now or starts after now
        horizon = min((b.start for b in on_air), default=now)
        self._recent = [b for b in self._recent if b.end > horizon]

    def _route(self, byte: RadioByte, states: dict[int, dict], on_air: list[RadioByte]) -> None:
        receivers = list(self.radios.items())
        if self.pc is not None:
            receivers.append((PC_RADIO, -1))
            states = {**states, PC_RADIO: {"receiving": not self.pc.transmitting(byte.end),
                                           "channel": self.pc.channel}}
        for receiver, index in receivers:
            state = states[receiver]
            if (receiver == byte.sender or not state["receiving"]
                    or tuple(state["channel"]) != byte.channel
                    or not self.in_range(byte.sender, receiver)):
                continue
            others = sorted({o.sender for o in (*self._recent, *on_air)
                             if o.sender not in (byte.sender, receiver)
                             and o.channel == byte.channel and o.overlaps(byte)
                             and self.in_range(o.sender, receiver)})
            value = byte.value
            if others:
                value = self._rng.randrange(256)
                self.garbled += 1
                if receiver not in self._colliding:
                    self._colliding.add(receiver)
                    self.emit(byte.end, {"event": "radio-collision", "module": receiver,
                                         "senders": [byte.sender, *others]})
            else:
                self._colliding.discard(receiver)
            self.delivered += 1
            if receiver == PC_RADIO:
                self.pc.hear(byte.end, value)  # type: ignore[union-attr]
            else:
                self.cluster.radio_deliver(index, byte.end, value)
