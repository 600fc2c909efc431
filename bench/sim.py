"""``hexbot bench sim``: simulator throughput, measured now on this machine.

    hexbot bench sim --json [--seconds S]

Cases (the real firmware images, the whole Python loop: IR medium, plant,
pin logs):
  idle-1   the ``single`` scenario, after boot;
  idle-7   ``flower7``, after boot;
  idle-50  50 modules in a hexagonal patch, after boot;
  busy-7   ``flower7`` while the PC runs a localization and rotation script
           (about 45 simulated seconds, whatever --seconds says).
Reference: raw simavr (its own run loop, stock atmega128 core) on one MCU in
a CPU-bound loop, measured in the same run (bench/raw_simavr.c).
"""

from __future__ import annotations

import argparse
import json
import time
from collections.abc import Callable

from hexbot.bench.raw import avr_program, raw_simavr_seconds
from hexbot.errors import HexBotError
from hexbot.hil_sim.geometry import Cell, neighbor
from hexbot.hil_sim.scenario import ModuleSpec, Scenario, load_scenario
from hexbot.hil_sim.simulator import Simulator
from hexbot.protocol.timing import BOOT_SLOTS, boot_seconds

BOOT_S = boot_seconds(range(1, BOOT_SLOTS + 1))  # simulated boot (every boot slot), excluded


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--json", action="store_true", help="print one JSON object")
    parser.add_argument(
        "--seconds", type=float, default=10.0, help="simulated seconds per idle case (default 10)"
    )
    parser.add_argument(
        "--repeat", type=int, default=3, help="runs per case; the best counts (default 3)"
    )


def patch_scenario(count: int) -> Scenario:
    """``count`` modules filling hexagonal rings around the origin, module 1 at the centre."""
    template = load_scenario("single").modules[0]
    cells: list[Cell] = [(0, 0)]
    ring = 1
    while len(cells) < count:
        cell = (ring, 0)  # walk ring r: start r steps along side 3, then turn
        for side in (5, 6, 1, 2, 3, 4):
            for _ in range(ring):
                cell = neighbor(cell, side)
                cells.append(cell)
        ring += 1
    modules = [
        ModuleSpec(i, cell, 0, template.firmware, 0) for i, cell in enumerate(cells[:count], 1)
    ]
    return Scenario(f"patch{count}", modules, base=1, seed=1)


def _measure(sim: Simulator, seconds: float, script: Callable[[Simulator], None] | None) -> dict:
    mcus = 2 * len(sim.modules)
    start_cycle = sim.cycle
    t0 = time.perf_counter()
    if script is None:
        sim.run(seconds)
    else:
        script(sim)
        remaining = seconds - (sim.cycle - start_cycle) / sim.hz
        if remaining > 0:
            sim.run(remaining)
    wall = time.perf_counter() - t0
    simulated = (sim.cycle - start_cycle) / sim.hz
    return {
        "sim_seconds_per_wall_second": round(simulated / wall, 2),
        "cycles_per_wall_second": round(simulated * sim.hz * mcus / wall),
    }


def localize_and_rotate(sim: Simulator) -> None:
    """Ref on module 1, Localize everyone, then a CW rotation of module 2 about module 1.

    Each step waits for the last acknowledgement it causes, as a PC would.
    """
    from hexbot.protocol.frames import encode_pc, make, select

    last = f"M{max(sim.modules):02d}: ACK".encode()
    script = [
        (select([1]), b"M01: ACKE"),
        (make("Ref"), b"S01: ACKA"),
        (select([0]), last + b"E"),
        (make("Localize"), last + b"B"),
        (select([1, 2]), b"M02: ACKE"),
        (make("CW", 4, 8, 4, 9, 4, 8, 4, 9), b"M02: ACKC"),
    ]
    for command, reply in script:
        sim.pc_write(encode_pc(command))
        sim.expect(reply, timeout=60.0)


def raw_reference(seconds: float, repeat: int = 3) -> int:
    elf = avr_program("cpuloop", "atmega128")
    cycles = round(seconds * 1_000_000)
    best = min(raw_simavr_seconds(elf, "atmega128", cycles) for _ in range(max(repeat, 1)))
    return round(cycles / best)


def measure(seconds: float, repeat: int = 3) -> dict:
    cases = []
    for name, make_scenario, script in (
        ("idle-1", lambda: load_scenario("single"), None),
        ("idle-7", lambda: load_scenario("flower7"), None),
        ("idle-50", lambda: patch_scenario(50), None),
        ("busy-7", lambda: load_scenario("flower7"), localize_and_rotate),
    ):
        runs = []
        for _ in range(repeat):
            sim = Simulator(make_scenario())
            sim.run(BOOT_S)
            runs.append(_measure(sim, seconds, script))
        best = max(runs, key=lambda r: r["cycles_per_wall_second"])
        cases.append({"name": name, **best})
    return {"raw_simavr_cycles_per_wall_second": raw_reference(2.0, repeat), "cases": cases}


def run(args: argparse.Namespace) -> int:
    if args.seconds <= 0:
        raise HexBotError(f"--seconds must be positive, not {args.seconds}")
    if args.repeat < 1:
        raise HexBotError(f"--repeat must be at least 1, not {args.repeat}")
    result = measure(args.seconds, args.repeat)
    if args.json:
        print(json.dumps(result))
        return 0
    print(f"raw simavr: {result['raw_simavr_cycles_per_wall_second']:,} cycles/s (1 MCU)")
    for case in result["cases"]:
        print(f"{case['name']:8} {case['sim_seconds_per_wall_second']:8.2f} x real time  "
              f"{case['cycles_per_wall_second']:>14,} cycles/s")
    return 0
