"""The IR medium: routes bytes between communication boards and the PC.

Each communication board's UART1 drives one of seven IR transceivers, chosen
by its channel selector (Table 3-5). The medium decides, byte by byte:

* A byte sent on side ``s`` (selector at the byte's *start*) reaches the module
  in the neighbouring cell if that module's selector is on the facing side
  ``s + 3`` while the byte is on the air. Nobody there, or a neighbour
  looking elsewhere all along: the byte is lost in the air.
* A byte sent on the centre channel reaches the PC. The PC's bytes reach every
  module whose selector is on the centre while the byte is on the air.
* **Cut bytes.** The communication board multiplexes one UART over its seven
  transceivers: when the sender's selector leaves the byte's channel before
  the byte ended (firmware that switches the mux after writing UDR, before
  TXC), the rest of the byte leaves by another transceiver; when the sender
  resets, its USART stops. A receiver whose selector is elsewhere for part
  of the byte sees only the rest. Where it does not see the byte its line
  idles high, and it gets what its UART samples (``ir_line.py``, the
  sampler of ``uart_line.py``): bits after the cut read 1 and so does the
  stop bit, a wrong byte *without* framing error (0x00 cut in data bit 4:
  0xF0); a cut in the start bit is a glitch: nothing. Only the part
  before the stop bit counts (from there on the line is high either way):
  a byte seen up to its stop bit arrives as before, and selector moves and
  resets from the stop bit on change nothing. The channel is the selector
  at the start bit, a write on that very cycle included (the write wins).
* **The receiver's own USART.** A receiver that was off for part of a
  byte (its comm board reset, or the firmware cleared RXEN) lost what it
  had of it: it reads the line from where it came on last and looks for a
  falling edge there; a line already low when it comes on is no start bit
  (a reset in data bit 1 of 0xF0 gives nothing, one in data bit 0 of 0x5A
  resynchronises on bit 2's edge and reads 0xEB). Off at the byte's
  horizon, the middle of its stop bit by the sender's bit time, it does
  not get the byte (``ir-dropped``, counted in its USART's ``rx_dropped``
  as the core counts it: ``Air.drop``). Its changes count up to that
  horizon (``Air.rx_since``). On there, the byte is its own (the core
  puts it into the receive buffer there); if the receiver goes off after
  the horizon, before this medium hands the byte over (at the boundary
  after the byte's end), the byte went with the buffer it would have been
  in (RXEN cleared or a reset flush it): lost, no event, not counted, as
  in the core (``Air.rx_went_off``), instead of landing in the buffer of
  the rebooted firmware.
* Two bytes from different senders that overlap in time at one receiver
  collide: the IR line idles high and a lit LED pulls it low, so the line is
  the AND of the two lines, each at its real start. The receiver gets what
  its UART samples of it, from the first start bit on (0xF0 and 0x3C three
  bits later read 0xE0), with the framing error flag set: a broken frame as
  before (the flag stays even where the stop bit samples high, as a real
  receiver's edge detection and 3-sample vote may see the second start
  edge). Bytes that started on the same cycle, whole, give the bitwise AND
  of the two as before (the sampling reads the same). A module receiver
  learns of the collision when the second byte ends, after the first was
  handed over: it gets the first as read alone and the collision as a
  second, broken byte. The PC's receiver waits until no overlapping byte
  can still come (one frame time) and gets one broken byte for the two.
* A receiver whose baud rate differs by more than ``BAUD_TOLERANCE``
  (protocol/timing.py, 4.5 %) from the sender's reads what its UART samples
  of the sender's levels (``uart_line.first_byte``): a wrong byte, often
  without a framing error, or nothing when the start bit is over before it
  looks; a byte it still reads right keeps a framing error, whole or cut
  (``uart_line.out_of_range``), so the result depends only on its
  samples. One whose word format (data bits, parity) differs gets a
  garbage byte from the seeded generator with the framing error flag.
* Fault injection per directed link: each data bit flips with probability
  ``bit_error_rate``; the whole byte vanishes with probability ``byte_loss``.
  Besides: a framing error (``framing_error_rate``: the stop bit reads low,
  the receiving USART flags the byte and our firmware drops it); a spurious
  start bit on the idle line after a byte (``spurious_byte_rate``: the
  receiver reads one more byte, mostly ones with the noise pulse's zeros);
  a burst (``burst_rate`` per byte: the next ``BURST_BITS`` bit times are
  noise, each bit right or wrong by chance, across byte boundaries, the
  stop bit included). One ``random.Random(seed)`` serves the medium, drawn
  in a fixed order, so a run is reproducible; the extended faults draw only
  when set, so older seeds keep their sequences.

The medium knows nothing of simavr: it talks to the world through the small
``Air`` protocol below, which the simulator implements.
"""

