"""Benchmark of the hex reconfiguration planners: planning time and moves vs module count.

    hexbot bench planning                     # per family and size (markdown), the issue's table
    hexbot bench planning --sizes 10,30 --seeds 5 --json   # one JSON object per pair
    hexbot bench planning --small             # exact (A*) vs robust on the small bank
    hexbot bench planning --cases             # the older per-case table (below)

The per-family table (``--families blob,scramble,holes``, with and without the
fixed module at (0, 0)): each pair is planned in a fresh process (peak
memory = that process's maximum resident set, interpreter and libraries
included) with the robust mode's time budget, then replayed by the
independent checker (:mod:`hexbot.planning.checker`); a pair counts as planned
only if the checker accepts it. Bounds: :mod:`hexbot.planning.bounds`
(moves: assignment; time steps: the pivot bound, and the plain bottleneck
beside it, the issue's first yardstick). Families: ``blob`` = two
independent random blobs grown from (0, 0); ``scramble`` = a blob and the
cells after 3n random legal moves of it; ``holes`` = two independent random
blobs with holes, about 4 % of n cells enclosed in pockets of 1-7 cells
(:mod:`hexbot.planning.generate`). A pair not planned makes the run exit 1.
Each pair runs in a fresh process (``spawn``, one task per child) so that its
peak memory is its own: ``ru_maxrss`` of that process, interpreter, numpy and
scipy included (about 79 MiB before any planning).

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
* ``--exhaustive N``: every ordered pair of distinct connected configurations
  of N modules (all polyhexes, sharing their smallest cell), free and with
  that cell's module fixed, each plan replayed by the independent checker;
* ``--hub N``: every connected configuration of N modules to the ball of N
  cells and back (so every pair is reachable through it), the same way.

Columns: ``method`` (robust mode: direct, direct backwards, middle ball, canonical strip),
moves and time steps with their lower bounds and the ratio plan / bound.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import resource
import statistics
import sys
import time
from collections.abc import Callable
from concurrent.futures import ProcessPoolExecutor
from pathlib import Path

from hexbot.bench.quiet_child import quiet_on_ctrl_c
from hexbot.cli_args import comma_list, count, one_of, whole_in
from hexbot.errors import UsageError
from hexbot.planning.bounds import plan_bounds
from hexbot.planning.budget import DEFAULT_BUDGET
from hexbot.planning.config_io import load_configuration
from hexbot.planning.configuration import Configuration
from hexbot.planning.generate import parallelogram, random_blob
from hexbot.planning.robust import plan_robust
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

#: The most modules of a pair built here (also the sweep kind ``plan``'s
#: ``modules``): growing a random blob takes time quadratic in its size (about
#: 1 s at 10,000 modules, 38 s at 100,000), so a larger count spends hours
#: building the pair, and 10^10 never gets past it.
MAX_MODULES = 100_000
#: A pair's module count: ``--sizes`` and the other size lists, and the plan kind.
module_count = whole_in(2, MAX_MODULES)
#: ``--exhaustive N`` and ``--hub N``: all polyhexes of N modules, N >= 2 (one
#: module has no pair to plan); the upper end is the module count of a pair.
polyhex_size = whole_in(2, MAX_MODULES)


def parallelogram_size(text: str) -> int:
    """argparse type of a parallelogram pair's module count: one that
    :data:`PARALLELOGRAMS` has shapes for (``--cases --sizes``, and the plan
    kind's ``family = "parallelogram"`` tasks); 7 was a KeyError traceback."""
    value = module_count(text)
    if value not in PARALLELOGRAMS:
        raise argparse.ArgumentTypeError(
            f"the parallelogram sizes are {', '.join(map(str, PARALLELOGRAMS))}, got {value}")
    return value


def size_list(text: str, option: str, size: Callable[[str], int] = module_count,
              none_ok: bool = False) -> list[int]:
    """A comma-separated list of module counts (each checked by ``size``); a
    bad one, an empty one (``10,,30``) or none (``""``, unless ``none_ok``:
    ``--cases --apart-sizes ""`` leaves that family out) is a usage error."""
    if none_ok and not text.strip():
        return []
    try:
        return comma_list(size)(text)
    except argparse.ArgumentTypeError as exc:
        raise UsageError(f"{option}: {exc}") from None


def timed(fn):
    start = time.perf_counter()
    result = fn()
    return result, time.perf_counter() - start


def row(family: str, n: int, plan, seconds: float, initial, goal) -> dict:
    bounds = plan_bounds(initial, goal, plan.fixed)
    return {
        "family": family,
        "modules": n,
        "mode": plan.mode,
        "reached": plan.reached,
        "seconds": round(seconds, 3),
        "moves": plan.move_count,
        "time_steps": plan.time_steps,
        "move_lower_bound": bounds.moves.value,
        "step_lower_bound": bounds.time_steps.value,
        "bottleneck": bounds.bottleneck.value,
        "method": plan.method,
        "reason": plan.reason,
        "tried": plan.tried,  # why the methods before ``method`` did not plan
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


def scan(count: int) -> int:
    """Completion over many small random pairs (counts per method, failures
    listed); 1 if any pair was not planned."""
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
    return 1 if methods["not reached"] else 0


def exhaustive(size: int) -> int:
    """Every ordered pair of distinct connected configurations of ``size``
    modules (all polyhexes, both placed with their smallest cell at (0, 0)),
    free and with that shared cell's module fixed. Prints the counts and every
    failure; 1 if any."""
    from hexbot.planning.generate import polyhexes

    shapes = polyhexes(size)
    pairs = [(a, b) for a in shapes for b in shapes if a != b]
    return _plan_all(pairs, f"{size} modules, {len(shapes)} shapes, {len(pairs)} pairs")


def through_hub(size: int) -> int:
    """Every connected configuration of ``size`` modules to a compact one (the
    hub: the ball of ``size`` cells, placed like the others with its smallest
    cell at (0, 0)) and back, free and with the (0, 0) module fixed. If all are
    planned, every ordered pair is reachable (through the hub). Prints the
    counts and every failure; 1 if any."""
    from hexbot.planning.generate import hub, polyhexes

    shapes = polyhexes(size)
    middle = hub(size)
    pairs = [p for shape in shapes if shape != middle for p in ((shape, middle), (middle, shape))]
    return _plan_all(pairs, f"{size} modules, {len(shapes)} shapes to the hub and back")


def _plan_all(pairs: list[tuple[frozenset, frozenset]], label: str) -> int:
    """Plan every pair free and with the (0, 0) module fixed, each plan replayed
    by the independent checker; one line of counts per case, one per failure."""
    from collections import Counter

    from hexbot.planning.checker import check_plan

    failures = 0
    for fixed in (None, (0, 0)):
        methods: Counter[str] = Counter()
        t0 = time.perf_counter()
        for a, b in pairs:
            start = Configuration.from_cells(a)
            plan = plan_robust(start, b, fixed=fixed)
            report = check_plan(start, b, plan.steps, fixed=fixed) if plan.reached else None
            if report is not None and report.ok:
                methods[plan.method] += 1
                continue
            failures += 1
            why = plan.reason or (report.problem if report else "")
            print(f"{sorted(a)} -> {sorted(b)} (fixed {fixed}): {why}")
        print(f"{label}, fixed {fixed}: "
              + ", ".join(f"{k} {v}" for k, v in methods.most_common())
              + f"; {time.perf_counter() - t0:.1f} s")
    return 1 if failures else 0


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
    parser.add_argument("--families", type=family_list, default=list(FAMILIES),
                        help=f"families to plan, comma-separated (default {','.join(FAMILIES)})")
    parser.add_argument("--fixed", choices=("both", "yes", "no"), default="both",
                        help="families: with the module at (0, 0) fixed to the base, without, "
                             "or both (default)")
    parser.add_argument("--budget", type=float, default=DEFAULT_BUDGET,
                        help=f"families: time budget per pair in seconds "
                             f"(default {DEFAULT_BUDGET:g})")
    parser.add_argument("--blob-sizes", default="10,30,100,1000",
                        help="--cases: random blob sizes (\"\": none)")
    parser.add_argument("--apart-sizes", default="10,30,100",
                        help="--cases: random blob sizes with the goal apart from the initial "
                             "(\"\": none)")
    parser.add_argument("--seeds", type=count, default=None,
                        help="pairs per size (families: default per size, see SEEDS; "
                             "--cases: 5)")
    parser.add_argument("--json", action="store_true", help="JSON lines instead of a table")
    parser.add_argument("--cases", action="store_true",
                        help="the per-case table: thesis, parallelograms, blobs, apart")
    parser.add_argument("--small", action="store_true",
                        help="only: exact vs robust on the small bank (optimality gap)")
    parser.add_argument("--scan", type=count, metavar="N",
                        help="only: completion over N small random pairs")
    parser.add_argument("--exhaustive", type=polyhex_size, metavar="N",
                        help="only: every pair of connected configurations of N modules, "
                             "free and fixed")
    parser.add_argument("--hub", type=polyhex_size, metavar="N",
                        help="only: every connected configuration of N modules to a compact "
                             "one and back, free and fixed")


def run(args: argparse.Namespace) -> int:
    if args.scan is not None:
        return scan(args.scan)
    if args.exhaustive is not None:
        return exhaustive(args.exhaustive)
    if args.hub is not None:
        return through_hub(args.hub)
    if args.small:
        return run_small(args)
    if not args.cases:
        return run_families(args)
    args.seeds = 5 if args.seeds is None else args.seeds
    # all checked before any work
    sizes = size_list(DEFAULT_SIZES if args.sizes is None else args.sizes, "--sizes",
                      parallelogram_size)
    blob_sizes = size_list(args.blob_sizes, "--blob-sizes", none_ok=True)
    apart_sizes = size_list(args.apart_sizes, "--apart-sizes", none_ok=True)
    rows = (bench_thesis() + bench_parallelograms(sizes) + bench_blobs(blob_sizes, args.seeds)
            + bench_blobs(apart_sizes, args.seeds, "apart"))
    if args.json:
        for r in rows:
            print(json.dumps(r))
        return 0
    print(markdown_table(rows))
    # (the thesis' own planners may stall on Test_All_S02: that row is theirs)
    failed = [r for r in rows if not r["reached"] and "faithful" not in r["family"]]
    for r in failed:
        print(f"\n{r['family']} ({r['modules']}): {r['reason']}")
    return 1 if failed else 0


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


#: pairs per module count (the 10,000-module pairs take minutes each)
SEEDS = {10: 10, 30: 10, 100: 6, 300: 4, 1000: 3, 10000: 1}
DEFAULT_SIZES = "10,30,100,300,1000"
#: the per-family table's families (``--families``)
FAMILIES = ("blob", "scramble", "holes")
#: ``--families``: some of FAMILIES, comma-separated
family_list = comma_list(one_of(FAMILIES, "family"))


def make_pair(family: str, n: int, seed: int):
    from hexbot.planning.generate import blob_pair, holes_pair, scramble

    if family == "holes":
        return holes_pair(n, seed)
    initial, other = blob_pair(n, seed)
    if family == "blob":
        return initial, other
    if family == "scramble":
        return initial, scramble(initial, 3 * n, seed)
    raise ValueError(f"unknown family {family!r} ({', '.join(FAMILIES)})")


def plan_pair(family: str, n: int, seed: int, fixed: bool, budget: float) -> dict:
    """Plan one pair, check it independently, measure it (runs in a child process)."""
    from hexbot.planning.checker import check_plan
    from hexbot.planning.configuration import Configuration
    from hexbot.planning.robust import plan_robust

    initial, goal = make_pair(family, n, seed)
    start = Configuration.from_cells(initial)
    anchor = (0, 0) if fixed else None
    t0 = time.perf_counter()
    plan = plan_robust(start, goal, fixed=anchor, budget=budget)
    seconds = time.perf_counter() - t0
    report = check_plan(start, goal, plan.steps, fixed=anchor) if plan.reached else None
    bounds = plan_bounds(initial, goal, anchor)
    moves, steps, plain = bounds.moves, bounds.time_steps, bounds.bottleneck
    return {
        "family": family, "modules": n, "seed": seed, "fixed": fixed,
        "planned": bool(report and report.ok),
        "method": plan.method,
        "reason": plan.reason or (report.problem if report and not report.ok else ""),
        "tried": plan.tried,  # why the methods before ``method`` did not plan
        "warnings": plan.warnings,  # e.g. the schedule ran out of time: one move per step
        "moves": plan.move_count, "move_bound": moves.value, "move_bound_kind": moves.kind,
        "steps": plan.time_steps, "step_bound": steps.value, "step_bound_kind": steps.kind,
        "bottleneck": plain.value, "bottleneck_kind": plain.kind,
        "seconds": round(seconds, 3),
        "peak_mib": round(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024, 1),
    }


def _ratio(a: int, b: int) -> float:
    return a / b if b else 1.0


def summary(rows: list[dict]) -> str:
    """One markdown row per (family, n, fixed)."""
    groups: dict[tuple, list[dict]] = {}
    for r in rows:
        groups.setdefault((r["family"], r["modules"], r["fixed"]), []).append(r)
    lines = ["| family | n | fixed | planned | moves / LB (min, median, max) "
             "| makespan / pivot bound (min, median, max) | median / plain bottleneck "
             "| slowest (s) | peak MiB | methods |",
             "|---|---:|---|---|---|---|---:|---:|---:|---|"]
    for (family, n, fixed), rs in sorted(groups.items()):
        ok = [r for r in rs if r["planned"]]
        def spread(key_a, key_b, ok=ok):
            if not ok:
                return "-"
            vals = sorted(_ratio(r[key_a], r[key_b]) for r in ok)
            return f"{vals[0]:.1f}, {statistics.median(vals):.1f}, {vals[-1]:.1f}"

        def median(key_a, key_b, ok=ok):
            vals = [_ratio(r[key_a], r[key_b]) for r in ok if key_b in r]
            return f"{statistics.median(vals):.1f}" if vals else "-"
        kinds = {r["move_bound_kind"] for r in rs} | {r["step_bound_kind"] for r in rs}
        weak = " (nearest bound)" if "nearest" in kinds else ""
        methods: dict[str, int] = {}
        for r in ok:
            methods[r["method"]] = methods.get(r["method"], 0) + 1
        lines.append(
            f"| {family} | {n:,} | {'yes' if fixed else 'no'} | {len(ok)}/{len(rs)} | "
            f"{spread('moves', 'move_bound')}{weak} | {spread('steps', 'step_bound')} | "
            f"{median('steps', 'bottleneck')} | "
            f"{max(r['seconds'] for r in rs):.2f} | {max(r['peak_mib'] for r in rs):.0f} | "
            + ", ".join(f"{k} {v}" for k, v in sorted(methods.items())) + " |")
    return "\n".join(lines)


def run_families(args: argparse.Namespace) -> int:
    counts = size_list(DEFAULT_SIZES if args.sizes is None else args.sizes, "--sizes")
    families = args.families
    fixed_options = {"both": (False, True), "yes": (True,), "no": (False,)}[args.fixed]
    jobs = [(family, n, seed, fixed, args.budget)
            for family in families for n in counts
            for seed in range(args.seeds if args.seeds is not None else SEEDS.get(n, 1))
            for fixed in fixed_options]
    rows = []
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(1, mp_context=context, max_tasks_per_child=1,
                             initializer=quiet_on_ctrl_c) as pool:
        for job, future in [(job, pool.submit(plan_pair, *job)) for job in jobs]:
            row = future.result()
            rows.append(row)
            if args.json:
                print(json.dumps(row), flush=True)
            elif not row["planned"]:
                print(f"not planned: {job[:4]}: {row['reason']}", file=sys.stderr, flush=True)
    if not args.json:
        print(summary(rows))
    missed = sum(not r["planned"] for r in rows)
    if missed:
        print(f"{missed} of {len(rows)} pairs not planned", file=sys.stderr)
    return 1 if missed else 0


def run_small(args: argparse.Namespace) -> int:
    """Exact (A*) vs robust on the small bank: the robust mode's optimality gap."""
    from hexbot.planning.bank import small_cases
    from hexbot.planning.checker import check_plan
    from hexbot.planning.exact import plan_exact
    from hexbot.planning.robust import plan_robust

    lines = ["| case | n | optimum (exact) | exact time (s) | robust moves | gap |",
             "|---|---:|---:|---:|---:|---:|"]
    gaps, missed = [], []
    for case in small_cases():
        t0 = time.perf_counter()
        exact = plan_exact(case.initial, case.goal, case.fixed, budget=args.budget)
        dt = time.perf_counter() - t0
        robust = plan_robust(case.initial, case.goal, fixed=case.fixed, budget=args.budget)
        legal = robust.reached and check_plan(case.initial, case.goal, robust.steps,
                                              case.fixed).ok
        gap = (robust.move_count / exact.move_count
               if exact.reached and legal and exact.move_count else None)
        if gap is not None:
            gaps.append(gap)
        if not legal:
            missed.append(case.name)
        row = {"case": case.name, "modules": len(case.initial),
               "optimum": exact.move_count if exact.reached else None,
               "exact_reason": exact.reason, "exact_seconds": round(dt, 3),
               "robust": robust.move_count if legal else None, "gap": gap}
        if args.json:
            print(json.dumps(row))
        lines.append(f"| {case.name} | {len(case.initial)} | "
                     f"{row['optimum'] if row['optimum'] is not None else exact.reason} | "
                     f"{dt:.2f} | {row['robust'] if legal else robust.reason} | "
                     f"{f'{gap:.2f}' if gap is not None else '-'} |")
    if not args.json:
        print("\n".join(lines))
        if gaps:
            print(f"\nrobust / optimum over {len(gaps)} cases: min {min(gaps):.2f}, "
                  f"median {statistics.median(gaps):.2f}, max {max(gaps):.2f}")
    if missed:  # the yardstick is for plans that exist and are legal
        print(f"robust mode did not plan (or the checker refused): {', '.join(missed)}",
              file=sys.stderr)
    return 1 if missed else 0
