"""What a UART receives when the two ends of a serial line disagree.

The simulated modules speak 300 baud 8N1 on the IR transceiver (4800 8N1
on a debug port). A PC port set to another baud rate, parity, word size or
stop bits does not get the modules' bytes on real hardware: it samples the
line at its own bit time and reads other bytes (or framing errors). So that
a wrong setting is caught in the simulator before it is met on the bench,
the simulated ports pass bytes through :func:`resample`, which draws the
sender's waveform (start bit, data bits LSB first, parity, stop bits, idle
high between bursts) and samples it as the receiver's UART does: wait for
a falling edge, sample each bit in its middle, re-arm after the middle of
the stop bit.

Decisions (documented in docs/simulator.md): a byte with a parity or
framing error is delivered as sampled (a port in raw mode without INPCK
does so); each call is one burst that starts and ends idle (reads and
writes are bursts: the time between them is not modelled); a break (a
whole frame low) is read once, and the next start bit looked for only
after the line is high again, as a PC's UART does.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass

#: parity bit for a data word, by pyserial's parity letters
_PARITY = {
    "N": None,
    "E": lambda word: bin(word).count("1") % 2,
    "O": lambda word: 1 - bin(word).count("1") % 2,
    "M": lambda word: 1,
    "S": lambda word: 0,
}


@dataclass(frozen=True)
class LineSettings:
    baud: int
    data_bits: int = 8
    parity: str = "N"  # N E O M S
    stop_bits: float = 1

    def __post_init__(self) -> None:
        if self.baud <= 0:
            raise ValueError(f"baud must be positive, got {self.baud}")
        if self.parity not in _PARITY:
            raise ValueError(f"parity must be one of {''.join(_PARITY)}, got {self.parity!r}")
        if self.data_bits not in (5, 6, 7, 8):
            raise ValueError(f"data bits must be 5..8, got {self.data_bits}")

    @property
    def frame_bits(self) -> float:
        """Bits on the wire per byte: start, data, parity, stop."""
        return 1 + self.data_bits + (self.parity != "N") + self.stop_bits

    def describe(self) -> str:
        return f"{self.baud} {self.data_bits}{self.parity}{self.stop_bits:g}"


def _waveform(data: bytes, tx: LineSettings, bit: float | None = None,
              t: float = 0.0) -> list[tuple[float, int]]:
    """(start time, level) of every bit, from ``t`` on, in seconds (or in
    the unit of ``bit``, the bit time: the IR medium draws in cycles)."""
    bit = 1.0 / tx.baud if bit is None else bit
    out: list[tuple[float, int]] = []
    parity = _PARITY[tx.parity]
    for byte in data:
        word = byte & ((1 << tx.data_bits) - 1)
        levels = [0] + [(word >> i) & 1 for i in range(tx.data_bits)]
        if parity is not None:
            levels.append(parity(word))
        for level in levels:
            out.append((t, level))
            t += bit
        out.append((t, 1))  # stop bits, then idle until the next start bit
        t += bit * tx.stop_bits
    out.append((t, 1))
    return out


def first_byte(byte: int, tx: LineSettings, rx: LineSettings,
               bits: tuple[float, float] | None = None) -> tuple[int, bool] | None:
    """One byte sent as ``tx``, as a receiver set to ``rx`` (the same word
    format, another baud rate) reads it: :func:`resample`'s reading, its
    first byte only (the IR medium delivers one byte per byte sent), with
    its framing error; None when the receiver finds no start bit in it. For
    rates outside the baud tolerance only: the sent byte never arrives as
    good (see the end). ``bits``: the sender's and the receiver's bit times
    in cycles, when the simulator knows them (else 1 / baud, in seconds).
    The simulator's C core (``m162_usart_resample``) reads the same; a test
    holds them together."""
    tx_bit, rx_bit = bits if bits is not None else (None, None)
    read = next(_read(_waveform(bytes([byte]), tx, tx_bit), rx, rx_bit), None)
    return None if read is None else out_of_range(read, byte, rx)


def out_of_range(read: tuple[int, bool], byte: int, rx: LineSettings) -> tuple[int, bool]:
    """What a receiver outside the datasheet's baud range, where nothing is
    promised, reports of ``byte`` when exact sampling reads ``read``: a byte
    that sampling still reads right keeps a framing error (a real receiver's
    edge detection and 3-sample vote may give it one). The one rule for a
    whole byte (:func:`first_byte`) and a cut one (the IR medium); the C
    core's twin is ``uart_line_out_of_range``."""
    value, framing_error = read
    return value, framing_error or value == byte & ((1 << rx.data_bits) - 1)


