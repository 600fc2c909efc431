"""STK500v2 message framing: bytes in, messages out, without any I/O.

A message is ``MESSAGE_START seq size_hi size_lo TOKEN body... checksum``;
the checksum is the XOR of every byte before it. The decoder follows the
programmer's receive state machine: bytes outside a frame are skipped, a
wrong token or an over-long size restarts the search for MESSAGE_START, and a
complete frame with a bad checksum is reported (the programmer answers it
with ANSWER_CKSUM_ERROR) instead of being executed.
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass
from enum import Enum, auto
from functools import reduce
from operator import xor

from hexbot.hil_sim.isp.avr068 import MAX_BODY, MESSAGE_START, TOKEN


def checksum(data: bytes) -> int:
    return reduce(xor, data, 0)


def encode(seq: int, body: bytes) -> bytes:
    """One complete frame around ``body`` with sequence number ``seq``."""
    if not 0 <= seq <= 0xFF:
        raise ValueError(f"sequence number must fit in a byte, got {seq}")
    if not 0 < len(body) <= 0xFFFF:
        raise ValueError(f"message body must hold 1..65535 bytes, got {len(body)}")
    head = bytes((MESSAGE_START, seq, len(body) >> 8, len(body) & 0xFF, TOKEN))
    frame = head + bytes(body)
    return frame + bytes((checksum(frame),))


@dataclass(frozen=True)
class Message:
    """A received frame: its sequence number, body, and whether the
    checksum held."""

    seq: int
    body: bytes
    checksum_ok: bool = True


class _State(Enum):
    START = auto()
    SEQ = auto()
    SIZE_HI = auto()
    SIZE_LO = auto()
    TOKEN = auto()
    BODY = auto()
    CHECKSUM = auto()


class FrameDecoder:
    """Incremental decoder; feed it any chunking of the byte stream."""

    def __init__(self, max_body: int = MAX_BODY) -> None:
        self.max_body = max_body
        self.dropped = 0  # bytes thrown away outside frames or in bad headers
        self.reset()

    def reset(self) -> None:
        """Forget a partial frame (the programmer's receive time-out)."""
        self._state = _State.START
        self._seq = 0
        self._size = 0
        self._body = bytearray()
        self._sum = 0
        self._pending = 0  # bytes of the frame under way, counted into dropped on reset

    @property
    def in_frame(self) -> bool:
        return self._state is not _State.START

    def feed(self, data: bytes) -> Iterator[Message]:
        for byte in data:
            msg = self._step(byte)
            if msg is not None:
                yield msg

    def _restart(self) -> None:
        self.dropped += self._pending
        self.reset()

    def _step(self, byte: int) -> Message | None:
        state = self._state
        self._pending += 1
        if state is _State.START:
            if byte != MESSAGE_START:
                self._restart()
                return None
            self._sum = byte
            self._state = _State.SEQ
            return None
        self._sum ^= byte
        if state is _State.SEQ:
            self._seq = byte
            self._state = _State.SIZE_HI
        elif state is _State.SIZE_HI:
            self._size = byte << 8
            self._state = _State.SIZE_LO
        elif state is _State.SIZE_LO:
            self._size |= byte
            # An empty or over-long body cannot be a command: resynchronise.
            if not 0 < self._size <= self.max_body:
                self._restart()
            else:
                self._state = _State.TOKEN
        elif state is _State.TOKEN:
            if byte != TOKEN:
                self._restart()
            else:
                self._state = _State.BODY
        elif state is _State.BODY:
            self._body.append(byte)
            if len(self._body) == self._size:
                self._state = _State.CHECKSUM
        else:  # CHECKSUM: the running XOR including this byte must be zero
            msg = Message(self._seq, bytes(self._body), self._sum == 0)
            self.reset()
            return msg
        return None
