"""Intel HEX reading (the ``intelhex`` package), strict enough to stop a bad
image before avrdude.

intelhex checks every record (syntax, length, type, checksum, data written
twice); we add what an ATmega162 image needs (an end-of-file record, nothing
after it, nothing beyond the flash) and name the file and the line of every
problem.
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path

from intelhex import (
    AddressOverlapError,
    HexRecordError,
    IntelHex,
    IntelHexError,
    RecordChecksumError,
    RecordLengthError,
    RecordTypeError,
)

from hexbot.errors import FlashingError

# intelhex's error classes -> our wording, most specific first
PROBLEMS: tuple[tuple[type[IntelHexError], str], ...] = (
    (RecordChecksumError, "checksum error (the record's bytes do not sum to 0)"),
    (RecordLengthError, "record length does not match its byte count"),
    (RecordTypeError, "unsupported record type"),
    (HexRecordError, "not a record: it must start with ':' and hold hexadecimal digits"),
)


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


def _records(path: Path, text: str) -> IntelHex:
    try:
        image = IntelHex()
        image.loadhex(io.StringIO(text))  # stops at the end-of-file record
    except AddressOverlapError as exc:
        raise FlashingError(
            f"{path}:{exc.line}: data at 0x{exc.address:05X} is written twice"
        ) from exc
    except IntelHexError as exc:
        problem = next((p for cls, p in PROBLEMS if isinstance(exc, cls)), str(exc))
        where = f":{exc.line}" if hasattr(exc, "line") else ""
        raise FlashingError(f"{path}{where}: {problem}") from exc
    return image


def _first_line_writing(text: str, addresses: list[int]) -> tuple[int, int]:
    """(line, address) of the first record that writes one of ``addresses``:
    intelhex reports the line of a write to an address already taken."""
    taken = IntelHex()
    for addr in addresses:
        taken[addr] = 0xFF
    try:
        taken.loadhex(io.StringIO(text))
    except AddressOverlapError as exc:
        return exc.line, exc.address
    raise AssertionError("the addresses came from this text")


def read_hex(path: str | Path, limit: int | None = None) -> HexImage:
    """Parse ``path``; with ``limit``, refuse data at or above that address."""
    path = Path(path)
    try:
        text = path.read_text(encoding="ascii")
    except FileNotFoundError:
        raise FlashingError(f"{path}: no such image file") from None
    except (OSError, UnicodeDecodeError) as exc:
        why = exc.strerror if isinstance(exc, OSError) and exc.strerror else exc
        raise FlashingError(f"{path}: cannot read as Intel HEX: {why}") from exc
    image = _records(path, text)
    lines = text.split("\n")  # numbered as intelhex numbers them
    # every line up to the end-of-file record is a valid record: its type is at [7:9]
    end = next((n for n, s in enumerate(lines, 1) if s.strip()[7:9] == "01"), None)
    if end is None:
        raise FlashingError(f"{path}: no end-of-file record (truncated file?)")
    after = next((n for n, s in enumerate(lines[end:], end + 1) if s.strip()), None)
    if after is not None:
        raise FlashingError(f"{path}:{after}: data after the end-of-file record")
    data = {addr: image[addr] for addr in image.addresses()}
    if not data:
        raise FlashingError(f"{path}: the image holds no data")
    beyond = [addr for addr in data if limit is not None and addr >= limit]
    if beyond:
        line, addr = _first_line_writing(text, beyond)
        raise FlashingError(f"{path}:{line}: data at 0x{addr:05X} lies beyond the "
                            f"{limit}-byte flash")
    return HexImage(path, data)