from __future__ import annotations

import random
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Protocol

from hexbot.protocol.timing import BAUD_IR, BAUD_TOLERANCE

from . import ir_line
from .geometry import CENTRE, Cell, facing, neighbor
from .ir_line import Part, Span, intersect, spans_where, stop_bit
from .scenario import PC, Faults
from .uart_line import LineSettings, first_byte, out_of_range

Endpoint = int | str  # module id or "pc"
#: Length of a noise burst in bit times (start, 8 data and stop bit make a
#: byte): 40 ms at 300 baud, the flicker of a lamp or a passing hand.
BURST_BITS = 12


@dataclass(frozen=True)
class Frame:
    """The line settings of one USART, as far as the medium cares.

    ``bit_cycles``: its bit time in cluster cycles when the simulator knows
    the part's clock (``simulator.frame_of``): its own cycles per bit times
    nominal over its clock, not rounded, the same double as the core's
    ``m162_bit_time``. Without it (the PC, tests' frames) the bit time is
    ``hz / baud`` for a receiver and the byte's length over its bits for a
    sender (:attr:`AirByte.bit`)."""

    baud: float
    data_bits: int = 8
    parity: str = "N"
    stop_bits: int = 1
    bit_cycles: float | None = field(default=None, repr=False)

    def same_word(self, other: Frame) -> bool:
        """Data bits and parity alike (what a receiver checks of the format)."""
        return (self.data_bits, self.parity) == (other.data_bits, other.parity)

    def line(self) -> LineSettings:
        return LineSettings(self.baud, self.data_bits, self.parity, self.stop_bits)

    def read_by(self, receiver: Frame, value: int, rng: random.Random,
                bits: tuple[float, float] | None = None) -> tuple[int, bool] | None:
        """A byte sent with these settings, as ``receiver`` reads it: (value,
        framing error), or None when it finds no start bit. Alike within the
        baud tolerance: the byte. Another rate: what its UART samples
        (:func:`~hexbot.hil_sim.uart_line.first_byte`). Another word format:
        a garbage byte from ``rng`` with a framing error. ``bits``: the
        sender's and the receiver's bit times in cycles (:meth:`matches`)."""
        bits = self._bits(receiver, bits)
        if self.matches(receiver, bits):
            return value, False
        if self.same_word(receiver):
            return first_byte(value, self.line(), receiver.line(), bits)
        return rng.randrange(256), True

    def _bits(self, other: Frame,
              bits: tuple[float, float] | None) -> tuple[float, float] | None:
        if bits is None and self.bit_cycles is not None and other.bit_cycles is not None:
            return self.bit_cycles, other.bit_cycles
        return bits

    def matches(self, other: Frame, bits: tuple[float, float] | None = None) -> bool:
        """A receiver set as ``other`` takes this sender's bytes: bit times
        within the tolerance, the same word format. The bit times are
        compared in cycles, relative to the sender's, as the core's
        m162_usart_frame_ok does: ``bits`` (sender's, receiver's) when the
        caller knows them (the IR medium: the byte's own, the PC's from its
        length over its bits, as ``ir_send_from_pc``), else the frames'
        ``bit_cycles`` when both are known, else 1 / baud (the same
        comparison: |1/a - 1/b| <= t/a is |a - b| <= t b)."""
        bits = self._bits(other, bits)
        if bits is not None:
            sent, own = bits
            if abs(sent - own) > BAUD_TOLERANCE * sent:
                return False
        elif abs(self.baud - other.baud) > BAUD_TOLERANCE * other.baud:
            return False
        # A receiver checks only the first stop bit: 8N2 into 8N1 is fine.
        return self.same_word(other)


PC_FRAME = Frame(float(BAUD_IR))


@dataclass(frozen=True)
class AirByte:
    sender: Endpoint
    start: int  # cycle of the start bit
    end: int  # cycle the stop bit ends
    value: int
    frame: Frame

    @property
    def bit(self) -> float:
        """The sender's bit time, in cycles: its frame's (its clock's, not
        rounded), else the byte's length over its bits (the PC's)."""
        if self.frame.bit_cycles is not None:
            return self.frame.bit_cycles
        return (self.end - self.start) / self.frame.line().frame_bits

    @property
    def stop(self) -> float:
        """Where its stop bit begins: its spans end there (ir_line.stop_bit)."""
        return stop_bit(self.start, self.bit, self.frame.line())


