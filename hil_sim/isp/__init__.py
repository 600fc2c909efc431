"""Simulated in-system programming: an STK500v2 programmer (AVR068) wired
to the ISP side of simulated ATmega162 chips, served on pseudo-terminals so
that unchanged avrdude can program them.

Layers, each testable alone: :mod:`framing` (bytes <-> frames),
:mod:`stk500v2` (the programmer, bytes in / bytes out), :mod:`chip` (the
chip's serial programming instructions), :mod:`memory` (the chip's
non-volatile memory), :mod:`cluster` (the same chip on a simulated board),
:mod:`pty_server` (the ports).
"""

from hexbot.hil_sim.isp.chip import Atmega162Isp, IspBackend, IspTarget, MemoryBackend
from hexbot.hil_sim.isp.memory import Atmega162Memory
from hexbot.hil_sim.isp.pty_server import IspPtyServer
from hexbot.hil_sim.isp.stk500v2 import Stk500v2Programmer


def standalone_programmer(memory: Atmega162Memory | None = None) -> Stk500v2Programmer:
    """An STK500v2 wired to one memory-backed ATmega162."""
    return Stk500v2Programmer(Atmega162Isp(MemoryBackend(memory)))


__all__ = [
    "Atmega162Isp", "Atmega162Memory", "IspBackend", "IspPtyServer", "IspTarget",
    "MemoryBackend", "Stk500v2Programmer", "standalone_programmer",
]
