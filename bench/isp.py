"""Throughput of the STK500v2 engine and the ATmega162 ISP model, no I/O.

    hexbot bench isp [--repeat 5]

Programs and reads back the whole 16 KiB flash with the frames avrdude sends
for an m162 (128-byte pages, 256-byte reads) and prints the best time.
"""

from __future__ import annotations

import argparse
import random
import time

from hexbot.cli_args import count
from hexbot.hil_sim.isp import standalone_programmer
from hexbot.hil_sim.isp.avr068 import Cmd
from hexbot.hil_sim.isp.framing import encode
from hexbot.hil_sim.isp.memory import FLASH_PAGE, FLASH_SIZE


def session_frames(image: bytes) -> list[bytes]:
    bodies = [bytes((Cmd.ENTER_PROGMODE_ISP, 200, 100, 25, 32, 0, 0x53, 3, 0xAC, 0x53, 0, 0)),
              bytes((Cmd.CHIP_ERASE_ISP, 9, 0, 0xAC, 0x80, 0, 0)),
              bytes((Cmd.LOAD_ADDRESS, 0, 0, 0, 0))]
    for addr in range(0, FLASH_SIZE, FLASH_PAGE):
        bodies.append(bytes((Cmd.PROGRAM_FLASH_ISP, 0, FLASH_PAGE, 0xC1, 10, 0x40, 0x4C, 0x20,
                             0xFF, 0xFF)) + image[addr:addr + FLASH_PAGE])
    bodies.append(bytes((Cmd.LOAD_ADDRESS, 0, 0, 0, 0)))
    bodies += [bytes((Cmd.READ_FLASH_ISP, 1, 0, 0x20))] * (FLASH_SIZE // 256)
    bodies.append(bytes((Cmd.LEAVE_PROGMODE_ISP, 1, 1)))
    return [encode(i & 0xFF, body) for i, body in enumerate(bodies)]


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--repeat", type=count, default=5)


def run(args: argparse.Namespace) -> int:
    image = bytes(random.Random(1).randrange(256) for _ in range(FLASH_SIZE))
    frames = session_frames(image)
    best = float("inf")
    for _ in range(args.repeat):
        programmer = standalone_programmer()
        start = time.perf_counter()
        for frame in frames:
            programmer.feed(frame)
        best = min(best, time.perf_counter() - start)
        assert bytes(programmer.target.backend.memory.flash) == image
    spi = programmer.stats.spi_bytes
    print(f"write+read 16 KiB through the engine: best {best * 1000:.1f} ms of {args.repeat} "
          f"({2 * FLASH_SIZE / best / 1024:.0f} KiB/s, {spi} SPI bytes, "
          f"{spi / best / 1e6:.2f} M SPI bytes/s)")
    return 0
