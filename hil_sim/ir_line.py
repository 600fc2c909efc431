"""What a receiver's UART reads of the IR line when bytes are cut or overlap.

The medium (ir_bus.py) decides byte by byte. A byte that left its sender's
transceiver whole, towards a receiver that listened all along, arrives as
sent. Otherwise the receiver's UART sees line levels (start bit, data LSB
first, parity, stop, idle high):

* A byte is visible at a receiver only while the sender's selector stays on
  the channel it had at the start bit (the tail of a byte whose selector
  moved leaves by another transceiver; an MCU reset stops the byte for
  good), and while the receiver's selector is on the facing side. Outside
  those spans the receiver's line idles high. Spans end where the stop bit
  begins (:func:`stop_bit`): from there on the line is high either way.
* Overlapping bytes of several senders are one line: a lit LED pulls it
  low, so the line is the AND of the bytes' levels, each at its real start.
* A receiver whose own USART was off for part of a byte (its MCU reset,
  RXEN cleared) lost what it had of it: it reads the line from where it
  came on last, and a line already low there is no start bit (``since``
  of :func:`read`). The medium (ir_bus.py) decides when that is.

That line is read by :func:`~hexbot.hil_sim.uart_line.read_first`, the
sampling rule of the simulated UARTs. Times are cluster cycles. The C
core's twin is hil_sim/core/ir_line.c; a test holds them together.
"""

from __future__ import annotations

from dataclasses import dataclass

from .uart_line import LineSettings, levels, read_first

Span = tuple[float, float]  # [from, to) in cycles
#: Spans kept per byte: a selector that leaves and comes back more often
#: within one byte shows the byte only in its first spans (the C twin's
#: fixed arrays, IR_MAX_SPANS).
MAX_SPANS = 4


@dataclass(frozen=True)
class Part:
    """One byte on a receiver's line: its levels where the receiver sees it."""

    start: float  # cycle of the start bit
    end: float  # cycle its (last) stop bit ends
    bit: float  # the sender's bit time, in cycles
    value: int
    tx: LineSettings  # the sender's word format
    spans: tuple[Span, ...]  # when the receiver sees the sender's transceiver

    @property
    def stop(self) -> float:
        """Where its stop bit begins (:func:`stop_bit`)."""
        return stop_bit(self.start, self.bit, self.tx)

    @property
    def whole(self) -> bool:
        """The receiver saw all of it up to the stop bit (its spans are cut
        there, :func:`stop_bit`): nothing was cut."""
        return self.spans == ((self.start, self.stop),)

    def level(self, t: float, wave: list[tuple[float, int]]) -> int:
        if not any(a <= t < b for a, b in self.spans):
            return 1
        at = 1
        for since, value in wave:  # the last level that began at or before t
            if since > t:
                break
            at = value
        return at if t < wave[-1][0] and t >= wave[0][0] else 1


def stop_bit(start: float, bit: float, tx: LineSettings) -> float:
    """Where the stop bit of a byte sent as ``tx`` from ``start`` begins.
    From there on its line is high whether the receiver sees it or not (a
    stop bit, or idle where cut), so selector moves and resets from there on
    change nothing a receiver can sample: the medium works out a byte's
    spans only up to here. (The C core knows another board's moves as of a
    quantum boundary: it reads a byte once a boundary at or after this
    point has passed, ``settled`` in ir_medium.c.)"""
    return start + (1 + tx.data_bits + (tx.parity != "N")) * bit


def spans_where(start: float, end: float, state: object,
                changes: list[tuple[float, object]], keep: object) -> list[Span]:
    """Parts of [start, end) where a state that was ``state`` at ``start``
    and moved at ``changes`` (cycle, new state; sorted) equals ``keep``."""
    out: list[Span] = []
    since = start if state == keep else None
    for cycle, new in changes:
        if cycle <= start or cycle >= end:
            continue
        if since is not None and new != keep:
            out.append((since, cycle))
            since = None
            if len(out) == MAX_SPANS:
                return out
        elif since is None and new == keep:
            since = cycle
    if since is not None and len(out) < MAX_SPANS:
        out.append((since, end))
    return out


def intersect(a: list[Span], b: list[Span]) -> list[Span]:
    out: list[Span] = []
    for a0, a1 in a:
        for b0, b1 in b:
            lo, hi = max(a0, b0), min(a1, b1)
            if lo < hi:
                out.append((lo, hi))
    return sorted(out)[:MAX_SPANS]


def line(parts: list[Part]) -> list[tuple[float, int]]:
    """The receiver's line: (time a level begins, level), idle high after.
    Low wherever some part is low where the receiver sees it: a sweep over
    the parts' low intervals (at boot the PC hears some 20 bytes at once)."""
    waves = [levels(p.value, p.tx, p.start, p.bit) for p in parts]
    times = sorted({t for wave in waves for t, _ in wave}
                   | {t for p in parts for span in p.spans for t in span})
    edges: dict[float, int] = {}  # time -> change of the count of low parts
    for part, wave in zip(parts, waves, strict=True):
        for (since, level), (until, _) in zip(wave, wave[1:], strict=False):
            if level:
                continue
            for a, b in part.spans:
                lo, hi = max(since, a), min(until, b)
                if lo < hi:
                    edges[lo] = edges.get(lo, 0) + 1
                    edges[hi] = edges.get(hi, 0) - 1
    out: list[tuple[float, int]] = []
    low = 0
    for t in times:
        low += edges.get(t, 0)
        level = 0 if low else 1
        if not out or out[-1][1] != level:
            out.append((t, level))
    return out


def read(parts: list[Part], rx: LineSettings, bit: float,
         since: float | None = None) -> tuple[int, bool] | None:
    """The first byte (value, framing error) a receiver set to ``rx`` with a
    bit time of ``bit`` cycles reads of ``parts``; None: no start bit.
    ``since``: the receiver's USART came on there (after a reset, RXEN
    set): it looks for a falling edge from there on
    (:func:`~hexbot.hil_sim.uart_line.read_first`); None: on all along."""
    return read_first(line(parts), rx, bit, since)