class Air(Protocol):
    """What the medium needs from the simulator."""

    def channel_at(self, module: int, cycle: int) -> int | None:
        """Side 1..6, CENTRE (0), or None (Y7) the selector chose at ``cycle``."""

    def channel_changes(self, module: int, after: int, until: int) -> list[tuple[int, int | None]]:
        """(cycle, channel) of each selector change in (after, until], in order."""

    def resets(self, module: int, after: int, until: int) -> list[int]:
        """Cycles in (after, until] at which the module's comm board reset."""

    def position(self, module: int) -> Cell: ...

    def module_at(self, cell: Cell) -> int | None: ...

    def listeners(self) -> list[int]:
        """Ids of every module, in a fixed order."""

    def rx_frame(self, module: int) -> Frame:
        """The current settings of the module's comm UART1 receiver."""

    def rx_since(self, module: int, before: float) -> int | None:
        """The cycle the module's comm UART1 receiver came on last (RXEN
        set; a reset turns it off) by its changes before ``before``, if it
        is on then; None if it is off."""

    def rx_went_off(self, module: int, after: float) -> bool:
        """Whether the module's comm UART1 receiver went off (RXEN cleared,
        a reset) at or after ``after``, by its changes up to now (the
        medium hands a byte over now)."""

    def drop(self, module: int) -> None:
        """A byte reached the module's comm UART1 while its receiver was
        off: count it as the USART counts one (``rx_dropped``)."""

    def deliver(self, module: int, value: int, framing_error: bool) -> bool:
        """Hand a byte to the module's comm UART1; False if the USART dropped it."""


@dataclass
class _Arrival:
    """What one receiver makes of one or more overlapping bytes."""

    start: int
    end: int
    senders: set[Endpoint]
    value: int
    framing_error: bool
    parts: list[Part] = field(default_factory=list)  # their levels, for a collision
    #: the receiver's settings (line, bit time, since when its USART is on)
    #: while the collision's value is still to be read: read once, when asked
    #: for (:meth:`read_value`), not again for every byte that joins (at boot
    #: the PC hears some 20 at once)
    unread: tuple[LineSettings, float, float | None] | None = None
    together: bool = field(init=False)  # every part whole and started with the first

    def __post_init__(self) -> None:
        self.together = all(p.whole and p.start == self.parts[0].start for p in self.parts)

    def overlaps(self, byte: AirByte) -> bool:
        return self.start < byte.end and byte.start < self.end and byte.sender not in self.senders

    def absorb(self, byte: AirByte, value: int, part: Part, rx: LineSettings,
               bit: float, since: float | None = None) -> None:
        """A byte of another sender overlapped: the receiver reads the AND of
        the lines. Bytes that started together and went out whole, heard
        from their start: the AND of the values (what sampling reads, and
        what the receiver read of each on its own). Else what its UART
        (``rx``, ``bit`` cycles, on since ``since``) samples of the AND of
        their levels, each at its real start. Flagged broken either way."""
        self.start, self.end = min(self.start, byte.start), max(self.end, byte.end)
        self.senders.add(byte.sender)
        self.parts.append(part)
        self.together = (self.together and part.whole
                         and part.start == self.parts[0].start)
        if self.together and (since is None or since <= part.start):
            self.value &= value
        else:
            self.unread = (rx, bit, since)
        self.framing_error = True

    def read_value(self) -> int:
        """The byte the receiver reads (a collision's, read now if not yet)."""
        if self.unread is not None:
            read = ir_line.read(self.parts, *self.unread)
            self.value = self.value if read is None else read[0]
            self.unread = None
        return self.value


