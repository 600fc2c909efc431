"""The RF12 radio link: the listing's command words and packet, and the
bridge's use of the payload.

On the air (third listing of Appendix A): preamble AA AA AA, sync 2D D4,
``PAYLOAD`` bytes, their 8-bit sum, then dummy AA bytes that flush the
transmitter. The packet has a fixed length, so the wireless bridge
(``firmware/rflink``) and the PC's radio use its first byte as the number
of link bytes that follow (0..``LINK_BYTES``); the rest is padding. The
firmware takes these numbers from the generated ``hexbot_codes.h``.
"""

from __future__ import annotations

#: Configuration words of the listing that decide who hears whom.
CMD_CONFIG = 0x80D7  # el, ef, 433 MHz band, 12.0 pF
CMD_FREQUENCY = 0xA640  # 434 MHz
CMD_DATA_RATE = 0xC647  # 4.79 kbps
CMD_SYNC_LOW = 0xCED4  # sync word 2D D4

PREAMBLE = bytes([0xAA, 0xAA, 0xAA])
SYNC = bytes([0x2D, CMD_SYNC_LOW & 0xFF])
PAYLOAD = 16
TRAILER = bytes([0xAA, 0xAA, 0xAA])
#: Link bytes one packet carries: the payload less its length byte.
LINK_BYTES = PAYLOAD - 1

#: RF12 crystal and the data-rate formula of the datasheet (0xC6xx).
XTAL_HZ = 10_000_000


def channel() -> tuple[int, int, int]:
    """(band, frequency word, data-rate byte) of the listing's words: what a
    receiver must share with a transmitter to hear it (hil_sim/radio.py)."""
    return ((CMD_CONFIG >> 4) & 0x3, CMD_FREQUENCY & 0x0FFF, CMD_DATA_RATE & 0xFF)


def rate_divider(rate_word: int = CMD_DATA_RATE) -> int:
    """Crystal cycles per bit of a 0xC6xx word: 29 (R + 1) (1 + 7 cs)."""
    r, cs = rate_word & 0x7F, (rate_word >> 7) & 1
    return 29 * (r + 1) * (1 + 7 * cs)


def bit_rate(rate_word: int = CMD_DATA_RATE) -> float:
    """Bits per second of a 0xC6xx word: 10 MHz / 29 / (R + 1) / (1 + 7 cs)."""
    return XTAL_HZ / rate_divider(rate_word)


def checksum(payload: bytes) -> int:
    return sum(payload) & 0xFF


def payloads(data: bytes) -> list[bytes]:
    """Link bytes cut into packet payloads: length byte, bytes, zero padding."""
    out = []
    for i in range(0, len(data), LINK_BYTES):
        chunk = data[i:i + LINK_BYTES]
        out.append(bytes([len(chunk)]) + chunk + bytes(LINK_BYTES - len(chunk)))
    return out


def packet(payload: bytes) -> bytes:
    """The bytes the listing's transmitter puts on the air for one payload."""
    if len(payload) != PAYLOAD:
        raise ValueError(f"an RF12 payload is {PAYLOAD} bytes, not {len(payload)}")
    return PREAMBLE + SYNC + payload + bytes([checksum(payload)]) + TRAILER


def link_bytes(payload: bytes) -> bytes | None:
    """The link bytes a payload carries, or None if its length byte is wrong."""
    n = payload[0]
    return payload[1:1 + n] if n <= LINK_BYTES else None


class PacketReceiver:
    """Byte stream from the air -> link bytes of the packets whose sum
    matched: the sync search, payload and checksum of the listing's receiver.
    A gap of more than ``gap`` cycles between bytes ends a packet."""

    def __init__(self, gap: int) -> None:
        self.gap = gap
        self.good = 0
        self.bad = 0
        self._last = -1
        self._window = b""
        self._body: bytearray | None = None  # payload + sum while inside a packet

    def push(self, end: int, value: int) -> bytes:
        """One byte that ended on the air at cycle ``end``; returns link bytes."""
        if self._last >= 0 and end - self._last > self.gap:
            self._window, self._body = b"", None
        self._last = end
        if self._body is None:
            self._window = (self._window + bytes([value]))[-2:]
            if self._window == SYNC:
                self._body, self._window = bytearray(), b""
            return b""
        self._body.append(value)
        if len(self._body) < PAYLOAD + 1:
            return b""
        body, self._body = bytes(self._body), None
        data = link_bytes(body[:PAYLOAD]) if checksum(body[:PAYLOAD]) == body[PAYLOAD] else None
        if data is None:
            self.bad += 1
            return b""
        self.good += 1
        return data
