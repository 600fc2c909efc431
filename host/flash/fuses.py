"""ATmega162 fuse and lock bytes: what they mean, and which would lock the
user out of a HexBot board.

Bits are active low: 0 = programmed. Layout (ATmega162 datasheet, "Fuse
Bits"): low = CKDIV8 CKOUT SUT1 SUT0 CKSEL3..0; high = OCDEN JTAGEN SPIEN
WDTON EESAVE BOOTSZ1 BOOTSZ0 BOOTRST; extended = - - - M161C BODLEVEL2..0 -;
lock = - - BLB12 BLB11 BLB02 BLB01 LB2 LB1.

The ATmega162 has no RSTDISBL fuse (its RESET pin is dedicated), so the
classic "reset disabled" lock-out cannot happen on it. On the HexBot boards
XTAL1/XTAL2 are not connected (thesis Tables 3-3, 3-4): any clock source but
the internal RC oscillator stops the chip, and a stopped chip cannot be
reached by ISP either; that is the lock-out these boards really risk.
"""

from __future__ import annotations

from dataclasses import dataclass

from hexbot.protocol import pins, wire

HFUSE_JTAGEN = 0x40
HFUSE_SPIEN = 0x20
HFUSE_WDTON = 0x10
EFUSE_M161C = 0x10
CKSEL_INTERNAL_RC = 0b0010
LFUSE_CKDIV8 = 0x80  # programmed (0): the 8 MHz RC clock divided by 8, Table 3-6's 1 MHz
LFUSE_CKOUT = 0x40  # programmed (0): the system clock drives CLOCK_OUT_PIN
CLOCK_OUT_PIN = ("B", 0)  # ATmega162 datasheet, "Clock Output Buffer"

CLOCK_SOURCES = {
    0b0000: "an external clock on XTAL1",
    0b0001: "a reserved clock setting",
    0b0010: "the internal RC oscillator",
    0b0011: "a reserved clock setting",
}


def clock_source(lfuse: int) -> str:
    cksel = lfuse & 0x0F
    if cksel in CLOCK_SOURCES:
        return CLOCK_SOURCES[cksel]
    if cksel < 0b1000:
        return "an external low-frequency crystal"
    return "an external crystal or resonator"


@dataclass(frozen=True)
class FuseSet:
    lfuse: int = wire.FUSE_LOW
    hfuse: int = wire.FUSE_HIGH
    efuse: int = wire.FUSE_EXTENDED
    lock: int = 0xFF

    def __str__(self) -> str:
        return (f"low 0x{self.lfuse:02X}, high 0x{self.hfuse:02X}, "
                f"extended 0x{self.efuse:02X}, lock 0x{self.lock:02X}")

    @property
    def lock_mode(self) -> int:
        return {0b11: 1, 0b10: 2}.get(self.lock & 0x03, 3)


TABLE_3_6 = FuseSet()


@dataclass(frozen=True)
class FuseProblem:
    """One reason not to write a fuse set; ``lockout`` if it would cut ISP
    off for good, else it "only" breaks the board's firmware."""

    text: str
    lockout: bool


def check_fuses(fuses: FuseSet) -> list[FuseProblem]:
    """Everything dangerous about writing ``fuses`` to a HexBot board."""
    problems: list[FuseProblem] = []
    if fuses.hfuse & HFUSE_SPIEN:
        problems.append(FuseProblem(
            f"high fuse 0x{fuses.hfuse:02X} leaves SPIEN unprogrammed: serial programming "
            "would be disabled and only a high-voltage programmer could reach the chip again",
            lockout=True))
    if fuses.lfuse & 0x0F != CKSEL_INTERNAL_RC:
        problems.append(FuseProblem(
            f"low fuse 0x{fuses.lfuse:02X} selects {clock_source(fuses.lfuse)} "
            f"(CKSEL={fuses.lfuse & 0x0F:04b}), but the HexBot boards have nothing on "
            "XTAL1/XTAL2: the chip would stop and ISP could not reach it any more",
            lockout=True))
    if fuses.lock & 0x03 != 0x03:
        what = ("flash and EEPROM could no longer be read or verified"
                if fuses.lock_mode == 3 else "flash and EEPROM could no longer be programmed")
        problems.append(FuseProblem(
            f"lock byte 0x{fuses.lock:02X} sets lock mode {fuses.lock_mode}: {what}, and the "
            "fuses are frozen, until a chip erase", lockout=True))
    if fuses.lock & 0x3C != 0x3C:
        problems.append(FuseProblem(
            f"lock byte 0x{fuses.lock:02X} programs boot lock bits (BLB0x/BLB1x): the "
            "firmware's own flash access would be restricted", lockout=False))
    if not fuses.hfuse & HFUSE_JTAGEN:
        problems.append(FuseProblem(
            f"high fuse 0x{fuses.hfuse:02X} enables JTAG: PC4..PC7 (DIP switches, LEDs) "
            "would turn into the JTAG port (Table 3-6 keeps JTAG off)", lockout=False))
    if not fuses.efuse & EFUSE_M161C:
        problems.append(FuseProblem(
            f"extended fuse 0x{fuses.efuse:02X} programs M161C: the chip would act as an "
            "ATmega161 and the ATmega162 firmware would not run", lockout=False))
    return problems


def _clock_out_warning() -> str:
    port, bit = CLOCK_OUT_PIN
    used = [f"the control board's electromagnet {i + 1} ({sign}) pin"
            for sign, pins_ in (("+", pins.MAGNET_POS_PINS), ("-", pins.MAGNET_NEG_PINS))
            for i, pin in enumerate(pins_) if pin == CLOCK_OUT_PIN]
    return (f"CKOUT puts the clock on P{port}{bit}" + (f", {used[0]}" if used else ""))


def fuse_notes(fuses: FuseSet) -> list[str]:
    """Harmless but noteworthy differences from Table 3-6."""
    notes = []
    changed = fuses.lfuse ^ TABLE_3_6.lfuse
    if fuses.lfuse & 0x0F == CKSEL_INTERNAL_RC and changed & LFUSE_CKDIV8:
        notes.append(f"low fuse 0x{fuses.lfuse:02X} is not Table 3-6's 0x{wire.FUSE_LOW:02X}: "
                     "its CKDIV8 bit differs, so the clock would not be 1 MHz and the "
                     "firmware's baud rates and 10 ms tick would be off")
    elif fuses.lfuse & 0x0F == CKSEL_INTERNAL_RC and changed:
        notes.append(f"low fuse 0x{fuses.lfuse:02X} is not Table 3-6's 0x{wire.FUSE_LOW:02X} "
                     "in its start-up time (SUT) or clock output (CKOUT) bits only: the "
                     "clock stays 1 MHz"
                     + (f"; {_clock_out_warning()}" if not fuses.lfuse & LFUSE_CKOUT else ""))
    if not fuses.hfuse & HFUSE_WDTON:
        notes.append("WDTON is programmed: the watchdog is always on")
    return notes