def resample(data: bytes, tx: LineSettings, rx: LineSettings) -> bytes:
    """The bytes a receiver set to ``rx`` reads from ``data`` sent as ``tx``."""
    if tx == rx or not data:
        return bytes(data)
    return bytes(value for value, _ in _read(_waveform(data, tx), rx))


def levels(byte: int, tx: LineSettings, start: float, bit: float) -> list[tuple[float, int]]:
    """The line of one byte sent as ``tx`` from ``start`` on: (time a level
    begins, level), idle high from the last entry on; times in the unit of
    ``bit`` (the IR medium: cycles)."""
    return _waveform(bytes([byte]), tx, bit, start)


def read_first(wave: list[tuple[float, int]], rx: LineSettings, bit: float,
               since: float | None = None) -> tuple[int, bool] | None:
    """The first byte (value, framing error) a receiver set to ``rx``, with
    a bit time of ``bit`` in the unit of ``wave``'s times, reads of the line
    ``wave`` (as :func:`levels` gives); None if it finds no start bit.
    ``since``: the receiver came on there (RXEN set, after a reset), after
    the line began: it looks for a falling edge at or after it, and a line
    already low there is no start bit (the datasheet: reception starts on a
    high-to-low transition); None: on all along. The IR medium's reading of
    cut and colliding bytes (hil_sim/ir_line.py); the C core's twin is
    ``uart_line_read`` (hil_sim/core/uart_line.c)."""
    return next(_read(wave, rx, bit, since), None)


def _read(wave: list[tuple[float, int]], rx: LineSettings, bit: float | None = None,
          since: float | None = None) -> Iterator[tuple[int, bool]]:
    """(byte, framing error) for each start bit a receiver set to ``rx``
    finds in ``wave``: wait for the line low, check the start bit in its
    middle (a glitch re-arms there), sample each data bit in its middle,
    the stop bit too, re-arm after the middle of the (first) stop bit.
    ``bit``: the receiver's bit time in the unit of the wave (default
    seconds, 1 / baud). ``since``: see :func:`read_first`."""
    end = wave[-1][0]
    starts = [t for t, _ in wave]

    def level(t: float) -> int:
        lo, hi = 0, len(starts) - 1  # the last bit that started at or before t
        while lo < hi:
            mid = (lo + hi + 1) // 2
            if starts[mid] <= t:
                lo = mid
            else:
                hi = mid - 1
        return wave[lo][1] if t < end else 1

    bit = 1.0 / rx.baud if bit is None else bit
    i, t = 0, wave[0][0]
    if since is not None and since > t:
        # came on at since: the first low level that begins at or after it
        # after a high one, a falling edge
        while i < len(wave) - 1 and (wave[i][0] < since or wave[i][1] != 0
                                     or (i > 0 and wave[i - 1][1] == 0)):
            i += 1
        if i >= len(wave) - 1:
            return
        t = wave[i][0]
    while True:
        # the line low at or after t: the first low bit that has not ended by t
        # (the waveform ends idle high, so a low bit always has a successor)
        while i < len(wave) - 1 and (wave[i][1] != 0 or wave[i + 1][0] <= t):
            i += 1
        if i >= len(wave) - 1:
            return
        edge = max(t, wave[i][0])
        if level(edge + bit / 2) != 0:  # a glitch, not a start bit
            t = edge + bit / 2
            continue
        word = 0
        for k in range(rx.data_bits):
            word |= level(edge + bit * (1.5 + k)) << k
        stop = edge + bit * (rx.frame_bits - rx.stop_bits + 0.5)
        framing_error = level(stop) == 0
        yield word, framing_error
        t = stop  # re-arm after the middle of the (first) stop bit
        if framing_error and word == 0:
            # a break: the line low for a whole frame. A PC's UART (a 16550,
            # the USB adapters after it) reads it as one NUL and looks for
            # the next start bit only once the line is high again. Re-arming
            # on the low line read a NUL per frame time of it: a port at
            # 4,000,000 baud read 13,000 per 300-baud bit (session 37). (Any
            # other framing error re-arms at once: the 16550 takes the low
            # stop bit for the next start bit.)
            while i < len(wave) - 1 and (wave[i][1] != 1 or wave[i + 1][0] <= t):
                i += 1
            t = max(t, wave[i][0])
