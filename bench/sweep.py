"""The sweep engine: speed-up of 2 workers over 1, and what each task costs it.

    hexbot bench sweep               # one JSON object
    hexbot bench sweep --tasks 20 --noop 100

* ``speedup``: the same locomotion sweep (Salvador's rules on random maps,
  n = 5, ``--tasks`` seeds) on an embedded cluster of 1 and of 2 worker
  processes; wall time of the sweep itself, the cluster's start-up apart.
* ``overhead``: ``--noop`` tasks of :func:`noop` (a dotted-path kind that
  does nothing) on 1 worker: wall time per task is the engine's cost
  (submit, schedule, run, send back, write the row). For the locomotion
  sweep, the same cost is wall x workers minus the tasks' own time.
"""

from __future__ import annotations

import argparse
import importlib
import json
import os
import tempfile
import time
from pathlib import Path

from hexbot.cli_args import count
from hexbot.errors import HexBotError
from hexbot.sweep.engine import connect, run_sweep
from hexbot.sweep.results import ResultStore, read_table
from hexbot.sweep.spec import load_spec

LOCOMOTION = """kind = "locomotion"
[grid]
ruleset = "salvador"
n = 5
seed = {{ start = 0, stop = {tasks} }}
"""
NOOP = """kind = "hexbot.bench.sweep:noop"
[grid]
seed = {{ start = 0, stop = {tasks} }}
"""


def noop(seed: int) -> dict:
    """A task that does nothing: what is left of its time is the engine's."""
    return {"echo": seed}


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--tasks", type=count, default=40, help="locomotion tasks (40)")
    parser.add_argument("--noop", type=count, default=200, help="empty tasks (200)")


def timed_sweep(folder: Path, text: str, workers: int) -> dict:
    """Run the sweep ``text`` on a fresh embedded cluster of ``workers`` processes."""
    spec_path = folder / f"spec-{workers}-{time.monotonic_ns()}.toml"
    spec_path.write_text(text)
    spec = load_spec(spec_path)
    start = time.perf_counter()
    with connect(workers=workers) as client:
        client.wait_for_workers(workers)
        # every worker imports the kind before the clock starts: steady state only
        client.run(importlib.import_module, spec.kind.target.partition(":")[0])
        started = time.perf_counter()
        with ResultStore(spec_path.with_suffix(".results"), spec.kind.name,
                         spec.param_names) as store:
            outcome = run_sweep(spec, client, store)
        wall = time.perf_counter() - started
    if outcome.stored != outcome.total:
        raise HexBotError(f"bench sweep: only {outcome.stored} of {outcome.total} tasks ran")
    task_s = sum(read_table(spec_path.with_suffix(".results")).column("seconds").to_pylist())
    return {"workers": workers, "tasks": outcome.total,
            "cluster_start_s": round(started - start, 2), "wall_s": round(wall, 3),
            "task_s": round(task_s, 3),
            # how much of the workers' wall time went into tasks (1.0: never idle)
            "busy_fraction": round(task_s / (wall * workers), 3),
            "overhead_ms_per_task": round(1000 * (wall * workers - task_s) / outcome.total, 2)}


def run(args: argparse.Namespace) -> int:
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        one = timed_sweep(folder, LOCOMOTION.format(tasks=args.tasks), 1)
        two = timed_sweep(folder, LOCOMOTION.format(tasks=args.tasks), 2)
        empty = timed_sweep(folder, NOOP.format(tasks=args.noop), 1)
    print(json.dumps({
        "cores": os.cpu_count(),
        "load_average_1min": round(os.getloadavg()[0], 2),
        "locomotion_1_worker": one,
        "locomotion_2_workers": two,
        "speedup_2_over_1": round(one["wall_s"] / two["wall_s"], 2),
        "noop_1_worker": empty,
        "per_task_overhead_ms": round(1000 * empty["wall_s"] / empty["tasks"], 2),
    }, indent=2))
    return 0
