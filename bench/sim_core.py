"""Speed of the simulator core (hexbot.hil_sim._avr), printed as JSON.

    hexbot bench sim-core [--busy-cycles N] [--idle-seconds S] [--repeat N]

Measures, in one run on this machine:
  raw_simavr      simavr's own run loop (avr_callback_run_raw) on its stock
                  atmega128 core, one MCU in a CPU-bound loop: the reference
                  (bench/raw_simavr.c, a program of its own).
  raw_loop_m162   the same stock loop on our ATmega162 core (no scheduler).
  busy_1, busy_14 our Cluster, 1 and 14 ATmega162s in the same CPU-bound loop.
  idle_7_modules  14 MCUs (7 modules) of idle firmware: a 10 ms timer tick,
                  idle sleep in between.
  idle_50_modules 100 MCUs (50 modules) of the same.
  firmware_7_modules  the real images firmware/build/comm.elf + control.elf,
                  7 wired pairs, IR and debug USARTs watched and drained
                  (skipped when the firmware is not built).
Throughput is simulated cycles per wall-clock second over all MCUs; the idle
runs report the real-time factor (simulated seconds per wall second).  Each
number is the best of --repeat runs (the machine is shared).
"""

from __future__ import annotations

import argparse
import json
import os
import platform
import time
from pathlib import Path

from hexbot.bench.raw import avr_program, raw_simavr_seconds
from hexbot.cli_args import count, seconds
from hexbot.hil_sim._avr import SIMAVR_VERSION, Cluster
from hexbot.protocol.wire import F_CPU

FIRMWARE = Path(__file__).resolve().parent.parent / "firmware" / "build"


def best_of(repeat: int, runs: dict) -> dict:
    """Interleave the measurements so machine load hits all of them alike."""
    times = {name: float("inf") for name in runs}
    for _ in range(repeat):
        for name, fn in runs.items():
            times[name] = min(times[name], fn())
    return times


def time_cluster(elf: str, count: int, cycles: int, quantum: int = 1000) -> float:
    c = Cluster(quantum)
    for i in range(count):
        c.add_mcu(elf, f"mcu{i}")
    t0 = time.perf_counter()
    reached = c.run(cycles)
    elapsed = time.perf_counter() - t0
    assert reached == cycles
    return elapsed


def time_firmware(pairs: int, cycles: int) -> float:
    """7 modules of real firmware as the simulator wires them (comm/control)."""
    c = Cluster()
    for i in range(pairs):
        comm = c.add_mcu(str(FIRMWARE / "comm.elf"), f"comm{i}")
        control = c.add_mcu(str(FIRMWARE / "control.elf"), f"control{i}")
        c.connect_uart(comm, 0, control, 0)
        c.set_input(control, "C", 0xFF, i + 1)
        c.watch_uart(comm, 1)
        c.watch_uart(control, 1)
    t0 = time.perf_counter()
    while c.run(cycles) < cycles:
        for m in range(2 * pairs):
            c.uart_take(m, 1)
    return time.perf_counter() - t0


def add_arguments(ap: argparse.ArgumentParser) -> None:
    ap.add_argument("--busy-cycles", type=count, default=20_000_000,
                    help="cycles per MCU for the CPU-bound runs (busy_14: a quarter)")
    ap.add_argument("--idle-seconds", type=seconds, default=10.0,
                    help="simulated seconds for the idle clusters")
    ap.add_argument("--repeat", type=count, default=3)


def run(args: argparse.Namespace) -> int:
    cycles = args.busy_cycles

    busy162 = avr_program("cpuloop", "atmega162")
    busy128 = avr_program("cpuloop", "atmega128")
    idle = avr_program("idle", "atmega162")

    def raw(elf: str, core: str) -> float:
        return raw_simavr_seconds(elf, core, cycles)

    idle_seconds = args.idle_seconds
    idle_cycles = int(idle_seconds * F_CPU)
    runs = {
        "raw": lambda: raw(busy128, "atmega128"),
        "raw162": lambda: raw(busy162, "atmega162"),
        "busy1": lambda: time_cluster(busy162, 1, cycles),
        "busy14": lambda: time_cluster(busy162, 14, cycles // 4),
        "idle7": lambda: time_cluster(idle, 14, idle_cycles),
        "idle50": lambda: time_cluster(idle, 100, idle_cycles),
    }
    have_firmware = (FIRMWARE / "comm.elf").exists() and (FIRMWARE / "control.elf").exists()
    if have_firmware:
        runs["fw7"] = lambda: time_firmware(7, idle_cycles)
    t = best_of(args.repeat, runs)
    raw_s, busy1_s, busy14_s, idle7_s, idle50_s = (
        t["raw"], t["busy1"], t["busy14"], t["idle7"], t["idle50"])

    raw_rate = cycles / raw_s
    result = {
        "command": f"hexbot bench sim-core --busy-cycles {cycles} "
                   f"--idle-seconds {args.idle_seconds} --repeat {args.repeat}",
        "machine": {"python": platform.python_version(), "cpus": os.cpu_count(),
                    "simavr": SIMAVR_VERSION},
        "raw_simavr": {"mcus": 1, "cycles_per_s": round(raw_rate)},
        "raw_loop_m162": {"mcus": 1, "cycles_per_s": round(cycles / t["raw162"]),
                          "vs_raw": round(cycles / t["raw162"] / raw_rate, 3)},
        "busy_1": {"mcus": 1, "cycles_per_s": round(cycles / busy1_s),
                   "vs_raw": round(cycles / busy1_s / raw_rate, 3)},
        "busy_14": {"mcus": 14, "cycles_per_s": round(14 * (cycles // 4) / busy14_s),
                    "vs_raw": round(14 * (cycles // 4) / busy14_s / raw_rate, 3)},
        "idle_7_modules": {"mcus": 14, "simulated_s": idle_seconds,
                           "realtime_factor": round(idle_seconds / idle7_s, 1)},
        "idle_50_modules": {"mcus": 100, "simulated_s": idle_seconds,
                            "realtime_factor": round(idle_seconds / idle50_s, 1)},
        "firmware_7_modules": (
            {"mcus": 14, "simulated_s": idle_seconds,
             "realtime_factor": round(idle_seconds / t["fw7"], 1)}
            if have_firmware else "skipped: firmware/build/comm.elf, control.elf not built"),
        "targets": {"idle_7_modules_realtime_factor": 20, "idle_50_modules_realtime_factor": 2,
                    "busy_vs_raw_min": 0.7},
    }
    print(json.dumps(result, indent=2))
    return 0