@dataclass
class IrMedium:
    air: Air
    seed: int = 0
    faults_for: Callable[[Endpoint, Endpoint], Faults] = lambda s, r: Faults()
    emit: Callable[[int, dict], None] = lambda cycle, event: None
    hz: float = 1e6  # cluster cycles per second: a receiver's bit time in cycles
    rng: random.Random = field(init=False)
    _last: dict[Endpoint, _Arrival] = field(default_factory=dict)
    _pc_pending: list[_Arrival] = field(default_factory=list)
    _pc_ready: bytearray = field(default_factory=bytearray)
    _longest_frame: int = 0
    _burst_left: dict[tuple[Endpoint, Endpoint], int] = field(default_factory=dict)

    def __post_init__(self) -> None:
        self.rng = random.Random(self.seed)

    def transmit(self, byte: AirByte) -> None:
        """A byte finished on the air (simulation time >= byte.end); route it now."""
        self._longest_frame = max(self._longest_frame, byte.end - byte.start)
        for receiver, spans in self._receivers(byte):
            self._arrive(byte, receiver, spans)

    def transmit_to(self, byte: AirByte, receiver: Endpoint) -> None:
        """A byte whose receiver the core's medium chose (hil_sim/core/ir_medium.c:
        bytes for the PC); the same rules from here on."""
        self._longest_frame = max(self._longest_frame, byte.end - byte.start)
        spans = [(byte.start, byte.stop)]
        if isinstance(byte.sender, int):
            channel = self.air.channel_at(byte.sender, byte.start)
            spans = self._sent_spans(byte, byte.sender, channel)
        self._arrive(byte, receiver, spans)

    def _receivers(self, byte: AirByte) -> list[tuple[Endpoint, list[Span]]]:
        """Who sees the byte, and when (spans of cycles; outside: idle high)."""
        if byte.sender == PC:
            heard = ((m, self._listening(byte, m, CENTRE)) for m in self.air.listeners())
            return [(m, spans) for m, spans in heard if spans]
        assert isinstance(byte.sender, int)
        channel = self.air.channel_at(byte.sender, byte.start)
        if channel is None:
            return []
        sent = self._sent_spans(byte, byte.sender, channel)
        if channel == CENTRE:
            return [(PC, sent)]
        other = self.air.module_at(neighbor(self.air.position(byte.sender), channel))
        if other is None:
            return []
        spans = intersect(sent, self._listening(byte, other, facing(channel)))
        return [(other, spans)] if spans else []

    def _sent_spans(self, byte: AirByte, sender: int, channel: int | None) -> list[Span]:
        """While the byte leaves by ``channel``'s transceiver: until the
        selector moves (the tail goes out elsewhere; back again, it goes on
        here), and never after the sender's reset (the USART stops). Up to
        its stop bit only: from there on its line is high either way."""
        stop = byte.stop
        until = int(stop)  # changes and resets are on whole cycles, before stop
        end = min(self.air.resets(sender, byte.start, until), default=stop)
        changes = self.air.channel_changes(sender, byte.start, until)
        return spans_where(byte.start, end, channel, changes, channel)

    def _listening(self, byte: AirByte, module: int, channel: int) -> list[Span]:
        """While ``module``'s selector is on ``channel`` during the byte, up
        to its stop bit."""
        changes = self.air.channel_changes(module, byte.start, int(byte.stop))
        return spans_where(byte.start, byte.stop, self.air.channel_at(module, byte.start),
                           changes, channel)

    def _arrive(self, byte: AirByte, receiver: Endpoint, spans: list[Span]) -> None:
        faults = self.faults_for(byte.sender, receiver)
        value = byte.value
        if faults.active:
            # Always draw the same number of values per byte and link: the
            # sequence stays aligned whatever the outcome.
            lost = self.rng.random() < faults.byte_loss
            flips = [self.rng.random() < faults.bit_error_rate for _ in range(8)]
            if lost:
                self._event(byte, receiver, "ir-lost", reason="fault: byte loss")
                return
            mask = sum(1 << bit for bit, flip in enumerate(flips) if flip)
            if mask:
                value ^= mask
                self._event(byte, receiver, "ir-bit-error", mask=mask)
        framing_error = False
        if faults.extended:
            value, framing_error = self._extended(byte, receiver, faults, value)
        rx = PC_FRAME if receiver == PC else self.air.rx_frame(receiver)  # type: ignore[arg-type]
        part = Part(byte.start, byte.end, byte.bit, value, byte.frame.line(), tuple(spans))
        rx_bit = self.hz / rx.baud if rx.bit_cycles is None else rx.bit_cycles
        # The receiver's own USART by its changes before the middle of the
        # byte's stop bit: off there, it does not get the byte (below); came
        # on within the byte, it lost what it had and looks for a falling
        # edge from there (ir_line.read).
        horizon = byte.stop + byte.bit / 2
        since: float | None = None
        if receiver != PC:
            since = self.air.rx_since(receiver, horizon)  # type: ignore[arg-type]
            on = since is not None
        else:
            on = True
        late = since is not None and since > byte.start
        # bit times in cycles, the PC's from its byte's length: one rule with
        # the core (m162_usart_frame_ok, m162_usart_resample)
        bits = (byte.bit, rx_bit)
        frame_ok = byte.frame.matches(rx, bits)
        if not frame_ok:
            self._event(
                byte, receiver, "ir-garbled", reason=f"sender {byte.frame}, receiver {rx}"
            )
        if (not part.whole or late) and byte.frame.same_word(rx):
            # cut: what the receiver's UART samples of the part it saw, from
            # where it came on, by the rule of a whole byte at its rate
            # (first_byte)
            read = ir_line.read([part], rx.line(), rx_bit, since)
            if read is None:
                return  # no start bit where the receiver looked: nothing
            if not frame_ok:
                read = out_of_range(read, value, rx.line())
            value, framing_error = read[0], framing_error or read[1]
        elif not frame_ok:
            read = byte.frame.read_by(rx, value, self.rng, bits)
            if read is None:
                return  # no start bit where the receiver looked: nothing
            value, framing_error = read
        if receiver == PC:
            # The PC's UART sees one broken frame where bytes overlap.
            for pending in reversed(self._pc_pending):
                if pending.overlaps(byte):
                    self._event(byte, receiver, "ir-collision", other=sorted(
                        pending.senders, key=str))
                    pending.absorb(byte, value, part, rx.line(), rx_bit)
                    return
            self._pc_pending.append(_Arrival(byte.start, byte.end, {byte.sender}, value,
                                             framing_error, [part]))
            return
        assert isinstance(receiver, int)
        arrival = _Arrival(byte.start, byte.end, {byte.sender}, value, framing_error, [part])
        previous = self._last.get(receiver)
        if previous is not None and previous.overlaps(byte):
            self._event(byte, receiver, "ir-collision", other=sorted(previous.senders, key=str))
            previous.absorb(byte, value, part, rx.line(), rx_bit, since)
            arrival = previous
        else:
            self._last[receiver] = arrival
        if not on:
            self.air.drop(receiver)  # counted as the core counts it
            self._event(byte, receiver, "ir-dropped", reason="receiver off (RXEN) or overrun")
        elif self.air.rx_went_off(receiver, horizon):
            pass  # it had the byte at the horizon; RXEN cleared or a reset flushed it since
        elif not self.air.deliver(receiver, arrival.read_value(), arrival.framing_error):
            self._event(byte, receiver, "ir-dropped", reason="receiver off (RXEN) or overrun")
        self._spurious(byte, receiver, faults)

    def _extended(self, byte: AirByte, receiver: Endpoint, faults: Faults,
                  value: int) -> tuple[int, bool]:
        """Burst and framing error on one byte: (value, framing error)."""
        link = (byte.sender, receiver)
        left = self._burst_left.get(link, 0)
        if faults.burst_rate > 0 and not left and self.rng.random() < faults.burst_rate:
            left = BURST_BITS
            self._event(byte, receiver, "ir-burst", bits=BURST_BITS)
        broken_stop = False
        if left:
            # bit times of this byte: start, data 0..7, stop
            noise = [self.rng.random() < 0.5 for _ in range(min(left, 10))]
            self._burst_left[link] = left - len(noise)
            for slot, wrong in enumerate(noise):
                if wrong and 1 <= slot <= 8:
                    value ^= 1 << (slot - 1)
                broken_stop |= wrong and slot in (0, 9)  # a start or stop bit read wrong
        if faults.framing_error_rate > 0 and self.rng.random() < faults.framing_error_rate:
            broken_stop = True
        if broken_stop:
            self._event(byte, receiver, "ir-framing-error")
        return value, broken_stop

    def _spurious(self, byte: AirByte, receiver: Endpoint, faults: Faults) -> None:
        """A noise pulse on the idle line after ``byte`` reads as a byte."""
        if not faults.spurious_byte_rate or self.rng.random() >= faults.spurious_byte_rate:
            return
        value = 0xFF & ~(1 << self.rng.randrange(8))  # the pulse's zero, idle ones after
        self._event(byte, receiver, "ir-spurious-byte", value=value)
        if receiver == PC:
            self._pc_pending.append(_Arrival(byte.end, byte.end, {"noise"}, value, False))
        else:
            self.air.deliver(receiver, value, False)  # type: ignore[arg-type]

    def settle(self, now: int) -> None:
        """Move PC bytes that nothing can collide with any more to the PC's buffer."""
        horizon = now - self._longest_frame
        while self._pc_pending and self._pc_pending[0].end <= horizon:
            arrival = self._pc_pending.pop(0)
            # A real RS232 converter passes a garbled byte on; so do we.
            self._pc_ready.append(arrival.read_value())

    def pc_take(self) -> bytes:
        data = bytes(self._pc_ready)
        self._pc_ready.clear()
        return data

    def _event(self, byte: AirByte, receiver: Endpoint, name: str, **extra: object) -> None:
        self.emit(
            byte.end,
            {"event": name, "from": byte.sender, "to": receiver, "byte": byte.value, **extra},
        )
