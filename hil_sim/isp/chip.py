"""The ISP side of a simulated ATmega162: SPI in, SPI out.

This is the chip's "Serial Downloading" interface (datasheet, Memory
Programming): while RESET is held low, every instruction is four bytes on
MOSI; the chip shifts out on MISO the byte it received one transfer earlier
(so the 0x53 of Programming Enable echoes during the third byte), except
during the fourth byte of a read instruction, which carries the data.
Nothing happens before a Programming Enable instruction; with the SPIEN fuse
unprogrammed the chip does not answer at all.

Where the memory comes from is a backend's business (:class:`IspBackend`):
a standalone memory model, or a board of the simulated cluster, which
hands its memory over while RESET is held and takes it back on release.
"""

from __future__ import annotations

from typing import Protocol

from hexbot.hil_sim.isp.memory import EEPROM_PAGE, FLASH_PAGE, Atmega162Memory

IDLE_MISO = 0xFF  # MISO is pulled high when the chip is not listening


class IspTarget(Protocol):
    """What a programmer drives: the RESET line and the SPI bus."""

    def set_reset(self, asserted: bool) -> None: ...

    def transfer(self, byte: int) -> int: ...


class IspBackend(Protocol):
    """Where the chip's non-volatile memory lives.

    ``acquire`` is called when RESET goes low and returns the memory, or
    ``None`` when no powered target is there; ``release`` is called when
    RESET goes high again, with ``changed`` true if anything was written.
    """

    def acquire(self) -> Atmega162Memory | None: ...

    def release(self, memory: Atmega162Memory, changed: bool) -> None: ...


class MemoryBackend:
    """A standalone chip whose memory simply stays in this object."""

    def __init__(self, memory: Atmega162Memory | None = None) -> None:
        self.memory = memory if memory is not None else Atmega162Memory()
        self.sessions = 0  # completed programming sessions (RESET released)

    def acquire(self) -> Atmega162Memory:
        return self.memory

    def release(self, memory: Atmega162Memory, changed: bool) -> None:
        self.sessions += 1


class Atmega162Isp:
    """Serial programming instruction decoder of one ATmega162."""

    def __init__(self, backend: IspBackend) -> None:
        self.backend = backend
        self._memory: Atmega162Memory | None = None
        self._enabled = False
        self._changed = False
        self._instr = bytearray(4)
        self._index = 0
        self._last_in = 0x00
        self._flash_buffer = bytearray(b"\xff" * FLASH_PAGE)
        self._eeprom_buffer: dict[int, int] = {}

    # -- pins -------------------------------------------------------------
    @property
    def in_reset(self) -> bool:
        return self._memory is not None

    @property
    def programming_enabled(self) -> bool:
        return self._enabled

    def set_reset(self, asserted: bool) -> None:
        if asserted and self._memory is None:
            self._memory = self.backend.acquire()
            self._index = 0
            self._enabled = False
            self._changed = False
        elif not asserted and self._memory is not None:
            memory, changed = self._memory, self._changed
            self._memory = None
            self._enabled = False
            self.backend.release(memory, changed)

    def transfer(self, byte: int) -> int:
        memory = self._memory
        if memory is None or not memory.spi_enabled:
            return IDLE_MISO
        byte &= 0xFF
        out = self._last_in
        self._instr[self._index] = byte
        self._last_in = byte
        if self._index < 3:
            self._index += 1
            return out
        self._index = 0
        result = self._execute(memory, *self._instr)
        return out if result is None else result

    # -- instruction set ----------------------------------------------------
    def _execute(self, mem: Atmega162Memory, b1: int, b2: int, b3: int, b4: int) -> int | None:
        if b1 == 0xAC and b2 == 0x53:
            self._enabled = True
            return None
        if not self._enabled:
            return None
        if b1 == 0xAC:
            return self._execute_ac(mem, b2, b4)
        if b1 & 0xF7 == 0x20:  # Read Program Memory, low (0x20) / high (0x28) byte
            word = ((b2 & 0x1F) << 8) | b3
            return mem.read_flash(word * 2 + (1 if b1 & 0x08 else 0))
        if b1 & 0xF7 == 0x40:  # Load Program Memory Page, low / high byte
            self._flash_buffer[(b3 & 0x3F) * 2 + (1 if b1 & 0x08 else 0)] = b4
            return None
        if b1 == 0x4C:  # Write Program Memory Page
            word = ((b2 & 0x1F) << 8) | b3
            mem.write_flash_page(word * 2, bytes(self._flash_buffer))
            self._flash_buffer[:] = b"\xff" * FLASH_PAGE
            self._changed = True
            return None
        eeprom_addr = ((b2 & 0x01) << 8) | b3
        if b1 == 0xA0:  # Read EEPROM Memory
            return mem.read_eeprom(eeprom_addr)
        if b1 == 0xC0:  # Write EEPROM Memory (one byte)
            mem.write_eeprom(eeprom_addr, b4)
            self._changed = True
            return None
        if b1 == 0xC1:  # Load EEPROM Memory Page
            self._eeprom_buffer[b3 & (EEPROM_PAGE - 1)] = b4
            return None
        if b1 == 0xC2:  # Write EEPROM Memory Page: only the loaded bytes change
            base = eeprom_addr & ~(EEPROM_PAGE - 1)
            for offset, value in sorted(self._eeprom_buffer.items()):
                mem.write_eeprom(base + offset, value)
            self._eeprom_buffer.clear()
            self._changed = True
            return None
        return self._execute_read(mem, b1, b2, b3)

    def _execute_ac(self, mem: Atmega162Memory, b2: int, b4: int) -> None:
        if b2 & 0xE0 == 0x80:  # Chip Erase
            mem.chip_erase()
            self._flash_buffer[:] = b"\xff" * FLASH_PAGE
        elif b2 == 0xA0:
            mem.write_fuse("lfuse", b4)
        elif b2 == 0xA8:
            mem.write_fuse("hfuse", b4)
        elif b2 == 0xA4:
            mem.write_fuse("efuse", b4)
        elif b2 & 0xE0 == 0xE0:
            mem.write_lock(b4)
        else:
            return None  # not an instruction of this part: ignored
        self._changed = True
        return None

    @staticmethod
    def _execute_read(mem: Atmega162Memory, b1: int, b2: int, b3: int) -> int | None:
        if b1 == 0x50 and b2 == 0x00:
            return mem.lfuse
        if b1 == 0x58 and b2 == 0x08:
            return mem.hfuse
        if b1 == 0x50 and b2 == 0x08:
            return mem.efuse
        if b1 == 0x58 and b2 == 0x00:
            return mem.lock
        if b1 == 0x30:  # Read Signature Byte; address 3 does not exist
            index = b3 & 0x03
            return mem.signature[index] if index < 3 else 0xFF
        if b1 == 0x38:
            return mem.calibration
        if b1 == 0xF0:  # Poll RDY/BSY: writes complete at once here, always ready
            return 0x00
        return None
