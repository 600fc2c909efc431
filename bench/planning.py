"""Benchmark of the hex reconfiguration planners: planning time and moves vs module count.

    hexbot bench planning                     # per family and size (markdown), the issue's table
    hexbot bench planning --sizes 10,30 --seeds 5 --json   # one JSON object per pair
    hexbot bench planning --small             # exact (A*) vs robust on the small bank
    hexbot bench planning --cases             # the older per-case table (below)

The per-family table (``--families blob,scramble``, with and without the
fixed module at (0, 0)): each pair is planned in a fresh process (peak
memory = that process's maximum resident set, interpreter and libraries
included) with the robust mode's time budget, then replayed by the
independent checker (:mod:`hexbot.planning.checker`); a pair counts as planned
only if the checker accepts it. Bounds: :mod:`hexbot.planning.bounds`
(moves: assignment; time steps: bottleneck). Families: ``blob`` = two
independent random blobs grown from (0, 0); ``scramble`` = a blob and the
cells after 3n random legal moves of it (:mod:`hexbot.planning.generate`).

Families of ``--cases`` (deterministic, no randomness outside the given seeds):

* ``parallelogram``: a w x h parallelogram into a wider, flatter one with the
  same module count, sharing the corner cell (0, 0);
* ``blob``: two seeded random compact blobs of the same size, both grown from
  (0, 0), so they overlap (success rate, plan quality);
* ``apart``: the same pairs with the goal shifted right until it no longer
  overlaps the initial configuration (one empty column between them);
* ``thesis``: Test_All_S02 with both faithful planners and the robust one;
* ``--scan N``: N random pairs of 3 to 30 modules, the initial of random
  compactness (the property test's generator); prints how many each method
  planned and every failure.

Columns: ``method`` (robust mode: direct, direct backwards, middle ball, canonical strip),
moves and time steps with their lower bounds and the ratio plan / bound.
"""

from __future__ import annotations

import argparse
import json
import time
from pathlib import Path

from hexbot.planning.budget import DEFAULT_BUDGET
from hexbot.planning.config_io import load_configuration
from hexbot.planning.configuration import Configuration
from hexbot.planning.generate import parallelogram, random_blob
from hexbot.planning.robust import plan_robust, step_lower_bound
from hexbot.planning.thesis.planner import plan_faithful

EXAMPLES = Path(__file__).resolve().parents[1] / "planning" / "examples"

#: module count -> (initial w, h, goal w, h)
PARALLELOGRAMS = {
    10: (5, 2, 10, 1),
    30: (6, 5, 10, 3),
    100: (10, 10, 20, 5),
    300: (20, 15, 30, 10),
    1000: (40, 25, 50, 20),
}


def timed(fn):
    start = time.perf_counter()
    result = fn()
    return result, time.perf_counter() - start


def row(family: str, n: int, plan, seconds: float, initial, goal) -> dict:
    return {
        "family": family,
        "modules": n,
        "mode": plan.mode,
        "reached": plan.reached,
        "seconds": round(seconds, 3),
        "moves": plan.move_count,
        "time_steps": plan.time_steps,
        "move_lower_bound": plan.lower_bound,
        "step_lower_bound": step_lower_bound(initial, goal),
        "method": plan.method,
        "reason": plan.reason,
    }


def bench_parallelograms(sizes: list[int]) -> list[dict]:
    out = []
    for n in sizes:
        w, h, w2, h2 = PARALLELOGRAMS[n]
        a, b = parallelogram(w, h), parallelogram(w2, h2)
        plan, dt = timed(lambda a=a, b=b: plan_robust(Configuration.from_cells(a), b))
        out.append(row("parallelogram", n, plan, dt, a, b))
    return out


def apart(initial: frozenset, goal: frozenset) -> frozenset:
    """``goal`` shifted right so that one empty column separates it from ``initial``."""
    dx = max(x for x, _ in initial) - min(x for x, _ in goal) + 2
    return frozenset((x + dx, y) for x, y in goal)


def bench_blobs(sizes: list[int], seeds: int, family: str = "blob") -> list[dict]:
    out = []
    for n in sizes:
        for seed in range(seeds):
            a, b = random_blob(n, 2 * seed, 0.8), random_blob(n, 2 * seed + 1, 0.8)
            if family == "apart":
                b = apart(a, b)
            plan, dt = timed(lambda a=a, b=b: plan_robust(Configuration.from_cells(a), b))
            out.append(row(f"{family} seed {seed}", n, plan, dt, a, b))
    return out


