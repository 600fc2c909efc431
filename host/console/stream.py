"""The raw views of a terminal: the bytes of a port as one continuous stream.

A port delivers bytes in reads of any size (1-8 bytes at 300 baud); a
serial terminal shows them as a stream, not one line per read. Text view:
a line ends after LF (and the CR the firmware sends after it, ``\\n\\r``),
control bytes are escaped. Hex view: 16 bytes a line with the stream's
offset and an ASCII column, as hexdump and CoolTerm show them. Each
direction (``>`` sent, ``<`` received) is its own stream with its own
offset; when the direction changes or the link changes state, the pending
line is closed so the order of what happened stays visible. Pure: no I/O,
no widgets.
"""

from __future__ import annotations

from dataclasses import dataclass

HEX_WIDTH = 16
LF, CR = 0x0A, 0x0D


@dataclass
class StreamLine:
    direction: str  # "tx" | "rx"
    t: float  # session time of its first byte
    wall: float | None  # the PC's clock when its first byte arrived
    offset: int  # of its first byte in the direction's stream
    data: bytearray


def escape_bytes(data: bytes) -> str:
    """Printable ASCII as it is, LF/CR as ``\\n``/``\\r``, the rest ``\\xNN``."""
    out = []
    for b in data:
        if b == LF:
            out.append("\\n")
        elif b == CR:
            out.append("\\r")
        elif 32 <= b < 127:
            out.append(chr(b))
        else:
            out.append(f"\\x{b:02x}")
    return "".join(out)


def hex_columns(line: StreamLine) -> str:
    """``00000010  0a 0d 4d 30 32 3a 20 41  43 4b 44 0a 0d           |..M02: ACKD..|``"""
    cells = [f"{b:02x}" for b in line.data] + ["  "] * (HEX_WIDTH - len(line.data))
    half = HEX_WIDTH // 2
    text = "".join(chr(b) if 32 <= b < 127 else "." for b in line.data)
    return (f"{line.offset:08x}  {' '.join(cells[:half])}  {' '.join(cells[half:])}  "
            f"|{text}|")


class ByteStream:
    """Turns reads into complete lines plus one pending line, for ``mode``
    "text" or "hex"."""

    def __init__(self, mode: str) -> None:
        if mode not in ("text", "hex"):
            raise ValueError(f"no stream view {mode!r}")
        self.mode = mode
        self.offsets = {"tx": 0, "rx": 0}
        self.pending: StreamLine | None = None

    def feed(self, direction: str, t: float, wall: float | None, data: bytes) -> list[StreamLine]:
        """Bytes of one read (or write); returns the lines they completed."""
        done: list[StreamLine] = []
        if self.pending is not None and self.pending.direction != direction:
            done.append(self._close())
        for b in data:
            line = self.pending
            if line is not None and self.mode == "text" and line.data[-1:] == b"\n":
                if b == CR:  # the CR of the firmware's LF CR ends the line
                    line.data.append(b)
                    self.offsets[direction] += 1
                    done.append(self._close())
                    continue
                done.append(self._close())  # a bare LF ended it
                line = None
            if line is None:
                line = self.pending = StreamLine(direction, t, wall, self.offsets[direction],
                                                 bytearray())
            line.data.append(b)
            self.offsets[direction] += 1
            if self.mode == "hex" and len(line.data) == HEX_WIDTH:
                done.append(self._close())
        return done

    def interrupt(self) -> list[StreamLine]:
        """Something else happened (a state change): close the pending line."""
        return [self._close()] if self.pending is not None else []

    def _close(self) -> StreamLine:
        line = self.pending
        assert line is not None
        self.pending = None
        return line
