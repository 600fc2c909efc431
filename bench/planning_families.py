"""``hexbot bench planning``: the per-family table and the small bank (see bench/planning.py).

Each pair runs in a fresh process (``spawn``, one task per child) so that its
peak memory is its own: ``ru_maxrss`` of that process, interpreter, numpy and
scipy included (about 60-70 MiB before any planning).
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import resource
import statistics
import sys
import time
from concurrent.futures import ProcessPoolExecutor

#: pairs per module count (the 10,000-module pairs take minutes each)
SEEDS = {10: 10, 30: 10, 100: 6, 300: 4, 1000: 3, 10000: 1}
DEFAULT_SIZES = "10,30,100,300,1000"


def make_pair(family: str, n: int, seed: int):
    from hexbot.planning.generate import blob_pair, scramble

    initial, other = blob_pair(n, seed)
    if family == "blob":
        return initial, other
    if family == "scramble":
        return initial, scramble(initial, 3 * n, seed)
    raise ValueError(f"unknown family {family!r} (blob, scramble)")


def plan_pair(family: str, n: int, seed: int, fixed: bool, budget: float) -> dict:
    """Plan one pair, check it independently, measure it (runs in a child process)."""
    from hexbot.planning.bounds import move_lower_bound, step_bound
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
    moves, steps = move_lower_bound(initial, goal), step_bound(initial, goal)
    return {
        "family": family, "modules": n, "seed": seed, "fixed": fixed,
        "planned": bool(report and report.ok),
        "method": plan.method,
        "reason": plan.reason or (report.problem if report and not report.ok else ""),
        "moves": plan.move_count, "move_bound": moves.value, "move_bound_kind": moves.kind,
        "steps": plan.time_steps, "step_bound": steps.value, "step_bound_kind": steps.kind,
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
             "| makespan / bottleneck (min, median, max) | slowest (s) | peak MiB | methods |",
             "|---|---:|---|---|---|---|---:|---:|---|"]
    for (family, n, fixed), rs in sorted(groups.items()):
        ok = [r for r in rs if r["planned"]]
        def spread(key_a, key_b, ok=ok):
            if not ok:
                return "-"
            vals = sorted(_ratio(r[key_a], r[key_b]) for r in ok)
            return f"{vals[0]:.1f}, {statistics.median(vals):.1f}, {vals[-1]:.1f}"
        kinds = {r["move_bound_kind"] for r in rs} | {r["step_bound_kind"] for r in rs}
        weak = " (nearest bound)" if "nearest" in kinds else ""
        methods: dict[str, int] = {}
        for r in ok:
            methods[r["method"]] = methods.get(r["method"], 0) + 1
        lines.append(
            f"| {family} | {n:,} | {'yes' if fixed else 'no'} | {len(ok)}/{len(rs)} | "
            f"{spread('moves', 'move_bound')}{weak} | {spread('steps', 'step_bound')} | "
            f"{max(r['seconds'] for r in rs):.2f} | {max(r['peak_mib'] for r in rs):.0f} | "
            + ", ".join(f"{k} {v}" for k, v in sorted(methods.items())) + " |")
    return "\n".join(lines)


def run_families(args: argparse.Namespace) -> int:
    sizes = [int(s) for s in (args.sizes or DEFAULT_SIZES).split(",") if s]
    families = [f for f in args.families.split(",") if f]
    fixed_options = {"both": (False, True), "yes": (True,), "no": (False,)}[args.fixed]
    jobs = [(family, n, seed, fixed, args.budget)
            for family in families for n in sizes
            for seed in range(args.seeds if args.seeds is not None else SEEDS.get(n, 1))
            for fixed in fixed_options]
    rows = []
    context = multiprocessing.get_context("spawn")
    with ProcessPoolExecutor(1, mp_context=context, max_tasks_per_child=1) as pool:
        for job, future in [(job, pool.submit(plan_pair, *job)) for job in jobs]:
            row = future.result()
            rows.append(row)
            if args.json:
                print(json.dumps(row), flush=True)
            elif not row["planned"]:
                print(f"not planned: {job[:4]}: {row['reason']}", file=sys.stderr, flush=True)
    if not args.json:
        print(summary(rows))
    return 0


def run_small(args: argparse.Namespace) -> int:
    """Exact (A*) vs robust on the small bank: the robust mode's optimality gap."""
    from hexbot.planning.bank import small_cases
    from hexbot.planning.checker import check_plan
    from hexbot.planning.exact import plan_exact
    from hexbot.planning.robust import plan_robust

    lines = ["| case | n | optimum (exact) | exact time (s) | robust moves | gap |",
             "|---|---:|---:|---:|---:|---:|"]
    gaps = []
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
    return 0