def scan(count: int) -> None:
    """Completion over many small random pairs (counts per method, failures listed)."""
    import random
    from collections import Counter

    methods: Counter[str] = Counter()
    for i in range(count):
        rng = random.Random(i)
        size, sa, sb = rng.randint(3, 30), rng.randint(0, 10**6), rng.randint(0, 10**6)
        a = random_blob(size, sa, compact=random.Random(sa).random())
        b = random_blob(size, sb, compact=0.6)
        plan = plan_robust(Configuration.from_cells(a), b)
        methods[plan.method if plan.reached else "not reached"] += 1
        if not plan.reached:
            print(f"pair {i} (size {size}, seeds {sa}, {sb}): {plan.reason}")
    print(f"{count} random pairs: " + ", ".join(f"{k}: {v}" for k, v in methods.most_common()))


def bench_thesis() -> list[dict]:
    initial = load_configuration(EXAMPLES / "test_all_s02_initial.txt")
    goal = load_configuration(EXAMPLES / "test_all_s02_goal.txt").cells
    out = []
    for label, fn in (
        ("faithful-serial", lambda: plan_faithful(initial, goal, parallel=False)),
        ("faithful-parallel", lambda: plan_faithful(initial, goal, parallel=True)),
        ("robust", lambda: plan_robust(initial, goal)),
    ):
        plan, dt = timed(fn)
        out.append(row(f"Test_All_S02 {label}", len(initial), plan, dt, initial.cells, goal))
    return out


def add_arguments(parser: argparse.ArgumentParser) -> None:
    parser.add_argument("--sizes", default=None,
                        help="module counts (families: default 10,30,100,300,1000; --cases: "
                             "parallelogram sizes among " + ",".join(map(str, PARALLELOGRAMS))
                             + ")")
    parser.add_argument("--families", default="blob,scramble", help="families to plan")
    parser.add_argument("--fixed", choices=("both", "yes", "no"), default="both",
                        help="families: with the module at (0, 0) fixed to the base, without, "
                             "or both (default)")
    parser.add_argument("--budget", type=float, default=DEFAULT_BUDGET,
                        help=f"families: time budget per pair in seconds "
                             f"(default {DEFAULT_BUDGET:g})")
    parser.add_argument("--blob-sizes", default="10,30,100,1000",
                        help="--cases: random blob sizes")
    parser.add_argument("--apart-sizes", default="10,30,100",
                        help="--cases: random blob sizes with the goal apart from the initial")
    parser.add_argument("--seeds", type=int, default=None,
                        help="pairs per size (families: default per size, see SEEDS; "
                             "--cases: 5)")
    parser.add_argument("--json", action="store_true", help="JSON lines instead of a table")
    parser.add_argument("--cases", action="store_true",
                        help="the per-case table: thesis, parallelograms, blobs, apart")
    parser.add_argument("--small", action="store_true",
                        help="only: exact vs robust on the small bank (optimality gap)")
    parser.add_argument("--scan", type=int, metavar="N",
                        help="only: completion over N small random pairs")


def run(args: argparse.Namespace) -> int:
    from hexbot.bench.planning_families import run_families, run_small

    if args.scan:
        scan(args.scan)
        return 0
    if args.small:
        return run_small(args)
    if not args.cases:
        return run_families(args)
    args.seeds = 5 if args.seeds is None else args.seeds
    sizes = [int(s) for s in (args.sizes or "10,30,100,300,1000").split(",") if s]
    blob_sizes = [int(s) for s in args.blob_sizes.split(",") if s]
    apart_sizes = [int(s) for s in args.apart_sizes.split(",") if s]
    rows = (bench_thesis() + bench_parallelograms(sizes) + bench_blobs(blob_sizes, args.seeds)
            + bench_blobs(apart_sizes, args.seeds, "apart"))
    if args.json:
        for r in rows:
            print(json.dumps(r))
        return 0
    print(markdown_table(rows))
    failed = [r for r in rows if not r["reached"] and "faithful" not in r["family"]]
    for r in failed:
        print(f"\n{r['family']} ({r['modules']}): {r['reason']}")
    return 0


def markdown_table(rows: list[dict]) -> str:
    """The table of docs/planning.md (also printed by ``hexbot sweep report``)."""
    lines = ["| case | modules | method | reached | time (s) | moves | move bound | ratio "
             "| steps | step bound | ratio |",
             "|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|"]
    for r in rows:
        lines.append(
            f"| {r['family']} | {r['modules']} | {r['method'] or '-'} | "
            f"{'yes' if r['reached'] else 'no'} | {r['seconds']:.3f} | {r['moves']} | "
            f"{r['move_lower_bound']} | {ratio(r['moves'], r['move_lower_bound'])} | "
            f"{r['time_steps']} | {r['step_lower_bound']} | "
            f"{ratio(r['time_steps'], r['step_lower_bound'])} |")
    return "\n".join(lines)


def ratio(value: int, bound: int | None) -> str:
    return f"{value / bound:.1f}" if bound else "-"
