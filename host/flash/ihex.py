"""Intel HEX reading, strict enough to stop a bad image before avrdude.

Only what avr-objcopy writes for an ATmega162 is accepted: data (00), end
of file (01) and the two address extensions (02, 04). Every problem names the
file and the line.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from hexbot.errors import FlashingError


@dataclass(frozen=True)
class HexImage:
    path: Path
    data: dict[int, int]  # byte address -> value

    @property
    def size(self) -> int:
        """Bytes the image occupies (the highest address written + 1)."""
        return max(self.data) + 1 if self.data else 0

    @property
    def used(self) -> int:
        return len(self.data)

    def to_bytes(self, fill: int = 0xFF) -> bytes:
        out = bytearray([fill] * self.size)
        for addr, value in self.data.items():
            out[addr] = value
        return bytes(out)


def read_hex(path: str | Path, limit: int | None = None) -> HexImage:
    """Parse ``path``; with ``limit``, refuse data at or above that address."""
    path = Path(path)
    try:
        text = path.read_text(encoding="ascii")
    except FileNotFoundError:
        raise FlashingError(f"{path}: no such image file") from None
    except (OSError, UnicodeDecodeError) as exc:
        raise FlashingError(f"{path}: cannot read as Intel HEX: {exc}") from exc
    data: dict[int, int] = {}
    base = 0
    ended = False
    for lineno, raw in enumerate(text.splitlines(), 1):
        line = raw.strip()
        if not line:
            continue

        def fail(problem: str, lineno: int = lineno) -> FlashingError:
            return FlashingError(f"{path}:{lineno}: {problem}")

        if ended:
            raise fail("data after the end-of-file record")
        if not line.startswith(":"):
            raise fail("a record must start with ':'")
        try:
            record = bytes.fromhex(line[1:])
        except ValueError:
            raise fail("not hexadecimal digits") from None
        if len(record) < 5 or len(record) != record[0] + 5:
            raise fail("record length does not match its byte count")
        if sum(record) & 0xFF:
            raise fail(f"checksum error (record sums to 0x{sum(record) & 0xFF:02X}, not 0)")
        count, offset, kind = record[0], int.from_bytes(record[1:3], "big"), record[3]
        payload = record[4:4 + count]
        if kind == 0x00:
            for i, value in enumerate(payload):
                addr = base + offset + i
                if limit is not None and addr >= limit:
                    raise fail(f"data at 0x{addr:05X} lies beyond the {limit}-byte flash")
                data[addr] = value
        elif kind == 0x01:
            ended = True
        elif kind == 0x02 and count == 2:
            base = int.from_bytes(payload, "big") << 4
        elif kind == 0x04 and count == 2:
            base = int.from_bytes(payload, "big") << 16
        elif kind in (0x03, 0x05):
            continue  # start address: meaningless for an AVR, ignored
        else:
            raise fail(f"unsupported record type 0x{kind:02X}")
    if not ended:
        raise FlashingError(f"{path}: no end-of-file record (truncated file?)")
    if not data:
        raise FlashingError(f"{path}: the image holds no data")
    return HexImage(path, data)
