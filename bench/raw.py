"""What the simulator benchmarks build: the raw-simavr reference and small AVR programs.

The reference (raw_simavr.c: simavr's own run loop on one MCU, timed) and the
programs (tests/hil_sim/avr) are built on demand with make, so these
benchmarks run from a source checkout, as the tests do.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from hexbot.errors import HexBotError

BENCH = Path(__file__).resolve().parent
AVR_PROGRAMS = BENCH.parent / "tests" / "hil_sim" / "avr"


def _make(directory: Path, target: str) -> Path:
    if not (directory / "Makefile").exists():
        raise HexBotError(f"{directory} is missing: this benchmark runs from a source checkout")
    try:
        subprocess.run(["make", "-s", "-C", str(directory), target], check=True)
    except (OSError, subprocess.CalledProcessError) as exc:
        raise HexBotError(f"cannot build {directory / target}: {exc}") from exc
    return directory / target


def avr_program(name: str, mcu: str = "atmega162") -> str:
    """Path of tests/hil_sim/avr/NAME.c built for ``mcu``."""
    return str(_make(AVR_PROGRAMS, f"build/{name}.{mcu}.elf"))


def raw_simavr_times(elf: str, core: str, cycles: int) -> tuple[float, float]:
    """(wall, CPU) seconds simavr's own loop takes for ``cycles`` of ``elf`` on ``core``."""
    harness = _make(BENCH, "build/raw_simavr")
    try:
        out = subprocess.run([str(harness), core, elf, str(cycles)], check=True,
                             capture_output=True, text=True).stdout
    except subprocess.CalledProcessError as exc:
        raise HexBotError(f"{harness.name} {core} {elf}: {exc.stderr.strip()}") from exc
    done, wall, cpu = out.split()
    if int(done) < cycles:
        raise HexBotError(f"{elf} stopped after {done} of {cycles} cycles on {core}")
    return float(wall), float(cpu)


def raw_simavr_seconds(elf: str, core: str, cycles: int) -> float:
    """Wall seconds simavr's own loop takes for ``cycles`` of ``elf`` on ``core``."""
    return raw_simavr_times(elf, core, cycles)[0]
