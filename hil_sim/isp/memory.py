"""The non-volatile state of an ATmega162 as its programming interface sees
it: flash, EEPROM, fuses, lock bits, signature and calibration byte.

The operations are the chip's, with the chip's rules (datasheet, "Memory
Programming"): a flash page write can only clear bits (cells are erased by a
chip erase only), an EEPROM write erases the byte first, lock bits can only
be programmed (cleared) and come back only with a chip erase, the fuses are
frozen once lock mode 2 or 3 is set, and chip erase keeps the EEPROM when the
EESAVE fuse is programmed.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from hexbot.protocol import wire

FLASH_SIZE = wire.FLASH_BYTES
FLASH_PAGE = 128  # bytes; 64 words
EEPROM_SIZE = 512
EEPROM_PAGE = 4

# Unused bits read as one (datasheet: extended fuse bits 7..5 and 0, lock
# byte bits 7..6).
EFUSE_UNUSED = 0xE1
LOCK_UNUSED = 0xC0
HFUSE_SPIEN = 0x20
HFUSE_EESAVE = 0x08
LOCK_LB_MASK = 0x03  # LB2:LB1; 11 = mode 1 (no lock)


@dataclass
class Atmega162Memory:
    """Memory-backed ATmega162 (or, with another ``signature``, any part
    with the same ISP instruction set, for the wrong-device case)."""

    flash: bytearray = field(default_factory=lambda: bytearray(b"\xff" * FLASH_SIZE))
    eeprom: bytearray = field(default_factory=lambda: bytearray(b"\xff" * EEPROM_SIZE))
    # Table 3-6 values: the modules leave the factory programmed with them.
    lfuse: int = wire.FUSE_LOW
    hfuse: int = wire.FUSE_HIGH
    efuse: int = wire.FUSE_EXTENDED
    lock: int = 0xFF
    signature: bytes = wire.SIGNATURE
    calibration: int = 0xA4  # OSCCAL factory value; any byte a real part may hold

    def __post_init__(self) -> None:
        if len(self.flash) != FLASH_SIZE or len(self.eeprom) != EEPROM_SIZE:
            raise ValueError(f"flash must hold {FLASH_SIZE} bytes and EEPROM {EEPROM_SIZE} bytes")
        if len(self.signature) != 3:
            raise ValueError(f"signature must be 3 bytes, got {self.signature.hex(' ')}")
        self.efuse |= EFUSE_UNUSED
        self.lock |= LOCK_UNUSED

    # -- lock state -----------------------------------------------------
    @property
    def lock_mode(self) -> int:
        """1 (no lock), 2 (no further programming) or 3 (nor verification)."""
        lb = self.lock & LOCK_LB_MASK
        return {0b11: 1, 0b10: 2}.get(lb, 3)

    @property
    def spi_enabled(self) -> bool:
        return not self.hfuse & HFUSE_SPIEN

    # -- operations ------------------------------------------------------
    def chip_erase(self) -> None:
        self.flash[:] = b"\xff" * FLASH_SIZE
        if self.hfuse & HFUSE_EESAVE:  # EESAVE unprogrammed: EEPROM goes too
            self.eeprom[:] = b"\xff" * EEPROM_SIZE
        self.lock = 0xFF

    def read_flash(self, byte_addr: int) -> int:
        if self.lock_mode == 3:
            return 0xFF  # verification disabled; we read ones (decision in docs)
        return self.flash[byte_addr % FLASH_SIZE]

    def write_flash_page(self, byte_addr: int, data: bytes) -> None:
        """Program one page from the page buffer: bits can only go 1 -> 0."""
        if self.lock_mode != 1:
            return
        start = (byte_addr % FLASH_SIZE) & ~(FLASH_PAGE - 1)
        for i, value in enumerate(data[:FLASH_PAGE]):
            self.flash[start + i] &= value

    def read_eeprom(self, addr: int) -> int:
        if self.lock_mode == 3:
            return 0xFF
        return self.eeprom[addr % EEPROM_SIZE]

    def write_eeprom(self, addr: int, value: int) -> None:
        if self.lock_mode != 1:
            return
        self.eeprom[addr % EEPROM_SIZE] = value & 0xFF

    def write_fuse(self, which: str, value: int) -> None:
        if self.lock_mode != 1:
            return
        if which == "lfuse":
            self.lfuse = value & 0xFF
        elif which == "hfuse":
            # SPIEN is not accessible in serial programming mode.
            self.hfuse = (value & ~HFUSE_SPIEN & 0xFF) | (self.hfuse & HFUSE_SPIEN)
        elif which == "efuse":
            self.efuse = (value | EFUSE_UNUSED) & 0xFF
        else:
            raise ValueError(f"no fuse byte {which!r}")

    def write_lock(self, value: int) -> None:
        # Programming can only clear lock bits; erasing them needs chip erase.
        self.lock &= value | LOCK_UNUSED

    def snapshot(self) -> Atmega162Memory:
        return Atmega162Memory(
            bytearray(self.flash), bytearray(self.eeprom), self.lfuse, self.hfuse,
            self.efuse, self.lock, bytes(self.signature), self.calibration,
        )
